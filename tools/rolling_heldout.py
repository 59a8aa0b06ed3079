#!/usr/bin/env python3
"""Every rolling law of the library against the held-out set over the whole domain
(tools/data/rolling_ref_heldout.csv: Kalker's exact theory, tools/rolling_exact/examples/heldout.rs,
500 points drawn at random over the patch shape, the skew of the rolling direction to the patch
axes, ν, the direction and the magnitude of the creepages; no law was fitted on them).

Each law runs through the per-step wrench (`contact_eval wrench --law L`, i.e. `contact::Rolling`:
the contact frame has x along the MAJOR axis, the rolling velocity (vrx, vry) in that frame, the
law evaluated on the aligned ellipse, the full slip on the real patch); `full-slip` is `best`
(the sliding law, whatever V). The patch: Hertz curvatures P ≤ Q with the reference's b/a
(Q/P = ((a/b)²E(m) − K(m))/(K(m) − E(m)), m = 1 − (b/a)², Johnson eq. 4.32), E* = 1e9 Pa,
h = 1e-5 m, f = 1; G set so that fN/(Gc²) is the reference's load ratio from the patch the
library computes (first pass with `best`). The reference's rolling frame (x along V, a₀ at θ
from x) is turned into the contact frame by ψ (the major axis' angle from x): vr = (cos ψ, −sin ψ),
slip v' = R(−ψ)(ξ, η)·V, ω = φV; forces turned back by R(ψ).

Error per point: |ΔF| = |(ΔF_x, ΔF_y)| ÷ fN, |ΔM_z| ÷ fNc; per family the worst and the median,
and the share of points where the law is worse than FASTSIM 32×32 by more than the reference's
own error estimate. Families: direction (the largest component of the unit linear-force
direction d the generator drew: ξ, η or φ), skew (the angle from the rolling direction to the
nearest patch axis), shape (the aligned ellipse's a/b along the rolling direction), the patch's
own b/a, ν, and the normalised magnitude q (linear force 3fN at q = 1). Cost: M4F f32
instructions per call from bench-results/qemu.csv (stage `rolling`: the law alone; the per-step
wrench along an axis, skewed, varying for `table`).

    cargo build --release --bin contact_eval && python3 tools/rolling_heldout.py [--csv OUT] [--md OUT] [--check]

(--check: fail if the committed outputs differ from what the laws give now.)

Writes (defaults) tools/data/rolling_heldout_laws.csv (every law's output per point, ÷ fN,
÷ fNc, in the reference's rolling frame) and bench-results/rolling-heldout.md (the tables).
"""
import math, pathlib, subprocess, sys, statistics

root = pathlib.Path(__file__).resolve().parent.parent
exe = root / "target/release/contact_eval"
ref_csv = root / "tools/data/rolling_ref_heldout.csv"
LAWS = ["table", "blend", "fastsim", "fastsim-16", "full-slip"]
SEED, POINTS = 29, 500  # as tools/rolling_exact/examples/heldout.rs
M64 = (1 << 64) - 1


