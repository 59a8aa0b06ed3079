#!/usr/bin/env python3
"""Capacity / representation experiment for the rolling surrogate (measurement only).

Base: the reach + 1-D strip base of tools/fit_rolling_long.py with /tmp/roll/reach_prm_long.npy.
Everything fitted on the training rows (with mirrors, + long2 rows); the held-out set only measured.

    tools/rolling_capacity/run_base.sh    # the /tmp/roll caches (≈ 10 min on a fresh machine)
    nice -n 10 "$(tools/venv.sh)" tools/rolling_capacity/cap.py prep   # from the repository root; outputs in /tmp/cap
    ... cap.py worst            # step 1: top-50 training rows of the reference 'log' correction
    ... cap.py feat  [names]    # step 2: feature variants (degree-3 ridge, 5-fold by patch)
    ... cap.py gate             # step 3: regime split by σ / ρ
    ... cap.py mlp H [decay] [iters]   # step 4: MLP on the residual, τ²(1−τ) factor
"""
import math
import pathlib
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
sys.argv += ["--fs-features", "--sigma"]  # features() flags, as fit_rolling_long
import fit_rolling_long as L  # noqa: E402
import fit_rolling_reach as R  # noqa: E402
import fit_rolling_surrogate as F  # noqa: E402

OUT = pathlib.Path("/tmp/cap")
OUT.mkdir(parents=True, exist_ok=True)
PREP = OUT / "prep.npz"
KEYS = ["aob", "theta", "nu", "nl", "s", "ref", "err", "k", "lin", "fs"]


def fs_shifted(d, prm):
    """W_fs at the shifted spin pole (as R.reach computes it, 48×96 quadrature)."""
    q = R.Quad()
    out = []
    for lo in range(0, len(d["aob"]), 2000):
        dd = {k: v[lo:lo + 2000] for k, v in d.items()}
        kxi, kap = R.pole_shift(prm, dd, R.sigma_major(dd))
        s = dd["s"].copy()
        sg = np.sign(s[:, 2]) * dd["nl"]
        s[:, 1] -= kap * sg
        s[:, 0] -= kxi * sg
        out.append(q.wrench(q.geometry(dd), s))
    return np.concatenate(out)


def prep():
    c = L.reach_cache()
    tr, ho = R.split(c, "tr"), R.split(c, "ho")
    l2 = L.load_long2()
    tr = {k: np.concatenate([tr[k], l2[k]]) for k in tr}
    prm = np.load("/tmp/roll/reach_prm_long.npy")
    out = {}
    for tag, d in [("tr", tr), ("ho", ho)]:
        t0 = time.time()
        b = L.base_of(d, prm, strip=True)
        fss = fs_shifted(d, prm)
        for k in KEYS:
            out[f"{tag}_{k}"] = d[k]
        out[f"{tag}_base"], out[f"{tag}_rho"], out[f"{tag}_lam"] = b
        out[f"{tag}_fss"] = fss
        print(tag, len(d["aob"]), f"{time.time() - t0:.0f} s", flush=True)
    np.savez(PREP, **out)


def load():
    c = dict(np.load(PREP))
    return R.split(c, "tr"), R.split(c, "ho")


# ---------------------------------------------------------------- features

def base_feats(d):
    """fit_rolling_long 'log' features (13) and the factor τ²(1 − τ)."""
    x, fac = F.features(d, d["lin"], d["rho"], d["fs"])
    return np.column_stack([x, 2 * d["lam"] - 1]), fac


def pole_feats(d):
    """The spin pole in the patch's own normalised axes (p along a, q along b; elliptic radius 1 on the
    edge), bounded p/√(1+p²), q/√(1+q²) (sign jumps with φ through 0: at φ → 0 the pole is at infinity)."""
    s = d["s"]
    a0 = np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    x, y = -s[:, 1], s[:, 0]
    u, v = (x * ct + y * st) / a0, (-x * st + y * ct) * a0  # pole × φ, normalised
    ph = s[:, 2]
    pu = u * np.sign(ph) / np.sqrt(ph * ph + u * u + 1e-300)
    pv = v * np.sign(ph) / np.sqrt(ph * ph + v * v + 1e-300)
    return np.column_stack([pu, pv])


