# Step 1 of the recovery of the course's Perlin lattice (docs/textures.md). From the
# official sphere_perlin image, the noise value at every visible point of one sphere:
# with ambient 0 a pixel is kd * D + S (D, S: the scene's six point lights, computed here
# with shadows), kd = (n + 1) / 2 for NoiseConversion linear, and the image truncates.
# usage: /usr/bin/python3 invert.py sphere_perlin 1 1   (scene, sphere index, NoiseScale)
# Writes /tmp/perlin/<scene>_<sphere>.npz. Needs numpy (Debian python3-numpy).
# Recover noise values n(p) at visible points of sphere_perlin's linear sphere from the
# official image: pixel = kd * D + S with kd = (n + 1) / 2 (truncated to 8 bits).
import numpy as np, zlib, struct, sys
def read_png(path):
    data=open(path,'rb').read(); pos=8; idat=b''; w=h=0
    while pos < len(data):
        ln,=struct.unpack('>I',data[pos:pos+4]); typ=data[pos+4:pos+8]; body=data[pos+8:pos+8+ln]; pos+=12+ln
        if typ==b'IHDR': w,h,bd,ct=struct.unpack('>IIBB',body[:10])
        if typ==b'IDAT': idat+=body
    raw=zlib.decompress(idat); ch={2:3,6:4}[ct]; stride=w*ch
    img=np.zeros((h,stride),np.int32); prev=np.zeros(stride,np.int32); i=0
    for y in range(h):
        f=raw[i]; line=np.frombuffer(raw[i+1:i+1+stride],np.uint8).astype(np.int32); i+=1+stride
        out=np.zeros(stride,np.int32)
        if f==0: out=line
        elif f==2: out=(line+prev)&255
        else:
            for x in range(stride):
                a=out[x-ch] if x>=ch else 0; b=prev[x]; c=prev[x-ch] if x>=ch else 0
                if f==1: p=a
                elif f==3: p=(a+b)//2
                else:
                    pa=abs(b-c); pb=abs(a-c); pc=abs(a+b-2*c)
                    p=a if pa<=pb and pa<=pc else (b if pb<=pc else c)
                out[x]=(line[x]+p)&255
        img[y]=out; prev=out
    return img.reshape(h,w,ch)[:,:,:3]
scene=sys.argv[1]; sphere=int(sys.argv[2]); scale=float(sys.argv[3])
ref=read_png(f'/work/shared/scenes/hw4/reference/{scene}.png').astype(np.float64)
W=H=800; cam=np.array([0,5,225.]); near=10.
centers=[np.array([-10,10,0.]),np.array([10,10,0.])]; R=10.
lights=[((20,20,20),1e5),((-15,30,5),1e5),((-15,20,50),1e5),((-15,-30,5),1e5),((-15,-20,50),1e5),((15,-20,50),1e5)]
ys,xs=np.mgrid[0:H,0:W]
su=(xs+0.5)/W*2-1; sv=1-(ys+0.5)/H*2
d=np.stack([su,sv,-near*np.ones_like(su)],-1); d/=np.linalg.norm(d,axis=-1,keepdims=True)
def hit(o,d,c):
    oc=o-c; b=(d*oc).sum(-1); cc=(oc*oc).sum(-1)-R*R; disc=b*b-cc
    t=-b-np.sqrt(np.maximum(disc,0)); return np.where((disc>0)&(t>1e-4),t,np.inf)
t0=hit(cam,d,centers[0]); t1=hit(cam,d,centers[1])
mine=(t1<t0) if sphere==1 else (t0<t1)
t=np.where(mine,np.minimum(t0,t1),np.inf); ok=np.isfinite(t)
p=cam+d*t[...,None]; c=centers[sphere]; n=(p-c)/R
D=np.zeros(p.shape[:2]); S=np.zeros(p.shape[:2])
other=centers[1-sphere]
for L,I in lights:
    L=np.array(L,float); tl=L-p; dist2=(tl*tl).sum(-1); wi=tl/np.sqrt(dist2)[...,None]
    cos=(n*wi).sum(-1)
    # shadow by the other sphere
    oc=p-other; b=(wi*oc).sum(-1); cc=(oc*oc).sum(-1)-R*R; disc=b*b-cc
    ts=-b-np.sqrt(np.maximum(disc,0)); sh=(disc>0)&(ts>0)&(ts*ts<dist2)
    vis=(cos>0)&~sh
    E=I/dist2
    h=wi-d; h/=np.linalg.norm(h,axis=-1,keepdims=True)
    ch=np.maximum((n*h).sum(-1),0)
    D+=np.where(vis,E*cos,0); S+=np.where(vis,E*ch**300,0)
g=ref[...,0]
kd=(g+0.5-S)/np.maximum(D,1e-9)
use=ok&(D>150)&(g<255)&(S<1)
noise=2*kd-1
print('pixels',use.sum(),'kd range',kd[use].min(),kd[use].max())
np.savez(f'/tmp/perlin/{scene}_{sphere}.npz',p=p[use]*scale,n=noise[use],err=(1/D[use]))
