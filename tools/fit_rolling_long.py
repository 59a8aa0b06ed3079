#!/usr/bin/env python3
"""The reach base (tools/fit_rolling_reach.py) and its ridge polynomial correction, refitted with the
dense long-patch training data (tools/data/rolling_ref_train_long2.csv: patches 5–20 times longer
than wide along the rolling direction, any skew that keeps them so, ρ 0.5–20) and measured on the
held-out set (tools/data/rolling_ref_heldout.csv, seed 29: never fitted on, no hyper-parameter chosen
on it) and by k-fold validation on the training rows, grouped by patch (a shape, ν and its mirror
image in one fold: a fold's patches were never seen by its fit). Prototype, Python.

Correction variants (`--variant`, several allowed; each the same base):
- `log2`: the same features, degree 2 (105 terms);
- `log`: fit_rolling_reach's 12 features + λ (ln(major/minor)/ln 20, cos 2ψ, sin 2ψ, 2ν, Ŵ_lin, τ,
  W_fs, 2σ − 1, 2λ − 1), degree 3 — the previous session's correction;
- `bounded`: the shape as bounded functions instead of the log: the aligned shape along the rolling
  direction as t = (a − b)/(a + b) ∈ (−1, 1) (a, b the sheared ellipse's extent along x and across;
  no a/b, no ln), plus the own shape's g = 1 − 2·minor/(major + minor) ∈ [0, 1) and cos 2ψ, sin 2ψ;
- `gated`: `log` plus a second degree-2 polynomial multiplied by the long-patch weight
  w = smoothstep((t − 0.5)/0.4) (0 below a/b ≈ 3 along x, 1 from a/b ≈ 10: a correction that is
  only fitted, and only acts, where the data are the long-patch rows);
- `lawson`: `log` refitted with Lawson's reweighting (weights × the row's error relative to the
  target, normalised, 6 rounds): a step towards the minimax fit instead of least squares.

Base (`--strip`): the reach base blended with the 1-D long-patch base of tools/rolling_strip1d.py by
the aligned shape along x (weight 0 up to a/b = 4 along x, 1 from 12; `--strip-band r₀ r₁`).
`--refit-base`: the reach base's 14 parameters refitted (fit_rolling_reach.py's Nelder–Mead and
objective) on its 6,000-row subset plus every long-patch row, written to /tmp/roll/reach_prm_long.npy;
`--prm-long` reuses them; otherwise `--prm FILE` (default /tmp/roll/reach_prm.npy, what
`tools/fit_rolling_reach.py` writes). `--sparse K …`: K greedy terms (fit_rolling_reach.sparse_select).

    "$(tools/venv.sh)" tools/fit_rolling_reach.py --degree 3          # the reach base's parameters (≈ 6 min)
    "$(tools/venv.sh)" tools/fit_rolling_long.py --refit-base --strip --variant log --kfold 0   # ≈ 3 min
    "$(tools/venv.sh)" tools/fit_rolling_long.py --prm-long --strip --variant log gated --sparse 100 150 \
        --kfold 5 --families --md bench-results/rolling-long.md                                  # ≈ 8 min

Everything is fitted on training rows only; the held-out set is only measured.
"""
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import fit_rolling_reach as R  # noqa: E402
import fit_rolling_surrogate as F  # noqa: E402

root = F.root
LONG2 = ["rolling_ref_train_long2.csv"]
CACHE2 = pathlib.Path("/tmp/roll/long2_prep.npz")


def prep(d):
    k = F.creep_k(d)
    d = dict(d)
    d["k"], d["lin"], d["fs"] = k, F.linear(d, k), F.full_slip(d)
    return d


def load_long2():
    files = [root / "tools/data" / f for f in LONG2]
    stamp = "".join(str(p.stat().st_mtime_ns) for p in files if p.exists())
    if CACHE2.exists():
        c = dict(np.load(CACHE2))
        if str(c.get("stamp", "")) == stamp:
            return {k: v for k, v in c.items() if k != "stamp"}
    d = prep(F.mirrored(F.read([str(p) for p in files if p.exists()])))
    np.savez(CACHE2, stamp=stamp, **d)
    return d


