#!/usr/bin/env python3
"""Builds the residual tables of the default rolling law `table` (src/friction/rolling/table.rs)
from the exact steady-rolling reference, writes them as Rust (src/friction/rolling/table_data.rs)
and prints the law's error against the reference on the magnitudes the tables hold (fit) and on
magnitudes they never saw (held out).

The law: `blend` (src/friction/rolling/blend.rs: Kalker's linear theory and the exact full slip
joined by fitted saturation shapes, exact at both limits) plus a residual
  ΔW = d_x·T_ξ(m) + d_y·T_η(m) + d_φ·T_φ(m)
       + 2|d_x d_y|·(sgn d_x R_ξη,x, sgn d_y R_ξη,y, sgn d_y R_ξη,m)(m)
       + 2 max(0, d_y d_φ)·sgn d_y·(0, R_ηφ,y, R_ηφ,m)(m),
l = κ(C11 ξ, C22 η, C23 cφ) (Kalker's linear forces, fN), m = |l|, d = l/m, each table a
function of ln m, piecewise linear between its nodes, ∝ (m/m_0)² below the first node and
∝ (m_N/m)² above the last (so the linear limit and full slip stay blend's, i.e. exact); then a
positive power removed and |F| ≤ fN, as blend does.

Tables per shape a/b ∈ {0.2, 0.5, 1, 2, 5} (ν = 0.25, the reference's creep curves): T_ξ (F_x),
T_η, T_φ (F_y, M_z), R_ξη (F_x, F_y, M_z), R_ηφ (F_y, M_z) — the reference's residual against
blend on the pure curves, and on the combined curves what the pure tables leave. Nothing is
fitted: the node values are the reference's residuals.

The exact reference on each creep curve: the 15 magnitudes of tools/data/rolling_ref.csv, the
14 geometric midpoints of tools/data/rolling_ref_mid.csv and the 28 quarter points of
tools/data/rolling_ref_quarter.csv (same solver: `cargo run --release --example midpoints
[-- quarter]` in tools/rolling_exact). Three node sets, all reported; the rows a set does not
hold are its held-out rows (never used to build it):
  all   (written, the law's tables): rolling_ref.csv + the midpoints, 29 nodes per curve;
        held out: the quarter points;
  ref   rolling_ref.csv's 15 magnitudes; held out: the midpoints and quarter points;
  half  every other magnitude of rolling_ref.csv (8 nodes); held out: the rest.

    cargo build --release --bin contact_eval && python3 tools/fit_rolling_table.py [--write|--check]

(--check: fail if the committed table_data.rs differs from what the reference and blend give.)
"""
import math, pathlib, sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from rolling_ref import evaluate, patch, read, root  # noqa: E402

out_rs = root / "src/friction/rolling/table_data.rs"
SH = [0.2, 0.5, 1.0, 2.0, 5.0]
DIRS = ["xi", "eta", "phi", "xieta", "etaphi"]


FAMS = ("xi", "eta", "phi", "combined", "fullslip", "contact_example", "contact_testbank")
ref = [r for r in read(root / "tools/data/rolling_ref.csv") if r[0] in FAMS]
mid = read(root / "tools/data/rolling_ref_mid.csv")
quarter = read(root / "tools/data/rolling_ref_quarter.csv")

shapes = sorted({(r[1], r[2]) for r in ref})
unit = []
for aob, nu in shapes:
    a, b = patch(aob)
    unit += [(a, b, 1, nu, 1, 1, 1, 1, 0, 0), (a, b, 1, nu, 1, 1, 1, 0, 1, 0), (a, b, 1, nu, 1, 1, 1, 0, 0, 1)]
lin = evaluate("linear", unit)
coef = {}
for k, key in enumerate(shapes):
    x, y, p = lin[3 * k: 3 * k + 3]
    coef[key] = (-x[0], -y[1], -p[1])  # C11, C22, C23