def unit_creep(d):
    """(φ, pole×φ) in the patch's normalised axes, as a unit vector (continuous; its first entry² = σ)."""
    s = d["s"]
    a0 = np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    x, y = -s[:, 1], s[:, 0]
    u, v = (x * ct + y * st) / a0, (-x * st + y * ct) * a0
    n = np.sqrt(s[:, 2] ** 2 + u * u + v * v) + 1e-300
    return np.column_stack([s[:, 2] / n, u / n, v / n])


def feat_set(d, extra):
    x, fac = base_feats(d)
    cols = [x]
    if "wb" in extra:
        cols.append(d["base"])
    if "fss" in extra:
        cols.append(d["fss"])
    if "pole" in extra:
        cols.append(pole_feats(d))
    if "uc" in extra:
        cols.append(unit_creep(d))
    if "lnrho" in extra:
        lr = np.log(np.maximum(d["rho"], 1e-12))
        cols.append((lr / np.sqrt(1 + lr * lr))[:, None])
    if "rbf" in extra:  # bumps in ln ρ at the knee (ρ = 0.7, 1.2, 2, 3.5; width 0.35 in ln ρ)
        lr = np.log(np.maximum(d["rho"], 1e-12))
        cols.append(np.column_stack([np.exp(-((lr - math.log(c)) / 0.35) ** 2) for c in (0.7, 1.2, 2.0, 3.5)]))
    if "talign" in extra:
        cols.append(L.aligned_t(d)[:, None])
    return np.column_stack(cols), fac


# ---------------------------------------------------------------- ridge in chunks, k-fold by patch

def folds(tr, kf=5):
    g = L.groups(tr)
    return np.random.default_rng(5).permutation(g.max() + 1)[g] % kf


def gram(blocks, res, fold, kf, chunk=4000, w=None):
    """Per fold: AᵀA and Aᵀres, blocks(lo, hi) → design rows (w: row weights)."""
    G = rr = None
    for lo in range(0, len(res), chunk):
        a = blocks(lo, lo + chunk)
        if w is not None:
            a = a * np.sqrt(w[lo:lo + chunk])[:, None]
        f = fold[lo:lo + chunk]
        if G is None:
            G = np.zeros((kf, a.shape[1], a.shape[1]))
            rr = np.zeros((kf, a.shape[1], 3))
        for k in range(kf):
            m = f == k
            if m.any():
                G[k] += a[m].T @ a[m]
                rr[k] += a[m].T @ (res[lo:lo + chunk][m] * (1.0 if w is None else np.sqrt(w[lo:lo + chunk][m])[:, None]))
    return G, rr


def ridge(G, r, n, lam):
    sc = np.maximum(np.sqrt(np.diag(G) / n), 1e-12)
    Gn = G / np.outer(sc, sc)
    return np.linalg.solve(Gn + lam * n * np.eye(len(sc)), r / sc[:, None]) / sc[:, None]


def stats(ef, em):
    return dict(wF=ef.max(), wM=em.max(), mF=np.median(ef), mM=np.median(em), qF=np.quantile(ef, .95),
                qM=np.quantile(em, .95))


def fmt(st):
    return (f"{st['wF']:.3f}/{st['wM']:.3f} (med {st['mF']:.4f}/{st['mM']:.4f}, 95% {st['qF']:.3f}/{st['qM']:.3f})")


def lam_arg():
    for a in sys.argv:
        if a.startswith("lam="):
            return float(a[4:])
    return 1e-4


