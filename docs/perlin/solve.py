# Step 2: noise is linear in the lattice gradients, so they follow by least squares
# from the values of step 1; prints how well the model fits and how close each gradient
# is to a cube-edge direction. usage: python3 solve.py /tmp/perlin/sphere_perlin_1.npz
import numpy as np, sys
z=np.load(sys.argv[1]); p=z['p']; n=z['n']
fade=lambda t:t*t*t*(t*(t*6-15)+10)
base=np.floor(p).astype(int); f=p-base
rows=[];cols=[];vals=[]
keys={}
def key(c):
    k=tuple(c)
    if k not in keys: keys[k]=len(keys)
    return keys[k]
M=len(p)
idx=np.zeros((M,8),int); coef=np.zeros((M,8,3))
for c in range(8):
    o=np.array([c&1,(c>>1)&1,(c>>2)&1])
    corner=base+o; dvec=f-o
    w=np.prod(np.where(o==1,fade(f),1-fade(f)),axis=1)
    ks=[key(tuple(x)) for x in corner]
    idx[:,c]=ks; coef[:,c,:]=w[:,None]*dvec
N=len(keys); print('lattice points',N,'pixels',M)
cidx=(idx[:,:,None]*3+np.arange(3)).reshape(M,24); cc=coef.reshape(M,24)
AtA=np.zeros((3*N,3*N)); Atb=np.zeros(3*N)
for a in range(24):
    np.add.at(Atb,cidx[:,a],cc[:,a]*n)
    for b in range(24):
        np.add.at(AtA,(cidx[:,a],cidx[:,b]),cc[:,a]*cc[:,b])
lam=1e-3
g=np.linalg.solve(AtA+lam*np.eye(3*N),Atb).reshape(N,3)
res=n-(cc*g.reshape(-1)[cidx]).sum(1)
print('rms residual',np.sqrt((res**2).mean()),'rms n',np.sqrt((n**2).mean()))
G=np.array([(1,1,0),(-1,1,0),(1,-1,0),(-1,-1,0),(1,0,1),(-1,0,1),(1,0,-1),(-1,0,-1),(0,1,1),(0,-1,1),(0,1,-1),(0,-1,-1)],float)
# support count per lattice point
cnt=np.bincount(idx.reshape(-1),minlength=N)
inv={v:k for k,v in keys.items()}
out=[]
for i in range(N):
    if cnt[i]<200: continue
    dots=G@g[i]/np.sqrt(2); j=np.argmax(dots)
    out.append((inv[i],j,np.linalg.norm(g[i]),dots[j]/max(np.linalg.norm(g[i]),1e-9)))
print('well-supported',len(out))
import collections
print('norm quantiles',np.percentile([o[2] for o in out],[10,50,90]))
print('cos quantiles',np.percentile([o[3] for o in out],[10,50,90]))
np.save(sys.argv[1].replace('.npz','_grad.npy'),np.array([list(o[0])+[o[1],o[2],o[3]] for o in out]))
