#!/usr/bin/env python3
"""Reference for `friction::best::ramp_stiffness` (κ of the ramped `best` law) and
`Friction::<T, Best>::stable_step`.

Independent of the crate: mpmath at dps 40 (A, B and the quartic's c40, c22 from ellipk/ellipe)
and a direct maximisation (numpy grid, then a pattern search in mpmath to 1e-20).

Below the slip scale (s = |vx| + |vy| + |aw| < delta) the wrapper gives
F = -(fN/delta) * s * P, P = -F_core/(fN). In units where aw = 1 and the IC is inside the
ellipse, P = (vx (A + k40m vx^2 + k22 vy^2), vy (B + k40 vy^2 + k22 vx^2)), k40 = 4 c40,
k40m = 4 c40/m1, k22 = 2 c22 (model.md section 3, the quartic), s = 1 + vx + vy
(first quadrant: the symmetries make the other quadrants mirror images), and the stiffness
matrix K = s dP/dv + P (1, 1)^T. kappa = max over the inside region
{vy^2 + vx^2/m1 <= 1} of K's largest eigenvalue (real there; where a pair is complex,
the Euler bound |lambda|^2/Re lambda is used). The crate's tests check on the whole direction
sphere, with the exact law, that nothing outside the ellipse or past the ramp is stiffer.

tools/data/best_stiffness.csv  columns m1,A,B,kappa,vx,vy  (vx, vy: the maximiser, aw = 1)
  m1 = 1 - e^2: 1, 0.95, ..., 0.05 (step 0.05) and 10^(-k/4) for k = 6..48 (0.03 ... 1e-12),
  plus e^2 = 0.99 and 0.999.

Run:  python3 tools/gen_best_stiffness.py
"""
import os
import mpmath as mp
import numpy as np

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))


def constants(m1):
    m1 = mp.mpf(m1)
    m = 1 - m1
    if m == 0:
        a = b = 3 * mp.pi / 8
        c40 = -3 * mp.pi / 128
    else:
        k, e = mp.ellipk(m), mp.ellipe(m)
        a = mp.mpf(3) / 2 * (k - e) / m
        b = mp.mpf(3) / 2 * (e - m1 * k) / m
        c40 = -((2 - m) * e - 2 * m1 * k) / (8 * m * m)
    c22 = -(a + 12 * c40) / 2
    return m1, a, b, c40, c22


def lam(vx, vy, m1, a, b, c40, c22, lib=mp):
    k40, k40m, k22 = 4 * c40, 4 * c40 / m1, 2 * c22
    s = 1 + vx + vy
    px = vx * (a + k40m * vx**2 + k22 * vy**2)
    py = vy * (b + k40 * vy**2 + k22 * vx**2)
    hxx = a + 3 * k40m * vx**2 + k22 * vy**2
    hyy = b + 3 * k40 * vy**2 + k22 * vx**2
    hxy = 2 * k22 * vx * vy
    a11, a12, a21, a22 = s * hxx + px, s * hxy + px, s * hxy + py, s * hyy + py
    tr, det = a11 + a22, a11 * a22 - a12 * a21
    disc = tr * tr / 4 - det
    if lib is np:
        re = tr / 2 + np.sqrt(np.maximum(disc, 0))
        im2 = np.maximum(-disc, 0)
        return np.where(disc >= 0, re, (tr * tr / 4 + im2) / (tr / 2))
    if disc >= 0:
        return tr / 2 + mp.sqrt(disc)
    return (tr * tr / 4 - disc) / (tr / 2)


def point(m1, vy, t):
    # vx = t * sqrt(m1 (1 - vy^2)): (vy, t) in [0, 1]^2 covers the inside region
    return t * mp.sqrt(m1 * (1 - vy * vy)), vy


def kappa(m1):
    m1, a, b, c40, c22 = constants(m1)
    fa = [float(v) for v in (m1, a, b, c40, c22)]
    g = np.linspace(0.0, 1.0, 401)
    vy, t = np.meshgrid(g, g)
    vx = t * np.sqrt(fa[0] * (1 - vy**2))
    L = lam(vx, vy, *fa, lib=np)
    i = np.unravel_index(np.argmax(L), L.shape)
    y, tt = mp.mpf(vy[i]), mp.mpf(t[i])

    def f(y, tt):
        vx, vy_ = point(m1, y, tt)
        return lam(vx, vy_, m1, a, b, c40, c22)

    best = f(y, tt)
    step = mp.mpf(1) / 400
    while step > mp.mpf("1e-20"):
        moved = False
        for dy, dt in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)):
            ny = min(max(y + dy * step, mp.mpf(0)), mp.mpf(1))
            nt = min(max(tt + dt * step, mp.mpf(0)), mp.mpf(1))
            v = f(ny, nt)
            if v > best:
                best, y, tt, moved = v, ny, nt, True
                break
        if not moved:
            step /= 2
    vx, vy_ = point(m1, y, tt)
    return a, b, best, vx, vy_


def main():
    m1s = [mp.mpf(k) / 20 for k in range(20, 0, -1)]
    m1s += [mp.mpf(10) ** (-mp.mpf(k) / 4) for k in range(6, 49)]
    m1s += [mp.mpf("0.01"), mp.mpf("0.001")]
    m1s = sorted(set(m1s), reverse=True)
    rows = ["m1,A,B,kappa,vx,vy"]
    for x in m1s:
        a, b, k, vx, vy = kappa(x)
        rows.append(",".join(mp.nstr(v, 25) for v in (x, a, b, k, vx, vy)))
        print(rows[-1], flush=True)
    with open(os.path.join(HERE, "data", "best_stiffness.csv"), "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
