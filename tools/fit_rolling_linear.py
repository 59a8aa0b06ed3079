#!/usr/bin/env python3
"""Builds the tables of the library's linear theory over the whole domain
(src/friction/rolling/creep_matrix.rs) from the exact reference's linear creep matrices
(tools/rolling_exact/examples/linear_table.rs) and writes them as Rust
(src/friction/rolling/creep_matrix_data.rs). Nothing is fitted: the tables hold the reference's
values at its nodes; the Rust module interpolates.

- ALIGNED (rolling along an axis): ln C₁₁, ln C₂₂, ln C₂₃, ln C₃₃ at a/b = 20^(i/8 − 1), i = 0 … 16
  (tools/data/rolling_linear_aligned.csv), ν = 0, ¼, ½; C₂₃ the mean of K₂₃ and −K₃₂ (reciprocity).
- SKEWED (a patch with r = a/b ≥ 1 rolled at θ from its major axis): six numbers per node of
  x = ln r = (i/6)·ln 20, i = 0 … 6, and t = (1 − ln(a_r/b_r)/ln r)/2 = j/8, j = 0 … 8 (a_r/b_r the
  aligned ellipse's ratio along the rolling direction; t = 0: along the major axis, 1: along the
  minor axis), ν = 0, ¼, ½ (tools/data/rolling_linear_skewed.csv; the rows t = 0, 1 and x = 0
  are the aligned patch: exactly 1 and 0):
  ρ₁₁ = K₁₁/C₁₁, ρ₂₂ = K₂₂/C₂₂, ρ₃₃ = K₃₃/C₃₃, ρ₂₃ = ½(K₂₃ − K₃₂)/C₂₃,
  κ₁₂ = ½(K₁₂ + K₂₁)/(√(C₁₁C₂₂)·sinθ cosθ), κ₁₃ = ½(K₁₃ − K₃₁)/(√(C₁₁C₃₃)·sinθ cosθ) (the couplings
  vanish like sin 2θ at the axes, i.e. like √t: divided by it they are smooth in t; at t = 0, 1
  linearly extrapolated),
  with the C's of the aligned ellipse a_r/b_r from ALIGNED (as the Rust module interpolates them).

    python3 tools/fit_rolling_linear.py [--write|--check]
"""
import math, pathlib, sys

root = pathlib.Path(__file__).resolve().parent.parent
data = root / "tools/data"
out_rs = root / "src/friction/rolling/creep_matrix_data.rs"
NU = (0.0, 0.25, 0.5)
LN20 = math.log(20.0)
NA, NX, NT = 17, 7, 9


def read(name):
    rows = []
    for line in (data / name).read_text().splitlines():
        if not line or line[0] == "#" or line.startswith("a_over_b"):
            continue
        f = line.split(",")
        v = [float(x) for x in f[:21]]
        rows.append(dict(r=v[0], theta=math.radians(v[1]), nu=v[2], k=[v[3:6], v[6:9], v[9:12]], e=[v[12:15], v[15:18], v[18:21]]))
    return rows


def coeffs(k):
    """(C₁₁, C₂₂, C₂₃, C₃₃) of an aligned matrix."""
    return (k[0][0], k[1][1], 0.5 * (k[1][2] - k[2][1]), k[2][2])


def hermite(ys, x0, h, x):
    """Cubic Hermite through ys at x0 + i·h with finite-difference slopes (one-sided at the ends),
    clamped to the range — the Rust module's scheme."""
    n = len(ys)
    t = min(max((x - x0) / h, 0.0), n - 1.0)
    i = min(int(t), n - 2)
    u = t - i

    def slope(k):
        if k == 0:
            return ys[1] - ys[0]
        if k == n - 1:
            return ys[n - 1] - ys[n - 2]
        return 0.5 * (ys[k + 1] - ys[k - 1])

    y0, y1, m0, m1 = ys[i], ys[i + 1], slope(i), slope(i + 1)
    return ((2 * u ** 3 - 3 * u ** 2 + 1) * y0 + (u ** 3 - 2 * u ** 2 + u) * m0 + (-2 * u ** 3 + 3 * u ** 2) * y1
            + (u ** 3 - u ** 2) * m1)


def aligned_table():
    rows = read("rolling_linear_aligned.csv")
    tab = [[[None] * 3 for _ in range(4)] for _ in range(NA)]
    for r in rows:
        i = round((math.log(r["r"]) / LN20 + 1.0) * 8.0)
        j = NU.index(r["nu"])
        assert abs(math.log(r["r"]) - LN20 * (i / 8.0 - 1.0)) < 1e-9
        for c, v in enumerate(coeffs(r["k"])):
            tab[i][c][j] = math.log(v)
    missing = [(i, c, j) for i in range(NA) for c in range(4) for j in range(3) if tab[i][c][j] is None]
    assert not missing, f"aligned rows missing: {missing[:5]}"
    return tab


