#!/usr/bin/env python3
"""Reference for `friction::best::ramp_stiffness` (kappa) and `spin_stiffness` (kappa_T): the
stiffness of the `best` law below delta, with the wrapper's ramp by the law's own dissipation.

Independent of the crate: mpmath at dps 40 (A, B, C and the quartic's c40, c22 from
ellipk/ellipe) and a direct maximisation (a
201 x 201 float grid, then pattern searches in mpmath to 1e-20, at most 3,000 moves: from
the grid's best point in 2-D and along each axis). Pure Python (no numpy).

Below c delta (c = 3/8) the wrapper scales the core by p/(c delta), p = -(F v_P + T_z omega)/(fN)
the full-slip law's dissipation per unit fN (m/s). For the exact law p = D(v_P, a omega)
= int sigma |v_M| dA/N (convex, degree one) and the core is -grad D, so the ramped law is
F = -(fN/(c delta)) grad_v G, T_z/a = -(fN/(c delta)) dG/d(a omega), G = D^2/2, and the
stiffness matrix is (fN/delta) (8/3) Hess G: symmetric positive semidefinite, degree 0. The
tables hold kappa and kappa_T in units of fN/delta (fN a^2/delta): 8/3 times the maxima below. With W = a omega > 0 and
the IC (X, Y) = (-vy, vx)/W inside the ellipse, D = W Psi(X, Y) (Psi: the quartic of model.md
section 3), so G = W^2 Psi^2/2 and
  - the translational block is the Hessian of g = Psi^2/2 in (Y, X) = (vx, vy)/W:
    g_XX = Psi_X^2 + Psi Psi_XX, ...; kappa = max over the inside region of its larger
    eigenvalue (pure translation gives 1, pure spin C diag(A, B));
  - the spin entry is d2G/dW2 = (1 - E)(2 - E) g (E = X d/dX + Y d/dY, Euler's operator): with
    Psi = C + Q2 + Q4 (homogeneous parts), k_T = C^2 + 3 (Q2^2 + 2 C Q4) + 20 Q2 Q4 + 21 Q4^2;
    kappa_T = its max over the inside region (pure spin gives C^2).
The crate's tests check on the whole direction sphere, with the exact law, that nothing with the
IC outside the ellipse or past the ramp is stiffer.

tools/data/best_stiffness.csv   columns m1,A,B,kappa,vx,vy   (vx, vy: the maximiser, aw = 1)
tools/data/spin_stiffness.csv   columns m1,C,kappa_t,X,Y     (X, Y: the maximiser, aw = 1)
  m1 = 1 - e^2: 1, 0.95, ..., 0.05 (step 0.05) and 10^(-k/4) for k = 6..48 (0.03 ... 1e-12),
  plus e^2 = 0.99 and 0.999.

Run:  python3 tools/gen_ramp_stiffness.py
"""
import math
import os

import mpmath as mp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
GRID = 201
MOVES = 3000


def constants(m1):
    m1 = mp.mpf(m1)
    m = 1 - m1
    if m == 0:
        a = b = 3 * mp.pi / 8
        c40 = -3 * mp.pi / 128
        c = 3 * mp.pi / 16
    else:
        k, e = mp.ellipk(m), mp.ellipe(m)
        a = mp.mpf(3) / 2 * (k - e) / m
        b = mp.mpf(3) / 2 * (e - m1 * k) / m
        c40 = -((2 - m) * e - 2 * m1 * k) / (8 * m * m)
        c = mp.mpf(3) / 8 * e
    c22 = -(a + 12 * c40) / 2
    return m1, a, b, c, c40, c22


def parts(x, y, m1, a, b, c, c40, c22):
    """Psi's homogeneous parts and derivatives at the IC (X, Y) = (x, y)."""
    q2 = b / 2 * x**2 + a / 2 * y**2
    q4 = c40 * (x**4 + y**4 / m1) + c22 * x**2 * y**2
    psi = c + q2 + q4
    px = x * (b + 4 * c40 * x**2 + 2 * c22 * y**2)
    py = y * (a + 4 * c40 / m1 * y**2 + 2 * c22 * x**2)
    pxx = b + 12 * c40 * x**2 + 2 * c22 * y**2
    pyy = a + 12 * c40 / m1 * y**2 + 2 * c22 * x**2
    pxy = 4 * c22 * x * y
    return q2, q4, psi, px, py, pxx, pyy, pxy


