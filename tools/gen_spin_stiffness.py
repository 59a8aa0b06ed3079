#!/usr/bin/env python3
"""Reference for `friction::best::spin_stiffness` (kappa_T of the ramped `best` law's drilling
torque) and `Friction::<T, Best>::stable_spin_step`.

Independent of the crate: mpmath at dps 40 (A, B, C and the quartic's c40, c22 from
ellipk/ellipe, as tools/gen_best_stiffness.py) and a direct maximisation (numpy grid, then a
pattern search in mpmath to 1e-20).

Below the slip scale (s = |vx| + |vy| + |aw| < delta) the wrapper gives
T_z = (fN a) (s/delta) tau, tau the core's torque (degree 0 in (vx, vy, aw)). With W = aw > 0
and the IC (X, Y) = (-vy, vx)/W inside the ellipse, tau = -Psi + X Psi_X + Y Psi_Y
= -C + q2 + q4, q2 = (B/2) X^2 + (A/2) Y^2, q4 = 3 (c40 (X^4 + Y^4/m1) + c22 X^2 Y^2)
(model.md section 3, the quartic), and dX/dW = -X/W, dY/dW = -Y/W, so the torque stiffness
-dT_z/d(omega) = (fN a^2/delta) k_T with

    k_T = -tau - s/W (X tau_X + Y tau_Y) = C - q2 - q4 + (1 + |X| + |Y|) (2 q2 + 4 q4).

kappa_T = max of k_T over the inside region {X^2 + Y^2/m1 <= 1} (degree 0: the same for every
W < delta/(1 + |X| + |Y|)). Pure spin (X = Y = 0) gives C. The crate's tests check on the whole
direction sphere, with the exact law, that nothing outside the ellipse or past the ramp is
stiffer (for e^2 <= 0.99; below m1 ~ 1e-5 the maximiser reaches the ellipse, rho = 1).

tools/data/spin_stiffness.csv  columns m1,C,kappa_t,X,Y  (X, Y: the maximiser, aw = 1)
  on the m1 grid of tools/gen_best_stiffness.py.

Run:  python3 tools/gen_spin_stiffness.py
"""
import os
import mpmath as mp
import numpy as np

from gen_best_stiffness import constants

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))


def k_t(x, y, m1, a, b, c, c40, c22):
    q2 = b / 2 * x**2 + a / 2 * y**2
    q4 = 3 * (c40 * (x**4 + y**4 / m1) + c22 * x**2 * y**2)
    return c - q2 - q4 + (1 + x + y) * (2 * q2 + 4 * q4)


def point(m1, rho, t, lib=mp):
    # (rho, t) in [0, 1]^2 covers the first quadrant of the inside region
    return rho * lib.cos(t * lib.pi / 2), lib.sqrt(m1) * rho * lib.sin(t * lib.pi / 2)


def kappa_t(m1):
    m1, a, b, c40, c22 = constants(m1)
    c = mp.mpf(3) / 8 * mp.ellipe(1 - m1)
    consts = (m1, a, b, c, c40, c22)
    fa = [float(v) for v in consts]
    g = np.linspace(0.0, 1.0, 401)
    rho, t = np.meshgrid(g, g)
    x, y = point(fa[0], rho, t, lib=np)
    kk = k_t(x, y, *fa)
    i = np.unravel_index(np.argmax(kk), kk.shape)
    r, tt = mp.mpf(rho[i]), mp.mpf(t[i])

    def f(r, tt):
        return k_t(*point(m1, r, tt), *consts)

    best = f(r, tt)
    step = mp.mpf(1) / 400
    while step > mp.mpf("1e-20"):
        moved = False
        for dr, dt in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)):
            nr = min(max(r + dr * step, mp.mpf(0)), mp.mpf(1))
            nt = min(max(tt + dt * step, mp.mpf(0)), mp.mpf(1))
            v = f(nr, nt)
            if v > best:
                best, r, tt, moved = v, nr, nt, True
                break
        if not moved:
            step /= 2
    x, y = point(m1, r, tt)
    return c, best, x, y


def main():
    m1s = [mp.mpf(k) / 20 for k in range(20, 0, -1)]
    m1s += [mp.mpf(10) ** (-mp.mpf(k) / 4) for k in range(6, 49)]
    m1s += [mp.mpf("0.01"), mp.mpf("0.001")]
    m1s = sorted(set(m1s), reverse=True)
    rows = ["m1,C,kappa_t,X,Y"]
    for m1 in m1s:
        c, k, x, y = kappa_t(m1)
        rows.append(",".join(mp.nstr(v, 25) for v in (m1, c, k, x, y)))
        print(rows[-1], flush=True)
    with open(os.path.join(HERE, "data", "spin_stiffness.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
