#!/usr/bin/env python3
"""Reference values for the exact Contensou–Erismann friction integrals.

Independent of the Rust code (which integrates in polar coordinates about the instantaneous
centre with closed-form radial integrals, and uses the quartic polynomial inside the ellipse):
here the paper's integrals (1.3)–(1.4) (equivalently (2.2)–(2.4), (3.1)–(3.3)) are integrated by
brute force over the patch in Cartesian coordinates, x outer and y = b√(1 − x²/a²)·s inner, as
a 2-D product tanh-sinh (double-exponential) rule in 80-bit extended precision (numpy
longdouble). The x-range is split at the instantaneous centre's (IC's) abscissa and the s-range
at its ordinate, so the IC and the line x = X₀ (across which the slip direction turns quickly
in a thin ellipse) lie on the edges of the integration rectangles; the √ edge of the Hertz
pressure is an endpoint as well. (Polar coordinates about the patch centre converge slowly for
thin ellipses when the IC is near the major axis: tried, dropped.)

Precision: every point is computed at two step sizes (h and h/2); the difference is the
recorded error estimate (column `err`). A random subset is re-checked with the paper's
(3.1)–(3.3) exactly as printed (elliptic-polar coordinates, ε = 1/u), integrated by mpmath.quad
(tanh-sinh) at dps = 30 — see `--mpmath-check N`. The closed forms
(circle, pure spin, pure translation, small-u slopes (3.5), large-u terms) and the quartic
polynomial of the notes (inside the ellipse) are checked at the end and their deviations
printed.

Last run (2 shared cores): 561 structured points in 98 s, max |h − h/2| = 1.7e-15; closed
forms: circle (u ≤ 1) 1.1e-16, pure spin 5.6e-17, the notes' quartic (IC inside, all 8 e²
values) 1.4e-17, large-u series at u = 1e3 4.2e-11 (= the O(u⁻³) torque term); mpmath re-check
of the paper's (3.1)–(3.3) at 10 random points (e² ≤ 0.9): identical in f64 (max dev 1.7e-22),
359 s; whole run 7.6 min. `--random 300`: 77 s, max |h − h/2| = 6.6e-16.

Output: tools/data/friction_ref.csv with columns
    e2,psi,u,fx,fy,tz,err
F in units of fN, T_z in units of fNa, u = v/(aω) with ω > 0; u = inf means pure translation
(aω = 0). x is along the major axis. Convention: on body B from body A, slip v_M = (v_x − ωy,
v_y + ωx).

Usage (from the crate root):
    python3 tools/gen_friction_ref.py [--mpmath-check N]   # friction_ref.csv
    python3 tools/gen_friction_ref.py --random N           # friction_ref_random.csv
"""

import math
import sys
import time

import numpy as np

L = np.longdouble
PI = L("3.14159265358979323846264338327950288")


def de_rule(h, tmax):
    """Tanh-sinh nodes on [0, 1] as (distance from 0, distance from 1, weight), longdouble."""
    k = np.arange(-int(round(tmax / h)), int(round(tmax / h)) + 1)
    t = L(h) * k.astype(L)
    z = (PI / 2) * np.sinh(t)
    # x = (1 + tanh z)/2 ; 1 - x = 1/(e^{2z} + 1), x = 1/(e^{-2z} + 1), no cancellation
    x_lo = L(1) / (np.exp(-2 * z) + 1)
    x_hi = L(1) / (np.exp(2 * z) + 1)
    w = L(h) * (PI / 2) * np.cosh(t) / (2 * np.cosh(z) ** 2)
    keep = (x_lo > 0) & (x_hi > 0) & (w > L(1e-40))
    return x_lo[keep], x_hi[keep], w[keep]


