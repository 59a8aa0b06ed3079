#!/usr/bin/env python3
"""The reach base (tools/fit_rolling_reach.py) and its ridge polynomial correction, refitted with the
dense long-patch training data (tools/data/rolling_ref_train_long2.csv: patches 5–20 times longer
than wide along the rolling direction, any skew that keeps them so, ρ 0.5–20) and measured on the
held-out set (tools/data/rolling_ref_heldout.csv, seed 29: never fitted on, no hyper-parameter chosen
on it) and by k-fold validation on the training rows, grouped by patch (a shape, ν and its mirror
image in one fold: a fold's patches were never seen by its fit). Prototype, Python.

Correction variants (`--variant`, several allowed; each the same base):
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

    "$(tools/venv.sh)" tools/fit_rolling_long.py [--no-long2] [--variant log bounded gated lawson]
        [--kfold 5] [--ridge 1e-4] [--families] [--md OUT]

The base's 14 parameters: /tmp/roll/reach_prm.npy (`tools/fit_rolling_reach.py` fits and writes them;
they are fitted on training rows only).
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
    weight w = smoothstep((t − 0.5)/0.28) of the aligned shape along x, t = (a − b)/(a + b)
    (w = 0 up to a/b = 3 along x, 1 from a/b = 8)."""
    if strip:
        import rolling_strip1d as S
        w0, rho, lam = base_of(d, prm)
        u = np.clip((aligned_t(d) - 0.5) / 0.28, 0.0, 1.0)
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
    a = F.design(x, fac, F.monomials(x.shape[1], 3))
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


def groups(d):
    """A patch (a/b, ν) and its mirror image: the same group."""
    key = np.round(np.log(d["aob"]), 6) * 1e3 + np.round(d["nu"], 6)
    _, inv = np.unique(key, return_inverse=True)
    return inv


def main():
    c = dict(np.load(R.CACHE))
    tr, ho = R.split(c, "tr"), R.split(c, "ho")
    if "--no-long2" not in sys.argv:
        l2 = load_long2()
        tr = {k: np.concatenate([tr[k], l2[k]]) for k in tr}
        print(f"long-patch rows (with mirrors): {len(l2['aob'])}", flush=True)
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