def evaluate(tr, ho, blocks_tr, blocks_ho, lam=None, kf=5, name="", predict_only=False):
    lam = lam_arg() if lam is None else lam
    name = name + ("" if lam == 1e-4 else f" ridge {lam:g}")
    res = tr["ref"] - tr["base"]
    n = len(res)
    fold = folds(tr, kf)
    t0 = time.time()
    G, r = gram(blocks_tr, res, fold, kf)
    Gt, rt = G.sum(0), r.sum(0)
    coef = ridge(Gt, rt, n, lam)
    rounds = int(([a[7:] for a in sys.argv if a.startswith("lawson=")] or ["0"])[0])
    if rounds:  # Lawson reweighting towards the minimax fit (weights from the full training fit; used in the folds too)
        w = np.ones(n)
        for _ in range(rounds):
            p = np.concatenate([blocks_tr(lo, lo + 4000) @ coef for lo in range(0, n, 4000)])
            ef, em = F.errors(tr["base"] + p, tr["ref"])
            w = w * (0.5 + np.maximum(ef / 0.03, em / 0.05))
            w = w / w.mean()
            G, r = gram(blocks_tr, res, fold, kf, w=w)
            Gt, rt = G.sum(0), r.sum(0)
            coef = ridge(Gt, rt, n, lam)
            print(f"    lawson: worst {ef.max():.3f}/{em.max():.3f}", flush=True)
        name = name + f" lawson{rounds}"
        out_name = name
    ptr = np.concatenate([blocks_tr(lo, lo + 4000) @ coef for lo in range(0, n, 4000)])
    pho = blocks_ho(0, len(ho["aob"])) @ coef
    out = dict(name=name, terms=G.shape[1])
    out["train"] = stats(*F.errors(tr["base"] + ptr, tr["ref"]))
    who, npro = F.passive(ho["base"] + pho, ho)
    out["ho"] = stats(*F.errors(who, ho["ref"]))
    out["npro"] = npro
    if kf > 1:
        cs = [ridge(Gt - G[k], rt - r[k], int((fold != k).sum()), lam) for k in range(kf)]
        pv = np.zeros_like(res)
        for lo in range(0, n, 4000):
            a = blocks_tr(lo, lo + 4000)
            f = fold[lo:lo + 4000]
            for k in range(kf):
                m = f == k
                pv[lo:lo + 4000][m] = a[m] @ cs[k]
        ef, em = F.errors(tr["base"] + pv, tr["ref"])
        out["cv"] = stats(ef, em)
        out["cv_e"] = np.maximum(ef / 0.03, em / 0.05)
    ef, em = F.errors(tr["base"] + ptr, tr["ref"])
    clean = (tr["err"][:, 0] < 0.01) & (tr["err"][:, 1] < 0.01)
    out["trc"] = (ef[clean].max(), em[clean].max(), int((~clean).sum()))
    out["tr_e"] = np.maximum(ef / 0.03, em / 0.05)
    out["coef"] = coef
    out["time"] = time.time() - t0
    return out


def report(o, fh=None):
    line = (f"| {o['name']} | {o['terms']} | {fmt(o['train'])} | " + (fmt(o['cv']) if 'cv' in o else '-') +
            f" | {fmt(o['ho'])} | {o['npro']} |" +
            (f" clean-ref train worst {o['trc'][0]:.3f}/{o['trc'][1]:.3f} (excl. {o['trc'][2]})" if 'trc' in o else ""))
    print(line, flush=True)
    if fh:
        with open(fh, "a") as f:
            f.write(line + "\n")


def rel_arg():
    for a in sys.argv:
        if a.startswith("rel="):
            return int(a[4:])
    return None