def arg(name, default):
    return pathlib.Path(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default


def draws():
    """The generator's draws (splitmix64, the order of heldout.rs's `draw`): per point the unit
    direction d and the magnitude q (the rest is in the CSV)."""
    state = SEED

    def uniform():
        nonlocal state
        state = (state + 0x9E3779B97F4A7C15) & M64
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & M64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & M64
        z ^= z >> 31
        return (z >> 11) / float(1 << 53)

    out = []
    for _ in range(POINTS):
        aob = math.exp(math.log(20.0) * (2.0 * uniform() - 1.0))
        uniform(), uniform(), uniform()  # aligned?, θ, ν
        z = 2.0 * uniform() - 1.0
        az = 2.0 * math.pi * uniform()
        w = math.sqrt(1.0 - z * z)
        d = (z, w * math.cos(az), w * math.sin(az))
        q = 0.01 * 1000.0 ** uniform()
        out.append((aob, d, q))
    return out


def read(path=ref_csv):
    """The rows of a reference file in the held-out set's format (default: the held-out set)."""
    rows = []
    for line in path.read_text().splitlines():
        if not line or line[0] == "#" or line.startswith("family"):
            continue
        f = line.split(",")
        v = [float(x) for x in f[1:]]
        rows.append(dict(aob=v[0], theta=math.radians(v[1]), nu=v[2], nl=v[3], xi=v[4], eta=v[5], phic=v[6],
                         ref=(v[7], v[8], v[9]), err=(v[10], v[11]), converged=v[12] == 1.0))
    return rows


def agm_ke(m):
    """Complete elliptic integrals K(m), E(m) (parameter m = k²) by the AGM."""
    a, b, p = 1.0, math.sqrt(1.0 - m), 1.0
    s = 0.5 * m
    for _ in range(40):  # quadratic convergence: ≤ 10 steps for m ≤ 1 − 1e-8
        if a - b <= 1e-15 * a:
            break
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        p *= 2.0
        s += 0.5 * p * c * c
    k = math.pi / (2.0 * a)
    return k, k * (1.0 - s)


def curvature_ratio(k):
    """Q/P of the Hertz patch with b/a = k ≤ 1 (Johnson eq. 4.32)."""
    if k >= 1.0 - 1e-12:
        return 1.0
    m = 1.0 - k * k
    kk, ee = agm_ke(m)
    return (ee / (k * k) - kk) / (kk - ee)


def frame(r):
    """(major/minor b/a ≤ 1, ψ): the patch's b/a and the major axis' angle from the rolling direction."""
    aob, th = r["aob"], r["theta"]
    return (1.0 / aob, th) if aob >= 1.0 else (aob, th + 0.5 * math.pi)


def run(law, text):
    out = subprocess.run([str(exe), "wrench", "--law", law], input=text, capture_output=True, text=True,
                         check=True).stdout.splitlines()
    head = out[0].split(",")
    return [dict(zip(head, (float(x) for x in l.split(",")))) for l in out[1:]]


def evaluate(rows):
    """Per law, per row: (F_x/fN, F_y/fN, M_z/(fNc)) in the rolling frame."""
    cols = "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega,G,nu,vrx,vry"
    base = []
    for r in rows:
        k, psi = frame(r)
        base.append((1.0, curvature_ratio(k), psi))
    # pass 1: the patch (N, a, b) the library computes
    text = cols + "\n" + "".join(f"{p!r},{q!r},1e9,0,1,0,1e-5,0,0,0,0,1e9,{r['nu']!r},0,0\n"
                                 for (p, q, _), r in zip(base, rows))
    patches = run("best", text)
    lines = []
    norms = []
    for (p, q, psi), r, pt in zip(base, rows, patches):
        n, a, b = pt["N"], pt["a"], pt["b"]
        c = math.sqrt(a * b)
        g = n / (r["nl"] * c * c)  # f = 1
        V = 1.0
        cs, sn = math.cos(psi), math.sin(psi)
        xi, eta, phi = r["xi"], r["eta"], r["phic"] / c
        vx, vy = (cs * xi + sn * eta) * V, (-sn * xi + cs * eta) * V
        lines.append(f"{p!r},{q!r},1e9,0,1,0,1e-5,0,{vx!r},{vy!r},{phi * V!r},{g!r},{r['nu']!r},"
                     f"{cs * V!r},{-sn * V!r}\n")
        norms.append((n, c, cs, sn, a / b))
    text = cols + "\n" + "".join(lines)
    got = {}
    for law in LAWS:
        out = run("best" if law == "full-slip" else law, text)
        res = []
        for o, (n, c, cs, sn, _) in zip(out, norms):
            fx, fy = o["Fx"] / n, o["Fy"] / n
            res.append((cs * fx - sn * fy, sn * fx + cs * fy, o["Tz"] / (n * c)))
        got[law] = res
    return got, norms


def pole_radius(r):
    """The spin pole of a reference row (where the rigid slip (ξ − φy, η + φx) vanishes, c = 1)
    in the patch's axes (a₀ at θ from the rolling direction), as a multiple of the patch's
    elliptic radius: < 1 inside the patch (spin-dominated), > 1 outside; ∞ without spin."""
    if r["phic"] == 0.0:
        return math.inf
    a0, b0 = math.sqrt(r["aob"]), 1.0 / math.sqrt(r["aob"])
    px, py = -r["eta"] / r["phic"], r["xi"] / r["phic"]
    cs, sn = math.cos(r["theta"]), math.sin(r["theta"])
    return math.hypot((cs * px + sn * py) / a0, (-sn * px + cs * py) / b0)


def families(r, d, q):
    """The point's family in each table."""
    k, psi = frame(r)
    th = math.degrees(r["theta"]) % 90.0
    skew = min(th, 90.0 - th)
    # aligned ellipse along the rolling direction (a₀ at θ): a_r/b_r
    a0, b0 = math.sqrt(r["aob"]), 1.0 / math.sqrt(r["aob"])
    big_a = math.cos(r["theta"]) ** 2 / a0 ** 2 + math.sin(r["theta"]) ** 2 / b0 ** 2
    ar = 1.0 / math.sqrt(big_a)
    aligned = ar * ar  # a_r/b_r with a_r·b_r = 1
    dom = max(range(3), key=lambda i: abs(d[i]))
    pole = pole_radius(r)
    bins = lambda x, edges, names: next(nm for e, nm in zip(edges, names) if x < e)
    return {
        "direction (largest linear share)": ["ξ", "η", "φ"][dom],
        "skew to the nearest axis": "aligned" if skew < 1e-9 else bins(
            skew, [15, 30, 45.001], ["0–15°", "15–30°", "30–45°"]),
        "shape along the rolling direction (aligned a/b)": bins(
            aligned, [0.1, 0.2, 0.5, 2.0, 5.0, 10.0, 1e9],
            ["0.05–0.1", "0.1–0.2", "0.2–0.5", "0.5–2", "2–5", "5–10", "10–20"]),
        "patch b/a (own)": bins(k, [0.1, 0.2, 0.5, 1.0001], ["0.05–0.1", "0.1–0.2", "0.2–0.5", "0.5–1"]),
        "ν": bins(r["nu"], [0.1, 0.2, 0.3, 0.4, 0.51], ["0–0.1", "0.1–0.2", "0.2–0.3", "0.3–0.4", "0.4–0.5"]),
        "magnitude q": bins(q, [0.1, 1.0, 11.0], ["0.01–0.1", "0.1–1", "1–10"]),
        "spin pole's radius in the patch (< 1: inside)": bins(
            min(pole, 1e300), [0.5, 0.8, 1.25, 2.0, 1e301], ["< 0.5", "0.5–0.8", "0.8–1.25", "1.25–2", "> 2"]),
    }


def cost():
    """M4F f32 instructions per call (bench-results/qemu.csv, stage `rolling`)."""
    c = {}
    for line in (root / "bench-results/qemu.csv").read_text().splitlines():
        f = line.split(",")
        if len(f) == 4 and f[0] == "rolling" and f[2] == "f32":
            c[f[1]] = int(f[3])
    return c


def main():
    rows = read()
    dq = draws()
    assert len(rows) <= POINTS
    for r, (aob, _, _) in zip(rows, dq):
        assert abs(r["aob"] / aob - 1.0) < 1e-5, (r["aob"], aob)  # the CSV and the draws agree
    got, norms = evaluate(rows)
    check = "--check" in sys.argv
    csv_out = arg("--csv", root / "tools/data/rolling_heldout_laws.csv")
    lines = [  # the per-point CSV
        "# Every rolling law on the held-out set (tools/rolling_heldout.py; rows of rolling_ref_heldout.csv in order):\n",
        "# F/(fN), Mz/(fNc) in the reference's rolling frame, through contact_eval wrench (full-slip = best).\n",
        "index,d_xi,d_eta,d_phi,q," + ",".join(f"{l}_fx,{l}_fy,{l}_mz" for l in LAWS) + "\n",
    ]
    for i, (r, (_, d, q)) in enumerate(zip(rows, dq)):
        vals = [f"{v:.6e}" for l in LAWS for v in got[l][i]]
        lines.append(f"{i},{d[0]:.6f},{d[1]:.6f},{d[2]:.6f},{q:.6e}," + ",".join(vals) + "\n")
    csv_text = "".join(lines)
    errs = {l: [] for l in LAWS}
    for l in LAWS:
        for r, g in zip(rows, got[l]):
            ref = r["ref"]
            errs[l].append((math.hypot(g[0] - ref[0], g[1] - ref[1]), abs(g[2] - ref[2])))
    fam = [families(r, d, q) for r, (_, d, q) in zip(rows, dq)]
    out = []
    p = out.append
    ref_ef = max(r["err"][0] for r in rows)
    ref_em = max(r["err"][1] for r in rows)
    p("# Rolling laws against the held-out set over the whole domain\n")
    p(f"`python3 tools/rolling_heldout.py` (reference: tools/data/rolling_ref_heldout.csv, {len(rows)} points, "
      f"{sum(not r['converged'] for r in rows)} not converged; its own grid error estimate: worst {ref_ef:.1e} fN, "
      f"{ref_em:.1e} fNc, median {statistics.median(r['err'][0] for r in rows):.1e} / "
      f"{statistics.median(r['err'][1] for r in rows):.1e}). Errors: ΔF = |(ΔF_x, ΔF_y)| (fN) / "
      "ΔM = |ΔM_z| (fNc); worst, then the median in brackets; n = points in the family.\n")
    c = cost()
    costs = {"table": c.get("table"), "blend": c.get("blend"), "fastsim": c.get("fastsim"),
             "fastsim-16": c.get("fastsim-16"), "full-slip": c.get("full-slip")}
    # the guide (docs/guide/src/rolling.md) includes the parts between the ANCHOR comments
    p("## Whole set, and cost\n")
    p("<!-- ANCHOR: whole -->")
    p("| law | worst ΔF | worst ΔM | median ΔF | median ΔM | 95 % ΔF | 95 % ΔM | points worse than FASTSIM 32×32 | M4F f32 instructions (law alone) |")
    p("|---|---|---|---|---|---|---|---|---|")
    fs = errs["fastsim"]
    pareto = []
    for l in LAWS:
        e = errs[l]
        ef, em = [x[0] for x in e], [x[1] for x in e]
        worse = sum(1 for x, y, r in zip(e, fs, rows) if x[0] > y[0] + r["err"][0] or x[1] > y[1] + r["err"][1])
        q95 = lambda v: sorted(v)[int(0.95 * (len(v) - 1))]
        p(f"| {l} | {max(ef):.3f} | {max(em):.3f} | {statistics.median(ef):.4f} | {statistics.median(em):.4f} | "
          f"{q95(ef):.3f} | {q95(em):.3f} | {worse} | {costs[l] if costs[l] else '—'} |")
        pareto.append((costs[l] or 0, max(max(ef), max(em)), l))
    front, best = [], math.inf
    for cst, worst, l in sorted(pareto):
        if worst < best:
            front.append(l)
            best = worst
    p(f"\n(points worse than FASTSIM: ΔF or ΔM above FASTSIM's by more than the reference's own estimate.) "
      f"Pareto front (cost against the worst of ΔF, ΔM): {', '.join(front)}. The per-step wrench "
      f"(`contact::Rolling`, `table`): {c.get('wrench-axis')} instructions along an axis, "
      f"{c.get('wrench-skewed')} skewed, {c.get('wrench-varying')} varying (bench-results/qemu.csv).\n")
    p("<!-- ANCHOR_END: whole -->\n")
    p("## Subsets\n")
    subsets = [
        ("aligned, a/b in [0.2, 5] (`blend`'s fitted range; `table`'s knee and ½-direction nodes)",
         lambda f, r: f["skew to the nearest axis"] == "aligned" and 0.2 <= r["aob"] <= 5.0),
        ("aligned, any a/b", lambda f, r: f["skew to the nearest axis"] == "aligned"),
        ("skewed, patch b/a ≥ 0.2", lambda f, r: f["skew to the nearest axis"] != "aligned" and 0.2 <= r["aob"] <= 5.0),
        ("skewed, patch b/a < 0.2", lambda f, r: f["skew to the nearest axis"] != "aligned" and not 0.2 <= r["aob"] <= 5.0),
        ("all", lambda f, r: True),
    ]
    p("| law | " + " | ".join(f"{nm} (n = {sum(1 for f, r in zip(fam, rows) if sel(f, r))})" for nm, sel in subsets) + " |")
    p("|---|" + "---|" * len(subsets))
    for l in LAWS:
        cells = []
        for _, sel in subsets:
            e = [x for x, f, r in zip(errs[l], fam, rows) if sel(f, r)]
            cells.append(f"{max(x[0] for x in e):.3f} / {max(x[1] for x in e):.3f} "
                         f"({statistics.median(x[0] for x in e):.3f} / {statistics.median(x[1] for x in e):.3f})")
        p(f"| {l} | " + " | ".join(cells) + " |")
    p("")
    p("## Per family\n")
    p("<!-- ANCHOR: families -->")
    for name in fam[0]:
        keys = sorted({f[name] for f in fam}, key=_sort_key)
        p(f"### By {name}\n")
        p("| law | " + " | ".join(f"{k} (n = {sum(1 for f in fam if f[name] == k)})" for k in keys) + " |")
        p("|---|" + "---|" * len(keys))
        for l in LAWS:
            cells = []
            for k in keys:
                e = [x for x, f in zip(errs[l], fam) if f[name] == k]
                cells.append(f"{max(x[0] for x in e):.3f} / {max(x[1] for x in e):.3f} "
                             f"({statistics.median(x[0] for x in e):.3f} / {statistics.median(x[1] for x in e):.3f})")
            p(f"| {l} | " + " | ".join(cells) + " |")
        p("")
    p("<!-- ANCHOR_END: families -->\n")
    p("## The worst points of `table`\n")
    p("| a/b (own) | θ (°) | ν | d (ξ, η, φ) | q | exact F_x, F_y, M_z | table | ΔF / ΔM | fastsim ΔF / ΔM | ref. est. |")
    p("|---|---|---|---|---|---|---|---|---|---|")
    worst = sorted(range(len(rows)), key=lambda i: -max(errs["table"][i]))[:12]
    for i in worst:
        r, (_, d, q) = rows[i], dq[i]
        g = got["table"][i]
        p(f"| {r['aob']:.3f} | {math.degrees(r['theta']):.1f} | {r['nu']:.3f} | {d[0]:+.2f}, {d[1]:+.2f}, {d[2]:+.2f} | "
          f"{q:.3f} | {r['ref'][0]:+.3f}, {r['ref'][1]:+.3f}, {r['ref'][2]:+.3f} | {g[0]:+.3f}, {g[1]:+.3f}, {g[2]:+.3f} | "
          f"{errs['table'][i][0]:.3f} / {errs['table'][i][1]:.3f} | {errs['fastsim'][i][0]:.3f} / {errs['fastsim'][i][1]:.3f} | "
          f"{r['err'][0]:.0e} / {r['err'][1]:.0e} |")
    text = "\n".join(out) + "\n"
    md = arg("--md", root / "bench-results/rolling-heldout.md")
    if check:
        stale = [str(f) for f, t in ((md, text), (csv_out, csv_text)) if not f.exists() or f.read_text() != t]
        if stale:
            sys.exit(f"not what the laws give now: {stale} — python3 {sys.argv[0]}")
        print("rolling-heldout: committed tables up to date")
        return
    md.write_text(text)
    csv_out.write_text(csv_text)
    print(text)


def _sort_key(k):
    if k == "aligned":
        return -1.0
    if k.startswith("< "):
        return float(k[2:]) - 1e-9  # before the bin that starts there
    if k.startswith("> "):
        return float(k[2:]) + 1e9
    head = k.split("–")[0].rstrip("°")
    try:
        return float(head)
    except ValueError:
        return {"ξ": 0, "η": 1, "φ": 2}.get(k, 9)


if __name__ == "__main__":
    main()
