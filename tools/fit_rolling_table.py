#!/usr/bin/env python3
"""Builds the residual tables of the default rolling law `table` (src/friction/rolling/table.rs)
from the exact steady-rolling reference, writes them as Rust (src/friction/rolling/table_data.rs)
and prints the law's error against the reference on its nodes (fit), on points it never saw
(held out) and on CONTACT's published cases (outside).

The law: `blend` (src/friction/rolling/blend.rs: Kalker's linear theory and the exact full slip
joined by fitted saturation shapes, exact at both limits) plus the reference's residual against
blend, tabulated on nine creep curves per shape and interpolated between them. With
l = κ(C11 ξ, C22 η, C23 cφ) (Kalker's linear forces, fN), m = |l|, d = l/m:

- symmetry: F_x is odd in ξ, (F_y, M_z) odd in (η, φ) (the y-reflection, and the reversal of all
  creepages), so d is reduced to d_x ≥ 0, d_φ ≥ 0 and the signs put back at the end;
- direction: u = 2 − 2 d_y/(|d_y| + d_φ) ∈ [0, 4] around the η–φ half plane (0: η, 1: η with φ
  of the same sign, 2: φ, 3: opposite signs, 4: −η) and v = 2 d_x² ∈ [0, 2] towards ξ (0: the
  η–φ plane, 1: 45°, 2: ξ); the residual is bilinear in (u, v) between the curves
      plane (v = 0): eta, etaphi, phi, etaphi_opp, (−eta)
      ring  (v = 1): xieta, xi_etaphi, xi_phi, xi_etaphi_opp, (xieta mirrored)
      ξ     (v = 2): xi;
- magnitude: each curve piecewise linear in ln m between its nodes, ∝ (m/m_0)² below the first
  and ∝ (m_N/m)² above the last (so the linear limit and full slip stay blend's, i.e. exact);
  then a positive power removed and |F| ≤ fN, as blend does.

Shapes: a/b = 0.2, 0.5, 1, 2, 5 (blend's fitted shapes) and the ends of the domain, 1/20 and 20
(rolling_ref_ends.csv: all nine curves there, laid out with the exact linear coefficients).
Nodes: the 29 magnitudes per curve uniform in ln m (rolling_ref.csv's 15 and the 14 geometric
midpoints of rolling_ref_mid.csv; rolling_ref_dir.csv for the four new curves); on the curves
with φ at a/b = 2 and 5 (the sharp knee of the spin force) the intervals KNEE (q ≈ 0.08–1.6)
are cut in four: their ½ points (rolling_ref_quarter.csv, rolling_ref_dir_quarter.csv) and ¼, ¾
points (rolling_ref_knee.csv). Shapes without knee nodes get the window filled linearly (the
same law), so the tables interpolate in ln(a/b) node by node. Nothing is fitted: the node values
are the reference's residuals.

Held out (never used to build the tables): the ½ points of the other intervals (the quarter
files), the ⅛ and ⅝ points of the knee intervals (rolling_ref_knee_held.csv), 12 random
directions per shape (rolling_ref_dir_random.csv); outside: CONTACT's cases (ν = 0.28, own load
ratios) and the full-slip family. All from tools/rolling_exact (examples `midpoints` and
`directions`).

    cargo build --release --bin contact_eval && python3 tools/fit_rolling_table.py [--write|--check] [--laws] [-v]

(--check: fail if the committed table_data.rs differs from what the reference and blend give;
--laws: every rolling law per family and set; -v: per shape.)
"""
import math, pathlib, sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from rolling_ref import creep_coefficients, evaluate, law_inputs, normalised, read, root  # noqa: E402

out_rs = root / "src/friction/rolling/table_data.rs"
data = root / "tools/data"
SH = [0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 20.0]
COARSE = 29
KNEE = (12, 8)  # first interval and number of intervals cut in four (spin curves)
FINE = COARSE + 3 * KNEE[1]
HALF = ["plane_u1.5", "plane_u2.5", "plane_u3.5"]
PLANE = ["eta", "etaphi", HALF[0], "phi", HALF[1], "etaphi_opp", HALF[2]]  # u = 0, 1, 1½, … 3½
RING = ["xieta", "xi_etaphi", "xi_phi", "xi_etaphi_opp"]  # u = 0, 1, 2, 3
SPIN = PLANE[1:] + RING[1:]  # the windowed curves
CHANNELS = {"xi": (0,), **{n: (1, 2) for n in PLANE}, **{n: (0, 1, 2) for n in RING}}
PLANE_SHAPES = (2.0, 5.0)  # the shapes with the u = ½ … 3½ curves (elsewhere: their neighbours' mean)
WINDOW_SHAPES = (1.0, 2.0, 5.0)  # knee window nodes: ½ points (all three), ¼ and ¾ (2 and 5)