def base_of(d, prm, strip=False):
    """The reach base; strip: blended with the 1-D long-patch base (tools/rolling_strip1d.py) by the
    weight w = smoothstep((t − t₀)/(t₁ − t₀)) of the aligned shape along x, t = (a − b)/(a + b)
    (w = 0 up to a/b = r₀ along x, 1 from r₁: `--strip-band r₀ r₁`, default 4 and 12, chosen by the
    k-fold validation's worst among (3, 8), (4, 12), (5, 10), (6, 15))."""
    if strip:
        import rolling_strip1d as S
        w0, rho, lam = base_of(d, prm)
        r0, r1 = (float(x) for x in F.args("--strip-band", ["4", "12"]))
        t0, t1 = (r0 - 1) / (r0 + 1), (r1 - 1) / (r1 + 1)
        u = np.clip((aligned_t(d) - t0) / (t1 - t0), 0.0, 1.0)
        w = u * u * (3 - 2 * u)
        ws = np.concatenate([S.strip_base({k: v[lo:lo + 2000] for k, v in d.items()})[0]
                             for lo in range(0, len(d["aob"]), 2000)])
        return (1 - w)[:, None] * w0 + w[:, None] * ws, rho, lam
    qh = R.Quad()
    parts = []
    for lo in range(0, len(d["aob"]), 2000):
        dd = {k: v[lo:lo + 2000] for k, v in d.items()}
        parts.append(R.reach(dd, dd["lin"], dd["fs"], prm, qh, qh.geometry(dd)))
    return tuple(np.concatenate([p[i] for p in parts]) for i in range(3))


def aligned_t(d):
    """(a − b)/(a + b) of the sheared ellipse along the rolling direction (c = 1: a = 1/√A, b = 1/a)."""
    a0 = np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    aa = ct * ct / a0 ** 2 + st * st * a0 ** 2  # A = 1/a²
    r = 1.0 / aa  # a/b along x
    return (r - 1.0) / (r + 1.0)


def feats(d, b, variant):
    """Features x and the factor τ²(1 − τ) (both limits kept) for a variant."""
    sys.argv += [] if "--fs-features" in sys.argv else ["--fs-features", "--sigma"]
    x, fac = F.features(d, d["lin"], b[1], d["fs"])
    x = np.column_stack([x, 2 * b[2] - 1])
    if variant == "bounded":
        r = np.where(d["aob"] >= 1.0, d["aob"], 1.0 / d["aob"])
        g = (r - 1.0) / (r + 1.0)
        x = np.column_stack([aligned_t(d), 2 * g - 1, x[:, 1:]])
    return x, fac


def long_weight(d):
    u = np.clip((aligned_t(d) - 0.5) / 0.4, 0.0, 1.0)
    return u * u * (3 - 2 * u)


def design(d, b, variant):
    x, fac = feats(d, b, "bounded" if variant == "bounded" else "log")
    a = F.design(x, fac, F.monomials(x.shape[1], 2 if variant == "log2" else 3))
    if variant == "gated":
        a = np.column_stack([a, F.design(x, fac * long_weight(d), F.monomials(x.shape[1], 2))])
    return a


def solve(a, res, lam, w=None):
    sc = np.maximum(np.sqrt((a * a).mean(0)), 1e-12)
    an = a / sc
    if w is not None:
        an_w = an * w[:, None]
        m, r = an_w.T @ an, an_w.T @ res
    else:
        m, r = an.T @ an, an.T @ res
    return np.linalg.solve(m + lam * len(an) * np.eye(an.shape[1]), r) / sc[:, None]


def fit(a, res, ref, basew, lam, lawson):
    if not lawson:
        return solve(a, res, lam)
    w = np.ones(len(a))
    for _ in range(6):
        c = solve(a, res, lam, w)
        ef, em = F.errors(basew + a @ c, ref)
        e = np.maximum(ef / 0.03, em / 0.05)
        w = w * (0.5 + e)
        w = w / w.mean()
    return c


