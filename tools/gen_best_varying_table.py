#!/usr/bin/env python3
"""Generate src/friction/best/varying_table.rs: the flash table of `best`'s per-step form
(`friction::Best`'s `FrictionLaw::traction`, what `VaryingContact` calls), in which e² is an
interpolated dimension — no per-contact build, no RAM table.

Outside the ellipse `best` writes the traction with seven coefficients c_j(e², z) of the
confocal structure (see tools/gen_best_table.py and src/friction/best.rs), z = √(1 − τ) ∈ [0, 1]
(z = 0 on the ellipse, z = 1 at u = ∞). Their values at both ends are known exactly at run time
(the quartic on the ellipse, F = −v/|v|, T_z = T₁/u at infinity), so only the remainder

    R_j(s, z) = c_j − [c_j(0)·(1 − z²) + c_j(1)·z²]      (zero at z = 0 and z = 1, slope 0 at z = 0)

is tabulated, over s = m₁^⅛ ∈ [M1_LO^⅛, 1] (e² ∈ [0, 1 − M1_LO], M1_LO = 1e-5: past the
contract's end, m₁ = 1.70e-5 at P/Q = 1e-4) and z. Near the line contact (m₁ → 0) the
coefficients follow ln m₁ (K ≈ ln(4/√m₁)), and ln m₁ = 8 ln s varies slowly and smoothly over
s ∈ [0.24, 1]: a uniform grid in s resolves the thin end and the circle alike (measured on the
remainder with NS = 25: 4.5e-5 fN, 3.3e-6 fNa; the former m₁^¼ over the same range and nodes
6.5e-4 fN):

  * NS uniform cells in s (NS + 1 nodes); at run time the 3-point Lagrange (quadratic)
    interpolation through the nodes j, j+1, j+2 of the cell j (j−1 … j+1 in the last cell):
    continuous in s, exact at every node, error O(h³) (4-point cubic with NS = 12 measured the
    same error at 17 KB but costs a fourth pass over the seven cubics: ≈60 M4F instructions);
  * at each node NZ uniform cubic pieces in z (monomial in r = NZ·z − i ∈ [0, 1]) through the
    Chebyshev–Lobatto points r = 0, 1/4, 3/4, 1 (continuous in z); the first piece keeps R's
    zero slope at z = 0 (c₀ + c₂r² + c₃r³ through r = 0, 1/2, 1), so there is no √-like onset
    at the ellipse.

Samples: the exact integrals of the crate (`contact_eval friction --model exact`, 5e-15 against
the independent reference tools/data/friction_ref.csv) through gen_best_table.coefficients (six
values of ν per (e², a_c), residual of the confocal structure printed). The table is checked on
an independent grid (s and z between the nodes; printed, and written into the header).
Run from the repository root:  python3 tools/gen_best_varying_table.py
"""
import sys

import numpy as np

sys.path.insert(0, "tools")
import gen_best_table as gbt  # noqa: E402

NS, NZ = 25, 12
M1_LO = 1e-5
S0 = M1_LO ** 0.125  # s = m1^(1/8) at the table's thin end
NODES_R = (0.0, 0.25, 0.75, 1.0)
INV = np.array([  # monomial coefficients from the values at NODES_R
    [1.0, 0.0, 0.0, 0.0],
    [-19.0 / 3.0, 8.0, -8.0 / 3.0, 1.0],
    [32.0 / 3.0, -56.0 / 3.0, 40.0 / 3.0, -16.0 / 3.0],
    [-16.0 / 3.0, 32.0 / 3.0, -32.0 / 3.0, 16.0 / 3.0],
])


def s_nodes():
    return S0 + (1 - S0) * np.arange(NS + 1) / NS


def ends(s):
    """Exact end values c_j(0) (from the sampled boundary: a_c = 1 exactly) are taken from the
    samples; c_j(1) (u = ∞) in closed form: (1, 0, 1, 0, −g5, g5·m, 0), g5 = 0.4/(1 + γ)."""
    g = s ** 4
    m = 1 - g * g
    g5 = 0.4 / (1 + g)
    return np.array([1.0, 0.0, 1.0, 0.0, -g5, g5 * m, 0.0])


def remainder(s_list, zs):
    """R[s][z][7] from exact samples; index 0 of zs must be z = 0."""
    gam = np.asarray(s_list) ** 4
    zs = np.asarray(zs, dtype=float)
    assert zs[0] == 0.0
    d, resid = gbt.coefficients(gam, zs)
    z2 = (zs ** 2)[None, :, None]
    e1 = np.array([ends(s) for s in s_list])[:, None, :]
    e0 = d[:, :1, :]
    return d - (e0 * (1 - z2) + e1 * z2), resid


def build():
    sn = s_nodes()
    zs = [0.0]
    for i in range(NZ):
        zs += [(i + r) / NZ for r in NODES_R[1:]]
    zs.append(0.5 / NZ)
    R, resid = remainder(sn, zs)
    half = R[:, -1, :]
    vals = R[:, :-1, :]  # z = 0, then 3 per piece
    table = np.zeros((NS + 1, NZ, 7, 4))
    for i in range(NZ):
        col = np.stack([vals[:, 0 if i == 0 else 3 * i, :]] +
                       [vals[:, 3 * i + k, :] for k in (1, 2, 3)], axis=-1)  # [node][7][4]
        c = col @ INV.T
        c[..., 0] = col[..., 0]
        c[..., 3] = col[..., 3] - c[..., 0] - c[..., 1] - c[..., 2]
        if i == 0:
            h, e = half - col[..., 0], col[..., 3] - col[..., 0]
            c[..., 1] = 0.0
            c[..., 3] = 2 * e - 8 * h
            c[..., 2] = e - c[..., 3]
        table[:, i] = c
    return table.astype(np.float32).astype(np.float64), resid