CURVE_FAMS = ("xi", "eta", "phi", "combined", "etaphi_opp", "xi_etaphi", "xi_phi", "xi_etaphi_opp") + tuple(HALF)
FAMS = CURVE_FAMS + ("fullslip", "contact_example", "contact_testbank", "direction")
ref = [r for r in read(data / "rolling_ref.csv") if r[0] in FAMS]
sets = {
    "ref": ref,
    "mid": read(data / "rolling_ref_mid.csv"),
    "quarter": read(data / "rolling_ref_quarter.csv"),
    "dir": read(data / "rolling_ref_dir.csv"),
    "dir_quarter": read(data / "rolling_ref_dir_quarter.csv"),
    "dir_quarter_knee": read(data / "rolling_ref_dir_quarter_knee.csv"),
    "knee": read(data / "rolling_ref_knee.csv"),
    "knee_held": read(data / "rolling_ref_knee_held.csv"),
    "half_held": read(data / "rolling_ref_half_held.csv"),
    "random": read(data / "rolling_ref_dir_random.csv"),
    "plane": read(data / "rolling_ref_plane.csv"),
    "ends": read(data / "rolling_ref_ends.csv"),
}

shapes = sorted({(r[1], r[2]) for r in ref + sets["ends"]})
coef = {key: c[:3] for key, c in creep_coefficients(shapes).items()}  # C11, C22, C23


def with_blend(rows):
    return list(zip(rows, normalised("blend", rows)))


blended = {k: with_blend(v) for k, v in sets.items()}


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
    return [(r, b) for r, b in rb if r[2] == 0.25 and r[0] in CURVE_FAMS]


def residual(r, bw):
    return tuple(w - b for w, b in zip(r[7:10], bw))


# the coarse grid of each (shape, curve): the 29 magnitudes of rolling_ref.csv + midpoints, or
# of rolling_ref_dir.csv
coarse = {}
for r, bw in on_curves(blended["ref"] + blended["mid"] + blended["dir"] + blended["ends"]):
    coarse.setdefault((r[1], curve_name(r)), []).append((direction(r)[0], r, bw))
grids = {}
for key, v in coarse.items():
    v.sort(key=lambda e: e[0])
    assert len(v) == COARSE, (key, len(v))
    x0 = math.log(v[0][0])
    dx = (math.log(v[-1][0]) - x0) / (COARSE - 1)
    for k, e in enumerate(v):  # uniform in ln m (the reference's curves are log-spaced)
        assert abs(math.log(e[0]) - x0 - k * dx) < 1e-6, key
    # 12 digits: curves on the same magnitudes get bit-identical grids (the law then finds
    # their common node once)
    grids[key] = (float(f"{x0:.12g}"), float(f"{dx:.12g}"))
for aob in SH:  # the u = ½ … 3½ curves: phi's grid (m = 3q on the spin magnitudes)
    for name in HALF:
        grids[(aob, name)] = grids[(aob, "phi")]


def position(r):
    """Where a curve row sits on its curve's coarse grid (node index units)."""
    x0, dx = grids[(r[1], curve_name(r))]
    return (math.log(direction(r)[0]) - x0) / dx


def fine(pos, windowed):
    """Coarse position → index in the curve's node array (the knee window cut in four)."""
    if not windowed:
        return pos
    return pos + 3 * min(max(pos - KNEE[0], 0.0), KNEE[1])