def with_blend(rows):
    inputs = []
    for fam, aob, nu, nl, xi, eta, phic, *_ in rows:
        a, b = patch(aob)
        inputs.append((a, b, 1, nu, 1, nl, 1, xi, eta, phic))
    return [(r, tuple(v / r[3] for v in w)) for r, w in zip(rows, evaluate("blend", inputs))]


ref_b = with_blend(ref)
mid_b = with_blend(mid)
quarter_b = with_blend(quarter)


def direction(r):
    fam, aob, nu, nl, xi, eta, phic = r[:7]
    c11, c22, c23 = coef[(aob, nu)]
    l = (c11 * xi / nl, c22 * eta / nl, c23 * phic / nl)
    m = math.sqrt(sum(v * v for v in l))
    return m, tuple(v / m for v in l) if m > 0 else (0.0, 0.0, 0.0)


def curve_name(r):
    if r[0] == "combined":
        return "xieta" if r[6] == 0 else "etaphi"
    return r[0]


def on_curves(rb):
    return [(r, b) for r, b in rb if r[2] == 0.25 and r[0] in ("xi", "eta", "phi", "combined")]


# the reference's curves per shape, in magnitude order: rolling_ref.csv at the even
# indices, the midpoints at the odd ones
curves = {}
for r, bw in on_curves(ref_b) + on_curves(mid_b):
    curves.setdefault((r[1], curve_name(r)), []).append((direction(r)[0], r, bw))
for v in curves.values():
    v.sort(key=lambda e: e[0])
    assert len(v) == 29, len(v)


def lookup(tab, m):
    """tab = (ln m_0, Δ ln m, [values...]); piecewise linear in ln m, quadratic tails."""
    x0, dx, vals = tab
    n = len(vals)
    if m <= 0:
        return 0.0
    u = (math.log(m) - x0) / dx
    if u <= 0:
        return vals[0] * math.exp(2 * u * dx)
    if u >= n - 1:
        return vals[-1] * math.exp(-2 * (u - n + 1) * dx)
    i = min(int(u), n - 2)
    t = u - i
    return vals[i] + t * (vals[i + 1] - vals[i])


def residual(r, bw):
    return tuple(w - b for w, b in zip(r[7:10], bw))


def build(step):
    """Tables on every `step`-th magnitude of each curve: {(shape, curve): (x0, dx, vals)}."""
    idx = list(range(0, 29, step))
    tables = {}

    def grid(cv):
        ms = [cv[k][0] for k in idx]
        x0 = math.log(ms[0])
        dx = (math.log(ms[-1]) - x0) / (len(ms) - 1)
        for k, mm in enumerate(ms):  # uniform in ln m (the reference's curves are log-spaced)
            assert abs(math.log(mm) - x0 - k * dx) < 1e-6
        return x0, dx

    for aob in SH:
        for name, chans in (("xi", (0,)), ("eta", (1, 2)), ("phi", (1, 2))):
            cv = curves[(aob, name)]
            x0, dx = grid(cv)
            sign = math.copysign(1.0, direction(cv[0][1])[1][DIRS.index(name)])
            vals = [[sign * residual(cv[k][1], cv[k][2])[c] if c in chans else 0.0 for k in idx]
                    for c in range(3)]
            tables[(aob, name)] = (x0, dx, vals)
    for aob in SH:
        for name in ("xieta", "etaphi"):
            cv = curves[(aob, name)]
            x0, dx = grid(cv)
            vals = [[], [], []]
            for k in idx:
                m, r, bw = cv[k]
                _, d = direction(r)
                p = pure_part(tables, aob, m, d)
                res = residual(r, bw)
                if name == "xieta":
                    w = 2 * abs(d[0] * d[1])
                    sg = (math.copysign(1, d[0]), math.copysign(1, d[1]), math.copysign(1, d[1]))
                else:  # ηφ: no F_x
                    w = 2 * max(0.0, d[1] * d[2])
                    sg = (0.0, math.copysign(1, d[1]), math.copysign(1, d[1]))
                for c in range(3):
                    vals[c].append(sg[c] * (res[c] - p[c]) / w if sg[c] != 0 else 0.0)
            tables[(aob, name)] = (x0, dx, vals)
    return tables