def poly_blocks(d, extra, degree=3, gates=None, gate_degree=None, rel=None):
    """Design rows for lo:hi: degree-`degree` polynomial × fac; gates: list of weight arrays, each
    multiplying a further full copy of the polynomial (degree gate_degree)."""
    x, fac = feat_set(d, extra)
    mons = F.monomials(x.shape[1], degree)
    gm = F.monomials(x.shape[1], gate_degree or degree)
    rel = rel_arg() if rel is None else rel
    if rel is not None:  # relative block: P_k(x)·τ²·(W_base − W_fs)_k, k = 1..3 (O(ρ²) at 0, → 0 at full slip)
        rm = F.monomials(x.shape[1], rel)
        tau = d["rho"] / (1 + d["rho"])
        dd = (d["base"] - d["fs"]) * (tau * tau)[:, None]

    def blocks(lo, hi):
        a = F.design(x[lo:hi], fac[lo:hi], mons)
        if gates:
            a = np.column_stack([a] + [F.design(x[lo:hi], fac[lo:hi] * g[lo:hi], gm) for g in gates])
        if rel is not None:
            a = np.column_stack([a] + [F.design(x[lo:hi], dd[lo:hi, k], rm) for k in range(3)])
        return a
    return blocks


# ---------------------------------------------------------------- step 1

def worst():
    tr, ho = load()
    o = evaluate(tr, ho, poly_blocks(tr, []), poly_blocks(ho, []), name="log (reference)")
    report(o)
    sig = F.spin_share(tr)
    t = L.aligned_t(tr)
    rx = (1 + t) / (1 - t)
    r = np.where(tr["aob"] >= 1, tr["aob"], 1 / tr["aob"])
    psi = np.degrees(np.where(tr["aob"] >= 1, tr["theta"], tr["theta"] + 0.5 * np.pi)) % 180
    psi = np.minimum(psi, 180 - psi)  # angle of the major axis to the rolling direction, 0..90
    ef, em = F.errors(tr["base"] + np.concatenate(
        [poly_blocks(tr, [])(lo, lo + 4000) @ o["coef"] for lo in range(0, len(tr["aob"]), 4000)]), tr["ref"])
    e = o["tr_e"]
    efb, emb = F.errors(tr["base"], tr["ref"])
    idx = np.argsort(-e)[:50]
    lines = ["| # | ΔF | ΔM | base ΔF/ΔM | a/b | a/b along x | ψ major∠x | ν | nl | σ | ρ | λ | source |", "|" + "---|" * 13]
    nt = 19380
    for i, j in enumerate(idx):
        lines.append(f"| {i} | {ef[j]:.3f} | {em[j]:.3f} | {efb[j]:.3f}/{emb[j]:.3f} | {r[j]:.2f} | {rx[j]:.2f} | {psi[j]:.0f} | "
                     f"{tr['nu'][j]:.2f} | {tr['nl'][j]:.3g} | {sig[j]:.2f} | {tr['rho'][j]:.2f} | {tr['lam'][j]:.2f} | "
                     f"{'long2' if j >= nt else 'main'} |")
    # distributions: all rows vs top 50 vs top 500 (by e), and the exceedance by bins
    def dist(name, v, bins):
        h_all = np.histogram(v, bins)[0]
        h50 = np.histogram(v[idx], bins)[0]
        h500 = np.histogram(v[np.argsort(-e)[:500]], bins)[0]
        ex = [(e[(v >= lo) & (v < hi)] > 1).mean() if ((v >= lo) & (v < hi)).any() else 0 for lo, hi in zip(bins[:-1], bins[1:])]
        mx = [e[(v >= lo) & (v < hi)].max() if ((v >= lo) & (v < hi)).any() else 0 for lo, hi in zip(bins[:-1], bins[1:])]
        return [f"**{name}** bins {np.round(bins, 3).tolist()}", f"  all {h_all.tolist()}", f"  top50 {h50.tolist()}",
                f"  top500 {h500.tolist()}", f"  share e>1 {np.round(ex, 3).tolist()}", f"  max e {np.round(mx, 2).tolist()}"]
    lines.append("")
    lines += dist("σ", sig, np.array([0, 0.05, 0.2, 0.4, 0.5, 0.6, 0.8, 0.95, 1.0001]))
    lines += dist("ρ", tr["rho"], np.array([0, 0.3, 0.7, 1, 1.5, 2, 3, 5, 10, 1e9]))
    lines += dist("a/b along x", rx, np.array([0, 0.1, 0.25, 0.5, 1, 2, 4, 8, 12, 1e9]))
    lines += dist("major a/b", r, np.array([1, 1.5, 2.5, 5, 10, 15, 1e9]))
    lines += dist("ψ (°)", psi, np.array([0, 10, 30, 60, 80, 90.01]))
    lines += dist("ν", tr["nu"], np.array([0, 0.1, 0.2, 0.3, 0.4, 0.51]))
    lines += dist("nl", tr["nl"], np.quantile(tr["nl"], [0, .2, .4, .6, .8, 1.0]) + np.array([0, 0, 0, 0, 0, 1e-9]))
    lines.append(f"rows with e>1 (training fit): {(e > 1).sum()} / {len(e)}; 5-fold: {(o['cv_e'] > 1).sum()}")
    txt = "\n".join(lines)
    print(txt)
    (OUT / "worst.md").write_text(txt + "\n")
    np.save(OUT / "ref_tr_e.npy", e)