def node_rows(use_knee):
    """{(shape, curve): {fine index: (row, blend)}} — the tables' nodes."""
    out = {}
    for r, bw in on_curves(blended["ref"] + blended["mid"] + blended["dir"] + blended["ends"]):
        key = (r[1], curve_name(r))
        out.setdefault(key, {})[round(fine(position(r), key[1] in SPIN))] = (r, bw)
    if use_knee:
        for r, bw in on_curves(blended["quarter"] + blended["dir_quarter"] + blended["dir_quarter_knee"]
                               + blended["knee"]):
            key = (r[1], curve_name(r))
            if key[1] not in SPIN or r[1] not in WINDOW_SHAPES:
                continue
            p = position(r)
            if KNEE[0] < p < KNEE[0] + KNEE[1]:
                g = fine(p, True)
                assert abs(g - round(g)) < 1e-6, (key, p)
                out[key][round(g)] = (r, bw)
    for r, bw in on_curves(blended["plane"]):
        g = fine(position(r), True)
        # on φ's grid: exactly with Table E3's coefficients (how the curves were laid out),
        # within 0.1 of an interval with the exact ones the laws now read (the ratio C₂₂/C₂₃
        # moved); the node takes the point's residual
        assert abs(g - round(g)) < 0.1, (r, g)
        out.setdefault((r[1], curve_name(r)), {})[round(g)] = (r, bw)
    return out


def coarse_position(i, windowed):
    """Fine index → coarse position (the inverse of `fine`)."""
    if not windowed or i <= KNEE[0]:
        return float(i)
    if i <= KNEE[0] + 4 * KNEE[1]:
        return KNEE[0] + (i - KNEE[0]) / 4
    return i - 3.0 * KNEE[1]


def build(use_knee=True):
    """{(shape, curve): (x0, dx, [[value per node] per channel])}: the values as the library
    holds them (quantised, `quantise`)."""
    nodes = node_rows(use_knee)
    tables = {}
    for aob in SH:
        for name in ["xi"] + [n for n in PLANE if n not in HALF] + RING + HALF:
            tables[(aob, name)] = curve_table(tables, aob, name, nodes.get((aob, name), {}))
    return quantise(tables)


def node_scales(tables):
    """Per node index (COARSE curves, FINE curves): the power of two s_k with
    max |value at node k| ≤ 32767 s_k over every shape, curve and channel."""
    scales = {}
    for n in (COARSE, FINE):
        top = [0.0] * n
        for (aob, name), (x0, dx, vals) in tables.items():
            if len(vals[0]) == n:
                for ch in vals:
                    top = [max(t, abs(v)) for t, v in zip(top, ch)]
        scales[n] = [2.0 ** math.ceil(math.log2(t / 32767)) if t > 0 else 1.0 for t in top]
    return scales


def quantise(tables):
    """Every value v at node k as round(v/s_k)·s_k (the i16 q = round(v/s_k) the library holds
    times the power of two s_k: exact in f32 and f64). Sets SCALES."""
    global SCALES
    SCALES = node_scales(tables)
    global QUANT_ERR
    out = {}
    QUANT_ERR = 0.0
    for key, (x0, dx, vals) in tables.items():
        s = SCALES[len(vals[0])]
        out[key] = (x0, dx, [[round(v / k) * k for v, k in zip(ch, s)] for ch in vals])
        QUANT_ERR = max([QUANT_ERR] + [abs(q - v) for cq, cv in zip(out[key][2], vals) for q, v in zip(cq, cv)])
    return out


def curve_table(tables, aob, name, pts):
    """One curve's (x0, dx, values): the nodes' residuals; the u = 1½, 2½, 3½ curves outside
    their nodes (and at shapes without them) the mean of their neighbours in u; the rest of the
    knee window linear between the curve's own nodes."""
    n = FINE if name in SPIN else COARSE
    vals = [[0.0] * n for _ in range(3)]
    have = [False] * n
    for i, (r, bw) in pts.items():
        res = residual(r, bw)
        for c in CHANNELS[name]:
            vals[c][i] = res[c]
        have[i] = True
    if name in HALF:
        k = PLANE.index(name)
        left = PLANE[k - 1]
        right = PLANE[k + 1] if k + 1 < len(PLANE) else None
        x0, dx = grids[(aob, name)]
        first, last = (min(pts), max(pts)) if pts else (n, n)
        for i in [i for i in range(n) if i < first or i > last]:
            m = math.exp(x0 + dx * coarse_position(i, True))
            a = lookup(tables[(aob, left)], left, m)
            b = lookup(tables[(aob, right)], right, m) if right else [-v for v in lookup(tables[(aob, "eta")], "eta", m)]
            for c in (1, 2):
                vals[c][i] = 0.5 * (a[c] + b[c])
            have[i] = True
    for i in range(n):  # the window of shapes without knee nodes: linear between nodes
        if not have[i]:
            lo = max(j for j in range(i) if have[j])
            hi = min(j for j in range(i + 1, n) if have[j])
            t = (i - lo) / (hi - lo)
            for c in range(3):
                vals[c][i] = vals[c][lo] + t * (vals[c][hi] - vals[c][lo])
    return (*grids[(aob, name)], vals)


