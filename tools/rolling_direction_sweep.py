#!/usr/bin/env python3
"""Where `table` errs between its direction curves: sweeps of the creepage direction through the
held-out points where it errs most, against the exact theory (a diagnosis; nothing is fitted on it).

Points: every ALIGNED point of the held-out set (tools/data/rolling_ref_heldout.csv, θ = 0) where
`table` errs by more than 0.07 fN or 0.10 fNc (tools/data/rolling_heldout_laws.csv). For each, with
its ν and its linear-force magnitude m = |l| (l = κ(C₁₁ξ, C₂₂η, C₂₃cφ), the law's own exact
coefficients), the direction d = l/m is turned towards ξ at a fixed split of (d_η, d_φ) — the
elevation d_x from 0 (the η–φ plane, `table`'s plane curves) through 1/√2 (its ring) to 1 (its ξ
curve), the sign of the point's own d_x — on the point's own a/b and ν (`own`), on the nearest
tabulated shape of `table` (1/20, 0.2, 0.5, 1, 2, 5, 20) at the point's ν (`node`), and on that
shape at the tables' own ν = 0.25 (`node25`: there the tables hold the reference's residuals
exactly on their curves, so an error is the interpolation between direction curves alone, not
between shapes or values of ν). On that last shape also three cases next to the ξ curve
(|d_⊥| = 0.02, 0.05, 0.1: `tan`, for its tangents). Then two bounds on what more data between
the families could give: two more rings of exact residuals, and the ξ curve's tangents.

    python3 tools/rolling_direction_sweep.py --cases > cases.txt      # the cases (a/b θ ν ξ η φc tag)
    (cd tools/rolling_exact && nice cargo run --release --example cases -- 1024 < cases.txt) \\
        > tools/data/rolling_diag_direction.csv                           # the exact theory (≈ 6 min)
    cargo build --release --bin contact_eval && python3 tools/rolling_direction_sweep.py [--check]

Writes bench-results/rolling-direction-sweep.md (--check: fail if it differs from what the laws
give now).
"""
import math, pathlib, sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import rolling_heldout as H  # noqa: E402
from rolling_ref import creep_coefficients  # noqa: E402

root = H.root
data = root / "tools/data/rolling_diag_direction.csv"
out_md = root / "bench-results/rolling-direction-sweep.md"
SHAPES = [0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 20.0]  # table's tabulated a/b (fit_rolling_table.py's SH)
ELEVATIONS = [0.0, 0.1, 0.2, 0.3, 0.383, 0.5, 0.6, 0.707, 0.8, 0.9, 0.95, 0.98, 1.0]
THRESHOLD = (0.07, 0.10)
LAWS = ["table", "blend", "fastsim"]
NU = 0.25  # the ν of the tables' reference curves
TANGENT = [0.02, 0.05, 0.1]  # |d_⊥| next to the ξ curve (the `tan` cases: tangents there)


def VARIANTS(r):
    """(name, a/b, ν) of the three sweeps through a held-out row."""
    return (("own", r["aob"], r["nu"]), ("node", nearest(r["aob"]), r["nu"]), ("node25", nearest(r["aob"]), NU))


def selected(indices=None):
    """(index, row, table's error) of the held-out points the sweeps go through: those over the
    threshold now, or (`indices`, the committed sweeps' points) those the data file holds."""
    rows = H.read()
    lines = [l for l in (root / "tools/data/rolling_heldout_laws.csv").read_text().splitlines() if l[0] != "#"]
    head = lines[0].split(",")
    laws = [dict(zip(head, map(float, l.split(",")))) for l in lines[1:]]
    out = []
    for i, (r, g) in enumerate(zip(rows, laws)):
        ref = r["ref"]
        e = (math.hypot(g["table_fx"] - ref[0], g["table_fy"] - ref[1]), abs(g["table_mz"] - ref[2]))
        over = r["theta"] == 0.0 and (e[0] > THRESHOLD[0] or e[1] > THRESHOLD[1])
        if (i in indices) if indices is not None else over:
            out.append((i, r, e))
    return out


def nearest(aob):
    return min(SHAPES, key=lambda s: abs(math.log(s / aob)))