def pure_part(tables, aob, m, d):
    out = [0.0, 0.0, 0.0]
    for name, j in (("xi", 0), ("eta", 1), ("phi", 2)):
        x0, dx, vals = tables[(aob, name)]
        for c in range(3):
            out[c] += d[j] * lookup((x0, dx, vals[c]), m)
    return out


def shape_tables(tables, aob):
    """The tables for a/b: linear in ln(a/b) between the fitted shapes (values and grids)."""
    x = math.log(min(max(aob, 0.2), 5.0))
    i = 0
    while i < 3 and x > math.log(SH[i + 1]):
        i += 1
    x0, x1 = math.log(SH[i]), math.log(SH[i + 1])
    u = min(max((x - x0) / (x1 - x0), 0.0), 1.0)
    out = {}
    for name in DIRS:
        a, b = tables[(SH[i], name)], tables[(SH[i + 1], name)]
        out[name] = (a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]),
                     [[p + u * (q - p) for p, q in zip(ca, cb)] for ca, cb in zip(a[2], b[2])])
    return out


def law(tables, r, bw):
    fam, aob, nu, nl, xi, eta, phic = r[:7]
    m, d = direction(r)
    tb = shape_tables(tables, aob)
    look = lambda name, c: lookup((tb[name][0], tb[name][1], tb[name][2][c]), m)
    dw = [0.0, 0.0, 0.0]
    for name, j in (("xi", 0), ("eta", 1), ("phi", 2)):
        for c in range(3):
            dw[c] += d[j] * look(name, c)
    w = 2 * abs(d[0] * d[1])
    if w > 0:
        dw[0] += math.copysign(w, d[0]) * look("xieta", 0)
        dw[1] += math.copysign(w, d[1]) * look("xieta", 1)
        dw[2] += math.copysign(w, d[1]) * look("xieta", 2)
    w = 2 * max(0.0, d[1] * d[2])
    if w > 0:
        dw[1] += math.copysign(w, d[1]) * look("etaphi", 1)
        dw[2] += math.copysign(w, d[1]) * look("etaphi", 2)
    out = [b + e for b, e in zip(bw, dw)]
    P = out[0] * xi + out[1] * eta + out[2] * phic
    if P > 0:
        u2 = xi * xi + eta * eta + phic * phic
        out = [v - P * c / u2 for v, c in zip(out, (xi, eta, phic))]
    fm = math.hypot(out[0], out[1])
    if fm > 1:
        out = [v / fm for v in out]
    return out


def report(name, step):
    tables = build(step)
    err = {}
    parts = []
    for r, bw in ref_b + mid_b:
        if r[0] in ("xi", "eta", "phi", "combined") and r[2] == 0.25:
            k = [e[1] for e in curves[(r[1], curve_name(r))]].index(r)
            parts.append(("fit" if k % step == 0 else "held-out", r, bw))
        else:
            parts.append(("outside", r, bw))
    parts += [("held-out", r, bw) for r, bw in on_curves(quarter_b)]
    for part, r, bw in parts:
        key = curve_name(r)
        g = law(tables, r, bw)
        ef = math.hypot(g[0] - r[7], g[1] - r[8])
        em = abs(g[2] - r[9])
        eb = (math.hypot(bw[0] - r[7], bw[1] - r[8]), abs(bw[2] - r[9]))
        for k in ((part, key), (part, "all"), (part, f"{key} a/b={r[1]:g}")):
            e = err.setdefault(k, [0, 0, 0, 0])
            e[0], e[1] = max(e[0], ef), max(e[1], em)
            e[2], e[3] = max(e[2], eb[0]), max(e[3], eb[1])
    print(f"== nodes '{name}': every {step} of the 29 magnitudes per curve")
    for (part, key), (f, m, bf, bm) in sorted(err.items()):
        if "a/b" in key and "-v" not in sys.argv:
            continue
        print(f"{part:9s} {key:24s} table |dF| {f:.4f} |dMz| {m:.4f}   (blend {bf:.4f} {bm:.4f})")
    return tables