# ---------------------------------------------------------------- step 2

def feat(names):
    tr, ho = load()
    hdr = "| variant | terms/output | training worst ΔF/ΔM | 5-fold worst | held-out worst | proj |"
    print(hdr, flush=True)
    variants = {"log": [], "+wb": ["wb"], "+fss": ["fss"], "+pole": ["pole"], "+uc": ["uc"], "+lnrho": ["lnrho"],
                "+wb+fss": ["wb", "fss"], "+all": ["wb", "fss", "pole", "lnrho"], "+all+uc": ["wb", "fss", "pole", "lnrho", "uc"],
                "+wb+fss+uc+lnrho": ["wb", "fss", "uc", "lnrho"],
                "+wb+rbf": ["wb", "rbf"], "+wb+fss+rbf": ["wb", "fss", "rbf"]}
    for nm in names or list(variants):
        ex = variants[nm]
        deg = 3
        deg = int(([a[4:] for a in sys.argv if a.startswith("deg=")] or ["3"])[0])
        o = evaluate(tr, ho, poly_blocks(tr, ex, deg), poly_blocks(ho, ex, deg),
                     name=nm + ("" if deg == 3 else f" deg{deg}") + ("" if rel_arg() is None else f" + rel{rel_arg()}×3"))
        report(o, OUT / "feat.md")
        np.save(OUT / f"cv_e_{nm}.npy", o["cv_e"])


# ---------------------------------------------------------------- step 3

def smooth(z):
    return 1.0 / (1.0 + np.exp(-z))


def gate(names):
    tr, ho = load()
    extra = [a for a in sys.argv if a.startswith("extra=")]
    ex = extra[0][6:].split(",") if extra else []
    gdeg = 3
    for a in sys.argv:
        if a.startswith("gdeg="):
            gdeg = int(a[5:])

    def gates(d, kind):
        sig = F.spin_share(d)
        lr = np.log(np.maximum(d["rho"], 1e-12))
        gs = smooth(12 * (sig - 0.5))  # pole inside
        if kind == "sigma":
            return [gs]
        if kind == "rho":
            return [smooth(3 * (lr - math.log(1.5)))]
        if kind == "sigma+rho":
            return [gs, smooth(3 * (lr - math.log(1.5)))]
        if kind == "sigma3":  # three σ bands: outside / near edge / inside
            return [smooth(12 * (sig - 0.3)), smooth(12 * (sig - 0.7))]
        if kind == "long":
            return [L.long_weight(d)]
        if kind == "sigma+long":
            return [gs, L.long_weight(d)]
        raise KeyError(kind)
    for kind in names or ["sigma", "rho", "sigma+rho"]:
        o = evaluate(tr, ho, poly_blocks(tr, ex, 3, gates(tr, kind), gdeg), poly_blocks(ho, ex, 3, gates(ho, kind), gdeg),
                     name=f"gate {kind} deg{gdeg} extra {','.join(ex) or '-'}")
        report(o, OUT / "gate.md")


