#!/usr/bin/env python3
"""Generate src/friction/best/table.rs: the outside-the-ellipse coefficients of the `best`
friction law, fitted to the EXACT Contensou integrals.

Outside the ellipse, with the IC in confocal coordinates (a_c, nu), q = sin^2 nu,
tau = (1 + gamma)/(a_c + b_c):

    F_x = -cos nu (a_x + b_x q),  F_y = -sin nu (a_y + b_y q),  T_z = tau (a_T + b_T q + c_T q^2)

(verified here: each slice (m, a_c) is fitted at 6 values of nu; the residual is printed).
The seven coefficients are smooth functions of
    lam = 2 (ln gamma - ln g0)/(ln g1 - ln g0) - 1  in [-1, 1]  (gamma = sqrt(1 - e^2) in [g0, g1])
    zh  = 2 z - 1,  z = sqrt(1 - tau)          in [-1, 1]  (z = 0: the ellipse, z = 1: u = inf)
and are stored as tensor Chebyshev series of degree (DG, DZ) in (lam, zh), one per range (RANGES):
"wide" gamma in [0.1, 1] (e^2 in [0, 0.99]) -> table.rs, "thin" gamma in [0.003, 0.1]
(e^2 up to 1 - 9e-6, past the contract's end m1 = 1.70e-5 at P/Q = 1e-4) -> table_thin.rs; in the
thin range the coefficients follow ln m1 (K ~ ln(4/sqrt m1)), which lam is linear in.

Samples: the exact integrals of the crate (`contact_eval friction --model exact`, 5e-15 against
the independent mpmath reference tools/data/friction_ref.csv) on a Chebyshev grid; least squares.
Run from the repository root:  python3 tools/gen_best_table.py [wide] [thin]
"""
import io
import subprocess
import sys

import numpy as np
import numpy.polynomial.chebyshev as C

NU = np.linspace(0.1, 1.45, 6)
# The two fitted ranges in gamma = sqrt(m1) = b/a: (file, gamma_lo, gamma_hi, DG, DZ, NG, NZ).
# "wide": e^2 in [0, 0.99]; "thin": e^2 in [0.99, 1 - 9e-6], past the contract's end
# (P/Q = 1e-4: m1 = 1.70e-5), where the coefficients follow ln m1 and vary faster in z.
RANGES = {
    "wide": ("src/friction/best/table.rs", 0.1, 1.0, 8, 10, 16, 24),
    "thin": ("src/friction/best/table_thin.rs", 0.003, 0.1, 6, 14, 14, 28),
}
EVAL = ["cargo", "run", "--quiet", "--release", "--bin", "contact_eval", "--",
        "friction", "--model", "exact"]


def exact(rows):
    text = "e2,psi,u\n" + "".join(f"{float(m)!r},{float(p)!r},{float(u)!r}\n" for m, p, u in rows)
    out = subprocess.run(EVAL, input=text, capture_output=True, text=True, check=True).stdout
    return np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1)[:, 3:6]


def polar(m, ac, nu):
    bc = np.sqrt(ac * ac - m)
    x0, y0 = -ac * np.sin(nu), bc * np.cos(nu)
    return np.arctan2(-x0, y0), np.hypot(x0, y0)


def a_c(m, tau):
    s = (1 + np.sqrt(1 - m)) / tau  # a_c + b_c
    return (s + m / s) / 2


def coefficients(gammas, zs):
    """[gamma][z][7]: (a_x, b_x, a_y, b_y, a_T, b_T, c_T), and the max fit residual."""
    rows, meta = [], []
    for g in gammas:
        m = 1 - g * g
        for z in zs:
            ac = a_c(m, max(1 - z * z, 1e-7))
            meta.append((m, ac))
            rows += [(m, *polar(m, ac, nu)) for nu in NU]
    f = exact(rows).reshape(len(meta), len(NU), 3)
    q = np.sin(NU) ** 2
    out, resid = [], 0.0
    for (m, ac), fi in zip(meta, f):
        tau = (1 + np.sqrt(1 - m)) / (ac + np.sqrt(ac * ac - m))
        c = []
        for col, fac, deg in ((0, -np.cos(NU), 1), (1, -np.sin(NU), 1), (2, tau, 2)):
            y = fi[:, col] / fac
            p = np.polyfit(q, y, deg)
            resid = max(resid, np.abs(np.polyval(p, q) - y).max())
            c += list(p[::-1])
        out.append(c)
    return np.array(out).reshape(len(gammas), len(zs), 7), resid


def f32(x):
    """Shortest literal that round-trips the nearest f32."""
    t = np.format_float_positional(np.float32(x), unique=True, trim="0")
    return t if "." in t else t + ".0"


