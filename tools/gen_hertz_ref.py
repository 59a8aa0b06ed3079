#!/usr/bin/env python3
"""Reference data for host-tests/hertz.rs: tools/data/hertz_ref.csv.

Independent of the crate: mpmath at dps 40 (hertz_mp.py) solves G(c) = P/Q with findroot and
evaluates model.md section 1 (a^2 = h D/(P K), b^2 = (1-c) a^2, N = kH h^{3/2},
kH = (2 pi/3) E* sqrt(D/P)/K^{3/2}, p0 = 3N/(2 pi a b)).

Every input (P, Q, E*, h) is exactly representable in f32, and Q is a power of two wherever
P/Q must be exact (grid, random), so that f32 and f64 runs see the same g.

Cases:
  sphere_plane   closed form, not solved: P = Q = 1/(2R), a = sqrt(R h), N = 4/3 E* sqrt(R) h^1.5
  bearing209_*   ball 12.7 mm, groove radii 6.6 mm, pitch 65 mm, contact angle 0; P, Q from the
                 torus geometry here (Harris' curvature sums), steel E* = 2.08e11/(2(1-0.3^2))
  grid           g = P/Q log-spaced over [1e-4, 1] (9 per decade) + points near 1 and 0.41721
  dense          g log-spaced over [1e-4, 1] (1,200) and [1e-4, 1e-3] (300): the f32 errors are
                 rounding noise everywhere, so the stated maxima come from a dense sweep
  random         g log-uniform in [1e-4, 1], random Q = 2^k, E*, h (seed 3)

Run:  python3 tools/gen_hertz_ref.py > tools/data/hertz_ref.csv
"""
import random
import struct
import mpmath as mp
import hertz_mp as H

mp.mp.dps = 40


def f32(x):
    return struct.unpack("f", struct.pack("f", float(x)))[0]


def row(case, p, q, estar, h, closed_form=False):
    p, q, estar, h = (mp.mpf(f32(v)) for v in (p, q, estar, h))
    if closed_form:
        assert p == q
        r = 1 / (2 * p)
        c, m1, k, e, b_, d_ = 0, 1, mp.pi / 2, mp.pi / 2, mp.pi / 4, mp.pi / 4
        a = mp.sqrt(r * h)
        b = a
        n = mp.mpf(4) / 3 * estar * mp.sqrt(r) * h ** mp.mpf(1.5)
    else:
        c, m1, k, e, b_, d_ = H.shape(p / q)
        c2, a, b, n = H.hertz(p, q, estar, h, c)
    p0 = 3 * n / (2 * mp.pi * a * b)
    vals = [c, m1, k, e, b_, d_, a, b, n, p0]
    ins = [repr(float(v)) for v in (p, q, estar, h)]
    return ",".join([case] + ins + [mp.nstr(mp.mpf(v), 25, strip_zeros=False) for v in vals])


def bearing(race):
    d, rg, dm = mp.mpf("0.0127"), mp.mpf("0.0066"), mp.mpf("0.065")
    gamma = d / dm  # contact angle 0
    ball = 2 / d
    roll = (2 / d) * (gamma / (1 - gamma)) if race == "inner" else -(2 / d) * (gamma / (1 + gamma))
    across = -1 / rg
    s1 = (ball + roll) / 2   # rolling direction
    s2 = (ball + across) / 2  # across the groove
    return min(s1, s2), max(s1, s2)


def main():
    print("case,P,Q,Estar,h,c,m1,K,E,B,D,a,b,N,p0")
    for r_, h in ((0.01, 1e-7), (0.01, 1e-5), (0.0075, 3e-6)):
        print(row("sphere_plane", 1 / (2 * r_), 1 / (2 * r_), 1.1e11, h, closed_form=True))
    estar = mp.mpf("2.08e11") / (2 * (1 - mp.mpf("0.3") ** 2))
    for race in ("inner", "outer"):
        p, q = bearing(race)
        for h in (1e-6, 5e-6, 2e-5):
            # exact decimal lengths: P, Q printed to 25 digits, not rounded to f32
            c, m1, k, e, b_, d_ = H.shape(p / q)
            es, hh = mp.mpf(f32(estar)), mp.mpf(f32(h))
            _, a, b, n = H.hertz(p, q, es, hh, c)
            p0 = 3 * n / (2 * mp.pi * a * b)
            vals = [c, m1, k, e, b_, d_, a, b, n, p0]
            print(",".join([f"bearing209_{race}", mp.nstr(p, 25), mp.nstr(q, 25), repr(float(es)), repr(float(hh))]
                           + [mp.nstr(v, 25, strip_zeros=False) for v in vals]))
    # the last point is the f32 just above 1e-4, so that it lies in the domain in both precisions
    grid = [mp.mpf(10) ** (-mp.mpf(i) / 9) for i in range(0, 36)] + [mp.mpf("1.0000001e-4")]
    grid += [mp.mpf(x) for x in ("0.41721", "0.7", "0.8", "0.9", "0.99", "0.999", "0.9999", "0.99999")]
    for g in grid:
        print(row("grid", g, 1, 1e11, 1e-6))
    # dense: the f32 table's error is rounding noise over the whole domain (no single peak), so
    # its stated maxima need a dense sweep — 1,200 g log-spaced over [1e-4, 1] and 300 more
    # towards the floor [1e-4, 1e-3] (f32-exact g, Q = 1)
    dense = {max(f32(10 ** (-4 + 4 * i / 1199)), f32(1.0000001e-4)) for i in range(1200)}
    dense |= {max(f32(10 ** (-4 + i / 299)), f32(1.0000001e-4)) for i in range(300)}
    for g in sorted(dense - {1.0}):
        print(row("dense", g, 1, 1e11, 1e-6))
    rnd = random.Random(3)
    for _ in range(150):
        g = max(10 ** rnd.uniform(-4, 0), 1.0000001e-4)
        q = 2.0 ** rnd.randint(-2, 12)
        print(row("random", g * q, q, 10 ** rnd.uniform(8, 12), 10 ** rnd.uniform(-9, -4)))


if __name__ == "__main__":
    main()