def f32(x):
    import struct
    return struct.unpack("f", struct.pack("f", x))[0]


def f32_literal(v):
    """The shortest decimal that reads back as the same f32."""
    for p in range(1, 10):
        t = f"{v:.{p}e}"
        if f32(float(t)) == v:
            return t
    return repr(v)


def lookup(tab, name, m):
    """Piecewise linear in ln m between the nodes, quadratic tails; [F_x, F_y, M_z]."""
    x0, dx, vals = tab
    u = (math.log(m) - x0) / dx
    if u <= 0:
        return [v[0] * math.exp(2 * u * dx) for v in vals]
    if u >= COARSE - 1:
        return [v[-1] * math.exp(-2 * (u - COARSE + 1) * dx) for v in vals]
    g = fine(u, name in SPIN)
    i = min(int(g), len(vals[0]) - 2)
    t = g - i
    return [v[i] + t * (v[i + 1] - v[i]) for v in vals]


def shape_tables(tables, aob):
    """The tables for a/b: linear in ln(a/b) between the fitted shapes (values and grids)."""
    x = math.log(min(max(aob, SH[0]), SH[-1]))
    i = 0
    while i < len(SH) - 2 and x > math.log(SH[i + 1]):
        i += 1
    x0, x1 = math.log(SH[i]), math.log(SH[i + 1])
    u = min(max((x - x0) / (x1 - x0), 0.0), 1.0)
    out = {}
    for name in ["xi"] + PLANE + RING:
        a, b = tables[(SH[i], name)], tables[(SH[i + 1], name)]
        out[name] = (a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]),
                     [[p + u * (q - p) for p, q in zip(ca, cb)] for ca, cb in zip(a[2], b[2])])
    return out


def correction(tb, m, d):
    """The interpolated residual at magnitude m, unit direction d."""
    sx = math.copysign(1.0, d[0])
    sy = -1.0 if d[2] < 0 else 1.0
    dy, dp = sy * d[1], sy * d[2]
    s1 = abs(dy) + dp
    u = 2 - 2 * dy / s1 if s1 > 0 else 0.0
    v = 2 * d[0] * d[0]
    def around(names, j):
        if j == len(names):  # u = 4: the first curve mirrored
            w = lookup(tb[names[0]], names[0], m)
            return [w[0], -w[1], -w[2]]
        return lookup(tb[names[j]], names[j], m)

    def mix(names):
        # node units: the ring u; the plane u up to 1, then 2u − 1 (nodes every ½)
        x = u if names is RING or u < 1 else 2 * u - 1
        j = min(int(x), len(names) - 1)
        t = x - j
        a = around(names, j)
        if t == 0:
            return a
        b = around(names, j + 1)
        return [p + t * (q - p) for p, q in zip(a, b)]

    # each channel leaves a family at the order its symmetry gives (table.rs): off the plane
    # F_x as d_x (weight √2·d_x), F_y, M_z as d_x² (v); towards ξ F_x as |d_⊥|² (v − 1),
    # F_y, M_z as |d_⊥| (the ring's weight √(2 − v))
    if v <= 1:
        w = [(1 - v) * x for x in mix(PLANE)]
        if v > 0:
            q = mix(RING)
            w = [x + v * y for x, y in zip(w, q)]
            w[0] = math.sqrt(2) * abs(d[0]) * q[0]
    else:
        q = mix(RING)
        x = lookup(tb["xi"], "xi", m)
        r = math.sqrt(max(2 - v, 0.0))
        w = [q[0] + (v - 1) * (x[0] - q[0]), r * q[1], r * q[2]]
    return [sx * w[0], sy * w[1], sy * w[2]]


def law(tables, r, bw):
    fam, aob, nu, nl, xi, eta, phic = r[:7]
    m, d = direction(r)
    out = list(bw)
    if m > 0:
        dw = correction(shape_tables(tables, aob), m, d)
        out = [b + e for b, e in zip(bw, dw)]
    P = out[0] * xi + out[1] * eta + out[2] * phic
    if P > 0:
        u2 = xi * xi + eta * eta + phic * phic
        out = [v - P * c / u2 for v, c in zip(out, (xi, eta, phic))]
    fm = math.hypot(out[0], out[1])
    if fm > 1:
        out = [v / fm for v in out]
    return out


