#!/usr/bin/env python3
"""Interpolation error of the Kalker coefficients (src/friction/rolling/kalker.rs) against
Table E3 itself: the table is split into even and odd rows in g; the scheme of kalker.rs
(cubic Hermite with finite-difference slopes in g) built on the even rows (spacing 0.2)
predicts the odd ones, and so does CONTACT's linear interpolation. The error of the scheme on
the full table (spacing 0.1) is that figure scaled by (1/2)^3 (Hermite with difference slopes
is O(h^3)), linear interpolation's by (1/2)^2. Reads the table from kalker.rs (no copy).

    python3 tools/kalker_interp_check.py
"""
import re, pathlib

src = pathlib.Path(__file__).resolve().parent.parent / "src/friction/rolling/kalker.rs"
text = src.read_text()

def table(name):
    block = text.split(f"const {name}: [[f64; 9]; 10] = [")[1].split("];")[0]
    return [[float(x) for x in re.findall(r"[0-9.]+", row)] for row in re.findall(r"\[([^\]]+)\]", block)]

def hermite(ys, u_nodes, g):
    # uniform nodes u_nodes (list of g), finite-difference slopes, one-sided at the ends
    h = u_nodes[1] - u_nodes[0]
    t = min(max((g - u_nodes[0]) / h, 0), len(ys) - 1)
    i = min(int(t), len(ys) - 2)
    u = t - i
    def m(k):
        if k == 0: return ys[1] - ys[0]
        if k == len(ys) - 1: return ys[-1] - ys[-2]
        return 0.5 * (ys[k + 1] - ys[k - 1])
    y0, y1, m0, m1 = ys[i], ys[i + 1], m(i), m(i + 1)
    return (2*u**3 - 3*u**2 + 1)*y0 + (u**3 - 2*u**2 + u)*m0 + (-2*u**3 + 3*u**2)*y1 + (u**3 - u**2)*m1

def linear(ys, u_nodes, g):
    h = u_nodes[1] - u_nodes[0]
    t = (g - u_nodes[0]) / h
    i = min(int(t), len(ys) - 2)
    u = t - i
    return (1 - u) * ys[i] + u * ys[i + 1]

names = ["C11", "C22", "C23"]

def power(side, col):
    """kalker.rs interpolates C·g^p for a > b, the asymptotic growth removed (C11, C22 ~ 1/g,
    C23 ~ g^(-3/2)), and C itself for a < b (there C23 ~ sqrt(g)·(1 + nu·ln(16/g)) is far from
    its asymptote inside the table: dividing by sqrt(g) makes the error 6.8 % on the half
    table instead of 1.9 %)."""
    k = col // 3
    if side == "NARROW":
        return 0.0
    return 1.5 if k == 2 else 1.0
for side in ["NARROW", "LONG"]:
    rows = table(side)
    gs = [0.1 * (k + 1) for k in range(10)]
    worst = {"hermite": (0, None), "linear": (0, None)}
    for col in range(9):
        p = power(side, col)
        ys = [r[col] * g ** p for r, g in zip(rows, gs)]
        even_g, even_y = gs[0::2], ys[0::2]  # 0.1, 0.3, ..., 0.9
        for k in range(1, 9, 2):  # odd rows inside the even span: 0.2 ... 0.8
            for kind, f in (("hermite", hermite), ("linear", linear)):
                e = abs(f(even_y, even_g, gs[k]) / ys[k] - 1) if kind == "hermite" else \
                    abs(f([r[col] for r in rows][0::2], even_g, gs[k]) / rows[k][col] - 1)
                if e > worst[kind][0]:
                    worst[kind] = (e, f"{names[col // 3]} nu={0.25 * (col % 3)} g={gs[k]:.1f}")
    for kind, p in (("hermite", 3), ("linear", 2)):
        e, where = worst[kind]
        print(f"{side:6s} {kind:7s}: half table max rel err {e:.2%} at {where}; "
              f"full table estimate {e / 2 ** p:.2%}")
