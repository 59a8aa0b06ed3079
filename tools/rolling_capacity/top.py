"""Top rows of a variant's training fit: cap.py top.py EXTRA REL (e.g. wb 2)."""
import sys; sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__))); import numpy as np
ex = sys.argv[1].split(',') if sys.argv[1] != '-' else []
rel = int(sys.argv[2]) if sys.argv[2] != '-' else None
sys.argv=['x','x']
import cap, math
import fit_rolling_surrogate as F, fit_rolling_long as L
tr,ho=cap.load()
o=cap.evaluate(tr,ho,cap.poly_blocks(tr,ex,3,rel=rel),cap.poly_blocks(ho,ex,3,rel=rel),name=str(ex)+str(rel))
cap.report(o)
for lab,e in (("train",o['tr_e']),("5-fold",o['cv_e'])):
    idx=np.argsort(-e)[:60:2]
    sig=F.spin_share(tr); t=L.aligned_t(tr); rx=(1+t)/(1-t)
    r=np.where(tr['aob']>=1,tr['aob'],1/tr['aob'])
    psi=np.degrees(np.where(tr['aob']>=1,tr['theta'],tr['theta']+0.5*np.pi))%180; psi=np.minimum(psi,180-psi)
    print(lab, "top 30 (of pairs): e, major a/b, a/b along x, psi, nu, sigma, rho, refErrF/M")
    for j in idx:
        print(f"  {e[j]:.2f} {r[j]:6.2f} {rx[j]:6.2f} {psi[j]:4.0f} {tr['nu'][j]:.2f} {sig[j]:.2f} {tr['rho'][j]:6.2f} {tr['err'][j,0]:.4f}/{tr['err'][j,1]:.4f} {'long2' if j>=19380 else 'main'}")
    for thr in (1,2,3):
        m=e>thr
        print(f"  e>{thr}: {m.sum()} rows; major a/b>5: {(m&(r>5)).sum()}, psi<10: {(m&(psi<10)).sum()}, rho 1-5: {(m&(tr['rho']>1)&(tr['rho']<5)).sum()}, sigma 0.3-0.7: {(m&(sig>.3)&(sig<.7)).sum()}")