def in_nu(c, nu):
    """1/C quadratic in ν through ν = 0, ¼, ½ (Kalker's form)."""
    inv = (nu - 0.25) * (nu - 0.5) * 8.0 / c[0] - (nu - 0.5) * nu * 16.0 / c[1] + nu * (nu - 0.25) * 8.0 / c[2]
    return 1.0 / inv


def quad_nu(c, nu):
    """Plain quadratic in ν through ν = 0, ¼, ½."""
    return (nu - 0.25) * (nu - 0.5) * 8.0 * c[0] - (nu - 0.5) * nu * 16.0 * c[1] + nu * (nu - 0.25) * 8.0 * c[2]


def aligned(tab, aob, nu):
    """(C₁₁, C₂₂, C₂₃, C₃₃) at a/b ∈ [1/20, 20] (clamped), ν — the Rust scheme."""
    x = math.log(aob)
    # 1/C quadratic in ν for C₁₁, C₂₂, C₂₃ (Kalker's form); C₃₃ itself quadratic (at a/b = 20 it
    # falls from 0.79 to 0.16 over ν ∈ [0, ½] nearly linearly, 1/C₃₃ far from it)
    return tuple((in_nu if c < 3 else quad_nu)(
        [math.exp(hermite([tab[i][c][j] for i in range(NA)], -LN20, LN20 / 8.0, x)) for j in range(3)], nu)
        for c in range(4))


def aligned_ratio(r, theta):
    """a_r/b_r of the aligned ellipse along the rolling direction (c = 1)."""
    big_a = math.cos(theta) ** 2 / r + math.sin(theta) ** 2 * r
    return 1.0 / big_a


def normalised(tab, r, theta, nu, k):
    """(ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) of a skewed matrix K (θ ∈ [0, 90°])."""
    c11, c22, c23, c33 = aligned(tab, aligned_ratio(r, theta), nu)
    sc = math.sin(theta) * math.cos(theta)
    return (k[0][0] / c11, k[1][1] / c22, k[2][2] / c33, 0.5 * (k[1][2] - k[2][1]) / c23,
            0.5 * (k[0][1] + k[1][0]) / (math.sqrt(c11 * c22) * sc), 0.5 * (k[0][2] - k[2][0]) / (math.sqrt(c11 * c33) * sc))


IDENTITY = (1.0, 1.0, 1.0, 1.0, 0.0, 0.0)


def skewed_table(tab):
    rows = read("rolling_linear_skewed.csv")
    sk = [[[[None] * 3 for _ in range(6)] for _ in range(NT)] for _ in range(NX)]
    for i in range(NX):
        for j in range(NT):
            if i == 0 or j in (0, NT - 1):
                for e in range(6):
                    sk[i][j][e] = [IDENTITY[e]] * 3
    for r in rows:
        i = round(math.log(r["r"]) / LN20 * 6.0)
        u = math.log(aligned_ratio(r["r"], r["theta"]))
        j = round((1.0 - u / math.log(r["r"])) / 2.0 * 8.0)
        col = NU.index(r["nu"])
        for e, v in enumerate(normalised(tab, r["r"], r["theta"], r["nu"], r["k"])):
            sk[i][j][e][col] = v
    # the couplings ÷ sinθcosθ at the axes (t = 0, 1): linear extrapolation from the two nearest
    # nodes (they are multiplied by sinθcosθ = 0 there; this only shapes the end intervals)
    for i in range(1, NX):
        for e in (4, 5):
            for col in range(3):
                a, b = sk[i][1][e][col], sk[i][2][e][col]
                if a is not None and b is not None:
                    sk[i][0][e][col] = 2.0 * a - b
                a, b = sk[i][NT - 2][e][col], sk[i][NT - 3][e][col]
                if a is not None and b is not None:
                    sk[i][NT - 1][e][col] = 2.0 * a - b
    missing = [(i, j) for i in range(NX) for j in range(NT) for e in range(6) for c in range(3) if sk[i][j][e][c] is None]
    return sk, sorted(set(missing))


def skewed(tab, sk, r, theta, nu):
    """The Rust scheme: K (3×3) of a patch r ≥ 1 rolled at θ from its major axis (any θ)."""
    th = theta % math.pi
    mirror = th > 0.5 * math.pi
    if mirror:
        th = math.pi - th
    q = aligned_ratio(r, th)
    c11, c22, c23, c33 = aligned(tab, q, nu)
    x = math.log(r)
    t = 0.5 * (1.0 - math.log(q) / x) if x > 0 else 0.0
    vals = []
    for e in range(6):
        per_x = [quad_nu([hermite([sk[i][j][e][c] for j in range(NT)], 0.0, 1.0 / 8.0, t) for c in range(3)], nu)
                 for i in range(NX)]
        vals.append(hermite(per_x, 0.0, LN20 / 6.0, x))
    r11, r22, r33, r23, k12, k13 = vals
    s = (-1.0 if mirror else 1.0) * math.sin(th) * math.cos(th)
    K12 = s * k12 * math.sqrt(c11 * c22)
    K13 = s * k13 * math.sqrt(c11 * c33)
    K23 = r23 * c23
    return [[r11 * c11, K12, K13], [K12, r22 * c22, K23], [-K13, -K23, r33 * c33]]