def cases():
    """The sweep cases: (tag, a/b, ν, ξ, η, φc)."""
    pts = selected()
    shapes = sorted({(s, nu) for _, r, _ in pts
                     for s, nu in ((r["aob"], r["nu"]), (nearest(r["aob"]), r["nu"]), (nearest(r["aob"]), NU))})
    coef = creep_coefficients(shapes)
    out = []
    for i, r, _ in pts:
        c11, c22, c23, _ = coef[(r["aob"], r["nu"])]
        l = (c11 * r["xi"], c22 * r["eta"], c23 * r["phic"])
        m = math.sqrt(sum(x * x for x in l))
        sx = 1.0 if l[0] >= 0 else -1.0
        perp = math.hypot(l[1], l[2])

        def case(tag, s, nu, dx, dp):
            """The row's magnitude and (η, φ) split at elevation (d_x, |d_⊥|) on shape s, ν."""
            k11, k22, k23, _ = coef[(s, nu)]
            d = (sx * dx, dp * l[1] / perp, dp * l[2] / perp)
            return (tag, s, nu, m * d[0] / k11, m * d[1] / k22, m * d[2] / k23)

        for which, s, nu in VARIANTS(r):
            out += [case(f"p{i}_{which}_{dx:g}", s, nu, dx, math.sqrt(max(0.0, 1.0 - dx * dx)))
                    for dx in ELEVATIONS]
        # next to the ξ curve on the node25 shape: |d_⊥| (not |d_x|) in the tag
        out += [case(f"p{i}_tan_{dp:g}", nearest(r["aob"]), NU, math.sqrt(1.0 - dp * dp), dp)
                for dp in TANGENT]
    return out


def projected(tags, rows, got):
    """The bands' worst (ΔF, ΔM) of `table` on the `node25` sweeps (tabulated shapes, ν = 0.25)
    as it is, and as a law with two more rings of exact residuals against `blend` would give
    them at best: at |d_x| = 0.383 (sin 22.5°) and 0.9 (the sweeps' point nearest sin 67.5°)
    with the sweep's own (η, φ) split and magnitude (so no interpolation in u or m), the
    residual piecewise linear between them as today's weights make it between the families
    (F_x in d_x off the plane, in v = 2d_x² towards ξ; F_y, M_z in v off the plane, in |d_⊥|
    towards ξ). Returns {band: (today, projected)}."""
    sweeps = {}
    for t, r, g, b in zip(tags, rows, got["table"], got["blend"]):
        i, which, x = t.split("_")
        if which == "node25":
            sweeps.setdefault(i, {})[float(x)] = (r["ref"], g, b)
    lin = lambda x, x0, x1, y0, y1: y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    out = {}
    for band, xs, mid in (("plane → ring", [0.1, 0.2, 0.3, 0.5, 0.6], 0.383),
                          ("ring → ξ", [0.8, 0.95, 0.98], 0.9)):
        today, proj = [0.0, 0.0], [0.0, 0.0]
        for d in sweeps.values():
            res = lambda x, c: d[x][0][c] - d[x][2][c]
            for x in xs:
                ref, g, b = d[x]
                new = []
                for c in range(3):
                    if mid < 0.5:  # plane (0) → mid → ring (0.707)
                        f = (lambda z: z) if c == 0 else (lambda z: 2 * z * z)
                        ends = [(0.0, 0.0 if c == 0 else res(0.0, c)), (mid, res(mid, c)), (0.707, res(0.707, c))]
                    else:  # ring → mid → ξ (1)
                        f = (lambda z: 2 * z * z) if c == 0 else (lambda z: -math.sqrt(max(0.0, 1 - z * z)))
                        ends = [(0.707, res(0.707, c)), (mid, res(mid, c)), (1.0, res(1.0, c) if c == 0 else 0.0)]
                    (x0, y0), (x1, y1) = (ends[0], ends[1]) if f(x) <= f(mid) else (ends[1], ends[2])
                    new.append(b[c] + lin(f(x), f(x0), f(x1), y0, y1))
                for acc, w in ((today, g), (proj, new)):
                    acc[0] = max(acc[0], math.hypot(w[0] - ref[0], w[1] - ref[1]))
                    acc[1] = max(acc[1], abs(w[2] - ref[2]))
        out[band] = (today, proj)
    return out


# Ring sets for `rings`: |d_x| of the rings (0.707: today's), each with its own held-out elevations.
RING_SETS = [[0.707], [0.383, 0.707, 0.9], [0.2, 0.5, 0.707, 0.8, 0.95],
             [0.2, 0.383, 0.6, 0.707, 0.8, 0.9, 0.95], [0.1, 0.3, 0.5, 0.707, 0.8, 0.9, 0.98],
             [0.1, 0.2, 0.383, 0.5, 0.707, 0.8, 0.9, 0.98]]
# Flash of one more ring: four curves (u = 0 … 3) × three channels × 53 magnitudes × seven
# shapes in i16, as today's ring and its ξ–η curve (src/friction/rolling/table_data.rs).
RING_BYTES = 4 * 3 * 53 * 7 * 2