def traction(m, psi, u, h):
    """Exact dimensionless (Fx, Fy, Tz) by the 2-D DE product rule with step h.

    Cartesian: x ∈ [−1, 1] (outer, split at the IC's X₀), y = γ√(1 − x²)·s with s ∈ [−1, 1]
    (inner, split at the IC's s₀(x) = Y₀/(γ√(1 − x²)) clipped to [−1, 1]). Then
    σ dA = (3/2π)(1 − x²)√(1 − s²) ds dx and every singular set of the slip direction (the IC
    itself, and the line x = X₀ across which it turns quickly in a thin ellipse) lies on the
    edges or corners of the integration rectangles.
    """
    m = L(m)
    gamma = np.sqrt(L(1) - m)
    psi = L(psi)
    u = L(u)
    X0, Y0 = -u * np.sin(psi), u * np.cos(psi)
    xl, xh, w = de_rule(h, 3.6)
    xpieces = [(L(-1), X0), (X0, L(1))] if -1 < X0 < 1 else [(L(-1), L(1))]
    total = np.zeros(3, dtype=L)
    for a, b in xpieces:
        x = a + (b - a) * xl
        one_m_x2 = ((L(1) + a) + (b - a) * xl) * ((L(1) - b) + (b - a) * xh)
        dx = x - X0  # exact offsets at the split
        if b == X0:
            dx = -(b - a) * xh
        elif a == X0:
            dx = (b - a) * xl
        half = gamma * np.sqrt(one_m_x2)  # half-width of the chord at x
        s0 = Y0 / half
        c = np.clip(s0, L(-1), L(1))
        wx = (b - a) * w * one_m_x2
        for piece in (0, 1):
            if piece == 0:  # s ∈ [−1, c]
                lo = c + 1
                s = (-1 + lo[:, None] * xl[None, :])
                s_m_c = -lo[:, None] * xh[None, :]
                one_p_s = lo[:, None] * xl[None, :]
                one_m_s = (1 - c)[:, None] + lo[:, None] * xh[None, :]
                ws = lo[:, None] * w[None, :]
            else:  # s ∈ [c, 1]
                hi = 1 - c
                s = c[:, None] + hi[:, None] * xl[None, :]
                s_m_c = hi[:, None] * xl[None, :]
                one_p_s = (1 + c)[:, None] + hi[:, None] * xl[None, :]
                one_m_s = hi[:, None] * xh[None, :]
                ws = hi[:, None] * w[None, :]
            y = half[:, None] * s
            dy = half[:, None] * s_m_c + (half * c - Y0)[:, None]  # y − Y₀
            vx, vy = -dy, np.broadcast_to(dx[:, None], dy.shape)  # (v_x − ωy, v_y + ωx)
            nv = np.sqrt(vx * vx + vy * vy)
            nv = np.where(nv > 0, nv, L(1))
            wt = wx[:, None] * ws * np.sqrt(one_p_s * one_m_s) / nv
            X = x[:, None]
            total[0] += np.sum(wt * vx)
            total[1] += np.sum(wt * vy)
            total[2] += np.sum(wt * (X * vy - y * vx))
    return -L(3) / (2 * PI) * total


def u_boundary(m, psi):
    return 1.0 / math.sqrt(math.sin(psi) ** 2 + math.cos(psi) ** 2 / (1.0 - m))


def mp_traction(m, psi, u, dps=30):
    """The paper's (3.1)–(3.3) exactly as printed (ε = 1/u, elliptic-polar ρ, φ), integrated
    with mpmath.quad (tanh-sinh) at dps, split at the IC (φ_IC; ρ_IC if inside): an independent
    parametrisation and arithmetic for the precision check. u > 0."""
    import mpmath as mp

    mp.mp.dps = dps
    m, psi, u = mp.mpf(m), mp.mpf(psi), mp.mpf(u)
    g = mp.sqrt(1 - m)
    al, be = mp.cos(psi), mp.sin(psi)
    eps = 1 / u
    xi0, eta0 = -u * be, u * al / g
    rho0 = mp.sqrt(xi0**2 + eta0**2)
    phi0 = mp.atan2(eta0, xi0)
    rs = [0, rho0, 1] if rho0 < 1 else [0, 1]
    out = []
    for comp in range(3):

        def f(r, p):
            c, s = mp.cos(p), mp.sin(p)
            zeta = mp.sqrt(abs(1 - 2 * eps * r * (al * g * s - be * c)
                               + eps**2 * r**2 * (c**2 + g**2 * s**2)))
            if comp == 0:
                num = r * (al - eps * g * r * s)
            elif comp == 1:
                num = r * (be + eps * r * c)
            else:
                num = r**2 * (c * (be + eps * r * c) - g * s * (al - eps * g * r * s))
            return mp.sqrt(1 - r * r) * num / zeta

        val = mp.quad(f, rs, [phi0, phi0 + 2 * mp.pi])
        out.append(-3 / (2 * mp.pi) * val)
    return [float(x) for x in out]


