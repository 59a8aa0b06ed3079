#!/usr/bin/env python3
"""Independent reference for `best`'s per-step (flash-table) form: the exact Contensou
integrals at the points where that form is weakest — e² at and between the table's nodes in
s = m₁^¼ (tools/gen_best_varying_table.py: 20 cells over e² ∈ [0, 0.99]; every other node and
the middle of every other cell) and at 0.99 itself,
u just inside and just outside the ellipse and through the band where the coefficients vary
fastest, ψ off the axes and on the major axis.

Integrator: tools/gen_friction_ref.py's brute-force 2-D tanh-sinh product rule in 80-bit
extended precision (independent of the Rust code), at steps 1/32 and 1/64; the difference is
the `err` column.

Output: tools/data/best_varying_ref.csv, columns e2,psi,u,fx,fy,tz,err (F in fN, T_z in fNa).
With --thin: tools/data/best_thin_ref.csv, the same at the thin patches (issue 21): e² = 0.992,
0.995, 0.999, 0.9995, 0.9999, 0.99995, 0.99999, the contract's end (P/Q = 1e-4) and the middle
of the per-step table's cells in s = m₁^⅛ over m₁ ∈ [1.7e-5, 0.01] (both `best` forms are
checked against it).
Run from the repository root:  python3 tools/gen_best_varying_ref.py [--thin]
(≈3 min on an idle core; --thin ≈2 min)
"""
import math
import sys
import time

import numpy as np

sys.path.insert(0, "tools")
from gen_friction_ref import traction, u_boundary  # noqa: E402

NS = 20
S0 = 0.1 ** 0.5


def e2_values():
    out = []
    for n in range(0, NS + 1, 2):  # every other node, the middle of every other cell
        for x in (n, n + 0.5) if n < NS else (n,):
            s = S0 + (1 - S0) * x / NS
            out.append(max(0.0, 1 - s ** 4))
    out += [0.99, 0.985, 0.5]
    return sorted(set(round(e, 15) for e in out))


M1_END = 1.7014448227e-5  # e² = 0.999982985551773 at P/Q = 1e-4 (contact_eval eccentricity)


def thin_e2_values():
    """The named thin patches and the middle of the per-step table's cells in s = m₁^⅛
    (NS = 25 over s ∈ [(1e-5)^⅛, 1]) between m₁ = 1.7e-5 and 0.01."""
    out = [0.992, 0.995, 0.999, 0.9995, 0.9999, 0.99995, 0.99999, 1 - M1_END]
    s0, ns = 1e-5 ** 0.125, 25
    for n in range(ns):
        s = s0 + (1 - s0) * (n + 0.5) / ns
        if M1_END <= s ** 8 <= 0.01:
            out.append(1 - s ** 8)
    return sorted(set(round(e, 15) for e in out))


def main():
    thin = "--thin" in sys.argv[1:]
    t0 = time.time()
    rows = []
    worst = 0.0
    for m in thin_e2_values() if thin else e2_values():
        for psi in (0.0, 0.0131, 0.7, 2.5):
            ub = u_boundary(m, psi)
            for u in (ub * (1 - 1e-6), ub * (1 + 1e-6), ub * 1.01, ub * 1.03, ub * 1.1, 3.0):
                if psi == 0.0 and u not in (ub * 1.01, ub * 1.03, ub * 1.1):
                    continue
                v1 = traction(m, psi, u, 1 / 32)
                v2 = traction(m, psi, u, 1 / 64)
                err = float(np.max(np.abs(v1 - v2)))
                worst = max(worst, err)
                rows.append((m, psi, u, *map(float, v2), err))
    name = "best_thin_ref.csv" if thin else "best_varying_ref.csv"
    with open(f"tools/data/{name}", "w") as fh:
        fh.write("e2,psi,u,fx,fy,tz,err\n")
        for r in rows:
            fh.write(",".join(repr(float(x)) for x in r) + "\n")
    print(f"{len(rows)} points in {time.time() - t0:.0f} s; max |h − h/2| {worst:.1e}")


if __name__ == "__main__":
    main()