def rings(tags, rows, got):
    """How many rings of exact residuals the aim needs on the node25 sweeps (tabulated shapes,
    ν = 0.25): for each ring set of RING_SETS, `table`'s worst (ΔF, ΔM) at the sweeps' other
    elevations strictly between the plane and ξ, with the residual against `blend` exact on
    the plane (F_x: 0), on every ring and on the ξ curve (F_y, M_z: 0), piecewise linear between
    them in each channel's variable (F_x: d_x up to 0.707, then 2d_x²; F_y, M_z: 2d_x², then
    −|d_⊥|) — no interpolation in u, m, shape or ν: an estimate of what rings alone leave.
    Also F_x as the ring's exact F_x/d_x times d_x (no new data: F_x linear in d_x at a fixed
    magnitude and split, as at point 20), between the plane and the ring. Returns
    ([(ring set, tested elevations, (ΔF, ΔM))], worst F_x error of the slope rule, per point)."""
    sweeps = {}
    for t, r, g, b in zip(tags, rows, got["table"], got["blend"]):
        i, which, x = t.split("_")
        if which == "node25":
            sweeps.setdefault(int(i[1:]), {})[float(x)] = (r["ref"], g, b)

    def var(c, z):  # monotone in d_x, 1 at the ring for every channel
        if z <= 0.707:
            return z / 0.707 if c == 0 else 2 * z * z / (2 * 0.707 ** 2)
        return 2 * z * z / (2 * 0.707 ** 2) if c == 0 else 2 - math.sqrt(max(0.0, 1 - z * z)) / math.sqrt(1 - 0.707 ** 2)

    out = []
    for rs in RING_SETS:
        knots = sorted({0.0, 1.0, *rs})
        tested = [x for x in ELEVATIONS if x not in knots]
        worst, today = [0.0, 0.0], [0.0, 0.0]
        for d in sweeps.values():
            def end(x, c):  # the exact residual at a knot (0 where the channel vanishes)
                if (x == 0.0 and c == 0) or (x == 1.0 and c > 0):
                    return 0.0
                return d[x][0][c] - d[x][2][c]
            for x in tested:
                ref, g, b = d[x]
                today = [max(today[0], math.hypot(g[0] - ref[0], g[1] - ref[1])), max(today[1], abs(g[2] - ref[2]))]
                k = max(j for j in range(len(knots) - 1) if knots[j] <= x)
                x0, x1 = knots[k], knots[k + 1]
                w = [b[c] + end(x0, c) + (end(x1, c) - end(x0, c)) * (var(c, x) - var(c, x0)) / (var(c, x1) - var(c, x0))
                     for c in range(3)]
                worst = [max(worst[0], math.hypot(w[0] - ref[0], w[1] - ref[1])), max(worst[1], abs(w[2] - ref[2]))]
        out.append((rs, tested, today, worst))
    slope = {}
    for i, d in sorted(sweeps.items()):
        s_ring = d[0.707][0][0] / 0.707
        slope[i] = max(abs(x * s_ring - d[x][0][0]) for x in ELEVATIONS if 0 < x < 0.707)
    return out, slope


def tangents(tags, rows, got):
    """Per point (index → (today, with tangents)): `table`'s worst (ΔF, ΔM) from |d_⊥| = 0.1 to
    the ring on the node25 sweep, as it is and with F_y, M_z's residual against `blend` quadratic
    in |d_⊥| through 0 with the exact slope next to the ξ curve (the `tan` case at |d_⊥| = 0.02)
    and through the ring's exact value (F_x as today). The spin pole's elliptic radius in the
    patch at |d_⊥| = 0.1 and 0.2 (R < 1: inside) tells the regime."""
    by = {}
    for t, r, g, b in zip(tags, rows, got["table"], got["blend"]):
        i, which, x = t.split("_")
        if which == "node25":
            p = round(math.sqrt(max(0.0, 1.0 - float(x) ** 2)), 4)
        elif which == "tan":
            p = float(x)
        else:
            continue
        by.setdefault(int(i[1:]), {})[p] = (r, g, b)
    ring = round(math.sqrt(1.0 - 0.707 ** 2), 4)
    out = {}
    for i, d in sorted(by.items()):
        res = lambda p, c: d[p][0]["ref"][c] - d[p][2][c]
        today, new_w = [0.0, 0.0], [0.0, 0.0]
        for p in sorted(d):
            if not 0.09 < p < ring:
                continue
            r, g, b = d[p]
            ref = r["ref"]
            new = list(g)
            for c in (1, 2):
                slope, q = res(0.02, c) / 0.02, res(ring, c)
                new[c] = b[c] + slope * p + (q - slope * ring) * (p / ring) ** 2
            for acc, w in ((today, g), (new_w, new)):
                acc[0] = max(acc[0], math.hypot(w[0] - ref[0], w[1] - ref[1]))
                acc[1] = max(acc[1], abs(w[2] - ref[2]))
        poles = [H.pole_radius(d[p][0]) for p in (0.1, min(d, key=lambda z: abs(z - 0.2)))]
        out[i] = (today, new_w, poles)
    return out