def parts(use_knee):
    """(part, row, blend): nodes 'fit', the rest of the curves 'held-out', random directions
    'directions', CONTACT's cases and full slip 'outside'."""
    nodes = node_rows(use_knee)
    is_node = {id(r) for pts in nodes.values() for r, _ in pts.values()}
    out = []
    for name in ("ref", "mid", "quarter", "dir", "dir_quarter", "dir_quarter_knee", "knee", "knee_held",
                 "half_held", "plane", "ends"):
        for r, bw in blended[name]:
            if r[2] == 0.25 and r[0] in CURVE_FAMS:
                out.append(("fit" if id(r) in is_node else "held-out", r, bw))
            elif name == "ref":
                out.append(("outside", r, bw))
    out += [("directions", r, bw) for r, bw in blended["random"]]
    return out


def report(use_knee):
    tables = build(use_knee)
    err = {}
    for part, r, bw in parts(use_knee):
        key = curve_name(r) if part != "outside" else r[0]
        g = law(tables, r, bw)
        ef = math.hypot(g[0] - r[7], g[1] - r[8])
        em = abs(g[2] - r[9])
        eb = (math.hypot(bw[0] - r[7], bw[1] - r[8]), abs(bw[2] - r[9]))
        for k in ((part, key), (part, "all"), (part, f"{key} a/b={r[1]:g}")):
            e = err.setdefault(k, [0, 0, 0, 0, 0])
            e[0], e[1] = max(e[0], ef), max(e[1], em)
            e[2], e[3] = max(e[2], eb[0]), max(e[3], eb[1])
            e[4] += 1
    print(f"== nodes: 29 per curve{', knee window cut in four at a/b = 2, 5' if use_knee else ''}; "
          f"i16 node values within {QUANT_ERR:.1e} of the residuals")
    for (part, key), (f, m, bf, bm, n) in sorted(err.items()):
        if "a/b" in key and "-v" not in sys.argv:
            continue
        print(f"{part:10s} {key:26s} {n:4d}  table |dF| {f:.4f} |dMz| {m:.4f}   (blend {bf:.4f} {bm:.4f})")
    return tables


report(False)
tables = report(True)


def rust(tables):
    def block(name, indent):
        x0, dx, vals = tables[name]
        pad = " " * indent
        lines = [f"{pad}({x0!r}, {dx!r}, ["]
        for c in CHANNELS[name[1]]:
            q = [round(v / k) for v, k in zip(vals[c], SCALES[len(vals[c])])]
            lines.append(f"{pad}    [" + ", ".join(str(v) for v in q) + "],")
        lines.append(f"{pad}], {f32_literal(f32(x0))}, {f32_literal(f32(dx))}),")
        return lines

    lines = ["//! Generated by `python3 tools/fit_rolling_table.py --write` from the exact rolling",
             "//! reference (tools/data/rolling_ref*.csv) and the `blend` law: the residual tables of",
             "//! [`super::table`] (see there). Do not edit.",
             "",
             "/// Nodes per curve, uniform in ln m.",
             f"pub(crate) const COARSE: usize = {COARSE};",
             "/// The curves with φ: the coarse intervals `KNEE_START..KNEE_START + KNEE_WIDTH` cut in",
             "/// four.",
             f"pub(crate) const KNEE_START: usize = {KNEE[0]};",
             "/// See [`KNEE_START`].",
             f"pub(crate) const KNEE_WIDTH: usize = {KNEE[1]};",
             "/// Nodes of the curves with φ.",
             "pub(crate) const FINE: usize = COARSE + 3 * KNEE_WIDTH;",
             "",
             "/// One curve: ln m of the first node, the coarse node spacing in ln m, the residual at",
             "/// the nodes per channel (node k: the `i16` times [`SCALE_COARSE`]`[k]` or",
             "/// [`SCALE_FINE`]`[k]`), and the first two rounded to `f32` (for an `f32` look-up",
             "/// without a run-time conversion; the same values as `x as f32`).",
             "pub(crate) type Data<const N: usize, const C: usize> = (f64, f64, [[i16; N]; C], f32, f32);",
             "",
             "/// The node scales of the curves of `COARSE` nodes: node k's residual is its `i16` times",
             "/// `SCALE_COARSE[k]`, a power of two (exact in `f32` and `f64`) with the largest |residual|",
             "/// at node k over every shape, curve and channel ≤ 32,767 · scale (so each value is within",
             "/// half a scale of the reference's residual).",
             "#[rustfmt::skip]",
             "pub(crate) static SCALE_COARSE: [f32; COARSE] = [" + ", ".join(f32_literal(v) for v in SCALES[COARSE]) + "];",
             "/// The same for the curves of `FINE` nodes.",
             "#[rustfmt::skip]",
             "pub(crate) static SCALE_FINE: [f32; FINE] = [" + ", ".join(f32_literal(v) for v in SCALES[FINE]) + "];",
             "",
             "/// One shape's curves (directions of the linear forces (ξ, η, φ) as named;",
             "/// u = 2 − 2d_η/(|d_η| + d_φ)).",
             "pub(crate) struct Shape {",
             "    /// ξ: F_x",
             "    pub(crate) xi: Data<COARSE, 1>,",
             "    /// η: F_y, M_z",
             "    pub(crate) eta: Data<COARSE, 2>,",
             "    /// ξ with η, equal shares: F_x, F_y, M_z",
             "    pub(crate) xieta: Data<COARSE, 3>,",
             "    /// the η–φ plane at u = 1 (η with φ, same sign), 1½, 2 (φ), 2½, 3 (η with φ,",
             "    /// opposite signs), 3½: F_y, M_z",
             "    pub(crate) plane: [Data<FINE, 2>; 6],",
             "    /// ξ at 45° to the plane at u = 1, 2, 3: F_x, F_y, M_z",
             "    pub(crate) ring: [Data<FINE, 3>; 3],",
             "}",
             "",
             "/// Per shape a/b = 1/20, 0.2, 0.5, 1, 2, 5, 20 (ν = 0.25).",
             "#[rustfmt::skip]",
             f"pub(crate) static SHAPES: [Shape; {len(SH)}] = ["]
    for aob in SH:
        lines.append("    Shape {")
        for field, names in (("xi", ["xi"]), ("eta", ["eta"]), ("xieta", ["xieta"])):
            lines.append(f"        {field}:")
            lines += block((aob, names[0]), 12)
        for field, names in (("plane", PLANE[1:]), ("ring", RING[1:])):
            lines.append(f"        {field}: [")
            for n in names:
                lines += block((aob, n), 12)
            lines.append("        ],")
        lines.append("    },")
    lines.append("];")
    return "\n".join(lines) + "\n"