# ---------------------------------------------------------------- step 4

def mlp():
    h = int(sys.argv[2])
    wd = float(sys.argv[3]) if len(sys.argv) > 3 and not sys.argv[3].startswith("-") else 1e-6
    iters = int(sys.argv[4]) if len(sys.argv) > 4 and not sys.argv[4].startswith("-") else 3000
    extra = [a for a in sys.argv if a.startswith("extra=")]
    ex = extra[0][6:].split(",") if extra else []
    kf = 5 if "cv" in sys.argv else 0
    tr, ho = load()
    xt, ft = feat_set(tr, ex)
    xh, fh = feat_set(ho, ex)
    res = tr["ref"] - tr["base"]
    t0 = time.time()
    th = F.mlp_fit(xt, ft, res, h, wd, iters=iters)
    ptr = ft[:, None] * F.mlp_apply(th, xt, h)[0]
    pho = fh[:, None] * F.mlp_apply(th, xh, h)[0]
    who, npro = F.passive(ho["base"] + pho, ho)
    o = dict(name=f"MLP {h}x{h} decay {wd:g} iters {iters} extra {','.join(ex) or '-'}", terms=F.mlp_size(xt.shape[1], h),
             train=stats(*F.errors(tr["base"] + ptr, tr["ref"])), ho=stats(*F.errors(who, ho["ref"])), npro=npro)
    print(f"fit {time.time() - t0:.0f} s", flush=True)
    if kf:
        fold = folds(tr, kf)
        pv = np.zeros_like(res)
        for k in range(kf):
            t = fold != k
            thk = F.mlp_fit(xt[t], ft[t], res[t], h, wd, iters=iters)
            pv[~t] = ft[~t, None] * F.mlp_apply(thk, xt[~t], h)[0]
            print(f"  fold {k} {time.time() - t0:.0f} s", flush=True)
        o["cv"] = stats(*F.errors(tr["base"] + pv, tr["ref"]))
    report(o, OUT / "mlp.md")
    np.save(OUT / f"mlp_{h}_{wd:g}_{iters}_{'-'.join(ex) or 'none'}.npy", th)


if __name__ == "__main__":
    cmd = sys.argv[1]
    names = [a for a in sys.argv[2:] if not a.startswith("-") and "=" not in a and a != "cv"]
    if cmd == "prep":
        prep()
    elif cmd == "worst":
        worst()
    elif cmd == "feat":
        feat(names)
    elif cmd == "gate":
        gate(names)
    elif cmd == "mlp":
        mlp()


# ---------------------------------------------------------------- step 4b: own MLP fit (weighted / Lp loss, progress)