def main():
    if "--cases" in sys.argv:
        for tag, s, nu, xi, eta, phic in cases():
            print(f"{s!r} 0 {nu!r} {xi!r} {eta!r} {phic!r} {tag}")
        return
    tags = []
    for line in data.read_text().splitlines():
        if line and line[0] != "#" and not line.startswith("family"):
            tags.append(line.split(",")[0])
    rows = H.read(data)
    got, _ = H.evaluate(rows)
    err = {l: [(math.hypot(g[0] - r["ref"][0], g[1] - r["ref"][1]), abs(g[2] - r["ref"][2]))
               for g, r in zip(got[l], rows)] for l in LAWS}
    # the points of the committed sweeps (after a change of the law, `--cases` selects anew)
    pts = selected({int(t.split("_")[0][1:]) for t in tags})
    out = []
    p = out.append
    p("# `table` between its direction curves: sweeps through its worst aligned held-out points\n")
    p(f"`python3 tools/rolling_direction_sweep.py` (reference: tools/data/rolling_diag_direction.csv, "
      f"{len(rows)} cases, the exact theory on the held-out set's grids, worst own error estimate "
      f"{max(r['err'][0] for r in rows):.0e} fN / {max(r['err'][1] for r in rows):.0e} fNc). Through each "
      f"aligned held-out point where `table` errs by more than {THRESHOLD[0]} fN or {THRESHOLD[1]} fNc "
      "(its ν and linear-force magnitude m; the split of (d_η, d_φ) kept) the direction is turned from the "
      "η–φ plane (|d_x| = 0, `table`'s plane curves) through its ring (|d_x| = 0.707) to ξ (|d_x| = 1), on "
      "the point's own a/b and on the nearest tabulated shape (where `table` holds the exact residuals on "
      "its curves), at the point's ν and at the tables' ν = 0.25. ΔF (fN) / ΔM (fNc) per law.\n")
    p("## Summary: worst error by elevation band\n")
    p("<!-- ANCHOR: summary -->")
    bands = [("plane (\\|d_x\\| = 0)", lambda x: x == 0.0),
             ("plane → ring (0 < \\|d_x\\| < 0.707)", lambda x: 0 < x < 0.707),
             ("ring (0.707)", lambda x: x == 0.707),
             ("ring → ξ (0.707 < \\|d_x\\| < 1)", lambda x: 0.707 < x < 1.0),
             ("ξ (1)", lambda x: x == 1.0)]
    p("| law, shape | " + " | ".join(b for b, _ in bands) + " |")
    p("|---|" + "---|" * len(bands))
    for l in LAWS:
        for which in ("own", "node", "node25"):
            cells = []
            for _, sel in bands:
                e = [x for x, t in zip(err[l], tags) if t.split("_")[1] == which and sel(float(t.split("_")[2]))]
                cells.append(f"{max(a for a, _ in e):.3f} / {max(b for _, b in e):.3f}")
            label = {"own": "own a/b, ν", "node": "nearest tabulated a/b, own ν",
                     "node25": "nearest tabulated a/b, ν = 0.25"}[which]
            p(f"| {l}, {label} | " + " | ".join(cells) + " |")
    p("<!-- ANCHOR_END: summary -->\n")
    p("## What two more rings would give, at best\n")
    p("<!-- ANCHOR: projected -->")
    p("| band (tabulated shapes, ν = 0.25) | `table` today | two more exact rings (bound) |")
    p("|---|---|---|")
    for band, (today, proj) in projected(tags, rows, got).items():
        p(f"| {band} | {today[0]:.3f} / {today[1]:.3f} | {proj[0]:.3f} / {proj[1]:.3f} |")
    p("<!-- ANCHOR_END: projected -->\n")
    p("(`projected`: the exact residual at \\|d_x\\| = 0.383 and 0.9 on each sweep's own (η, φ) split and "
      "magnitude, piecewise linear between them as today's weights are between the families — an optimistic "
      "bound for rings on the tables' u and m nodes.)\n")
    p("## How many rings the aim would need\n")
    ring_rows, slope = rings(tags, rows, got)
    p("<!-- ANCHOR: rings -->")
    p("| rings at \\|d_x\\| | more rings than today | tested at \\|d_x\\| | `table` today there | worst ΔF / ΔM (estimate) | more flash (bytes) |")
    p("|---|---|---|---|---|---|")
    for rs, tested, today, w in ring_rows:
        extra = len(rs) - 1
        p(f"| {', '.join(f'{x:g}' for x in rs)} | {extra} | {', '.join(f'{x:g}' for x in tested)} | "
          f"{today[0]:.3f} / {today[1]:.3f} | {w[0]:.3f} / {w[1]:.3f} | {extra * RING_BYTES:,} |")
    p("<!-- ANCHOR_END: rings -->\n")
    p(f"(Residuals exact on the plane, every ring and the ξ curve, piecewise linear between them in each channel's "
      f"variable; no interpolation in u, m, shape or ν, whose own errors come on top (0.06 / 0.13 on the plane "
      f"itself, table above). Not a strict bound: the first row, today's ring so interpolated, errs a little more "
      f"than `table` itself on its M_z, as the table's interpolation in u and m happens to help there. One ring ≈ {RING_BYTES:,} bytes: four "
      "curves × three channels × 53 magnitudes × seven shapes in i16. The flash column is what the rings add to "
      "`table`'s flash (the `rolling,table,f32` probe of bench-results/flash.csv: 63.6 KB; the aim is ≤ 64 KB).)\n")
    p("F_x as the ring's exact F_x/d_x times d_x between the plane and the ring (no new data; exact where F_x is "
      "linear in d_x at a fixed magnitude and split, as at point 20): worst F_x error per point "
      + ", ".join(f"{i} {e:.3f}" for i, e in slope.items()) + ".\n")
    p("## Tangents along the ξ curve instead: a regime switch breaks them\n")
    p("<!-- ANCHOR: tangents -->")
    p("| held-out point | ring → ξ today (\\|d_⊥\\| 0.1 … 0.6) | with the ξ curve's tangents (bound) | spin pole's radius at \\|d_⊥\\| = 0.1 / 0.2 |")
    p("|---|---|---|---|")
    for i, (today, new, poles) in tangents(tags, rows, got).items():
        p(f"| {i} | {today[0]:.3f} / {today[1]:.3f} | {new[0]:.3f} / {new[1]:.3f} | {poles[0]:.2f} / {poles[1]:.2f} |")
    p("<!-- ANCHOR_END: tangents -->\n")
    p("(F_y, M_z's residual quadratic in \\|d_⊥\\| through 0 with the exact slope at \\|d_⊥\\| = 0.02 and "
      "through the ring's exact value; F_x as today. The pole's radius is where the rigid slip vanishes, "
      "in units of the patch's elliptic radius: < 1 inside the patch.)\n")
    p("## Per point\n")
    for i, r, e in pts:
        p(f"### Held-out point {i}: a/b {r['aob']:.3f} (nearest tabulated {nearest(r['aob']):g}), ν {r['nu']:.3f}; "
          f"`table` there {e[0]:.3f} / {e[1]:.3f}\n")
        p("| \\|d_x\\| | a/b, ν | exact F_x, F_y, M_z | table | table ΔF / ΔM | blend ΔF / ΔM | fastsim ΔF / ΔM |")
        p("|---|---|---|---|---|---|---|")
        for which in ("own", "node", "node25"):
            for k, t in enumerate(tags):
                ti, tw, tx = t.split("_")
                if ti != f"p{i}" or tw != which:
                    continue
                ref, g = rows[k]["ref"], got["table"][k]
                p(f"| {float(tx):g} | {rows[k]['aob']:.3f}, {rows[k]['nu']:.3f} | {ref[0]:+.3f}, {ref[1]:+.3f}, {ref[2]:+.3f} | "
                  f"{g[0]:+.3f}, {g[1]:+.3f}, {g[2]:+.3f} | " +
                  " | ".join(f"{err[l][k][0]:.3f} / {err[l][k][1]:.3f}" for l in LAWS) + " |")
        p("")
    text = "\n".join(out) + "\n"
    if "--check" in sys.argv:
        if not out_md.exists() or out_md.read_text() != text:
            sys.exit(f"not what the laws give now: {out_md} — python3 {sys.argv[0]}")
        print("rolling-direction-sweep: up to date")
        return
    out_md.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
