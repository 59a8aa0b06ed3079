#!/usr/bin/env python3
"""Reference data for the stability map (examples/stability.rs, host-tests/stability.rs).

Independent of the crate: mpmath at dps 50.

tools/data/stability_elliptic.csv  columns kind,x,K,E,D
  kind = m1: x = m1 = 1 - m (f32-exact: f32(10^(-k/8)), k = 1..96, plus 1/2, 2^-24 and 1e-12: the f32 and f64 domain edges), near m -> 1
  kind = m:  x = m (f32-exact: f32(10^(-k/8)), k = 3..88), small m
  K, E, D = (K - E)/m at that parameter (mpmath ellipk/ellipe, D by the series
  D = (pi/4) sum w_n w_{n+1} m^n for m < 1e-3 so nothing cancels).

tools/data/stability_shape.csv  columns g,c,m1,K,E,B,D,a,b,N
  g = P/Q (f32-exact: f32(10^(-k/8)), k = 0..96, so 1 ... 1e-12, plus points at the knee of
  the paper's G*: 0.69, 0.7, 0.71, and near the volumetric law's edge: 0.55, 0.5, 0.45, and g = 1e-4 = Ratio::MIN exactly in f64), solved G(c) = g by hertz_mp.shape; a, b, N for
  P = g, Q = 1, E* = 1, h = 1 (model.md section 1).

Run:  python3 tools/gen_stability_ref.py   (writes both files)
"""
import os
import struct
import mpmath as mp
import hertz_mp as H

mp.mp.dps = 50
HERE = os.path.dirname(os.path.abspath(__file__))


def f32(x):
    return struct.unpack("f", struct.pack("f", float(x)))[0]


def s(v):
    return mp.nstr(mp.mpf(v), 25, strip_zeros=False)


def d_small(m):
    # D(m) = (pi/2) sum_n w_n w_{n+1} m^n, w_n = C(2n, n)/4^n  (K - E = m D)
    tot, w, n = mp.mpf(0), mp.mpf(1), 0
    while True:
        w_next = w * (2 * n + 1) / (2 * n + 2)
        term = w * w_next * m**n
        tot += term
        if abs(term) < mp.mpf(10) ** (-60):
            break
        w, n = w_next, n + 1
    return mp.pi / 2 * tot


def kedd(m):
    m = mp.mpf(m)
    k, e = mp.ellipk(m), mp.ellipe(m)
    d = d_small(m) if m < mp.mpf("1e-3") else (k - e) / m
    return k, e, d


def elliptic():
    rows = ["kind,x,K,E,D"]
    m1s = sorted({f32(10 ** (-k / 8)) for k in range(1, 97)} | {0.5, 1e-12, 2.0**-24}, reverse=True)
    for x in m1s:
        k, e, d = kedd(1 - mp.mpf(x))
        rows.append(f"m1,{x!r},{s(k)},{s(e)},{s(d)}")
    for x in sorted({f32(10 ** (-k / 8)) for k in range(3, 89)}, reverse=True):
        k, e, d = kedd(mp.mpf(x))
        rows.append(f"m,{x!r},{s(k)},{s(e)},{s(d)}")
    return rows


def shape():
    rows = ["g,c,m1,K,E,B,D,a,b,N"]
    gs = sorted({f32(10 ** (-k / 8)) for k in range(0, 97)} | {f32(v) for v in (0.69, 0.7, 0.71, 0.55, 0.5, 0.45)} | {1e-4},
                reverse=True)
    for g in gs:
        if g == 1.0:
            c, m1, k, e, b_, d_ = 0, 1, mp.pi / 2, mp.pi / 2, mp.pi / 4, mp.pi / 4
        else:
            c, m1, k, e, b_, d_ = H.shape(mp.mpf(g))
        p = mp.mpf(g)
        a = mp.sqrt(d_ / (p * k))
        b = mp.sqrt(m1) * a
        n = 2 * mp.pi / 3 * mp.sqrt(d_ / p) / k ** mp.mpf(1.5)
        rows.append(",".join([repr(g)] + [s(v) for v in (c, m1, k, e, b_, d_, a, b, n)]))
    return rows


if __name__ == "__main__":
    for name, rows in (("stability_elliptic.csv", elliptic()), ("stability_shape.csv", shape())):
        with open(os.path.join(HERE, "data", name), "w") as f:
            f.write("\n".join(rows) + "\n")
