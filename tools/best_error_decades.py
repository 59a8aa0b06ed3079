#!/usr/bin/env python3
"""Max error of `best` against the exact integrals per decade of m1 = 1 - e^2 (issue 21): the
per-decade table of the guide's `best` chapter (docs/guide/src/best.md) and of src/friction/best.rs.

Both forms (`contact_eval friction --model best`: the per-contact BestContact; `--model
best-varying`: the per-step flash table) and both precisions, against `--model exact` (f64;
for f32 at the f32-rounded inputs). Per decade: 9 values of m1 log-spaced over it (the last
decade ends at the contract's end, m1 = 1.70e-5 at P/Q = 1e-4), 25 psi (all quadrants, on and
near the axes), u log-spaced over [0.005, 300] plus u_b(1 + d), d = 1e-7 ... 0.6, u_b(1 - d)
and u = 1e4, 1e7. Prints a markdown-ish table: force fN / torque fNa.
Needs numpy. Run from the repository root:  python3 tools/best_error_decades.py   (≈30 s)
"""
import io
import subprocess

import numpy as np

EVAL = ["cargo", "run", "--quiet", "--release", "--bin", "contact_eval", "--", "friction"]
M1_END = 1.7014448227e-5


def run(model, precision, text):
    r = subprocess.run(EVAL + ["--model", model, "--precision", precision], input=text,
                       capture_output=True, text=True, check=True)
    return np.loadtxt(io.StringIO(r.stdout), delimiter=",", skiprows=1)


def csv(rows):
    return "e2,psi,u\n" + "".join(f"{float(a)!r},{float(b)!r},{float(c)!r}\n" for a, b, c in rows)


def main():
    psis = np.concatenate([np.linspace(0, np.pi / 2, 13), np.linspace(np.pi / 2, 2 * np.pi, 10)[1:],
                           [1e-4, 0.0131]])
    decades = [(1.0, 0.1), (0.1, 0.01), (0.01, 1e-3), (1e-3, 1e-4), (1e-4, M1_END)]
    print("m1 decade | e2 range | best f64 | best f32 | best-varying f64 | best-varying f32")
    for hi, lo in decades:
        m1s = np.geomspace(hi, lo, 9)
        if hi == 1.0:
            m1s = np.concatenate([[1.0], np.geomspace(0.999, lo, 8)])
        rows = []
        for m1 in m1s:
            for p in psis:
                ub = 1 / np.sqrt(np.sin(p) ** 2 + np.cos(p) ** 2 / m1)
                d = np.array([1e-7, 1e-4, 1e-3, 1e-2, 0.03, 0.05, 0.1, 0.2, 0.3, 0.6])
                us = np.concatenate([np.geomspace(0.005, 300, 70), ub * (1 + d),
                                     ub * (1 - np.array([1e-7, 1e-3, 0.1, 0.5])), [1e4, 1e7]])
                rows += [(1 - m1, p, u) for u in us]
        ref = {"f64": run("exact", "f64", csv(rows)),
               "f32": run("exact", "f64", csv([tuple(np.float32(x) for x in r) for r in rows]))}
        cells = []
        for model in ("best", "best-varying"):
            for prec in ("f64", "f32"):
                a, r = run(model, prec, csv(rows)), ref[prec]
                df = np.maximum(np.abs(a[:, 3] - r[:, 3]), np.abs(a[:, 4] - r[:, 4])).max()
                dt = np.abs(a[:, 5] - r[:, 5]).max()
                cells.append(f"{df:.1e} / {dt:.1e}")
        print(f"[{hi:g}, {lo:.3g}] | {1 - hi:.6g} … {1 - lo:.6g} | " + " | ".join(cells))


if __name__ == "__main__":
    main()
