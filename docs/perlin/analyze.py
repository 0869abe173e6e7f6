# Step 3: keeps the confidently recovered lattice gradients (as ids of the 12 edge
# directions) and tests which periods the lattice has along each axis; writes
# /tmp/perlin/gamma.npy. usage: python3 analyze.py /tmp/perlin/sphere_perlin_1_grad.npy
import numpy as np, sys, collections
a=np.load(sys.argv[1])
good=a[(a[:,5]>0.98)&(a[:,4]>1.2)]
Gam={(int(r[0]),int(r[1]),int(r[2])):int(r[3]) for r in good}
print('confident',len(Gam))
for axis in range(3):
  for period in (8,16,32,256):
    same=tot=0
    for k,v in Gam.items():
        k2=list(k); k2[axis]+=period; k2=tuple(k2)
        if k2 in Gam: tot+=1; same+=(Gam[k2]==v)
    print('axis',axis,'period',period,same,'/',tot)
xs=sorted(set(k[0] for k in Gam)); ys=sorted(set(k[1] for k in Gam)); zs=sorted(set(k[2] for k in Gam))
print(xs[0],xs[-1],ys[0],ys[-1],zs[0],zs[-1])
np.save('/tmp/perlin/gamma.npy',np.array([list(k)+[v] for k,v in Gam.items()]))