report("half", 4)
report("ref", 2)
tables = report("all", 1)


def rust(tables):
    n = len(tables[(SH[0], "xi")][2][0])
    lines = ["//! Generated by `python3 tools/fit_rolling_table.py --write` from",
             "//! tools/data/rolling_ref.csv and the `blend` law: the residual tables of",
             "//! [`super::table`] (see there). Do not edit.",
             "",
             f"/// Nodes per curve.",
             f"pub(crate) const NODES: usize = {n};",
             "",
             "/// Per shape (a/b = 0.2, 0.5, 1, 2, 5) and curve (ξ, η, φ, ξη, ηφ): ln m of the first",
             "/// node, the node spacing in ln m, and the residual F_x, F_y, M_z (fN, fN, fNc) at the",
             "/// nodes.",
             "pub(crate) type Curves = [[(f64, f64, [[f64; NODES]; 3]); 5]; 5];",
             "",
             "/// The tables.",
             "#[rustfmt::skip]",
             "pub(crate) static TABLES: Curves = ["]
    for aob in SH:
        lines.append("    [")
        for name in DIRS:
            x0, dx, vals = tables[(aob, name)]
            lines.append(f"        ({x0!r}, {dx!r}, [")
            for c in range(3):
                lines.append("            [" + ", ".join(f"{v:.6e}" for v in vals[c]) + "],")
            lines.append("        ]),")
        lines.append("    ],")
    lines.append("];")
    return "\n".join(lines) + "\n"


if "--write" in sys.argv:
    out_rs.write_text(rust(tables))
    print("wrote", out_rs)
if "--check" in sys.argv and out_rs.read_text() != rust(tables):
    sys.exit(f"{out_rs} is not what the reference and blend give: python3 {sys.argv[0]} --write")


def compare_laws():
    """Every rolling law of contact_eval against the exact reference per curve family, on the
    quarter points (held out from `table`'s tables; no law was fitted on them) and on all
    curve points (rolling_ref.csv + midpoints + quarter points), plus CONTACT's cases."""
    sets = {"quarter": on_curves([(r, None) for r in quarter]),
            "curves": on_curves([(r, None) for r in ref + mid + quarter]),
            "contact": [(r, None) for r in ref if r[0].startswith("contact")]}
    laws = ["table", "blend", "fastsim", "fastsim-16", "full-slip"]
    print("law        set      " + "  ".join(f"{f:>13s}" for f in ("xi", "eta", "phi", "etaphi", "xieta", "all")))
    for law_name in laws:
        for set_name, rows in sets.items():
            rows = [r for r, _ in rows]
            inputs = []
            for fam, aob, nu, nl, xi, eta, phic, *_ in rows:
                a, b = patch(aob)
                inputs.append((a, b, 1, nu, 1, nl, 1, xi, eta, phic))
            got = evaluate(law_name, inputs)
            err = {}
            for r, w in zip(rows, got):
                w = [v / r[3] for v in w]
                e = (math.hypot(w[0] - r[7], w[1] - r[8]), abs(w[2] - r[9]))
                for k in (curve_name(r) if set_name != "contact" else "all", "all"):
                    o = err.setdefault(k, [0, 0])
                    o[0], o[1] = max(o[0], e[0]), max(o[1], e[1])
            cols = ("xi", "eta", "phi", "etaphi", "xieta", "all")
            print(f"{law_name:10s} {set_name:8s} " + "  ".join(
                f"{err[c][0]:.3f}/{err[c][1]:.3f}" if c in err else f"{'':13s}" for c in cols))


if "--laws" in sys.argv:
    compare_laws()