def check(tab, sk):
    """The scheme against the held-out matrices (rolling_linear_check.csv)."""
    rows = read("rolling_linear_check.csv")
    worst = {}
    print("a/b(own)  θ°      ν      max rel. dev. C11..C33 / couplings (÷ the diagonal scale)   ref est.")
    for r in rows:
        aob, th = r["r"], r["theta"]
        if aob < 1.0:  # the same patch with its major axis at θ + 90°
            aob, th = 1.0 / aob, th + 0.5 * math.pi
        k = skewed(tab, sk, aob, th, r["nu"])
        ref = r["k"]
        dev = {}
        for (a, b), name in (((0, 0), "K11"), ((1, 1), "K22"), ((2, 2), "K33")):
            dev[name] = k[a][b] / ref[a][b] - 1.0
        dev["K23"] = k[1][2] / (0.5 * (ref[1][2] - ref[2][1])) - 1.0
        dev["K12"] = (k[0][1] - 0.5 * (ref[0][1] + ref[1][0])) / math.sqrt(ref[0][0] * ref[1][1])
        dev["K13"] = (k[0][2] - 0.5 * (ref[0][2] - ref[2][0])) / math.sqrt(ref[0][0] * ref[2][2])
        for n, v in dev.items():
            worst[n] = max(worst.get(n, 0.0), abs(v))
        est = max(max(row) for row in r["e"])
        print(f"{r['r']:8.4f} {math.degrees(r['theta']):6.2f} {r['nu']:.3f}  " + " ".join(f"{n} {v:+.4f}" for n, v in dev.items())
              + f"  {est:.1e}")
    print("worst: " + ", ".join(f"{n} {v:.4f}" for n, v in worst.items()))
    return worst


def rust(tab, sk):
    def num(v):
        s = repr(float(v))
        return s if ("." in s or "e" in s) else s + ".0"
    out = ["//! Generated by tools/fit_rolling_linear.py from the exact reference's linear creep matrices",
           "//! (tools/data/rolling_linear_aligned.csv, rolling_linear_skewed.csv); do not edit.",
           "",
           "/// ln C₁₁, ln C₂₂, ln C₂₃, ln C₃₃ at a/b = 20^(i/8 − 1), i = 0 … 16, ν = 0, ¼, ½.",
           "#[allow(clippy::excessive_precision)]",
           "#[rustfmt::skip]",
           f"pub(super) const ALIGNED: [[[f64; 3]; 4]; {NA}] = ["]
    for i in range(NA):
        out.append("    [" + ", ".join("[" + ", ".join(num(v) for v in tab[i][c]) + "]" for c in range(4)) + "],")
    out.append("];")
    out.append("")
    out.append("/// (ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) at x = ln r = (i/6)·ln 20, t = j/8, ν = 0, ¼, ½.")
    out.append("#[allow(clippy::excessive_precision)]")
    out.append("#[rustfmt::skip]")
    out.append(f"pub(super) const SKEWED: [[[[f64; 3]; 6]; {NT}]; {NX}] = [")
    for i in range(NX):
        out.append("    [")
        for j in range(NT):
            out.append("        [" + ", ".join("[" + ", ".join(num(v) for v in sk[i][j][e]) + "]" for e in range(6)) + "],")
        out.append("    ],")
    out.append("];")
    return "\n".join(out) + "\n"


def main():
    tab = aligned_table()
    sk, missing = skewed_table(tab)
    if missing:
        print(f"skewed nodes missing ({len(missing)}): filled with the aligned patch's values", missing[:8])
        for i, j in missing:
            for e in range(6):
                if sk[i][j][e][0] is None or sk[i][j][e][1] is None or sk[i][j][e][2] is None:
                    sk[i][j][e] = [IDENTITY[e]] * 3
    if (data / "rolling_linear_check.csv").exists():
        check(tab, sk)
    text = rust(tab, sk)
    if "--write" in sys.argv:
        out_rs.write_text(text)
        print("wrote", out_rs)
    if "--check" in sys.argv and out_rs.read_text() != text:
        sys.exit(f"{out_rs} is not what the reference gives: python3 {sys.argv[0]} --write")


if __name__ == "__main__":
    main()