def lagrange(x):
    """Weights of the 3-point Lagrange interpolation at x ∈ [0, 2] (nodes 0, 1, 2)."""
    a, b, c = x, x - 1, x - 2
    return np.array([b * c / 2, -a * c, a * b / 2])


def evaluate(table, s, z):
    """R_j(s, z) as the Rust code computes it (f64 here)."""
    x = min(max((s - S0) * NS / (1 - S0), 0.0), float(NS))
    j = min(int(x), NS - 1)
    j0 = min(j, NS - 2)
    w = lagrange(x - j0)
    zn = z * NZ
    i = min(int(zn), NZ - 1)
    r = zn - i
    p = table[j0:j0 + 3, i]  # [3][7][4]
    v = p[..., 0] + r * (p[..., 1] + r * (p[..., 2] + r * p[..., 3]))
    return w @ v


def check(table):
    """Max error of the remainder on an independent grid, per coefficient, and as force and
    torque errors: max over q ∈ [0, 1] of |Δa + Δb·q| (F_x, F_y) and |Δa + Δb·q + Δc·q²|·τ (T_z)."""
    st = S0 + (1 - S0) * (np.arange(4 * NS + 1) + 0.37) / (4 * NS + 0.74)
    zt = np.concatenate([np.linspace(0, 1, 61)[1:-1], [1e-3, 5e-3, 0.02]])
    Rt, _ = remainder(st, np.concatenate([[0.0], zt]))
    q = np.linspace(0, 1, 21)
    worst = np.zeros(7)
    fx = fy = tz = (0.0, None)
    for a, s in enumerate(st):
        for b, z in enumerate(zt):
            dv = evaluate(table, s, z) - Rt[a, b + 1]
            worst = np.maximum(worst, np.abs(dv))
            tau = 1 - z * z
            for name, val in (("fx", np.abs(dv[0] + dv[1] * q).max()),
                              ("fy", np.abs(dv[2] + dv[3] * q).max()),
                              ("tz", tau * np.abs(dv[4] + dv[5] * q + dv[6] * q * q).max())):
                cur = {"fx": fx, "fy": fy, "tz": tz}[name]
                if val > cur[0]:
                    cur = (val, (1 - s ** 8, z))
                if name == "fx":
                    fx = cur
                elif name == "fy":
                    fy = cur
                else:
                    tz = cur
    return worst, fx, fy, tz


def f32(x):
    return gbt.f32(x)


def main():
    table, resid = build()
    print(f"confocal structure: max residual {resid:.1e}", file=sys.stderr)
    worst, fx, fy, tz = check(table)
    names = "a_x b_x a_y b_y a_T b_T c_T".split()
    per = ", ".join(f"{n} {e:.1e}" for n, e in zip(names, worst))
    print("remainder max error per coefficient: " + per, file=sys.stderr)
    where = lambda w: f"{w[0]:.1e} (e² = {w[1][0]:.6f}, z = {w[1][1]:.3f})"
    summary = f"F_x {where(fx)}, F_y {where(fy)}, T_z {where(tz)}"
    print("as traction errors: " + summary, file=sys.stderr)
    nbytes = table.size * 4
    with open("src/friction/best/varying_table.rs", "w") as f:
        f.write("//! Generated by `tools/gen_best_varying_table.py` — do not edit.\n//!\n")
        f.write("//! The remainder R_j(s, z) of `best`'s seven outside coefficients after their exact\n")
        f.write("//! ends, at the nodes s_n = S0 + n(1 − S0)/NS of s = m₁^⅛, each as NZ cubic pieces in z\n")
        f.write(f"//! (monomial in r = NZ·z − i). Stored as `f32`: {nbytes:,} bytes.\n")
        f.write("//! Max error on an independent grid (s, z between the nodes), per coefficient:\n")
        f.write(f"//! {per};\n//! as traction: {summary}.\n\n")
        f.write(f"/// Cells in s = m₁^⅛ over [S0, 1].\npub(crate) const NS: usize = {NS};\n")
        f.write(f"/// Cubic pieces in z.\npub(crate) const NZ: usize = {NZ};\n")
        f.write(f"/// s at the table's thin end m₁ = {M1_LO} (e² = {1 - M1_LO}).\npub(crate) const S0: f64 = {S0!r};\n\n")
        write_table(f, [[[[f32(x) for x in table[n, i, j]] for j in range(7)] for i in range(NZ)] for n in range(NS + 1)])


def write_table(f, rows):
    """The table, one cubic piece (7 coefficients × 4 monomials) per line: the crate ships
    this file, so it is kept compact (`cargo package` size bound in .ci/run)."""
    f.write("/// `TABLE[node][piece][coefficient]`: the cubic's monomial coefficients in r.\n")
    f.write("#[rustfmt::skip]\n")
    f.write("pub(crate) static TABLE: [[[[f32; 4]; 7]; NZ]; NS + 1] = [\n")
    for n, node in enumerate(rows):
        f.write(f"// s node {n}\n[\n")
        for piece in node:
            f.write("[" + ",".join("[" + ",".join(c) + "]" for c in piece) + "],\n")
        f.write("],\n")
    f.write("];\n")


if __name__ == "__main__":
    main()