if "--write" in sys.argv:
    out_rs.write_text(rust(tables))
    print("wrote", out_rs)
if "--check" in sys.argv and out_rs.read_text() != rust(tables):
    sys.exit(f"{out_rs} is not what the reference and blend give: python3 {sys.argv[0]} --write")


def compare_laws():
    """Every rolling law of contact_eval against the exact reference per curve family: on the
    held-out points of `table` (no law was fitted on them), on all curve points, on the random
    directions and on CONTACT's cases."""
    ps = parts(True)
    groups = {"held-out": [r for p, r, _ in ps if p == "held-out"],
              "curves": [r for p, r, _ in ps if p in ("fit", "held-out")],
              "directions": [r for p, r, _ in ps if p == "directions"],
              "contact": [r for p, r, _ in ps if p == "outside" and r[0].startswith("contact")]}
    laws = ["table", "blend", "fastsim", "fastsim-16", "full-slip"]
    exe = None
    if "--old" in sys.argv:  # the law of another contact_eval binary, as `table-old`
        exe = sys.argv[sys.argv.index("--old") + 1]
        laws.insert(1, "table-old")
    cols = ("xi", "eta", "phi", "etaphi", "etaphi_opp", "xieta", "xi_etaphi", "xi_phi", "xi_etaphi_opp", "all")
    print("law        set        " + " ".join(f"{f:>13s}" for f in cols))
    for law_name in laws:
        for set_name, rows in groups.items():
            got = evaluate("table" if law_name == "table-old" else law_name, law_inputs(rows),
                           exe if law_name == "table-old" else None)
            err = {}
            for r, w in zip(rows, got):
                w = [v / r[3] for v in w]
                e = (math.hypot(w[0] - r[7], w[1] - r[8]), abs(w[2] - r[9]))
                for k in (curve_name(r), "all"):
                    o = err.setdefault(k, [0, 0])
                    o[0], o[1] = max(o[0], e[0]), max(o[1], e[1])
            print(f"{law_name:10s} {set_name:10s} " + " ".join(
                f"{err[c][0]:.3f}/{err[c][1]:.3f}" if c in err else f"{'':13s}" for c in cols))


if "--laws" in sys.argv:
    compare_laws()