def mlp2_fit(x, fac, res, h, lam, iters, p=2, seed=1, log=None, theta0=None):
    """fac·MLP(x) against res, loss mean(((r_F/0.03)² + (r_M/0.05)²)^(p/2)) (p = 2: weighted least squares;
    p > 2 leans towards the worst rows), tanh, two hidden layers, L-BFGS, weight decay lam."""
    from scipy.optimize import minimize
    rng = np.random.default_rng(seed)
    nin = x.shape[1]
    if theta0 is None:
        ws = F.mlp_unpack(rng.normal(0, 1, F.mlp_size(nin, h)), nin, h)
        ws[0] /= np.sqrt(nin); ws[2] /= np.sqrt(h); ws[4] *= 0.01 / np.sqrt(h)
        for b in (ws[1], ws[3], ws[5]):
            b[:] = 0
        theta0 = np.concatenate([w.ravel() for w in ws])
    n = len(x)
    sc = np.array([1 / 0.03, 1 / 0.03, 1 / 0.05])
    it = [0]
    t0 = time.time()

    def f(theta):
        w1, b1, w2, b2, w3, b3 = F.mlp_unpack(theta, nin, h)
        a1 = np.tanh(x @ w1 + b1)
        a2 = np.tanh(a1 @ w2 + b2)
        y = a2 @ w3 + b3
        r = (fac[:, None] * y - res) * sc
        q = r[:, 0] ** 2 + r[:, 1] ** 2 + r[:, 2] ** 2
        if p == 2:
            loss = q.sum() / n
            gr = 2 * r / n
        else:
            loss = (q ** (p / 2)).sum() / n
            gr = (p * q ** (p / 2 - 1))[:, None] * r / n
        gy = gr * sc * fac[:, None]
        grad = F.mlp_grad(theta, x, h, gy, (a1, a2), lam)
        return loss + lam * (theta * theta).sum(), grad

    def cb(th):
        it[0] += 1
        if log and it[0] % 500 == 0:
            print(f"    iter {it[0]} loss {f(th)[0]:.4g} {time.time() - t0:.0f} s", flush=True)
    return minimize(f, theta0, jac=True, method="L-BFGS-B", callback=cb, options=dict(maxiter=iters, maxfun=2 * iters)).x


def mlp2():
    h = int(sys.argv[2])
    kv = dict(a.split("=") for a in sys.argv[3:] if "=" in a)
    wd, iters, p = float(kv.get("decay", 1e-7)), int(kv.get("iters", 3000)), float(kv.get("p", 2))
    ex = kv["extra"].split(",") if kv.get("extra") else []
    cont = int(kv.get("cont", 0))  # Lp continuation: first p = 2, then p
    kf = int(kv.get("kf", 0))
    tr, ho = load()
    xt, ft = feat_set(tr, ex)
    xh, fh = feat_set(ho, ex)
    res = tr["ref"] - tr["base"]
    t0 = time.time()

    def fitp(x, f, r):
        if cont:
            th = mlp2_fit(x, f, r, h, wd, iters, 2, log=True)
            return mlp2_fit(x, f, r, h, wd, cont, p, log=True, theta0=th)
        return mlp2_fit(x, f, r, h, wd, iters, p, log=True)
    th = fitp(xt, ft, res)
    ptr = ft[:, None] * F.mlp_apply(th, xt, h)[0]
    pho = fh[:, None] * F.mlp_apply(th, xh, h)[0]
    who, npro = F.passive(ho["base"] + pho, ho)
    ef, em = F.errors(tr["base"] + ptr, tr["ref"])
    clean = (tr["err"][:, 0] < 0.01) & (tr["err"][:, 1] < 0.01)
    o = dict(name=f"MLP2 {h}x{h} weighted p={p:g}{' (cont from p=2)' if cont else ''} decay {wd:g} iters {iters}+{cont} extra {','.join(ex) or '-'}",
             terms=F.mlp_size(xt.shape[1], h), train=stats(ef, em), ho=stats(*F.errors(who, ho["ref"])), npro=npro,
             trc=(ef[clean].max(), em[clean].max(), int((~clean).sum())))
    print(f"fit {time.time() - t0:.0f} s", flush=True)
    np.save(OUT / f"mlp2_{h}_p{p:g}_{'-'.join(ex) or 'none'}.npy", th)
    if kf:
        fold = folds(tr, kf)
        pv = np.zeros_like(res)
        for k in range(kf):
            t = fold != k
            thk = fitp(xt[t], ft[t], res[t])
            pv[~t] = ft[~t, None] * F.mlp_apply(thk, xt[~t], h)[0]
            print(f"  fold {k} {time.time() - t0:.0f} s", flush=True)
        o["cv"] = stats(*F.errors(tr["base"] + pv, tr["ref"]))
    report(o, OUT / "mlp.md")


if __name__ == "__main__" and sys.argv[1] == "mlp2":
    mlp2()
