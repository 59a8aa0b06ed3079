#!/usr/bin/env python3
"""Reference values of the complete elliptic integrals K, E, B, D (parameter m = k²).

Writes tools/data/elliptic_ref.csv with columns m,m1,K,E,B,D where

    K = ∫ dθ/√(1 − m sin²θ),  E = ∫ √(1 − m sin²θ) dθ            (θ from 0 to π/2)
    B = (E − m1·K)/m = ∫ cos²θ/√(1 − m sin²θ) dθ,  D = (K − E)/m = ∫ sin²θ/√(…) dθ

computed by mpmath (ellipk/ellipe) at 60 significant digits (dps 60 so that the quotients B, D
keep > 40 digits at m = 1e-12; B = D = π/4 at m = 0), printed to 22 significant digits.

Every input pair (m, m1 = 1 − m) is printed as EXACT decimals of binary floats:
  * "small-m" rows: m is a binary64 value that is a multiple of 2⁻⁵³ (so 1 − m is exact in
    binary64 too, for m ≤ ½);
  * "near-1" rows: m1 is a multiple of 2⁻⁵³ (so m = 1 − m1 is exact in binary64);
  * rows tagged for f32 (m or m1 a multiple of 2⁻²⁴ and exactly representable in binary32) let
    the f32 tests evaluate at exactly the reference input. The tests pick f32 rows by checking
    that the relevant input (m for m ≤ ½, m1 above) round-trips through f32.
Rerun: python3 tools/gen_elliptic_ref.py   (deterministic; takes a few seconds)
"""
import math
import os
import struct
from decimal import Decimal, localcontext

import mpmath as mp

mp.mp.dps = 60


def f32_exact(x):
    return struct.unpack("f", struct.pack("f", x))[0] == x


def quantise(x, bits, up=False):
    """Nearest (or next larger) multiple of 2**-bits (exact in binary64 for x < 1)."""
    s = 2.0 ** bits
    return (math.ceil(x * s) if up else round(x * s)) / s


def decimal_exact(x):
    with localcontext() as c:
        c.prec = 400
        d = Decimal(x).normalize()
    s = format(d, "f")
    return s


def complement(x):
    with localcontext() as c:
        c.prec = 400
        return format((Decimal(1) - Decimal(x)).normalize(), "f")


def logspace(lo, hi, n):
    return [float(mp.mpf(10) ** (mp.log10(lo) + (mp.log10(hi) - mp.log10(lo)) * i / (n - 1))) for i in range(n)]


def rows():
    """(m or m1 as a float, which one) pairs."""
    small, near1 = set(), set()
    # exactly 0 and dense near 0, f64 grid (multiples of 2^-53) and f32 grid (f32 values)
    small.add(0.0)
    for x in logspace(1e-12, 0.1, 56):
        small.add(quantise(x, 53))
        small.add(float(struct.unpack("f", struct.pack("f", x))[0]))
    # uniform over [0, 1]: multiples of 2^-24 (exact in f32 and, with their complement, in f64)
    for i in range(1, 200):
        x = quantise(i / 200, 24)
        (small if x <= 0.5 else near1).add(x if x <= 0.5 else 1.0 - x)
    # near 1: m1 log-spaced from 1e-12 (f64 domain edge) and from 2^-24 (f32 domain edge)
    # (rounded up so that m1 >= 1e-12, resp. >= 2^-24: the domain edges)
    for x in logspace(1e-12, 0.1, 56):
        near1.add(quantise(x, 53, up=True))
    # dense where the errors peak, at the domain edges m -> 1: m1 in [1e-12, 1e-9] (f64; AGM's
    # E peaks near m1 = 1.5e-12) and [2^-24, 2^-20] (f32), so the stated maxima are maxima
    for x in logspace(1e-12, 1e-9, 1000):
        near1.add(quantise(x, 53, up=True))
    for x in logspace(2.0 ** -24, 2.0 ** -20, 60):
        near1.add(quantise(x, 24, up=True))
    for x in logspace(2.0 ** -24, 0.1, 40):
        near1.add(quantise(x, 24, up=True))
    for k in (1, 2, 3, 5):
        near1.add(k * 2.0 ** -24)
    near1.discard(0.0)
    out = [(x, "m") for x in sorted(small)] + [(x, "m1") for x in sorted(near1, reverse=True)]
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "data", "elliptic_ref.csv")
    lines = ["m,m1,K,E,B,D"]
    for x, which in rows():
        if which == "m":
            m_s, m1_s = decimal_exact(x), complement(x)
        else:
            m_s, m1_s = complement(x), decimal_exact(x)
        m, m1 = mp.mpf(m_s), mp.mpf(m1_s)
        assert m + m1 == 1
        if m == 0:
            K = E = mp.pi / 2
            B = D = mp.pi / 4
        else:
            K, E = mp.ellipk(m), mp.ellipe(m)
            B, D = (E - m1 * K) / m, (K - E) / m
        vals = [mp.nstr(v, 22) for v in (K, E, B, D)]
        lines.append(",".join([m_s, m1_s] + vals))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {len(lines) - 1} rows to {path}")


if __name__ == "__main__":
    main()