def ellip_ke(m):
    import mpmath as mp

    mp.mp.dps = 30
    return mp.ellipk(m), mp.ellipe(m)


def quartic(m, psi, u):
    """The notes' polynomial (inside the ellipse), evaluated with mpmath."""
    import mpmath as mp

    mp.mp.dps = 30
    m = mp.mpf(m)
    K, E = ellip_ke(m)
    if m == 0:
        A = Bc = 3 * mp.pi / 8
        c40 = -3 * mp.pi / 128
    else:
        A = mp.mpf(3) / 2 * (K - E) / m
        Bc = mp.mpf(3) / 2 * (K + (E - K) / m)
        c40 = -((2 - m) * E - 2 * (1 - m) * K) / (8 * m * m)
    C = 3 * E / 8
    c22 = -(A + 12 * c40) / 2
    X, Y = -mp.mpf(u) * mp.sin(psi), mp.mpf(u) * mp.cos(psi)
    Psi = C + Bc / 2 * X**2 + A / 2 * Y**2 + c40 * (X**4 + Y**4 / (1 - m)) + c22 * X**2 * Y**2
    PX = Bc * X + 4 * c40 * X**3 + 2 * c22 * X * Y**2
    PY = A * Y + 4 * c40 * Y**3 / (1 - m) + 2 * c22 * X**2 * Y
    return [float(-PY), float(PX), float(-Psi + X * PX + Y * PY)]


def points():
    e2s = [0.0, 0.3, 0.687, 0.9, 0.99]
    psis = [0.0, 0.3, math.pi / 4, 1.2, math.pi / 2]
    others = [2.5, -0.7, 3.9, -2.0]
    us = [1e-3, 1e-2, 0.1, 0.3, 0.7, 1.0, 1.5, 3.0, 10.0, 100.0, 1e3]
    pts = []
    for m in e2s:
        for psi in psis:
            ub = u_boundary(m, psi)
            for u in [0.0] + us + [ub * (1 - 1e-6), ub * (1 + 1e-6), float("inf")]:
                pts.append((m, psi, u))
        for psi in others:
            ub = u_boundary(m, psi)
            for u in [0.05, 0.5, ub * (1 - 1e-6), ub * (1 + 1e-6), 1.3, 5.0]:
                pts.append((m, psi, u))
    for psi in [0.0, 0.9, math.pi / 2]:  # very thin patch
        ub = u_boundary(0.9999, psi)
        for u in [0.0, 0.005, 0.3, ub * (1 - 1e-6), ub * (1 + 1e-6), 1.2, 4.0, 50.0]:
            pts.append((0.9999, psi, u))
    for m in [1 - 1e-8, 1 - 1.5e-12]:  # extreme patches (m₁ = 1 − m is exact in f64)
        for psi in [0.0, 0.9, math.pi / 2]:
            ub = u_boundary(m, psi)
            for u in [0.3 * ub, ub * (1 - 1e-6), ub * (1 + 1e-6), 2 * ub, 0.5, 1.2, 4.0]:
                pts.append((m, psi, u))
    return pts


def random_set(n):
    """n random states: m₁ = 1 − e² log-uniform in [1e-4, 1] (half) or e² uniform in [0, 1),
    ψ uniform in (−π, π], u log-uniform in [1e-2, 1e2]. Written to friction_ref_random.csv."""
    import random

    random.seed(20091)
    t0 = time.time()
    worst = 0.0
    with open("tools/data/friction_ref_random.csv", "w") as fh:
        fh.write("e2,psi,u,fx,fy,tz,err\n")
        for _ in range(n):
            if random.random() < 0.5:
                m = 1.0 - 10 ** random.uniform(-4, 0)
            else:
                m = random.uniform(0, 0.9999)
            psi = random.uniform(-math.pi, math.pi)
            u = 10 ** random.uniform(-2, 2)
            v1 = traction(m, psi, u, 1 / 32)
            v2 = traction(m, psi, u, 1 / 64)
            err = float(np.max(np.abs(v1 - v2)))
            worst = max(worst, err)
            fh.write(",".join(repr(float(x)) for x in (m, psi, u, *v2, err)) + "\n")
    print(f"random set: {n} points in {time.time() - t0:.1f} s; max |h − h/2| {worst:.2e}")


