#!/usr/bin/env python3
"""Exploration (not a reference, not used by tests): how much the coupling of translation and
spin shortens the stable explicit step of the ramped `best` law when v_P and omega both move.

State (vx, vy, W = a*omega), masses m and I; in units of fN/(m delta) the ramped law inside the
ellipse gives d/dt (vx, vy, W) = s * (Fx, Fy, mu * tau) with mu = m a^2 / I, the exact quartic's
force and torque (see tools/gen_spin_stiffness.py), s = |vx| + |vy| + |W| (scaled to s = delta/2).
For each direction on a grid, the 3 x 3 Jacobian J (finite differences, numpy) gives Euler's
bound |lambda|^2/Re(lambda) per eigenvalue; Lambda = max over directions and eigenvalues,
compared with max(kappa, mu * kappa_T) (the translational and spin limits taken separately).

Output: circle: Lambda / max = 1.003 (mu 0.1), 1.041 (1), 1.162 (2.5), 1.014 (10);
m1 = 0.1: 1.0001, 1.0007, 1.003, 1.016.

Run:  python3 tools/explore_coupled_step.py
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_best_stiffness import constants
import mpmath as mp
def run(m1, mu, n=120):
    m1_,a,b,c40,c22 = [float(v) for v in constants(m1)]
    C = 3/8*float(mp.ellipe(1-m1))
    def G(vx,vy,W):
        X, Y = -vy/W, vx/W
        PsiX = b*X + 4*c40*X**3 + 2*c22*X*Y**2
        PsiY = a*Y + 4*c40*Y**3/m1_ + 2*c22*X**2*Y
        Psi = C + b/2*X**2 + a/2*Y**2 + c40*(X**4+Y**4/m1_) + c22*X**2*Y**2
        s = abs(vx)+abs(vy)+abs(W)
        return np.array([s*(-PsiY), s*PsiX, mu*s*(-Psi + X*PsiX + Y*PsiY)])
    best=(0,None); kap=0; kapT=0
    for r in np.linspace(0,1,n):
        for th in np.linspace(0,np.pi/2,n):
            X, Y = r*np.cos(th), np.sqrt(m1_)*r*np.sin(th)
            W = 1.0; vx, vy = Y*W, -X*W
            sc = 0.5/(1+X+Y); vx,vy,W = vx*sc,vy*sc,W*sc
            h=1e-7
            g0=G(vx,vy,W)
            J=np.zeros((3,3))
            for j,(dx,dy,dw) in enumerate([(h if vx>=0 else -h,0,0),(0,h if vy>=0 else -h,0),(0,0,h)]):
                J[:,j]=-(G(vx+dx,vy+dy,W+dw)-g0)/(dx+dy+dw)
            ev=np.linalg.eigvals(J)
            lam=max((abs(l)**2/l.real if l.real>0 else np.inf) for l in ev)
            kap=max(kap, max(np.linalg.eigvals(J[:2,:2]).real)); kapT=max(kapT,J[2,2]/mu)
            if lam>best[0]: best=(lam,(X,Y))
    return best, kap, kapT
for m1 in [1.0, 0.1]:
    for mu in [0.1, 1.0, 2.5, 10.0]:
        (lam,xy),kap,kapT = run(m1,mu)
        ref = max(kap, mu * kapT)
        print(f"m1 {m1} mu {mu}: Lambda {lam:.4f} (IC {xy[0]:.3f}, {xy[1]:.3f}), max(kappa, mu kappa_T) {ref:.4f}, ratio {lam / ref:.4f}")