def refit_base(tr, l2, out):
    """The reach base's 14 parameters refitted as fit_rolling_reach.py fits them (Nelder–Mead, the same
    objective and steps, 16 × 32 quadrature) on its 6,000-row subset of the training rows plus every
    long-patch row, from the parameters fit_rolling_reach.py gives (`--prm`)."""
    from scipy.optimize import minimize
    rng = np.random.default_rng(1)
    sub = rng.choice(len(tr["aob"]), size=6000, replace=False)
    d = {k: np.concatenate([tr[k][sub], l2[k]]) for k in tr}
    q = R.Quad(16, 32)
    xy = q.geometry(d)
    fs = q.wrench(xy, d["s"])
    start = np.load(F.args("--prm", ["/tmp/roll/reach_prm.npy"])[0])
    simplex = np.vstack([start] + [start + np.eye(R.NPRM)[i] * R.STEPS[i] for i in range(R.NPRM)])
    r = minimize(lambda p: R.score(R.reach(d, d["lin"], fs, p, q, xy)[0], d["ref"]), start, method="Nelder-Mead",
                 options=dict(maxiter=1500, xatol=1e-3, fatol=1e-4, initial_simplex=simplex))
    print("refitted base:", r.fun, np.round(r.x, 4).tolist(), flush=True)
    np.save(out, r.x)
    return r.x


def groups(d):
    """A patch (a/b, ν) and its mirror image: the same group."""
    key = np.round(np.log(d["aob"]), 6) * 1e3 + np.round(d["nu"], 6)
    _, inv = np.unique(key, return_inverse=True)
    return inv


def reach_cache():
    """fit_rolling_reach.py's prepared training and held-out rows (built and cached if absent)."""
    if not R.CACHE.exists():
        R.CACHE.parent.mkdir(parents=True, exist_ok=True)
        np.savez(R.CACHE, **R.load())
    return dict(np.load(R.CACHE))