def main():
    if "--random" in sys.argv:
        random_set(int(sys.argv[sys.argv.index("--random") + 1]))
        return
    nmp = 0
    if "--mpmath-check" in sys.argv:
        nmp = int(sys.argv[sys.argv.index("--mpmath-check") + 1])
    t0 = time.time()
    rows = []
    worst = 0.0
    for m, psi, u in points():
        if math.isinf(u):
            al, be = math.cos(psi), math.sin(psi)
            val, err = [-al, -be, 0.0], 0.0
        else:
            v1 = traction(m, psi, u, 1 / 32)
            v2 = traction(m, psi, u, 1 / 64)
            err = float(np.max(np.abs(v1 - v2)))
            val = [float(x) for x in v2]
        worst = max(worst, err)
        rows.append((m, psi, u, *val, err))
    t1 = time.time()
    with open("tools/data/friction_ref.csv", "w") as fh:
        fh.write("e2,psi,u,fx,fy,tz,err\n")
        for r in rows:
            fh.write(",".join(repr(float(x)) for x in r) + "\n")
    print(f"{len(rows)} points in {t1 - t0:.1f} s; max |h − h/2| difference {worst:.2e}")

    # Closed-form checks.
    dev = 0.0
    for m, psi, u, fx, fy, tz, _ in rows:
        if m == 0.0 and u <= 1.0:
            fmag = 3 * math.pi / 8 * u * (1 - u * u / 4)
            t = -3 * math.pi / 16 * (1 - u * u + 3 * u**4 / 8)
            dev = max(dev, abs(math.hypot(fx, fy) - fmag), abs(tz - t))
    print(f"circle closed form (u ≤ 1): max dev {dev:.2e}")
    dev = 0.0
    for m, psi, u, fx, fy, tz, _ in rows:
        if u == 0.0:
            _, E = ellip_ke(m)
            dev = max(dev, abs(fx), abs(fy), abs(tz + 3 * float(E) / 8))
    print(f"pure spin −(3/8)E(m): max dev {dev:.2e}")
    dev = 0.0
    for m, psi, u, fx, fy, tz, _ in rows:
        if 0 < u and u <= u_boundary(m, psi):
            q = quartic(m, psi, u)
            dev = max(dev, abs(q[0] - fx), abs(q[1] - fy), abs(q[2] - tz))
    print(f"notes' quartic polynomial (IC inside): max dev {dev:.2e}")
    dev = 0.0
    for m, psi, u, fx, fy, tz, _ in rows:
        if u == 1e3:
            al, be = math.cos(psi), math.sin(psi)
            f2x = -(-0.5 * al - m * ((1.5 * al * al - 0.5) * al - al)) / 5
            f2y = -(-0.5 * be - m * ((1.5 * al * al - 0.5) * be)) / 5
            t1 = -(1 - m * be * be) / 5
            dev = max(dev, abs(fx - (-al + f2x / u**2)), abs(fy - (-be + f2y / u**2)),
                      abs(tz - t1 / u))
    print(f"large-u series F0 + F2/u², T1/u at u = 1e3: max dev {dev:.2e}")

    if nmp:
        import random

        random.seed(5)
        # the paper's printed (3.1)–(3.3) in mpmath; thin patches are slow there, so e² ≤ 0.9
        pool = [r for r in rows if 0 < r[2] < math.inf and r[0] <= 0.9]
        sample = random.sample(pool, nmp)
        dev = 0.0
        t2 = time.time()
        for m, psi, u, fx, fy, tz, _ in sample:
            ref = mp_traction(m, psi, u)
            d = max(abs(ref[0] - fx), abs(ref[1] - fy), abs(ref[2] - tz))
            print(f"  mpmath check e2={m} psi={psi:.4f} u={u:.6g}: dev {d:.2e}", flush=True)
            dev = max(dev, d)
        print(f"mpmath (dps 30) re-check of {nmp} points: max dev {dev:.2e} ({time.time() - t2:.0f} s)")


if __name__ == "__main__":
    main()
