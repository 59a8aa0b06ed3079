"""Residual along the creep curves through the worst rows of the +wb rel2 fit."""
import sys; sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__))); import numpy as np
sys.argv=['x','x']
import cap
import fit_rolling_surrogate as F
tr,ho=cap.load()
bt=cap.poly_blocks(tr,['wb'],3,rel=2)
o=cap.evaluate(tr,ho,bt,cap.poly_blocks(ho,['wb'],3,rel=2),kf=5,name='wb rel2')
fit=tr['base']+np.concatenate([bt(lo,lo+4000)@o['coef'] for lo in range(0,len(tr['aob']),4000)])
e=o['tr_e']
u=tr['s']/np.linalg.norm(tr['s'],axis=1)[:,None]
done=[]
for j in np.argsort(-e)[:40]:
    m=(np.abs(tr['aob']-tr['aob'][j])<1e-9)&(np.abs(tr['theta']-tr['theta'][j])<1e-9)&(np.abs(tr['nu']-tr['nu'][j])<1e-9)&(np.abs(u-u[j]).sum(1)<1e-6)
    key=tuple(np.where(m)[0][:1])
    if key in done or m.sum()<3: continue
    done.append(key)
    if len(done)%2==0: continue
    idx=np.where(m)[0]; idx=idx[np.argsort(tr['rho'][idx])]
    print(f"curve a/b {tr['aob'][j]:.2f} theta {np.degrees(tr['theta'][j]):.1f} nu {tr['nu'][j]:.2f} dir {np.round(u[j],3)} sigma {F.spin_share(tr)[j]:.2f}, {m.sum()} pts")
    for i in idx:
        print(f"   rho {tr['rho'][i]:7.3f} ref {np.round(tr['ref'][i],3)} base {np.round(tr['base'][i],3)} fit {np.round(fit[i],3)} e {e[i]:.2f} referr {np.round(tr['err'][i],4)}")
    if len(done)>=8: break