def lam(x, y, *k, sqrt=math.sqrt):
    _, _, psi, px, py, pxx, pyy, pxy = parts(x, y, *k)
    gxx = px * px + psi * pxx
    gyy = py * py + psi * pyy
    gxy = px * py + psi * pxy
    return (gxx + gyy) / 2 + sqrt((gxx - gyy) ** 2 / 4 + gxy * gxy)


def k_t(x, y, *k, sqrt=None):
    m1, a, b, c, c40, c22 = k
    q2, q4, *_ = parts(x, y, *k)
    return c * c + 3 * (q2 * q2 + 2 * c * q4) + 20 * q2 * q4 + 21 * q4 * q4


def point(m1, rho, t, lib=math):
    # (rho, t) in [0, 1]^2 covers the first quadrant of the inside region X^2 + Y^2/m1 <= 1
    return rho * lib.cos(t * lib.pi / 2), lib.sqrt(m1) * rho * lib.sin(t * lib.pi / 2)


def search(f, r, tt, dirs):
    """Pattern search from (r, tt) over `dirs`, at most MOVES moves, down to a step of 1e-20."""
    best = f(r, tt)
    step = mp.mpf(1) / (GRID - 1)
    for _ in range(MOVES):
        if step <= mp.mpf("1e-20"):
            break
        moved = False
        for dr, dt in dirs:
            nr = min(max(r + dr * step, mp.mpf(0)), mp.mpf(1))
            nt = min(max(tt + dt * step, mp.mpf(0)), mp.mpf(1))
            v = f(nr, nt)
            if v > best:
                best, r, tt, moved = v, nr, nt, True
                break
        if not moved:
            step /= 2
    return best, r, tt


def maximise(fun, m1, k):
    """The grid's best point refined in 2-D, and each axis (t = 0, 1) refined along itself
    (the thin patches' maxima lie on an axis, at the end of a ridge that curves in (rho, t))."""
    kf = [float(v) for v in k]
    starts = [(-1.0, 0.0, 0.0)] * 3
    for i in range(GRID):
        for j in range(GRID):
            r, t = i / (GRID - 1), j / (GRID - 1)
            v = fun(*point(kf[0], r, t), *kf)
            for n, on in enumerate((True, j == 0, j == GRID - 1)):
                if on and v > starts[n][0]:
                    starts[n] = (v, r, t)

    def f(r, tt):
        return fun(*point(m1, r, tt, lib=mp), *k, sqrt=mp.sqrt)

    every = ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1))
    found = [
        search(f, mp.mpf(r), mp.mpf(t), every if n == 0 else every[:2])
        for n, (_, r, t) in enumerate(starts)
    ]
    best, r, tt = max(found, key=lambda x: x[0])
    return best, point(m1, r, tt, lib=mp)


def main():
    m1s = [mp.mpf(k) / 20 for k in range(20, 0, -1)]
    m1s += [mp.mpf(10) ** (-mp.mpf(k) / 4) for k in range(6, 49)]
    m1s += [mp.mpf("0.01"), mp.mpf("0.001")]
    m1s = sorted(set(m1s), reverse=True)
    slip = ["m1,A,B,kappa,vx,vy"]
    spin = ["m1,C,kappa_t,X,Y"]
    for m1 in m1s:
        k = constants(m1)
        _, a, b, c, _, _ = k
        kappa, (x, y) = maximise(lam, k[0], k)
        # the IC (X, Y) = (vy, vx) at aw = 1
        gain = mp.mpf(8) / 3
        slip.append(",".join(mp.nstr(v, 25) for v in (m1, a, b, gain * kappa, y, x)))
        kt, (x2, y2) = maximise(k_t, k[0], k)
        spin.append(",".join(mp.nstr(v, 25) for v in (m1, c, gain * kt, x2, y2)))
        print(slip[-1], spin[-1], sep="\n", flush=True)
    with open(os.path.join(HERE, "data", "best_stiffness.csv"), "w") as f:
        f.write("\n".join(slip) + "\n")
    with open(os.path.join(HERE, "data", "spin_stiffness.csv"), "w") as f:
        f.write("\n".join(spin) + "\n")


if __name__ == "__main__":
    main()