def main():
    c = reach_cache()
    tr, ho = R.split(c, "tr"), R.split(c, "ho")
    if "--no-long2" not in sys.argv:
        l2 = load_long2()
        tr = {k: np.concatenate([tr[k], l2[k]]) for k in tr}
        print(f"long-patch rows (with mirrors): {len(l2['aob'])}", flush=True)
    if "--refit-base" in sys.argv:
        c0 = reach_cache()
        prm = refit_base(R.split(c0, "tr"), load_long2(), "/tmp/roll/reach_prm_long.npy")
    elif "--prm-long" in sys.argv:  # the last --refit-base
        prm = np.load("/tmp/roll/reach_prm_long.npy")
    else:
        prm = np.load(F.args("--prm", ["/tmp/roll/reach_prm.npy"])[0])
    strip = "--strip" in sys.argv
    bt, bh = base_of(tr, prm, strip), base_of(ho, prm, strip)
    lam = float(F.args("--ridge", ["1e-4"])[0])
    kf = int(F.args("--kfold", ["5"])[0])
    res = tr["ref"] - bt[0]
    lines = [f"training rows {len(tr['aob'])}, held-out {len(ho['aob'])}; ridge {lam:g}", "",
             "| law | rows | worst ΔF | worst ΔM | median ΔF | median ΔM | 95 % ΔF | 95 % ΔM |",
             "|---|---|---|---|---|---|---|---|"]

    def row(name, rows, ef, em):
        return (f"| {name} | {rows} | {ef.max():.3f} | {em.max():.3f} | {np.median(ef):.4f} | {np.median(em):.4f} | "
                f"{np.quantile(ef, 0.95):.3f} | {np.quantile(em, 0.95):.3f} |")

    bname = "reach + 1-D strip base" if strip else "reach base"
    lines.append(row(bname, "training", *F.errors(bt[0], tr["ref"])))
    lines.append(row(bname, "held-out", *F.errors(bh[0], ho["ref"])))
    lines.append(f"(held-out rows with W·(ξ, η, φc) > 0 before any projection: {F.passive(bh[0], ho)[1]}; training: {F.passive(bt[0], tr)[1]})")
    long_tr = aligned_t(tr) > (10 - 1) / (10 + 1)
    laws = {bname: bh[0]}
    for variant in F.args("--variant", ["log", "bounded", "gated", "lawson"]):
        a = design(tr, bt, variant)
        ah = design(ho, bh, variant)
        coef = fit(a, res, tr["ref"], bt[0], lam, variant == "lawson")
        wh, npro = F.passive(bh[0] + ah @ coef, ho)
        name = f"{bname} + {variant} ({a.shape[1]} terms × 3)"
        lines.append(row(name, "training", *F.errors(bt[0] + a @ coef, tr["ref"])))
        lines.append(row(name, "training a/b > 10 along x", *F.errors((bt[0] + a @ coef)[long_tr], tr["ref"][long_tr])))
        lines.append(row(name, f"held-out (projected: {npro})", *F.errors(wh, ho["ref"])))
        laws[f"{bname} + {variant}"] = wh
        if kf > 1:
            g = groups(tr)
            fold = np.random.default_rng(5).permutation(g.max() + 1)[g] % kf
            pred = np.zeros_like(res)
            for k in range(kf):
                t = fold != k
                ck = fit(a[t], res[t], tr["ref"][t], bt[0][t], lam, variant == "lawson")
                pred[~t] = a[~t] @ ck
            ef, em = F.errors(bt[0] + pred, tr["ref"])
            lines.append(row(name, f"{kf}-fold validation (by patch)", ef, em))
            lines.append(row(name, f"{kf}-fold validation, a/b > 10 along x", ef[long_tr], em[long_tr]))
            t = aligned_t(tr)
            sig = F.spin_share(tr)
            for j in np.argsort(-np.maximum(ef / 0.03, em / 0.05))[:8:2]:  # rows come with their mirror image
                print(f"    validation worst: ΔF {ef[j]:.3f} ΔM {em[j]:.3f} at a/b {tr['aob'][j]:.2f} θ {math.degrees(tr['theta'][j]):.0f}° "
                      f"(a/b along x {(1 + t[j]) / (1 - t[j]):.2f}) ν {tr['nu'][j]:.2f} ρ {bt[1][j]:.2f} σ {sig[j]:.2f}", flush=True)
        for kk in [int(x) for x in F.args("--sparse", [])]:  # greedy subset (fit_rolling_reach.sparse_select)
            sc = np.maximum(np.sqrt((a * a).mean(0)), 1e-12)
            sel = R.sparse_select(a / sc, res, kk, lam)
            cs = solve(a[:, sel], res, lam)
            ws, npro = F.passive(bh[0] + ah[:, sel] @ cs, ho)
            nm = f"{bname} + {variant}, {kk} greedy terms × 3"
            lines.append(row(nm, "training", *F.errors(bt[0] + a[:, sel] @ cs, tr["ref"])))
            lines.append(row(nm, f"held-out (projected: {npro})", *F.errors(ws, ho["ref"])))
            laws[f"{bname} + {variant} s{kk}"] = ws
            if kf > 1:
                pred = np.zeros_like(res)
                for k in range(kf):
                    t = fold != k
                    pred[~t] = a[~t][:, sel] @ solve(a[t][:, sel], res[t], lam)
                lines.append(row(nm, f"{kf}-fold validation (by patch; the selection on all rows)", *F.errors(bt[0] + pred, tr["ref"])))
        print("\n".join(lines[-5:]), flush=True)
        np.save(f"/tmp/roll/long_coef_{variant}.npy", coef)
    if "--families" in sys.argv:
        laws.update(F.committed_laws(len(ho["aob"])))
        lines += F.family_tables(ho, laws)
    print("\n".join(lines))
    if "--md" in sys.argv:
        title = ["# Rolling: the reach base with dense long-patch training data", "",
                 "`" + " ".join(["tools/fit_rolling_long.py"] + [a for a in sys.argv[1:] if a not in ("--fs-features", "--sigma")]) + "`", ""]
        pathlib.Path(F.args("--md", [""])[0]).write_text("\n".join(title + lines) + "\n")
    np.savez("/tmp/roll/long_fit.npz", **{k.replace(" ", "_"): v for k, v in laws.items()})


if __name__ == "__main__":
    main()