def fit(name):
    path, glo, ghi, DG, DZ, NG, NZ = RANGES[name]
    l0, l1 = np.log(glo), np.log(ghi)

    def lam_of(g):
        return 2 * (np.log(g) - l0) / (l1 - l0) - 1

    cheb = lambda n: np.cos(np.pi * (np.arange(n) + 0.5) / n)
    gam = np.exp((cheb(NG) + 1) / 2 * (l1 - l0) + l0)
    zn = (cheb(NZ) + 1) / 2
    d, resid = coefficients(gam, zn)
    print(f"confocal structure: max residual {resid:.1e}", file=sys.stderr)
    # The exact coefficients grow like z^2 off the ellipse (smooth in a_c): the fit keeps
    # dP/dz = 0 at z = 0 (basis T_l - (-1)^(l+1) l^2 T_1, l >= 2, in zh; no free T_1), so the
    # model has no sqrt-like onset at the boundary.
    grid = np.meshgrid(lam_of(gam), 2 * zn - 1, indexing="ij")
    v = C.chebvander2d(*grid, [DG, DZ]).reshape(NG * NZ, DG + 1, DZ + 1)
    slope = np.array([0.0, 1.0] + [(-1.0) ** (l + 1) * l * l for l in range(2, DZ + 1)])
    basis = v - v[:, :, 1:2] * slope  # column l: T_l - slope_l T_1 (column 1 becomes 0)
    keep = [l for l in range(DZ + 1) if l != 1]
    vb = basis[:, :, keep].reshape(NG * NZ, -1)
    cs = []
    for j in range(7):
        a = np.linalg.lstsq(vb, d[:, :, j].ravel(), rcond=None)[0].reshape(DG + 1, DZ)
        c = np.zeros((DG + 1, DZ + 1))
        c[:, keep] = a
        c[:, 1] = -(a[:, 1:] * slope[2:]).sum(axis=1)
        cs.append(c)
    # independent check grid (not the fit nodes)
    gt = np.exp(np.linspace(l0, l1, 11))
    zt = np.linspace(0, 1, 37)
    dt, _ = coefficients(gt, zt)
    tg = np.meshgrid(lam_of(gt), 2 * zt - 1, indexing="ij")
    cs = [c.astype(np.float32).astype(np.float64) for c in cs]  # stored as f32
    err = [np.abs(C.chebval2d(*tg, cs[j]) - dt[:, :, j]).max() for j in range(7)]
    print(f"{name}: fit max error per coefficient: " + " ".join(f"{e:.1e}" for e in err),
          file=sys.stderr)
    # passivity of the forces: the brackets a + b q (q in [0, 1]) stay positive
    low = min(min(dt[:, :, 0].min(), (dt[:, :, 0] + dt[:, :, 1]).min()),
              min(dt[:, :, 2].min(), (dt[:, :, 2] + dt[:, :, 3]).min()))
    print(f"{name}: smallest force bracket a + b q on the check grid: {low:.3f}", file=sys.stderr)
    names = "a_x b_x a_y b_y a_T b_T c_T".split()
    nbytes = 7 * (DG + 1) * (DZ + 1) * 4
    lam_doc = (f"2(ln γ − ln {glo})/(ln {ghi} − ln {glo}) − 1, "
               f"γ = √m₁ ∈ [{glo}, {ghi}]")
    return lambda: write(name, path, glo, ghi, DG, DZ, l0, l1, cs, err, nbytes, lam_doc)


def write(name, path, glo, ghi, DG, DZ, l0, l1, cs, err, nbytes, lam_doc):
    names = "a_x b_x a_y b_y a_T b_T c_T".split()
    with open(path, "w") as f:
        f.write("//! Generated by `tools/gen_best_table.py` — do not edit.\n//!\n")
        f.write("//! Tensor Chebyshev coefficients of the seven outside coefficients\n")
        f.write("//! (a_x, b_x, a_y, b_y, a_T, b_T, c_T) of the `best` law in (λ, ẑ):\n")
        f.write(f"//! `TABLE[j][k][l]` multiplies T_k(λ)·T_l(ẑ); stored as `f32` ({nbytes:,} bytes).\n//! Fit max error per coefficient on an\n")
        f.write("//! independent grid: " + ", ".join(f"{n} {e:.1e}" for n, e in zip(names, err)) + ".\n\n")
        f.write(f"/// Degree in λ = {lam_doc}.\npub(super) const DG: usize = {DG};\n")
        f.write(f"/// Degree in ẑ = 2z − 1, z = √(1 − τ).\npub(super) const DZ: usize = {DZ};\n")
        span = float(1.0 / (l1 - l0))
        if name == "wide":  # the switch to the thin table
            f.write(f"/// The range's lower end in γ = √m₁.\npub(super) const G0: f64 = {glo!r};\n")
        f.write("/// λ = LAM_SCALE·ln m₁ − LAM_SHIFT (the definition above, from ln m₁ = 2 ln γ).\n")
        f.write(f"pub(super) const LAM_SCALE: f64 = {span!r};\n")
        f.write(f"pub(super) const LAM_SHIFT: f64 = {float(2 * l0 * span + 1)!r};\n\n")
        f.write("/// `[coefficient][λ degree][ẑ degree]`.\n")
        f.write("pub(super) static TABLE: [[[f32; DZ + 1]; DG + 1]; 7] = [\n")
        for j in range(7):
            f.write(f"    // {names[j]}\n    [\n")
            for k in range(DG + 1):
                f.write("        [" + ", ".join(f32(x) for x in cs[j][k]) + "],\n")
            f.write("    ],\n")
        f.write("];\n")


def main():
    # fit everything first (the fits run the crate's exact integrals), then write
    for w in [fit(name) for name in sys.argv[1:] or RANGES]:
        w()


if __name__ == "__main__":
    main()
