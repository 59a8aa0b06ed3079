#!/usr/bin/env python3
"""Prototype of a rolling law over the whole domain: a base law exact at both limits (the linear
creep matrix of the real, possibly skewed patch composed with the exact full slip of that patch)
plus a least-squares correction surface, fitted on a TRAINING set drawn from the exact
steady-rolling solver with another seed than the held-out set, and measured on the held-out set
(tools/data/rolling_ref_heldout.csv, seed 29: never fitted on).

Inputs
- training: tools/rolling_exact `--example heldout -- OUT FIRST LAST SEED` with SEED ≠ 29 (family
  `train`; the same distribution as the held-out set), files given by --train (default
  tools/data/rolling_ref_train.csv);
- the linear creep matrix K per point: `tools/rolling_exact --example creep_k` (the library's
  CreepMatrix, within 1 % of the exact theory for any patch and skew);
- the full slip: the Contensou–Erismann integrals of the patch in the rolling frame, here by
  quadrature (traction −f·p·ŵ, w = (ξ − φy, η + φx) the rigid slip; Gauss–Legendre in the
  polar angle of the unit disk mapped on the skewed ellipse, 48 × 96 nodes).

Normalisation (as the reference: c = √(ab) = 1, G = 1, f = 1, N/(Gc²) = nl): W = (F_x/fN,
F_y/fN, M_z/(fNc)); the linear wrench W_lin = −K·(ξ, η, φc)/nl.

Base law (`base`): ρ = |W_lin|/|W_fs| (how many full-slip wrenches the linear wrench amounts
to), g(ρ) = 1 − (1 − ρ/3)³ for ρ < 3 else 1 (Johnson–Vermeulen),
h(ρ) = (1 − ρ/3)³ for ρ < 3 else 0:
    W = g(ρ)·W_fs + h(ρ)·(W_lin − ρ·W_fs).
Small creepage: W = W_lin + O(ρ²) (the linear theory, exact tangent); ρ ≥ 3: the full slip.

Correction (`surrogate`): W += τ²(1 − τ)·P(x), τ = ρ/(1 + ρ), P a polynomial (ridge least
squares) in the features x: the patch's ln(major/minor)/ln 20, the rolling direction's angle ψ to
the major axis (cos 2ψ, sin 2ψ), ν, the unit direction of the linear wrench (3) and τ. The factor
keeps both limits: O(ρ²) at small creepage, → 0 at full slip.

    python3 tools/fit_rolling_surrogate.py [--train FILE ...] [--degree D] [--md OUT]
"""
import math
import pathlib
import subprocess
import sys

import numpy as np

root = pathlib.Path(__file__).resolve().parent.parent
HELDOUT = root / "tools/data/rolling_ref_heldout.csv"
CREEP_K = root / "tools/rolling_exact/target/release/examples/creep_k"


def args(name, default):
    if name not in sys.argv:
        return default
    i = sys.argv.index(name) + 1
    out = []
    while i < len(sys.argv) and not sys.argv[i].startswith("--"):
        out.append(sys.argv[i])
        i += 1
    return out


def read(paths):
    rows = []
    for path in paths:
        for line in pathlib.Path(path).read_text().splitlines():
            if not line or line[0] == "#" or line.startswith("family"):
                continue
            f = line.split(",")
            if len(f) == 12:  # the aligned files (no θ, all converged): θ = 0
                f = f[:2] + ["0"] + f[2:] + ["1"]
            elif len(f) < 15 or f[13] != "1":
                continue  # unconverged or cut short
            rows.append([float(x) for x in f[1:13]])
    a = np.array(rows)
    return dict(aob=a[:, 0], theta=np.radians(a[:, 1]), nu=a[:, 2], nl=a[:, 3], s=a[:, 4:7],
                ref=a[:, 7:10], err=a[:, 10:12])


def mirrored(d):
    """d and its mirror image y → −y (the patch's axis at −θ, (ξ, η, φ) → (ξ, −η, −φ), the wrench
    (F_x, −F_y, −M_z)): the exact theory's symmetry, twice the training points."""
    flip = np.array([1.0, -1.0, -1.0])
    m = dict(aob=d["aob"], theta=np.mod(-d["theta"], np.pi), nu=d["nu"], nl=d["nl"], s=d["s"] * flip,
             ref=d["ref"] * flip, err=d["err"])
    return {k: np.concatenate([d[k], m[k]]) for k in d}


def creep_k(d):
    text = "".join(f"{float(a)!r} {math.degrees(t)!r} {float(n)!r}\n" for a, t, n in zip(d["aob"], d["theta"], d["nu"]))
    if not CREEP_K.exists():
        subprocess.run(["cargo", "build", "--release", "--example", "creep_k"], cwd=CREEP_K.parents[3], check=True)
    out = subprocess.run([str(CREEP_K)], input=text, capture_output=True, text=True, check=True).stdout
    return np.array([[float(x) for x in l.split(",")] for l in out.split()]).reshape(-1, 3, 3)


def full_slip(d, nr=48, nt=96):
    """W_fs: the Contensou–Erismann integrals of the (skewed) Hertz patch in the rolling frame."""
    al, wa = np.polynomial.legendre.leggauss(nr)
    al = 0.25 * np.pi * (al + 1.0)  # ρ = sin α, α ∈ [0, π/2]
    wa = 0.25 * np.pi * wa * np.cos(al) ** 2 * np.sin(al)  # √(1 − ρ²)·ρ dρ = cos²α sin α dα
    t = (np.arange(nt) + 0.5) * 2 * np.pi / nt
    rho = np.sin(al)[:, None]
    u, v = (rho * np.cos(t)).ravel(), (rho * np.sin(t)).ravel()
    w = np.repeat(wa, nt)
    w = w / w.sum()
    a0, b0 = np.sqrt(d["aob"]), 1.0 / np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    x = ct[:, None] * a0[:, None] * u - st[:, None] * b0[:, None] * v
    y = st[:, None] * a0[:, None] * u + ct[:, None] * b0[:, None] * v
    xi, eta, phi = (d["s"][:, i:i + 1] for i in range(3))
    sx, sy = xi - phi * y, eta + phi * x
    n = np.hypot(sx, sy)
    n = np.where(n > 0, n, 1.0)
    tx, ty = -sx / n, -sy / n
    return np.stack([(tx * w).sum(1), (ty * w).sum(1), ((x * ty - y * tx) * w).sum(1)], axis=1)


def linear(d, k):
    """W_lin = −K·(ξ, η, φc)/nl."""
    return -np.einsum("nij,nj->ni", k, d["s"]) / d["nl"][:, None]


def base(lin, fs, prm):
    """The base law: magnitude |W_fs|·g(ρ), direction from the linear wrench's towards the full
    slip's; ρ = |W_lin|/|W_fs|, g(ρ) = ρ/(1 + ρⁿ)^(1/n), λ = (ρ/ρ₀)^m/(1 + (ρ/ρ₀)^m)."""
    rho0, n, m = prm
    ml, mf = np.linalg.norm(lin, axis=1), np.maximum(np.linalg.norm(fs, axis=1), 1e-12)
    rho = ml / mf
    g = rho / (1.0 + rho ** n) ** (1.0 / n)
    lam = (rho / rho0) ** m / (1.0 + (rho / rho0) ** m)
    u = (1.0 - lam)[:, None] * lin / np.maximum(ml, 1e-300)[:, None] + lam[:, None] * fs / mf[:, None]
    u /= np.maximum(np.linalg.norm(u, axis=1), 1e-300)[:, None]
    return (g * mf)[:, None] * u, rho


def fit_base(lin, fs, ref):
    """(ρ₀, n, m) minimising the 95 % quantile of max(ΔF, ΔM) on the training set."""
    from scipy.optimize import minimize

    def score(prm):
        if min(prm) <= 0.05 or prm[1] > 8:
            return 1e9
        ef, em = errors(base(lin, fs, prm)[0], ref)
        return np.quantile(np.maximum(ef, em), 0.95)

    fits = [minimize(score, x0, method="Nelder-Mead", options=dict(maxiter=300))
            for x0 in [(1.0, 2.0, 2.0), (3.0, 1.5, 1.0), (5.0, 3.0, 2.0)]]
    return min(fits, key=lambda r: r.fun).x


def spin_share(d):
    """σ = φ²/(φ² + R²φ²) = 1/(1 + R²), R the elliptic radius of the spin pole (the point where the rigid
    slip (ξ − φy, η + φx) vanishes: x = −η/φ, y = ξ/φ) in the patch's own axes (R = 1 on the patch's edge):
    1 for pure spin, ½ with the pole on the edge, → 0 without spin. With the pole inside the patch a stuck
    zone around it survives any creepage and the wrench approaches full slip slowly (a 1/ρ tail); with
    the pole outside the patch translation-like creep saturates at a finite ρ ≈ 3."""
    s = d["s"]
    a0 = np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    x, y = -s[:, 1], s[:, 0]  # the pole times φ
    u, v = x * ct + y * st, -x * st + y * ct
    q = u * u / a0 ** 2 + v * v * a0 ** 2
    phi2 = s[:, 2] ** 2
    return phi2 / np.maximum(phi2 + q, 1e-300)


def features(d, lin, rho, fs):
    """x: the correction's features; fac: the factor that keeps both limits."""
    r = np.where(d["aob"] >= 1.0, d["aob"], 1.0 / d["aob"])
    psi = np.where(d["aob"] >= 1.0, d["theta"], d["theta"] + 0.5 * np.pi)  # major axis from x
    u = lin / np.linalg.norm(lin, axis=1)[:, None]
    tau = rho / (1.0 + rho)
    x = np.column_stack([np.log(r) / math.log(20.0), np.cos(2 * psi), np.sin(2 * psi), 2 * d["nu"],
                         u[:, 0], u[:, 1], u[:, 2], tau])
    if "--fs-features" in sys.argv:  # + the full slip's wrench
        x = np.column_stack([x, fs])
    if "--sigma" in sys.argv:  # + the spin pole's share 2σ − 1 (see spin_share)
        x = np.column_stack([x, 2.0 * spin_share(d) - 1.0])
    if "--no-full-slip-factor" in sys.argv:  # diagnostic only: not exact at full slip
        return x, tau ** 2
    return x, tau ** 2 * (1.0 - tau)


def monomials(nvar, degree):
    out = [()]
    for deg in range(1, degree + 1):
        def rec(start, left, cur):
            if left == 0:
                out.append(tuple(cur))
                return
            for i in range(start, nvar):
                rec(i, left - 1, cur + [i])
        rec(0, deg, [])
    return out


def design(x, fac, mons):
    cols = [np.prod(x[:, list(m)], axis=1) if m else np.ones(len(x)) for m in mons]
    return np.column_stack(cols) * fac[:, None]


def mlp_unpack(theta, nin, h):
    shapes = [(nin, h), (h,), (h, h), (h,), (h, 3), (3,)]
    out, k = [], 0
    for sh in shapes:
        n = int(np.prod(sh))
        out.append(theta[k:k + n].reshape(sh))
        k += n
    return out


def mlp_size(nin, h):
    return nin * h + h + h * h + h + 3 * h + 3


def mlp_apply(theta, x, h):
    w1, b1, w2, b2, w3, b3 = mlp_unpack(theta, x.shape[1], h)
    a1 = np.tanh(x @ w1 + b1)
    a2 = np.tanh(a1 @ w2 + b2)
    return a2 @ w3 + b3, (a1, a2)


def mlp_grad(theta, x, h, gy, hidden, lam):
    """The gradient of a loss over the parameters from its gradient gy over the outputs (backprop through
    mlp_apply's two tanh layers), plus the weight decay 2·lam·theta."""
    w1, b1, w2, b2, w3, b3 = mlp_unpack(theta, x.shape[1], h)
    a1, a2 = hidden
    gw3, gb3 = a2.T @ gy, gy.sum(0)
    g2 = (gy @ w3.T) * (1 - a2 * a2)
    gw2, gb2 = a1.T @ g2, g2.sum(0)
    g1 = (g2 @ w2.T) * (1 - a1 * a1)
    gw1, gb1 = x.T @ g1, g1.sum(0)
    return np.concatenate([g.ravel() for g in (gw1, gb1, gw2, gb2, gw3, gb3)]) + 2 * lam * theta


def mlp_fit(x, fac, res, h, lam, seed=1, iters=3000):
    """Least squares of fac·MLP(x) against res (tanh, two hidden layers of h), L-BFGS, weight decay lam."""
    from scipy.optimize import minimize
    rng = np.random.default_rng(seed)
    nin = x.shape[1]
    theta0 = rng.normal(0, 1, mlp_size(nin, h))
    ws = mlp_unpack(theta0, nin, h)
    ws[0] /= np.sqrt(nin); ws[2] /= np.sqrt(h); ws[4] *= 0.01 / np.sqrt(h)
    for b in (ws[1], ws[3], ws[5]):
        b[:] = 0
    theta0 = np.concatenate([w.ravel() for w in ws])
    n = len(x)

    def f(theta):
        y, (a1, a2) = mlp_apply(theta, x, h)
        r = fac[:, None] * y - res
        loss = (r * r).sum() / n + lam * (theta * theta).sum()
        gy = 2 * fac[:, None] * r / n
        return loss, mlp_grad(theta, x, h, gy, (a1, a2), lam)

    return minimize(f, theta0, jac=True, method="L-BFGS-B", options=dict(maxiter=iters)).x


def passive(w, d):
    """W with its power W·(ξ, η, φc) made ≤ 0 by removing its component along the creepages where
    it is positive (the projection the Rust law would use); the number of points projected."""
    sv = d["s"]
    pw = (w * sv).sum(1)
    bad = pw > 0
    w = w - np.where(bad, pw / np.maximum((sv * sv).sum(1), 1e-300), 0.0)[:, None] * sv
    return w, int(bad.sum())


def errors(w, ref):
    return np.hypot(w[:, 0] - ref[:, 0], w[:, 1] - ref[:, 1]), np.abs(w[:, 2] - ref[:, 2])


def prepare(d):
    k = creep_k(d)
    return dict(k=k, fs=full_slip(d), lin=linear(d, k))


def finish(d, p, prm):
    p["base"], p["rho"] = base(p["lin"], p["fs"], prm)
    p["x"], p["fac"] = features(d, p["lin"], p["rho"], p["fs"])


def family_tables(ho, laws):
    """Per family (tools/rolling_heldout.py's families), worst ΔF / ΔM (median) per law; laws: name → W."""
    sys.path.insert(0, str(root / "tools"))
    import rolling_heldout as rh
    rows = [dict(aob=a, theta=t, nu=n) for a, t, n in zip(ho["aob"], ho["theta"], ho["nu"])]
    fams = [rh.families(r, d, q) for r, (_, d, q) in zip(rows, rh.draws())]
    errs = {name: errors(w, ho["ref"]) for name, w in laws.items()}
    out = []
    for key in fams[0]:
        names = sorted({f[key] for f in fams}, key=rh._sort_key)
        out += ["", f"### By {key}", "",
                "| law | " + " | ".join(f"{nm} (n = {sum(f[key] == nm for f in fams)})" for nm in names) + " |",
                "|---|" + "---|" * len(names)]
        for law, (ef, em) in errs.items():
            cells = []
            for nm in names:
                m = np.array([f[key] == nm for f in fams])
                cells.append(f"{ef[m].max():.3f} / {em[m].max():.3f} ({np.median(ef[m]):.3f} / {np.median(em[m]):.3f})")
            out.append(f"| {law} | " + " | ".join(cells) + " |")
    fs_f, fs_m = errs["fastsim"]
    ref_e = ho["err"]
    out += ["", "Points worse than FASTSIM 32×32 (ΔF or ΔM above FASTSIM's by more than the reference's own estimate): " +
            ", ".join(f"{law} {int(np.sum((ef > fs_f + ref_e[:, 0]) | (em > fs_m + ref_e[:, 1])))}"
                      for law, (ef, em) in errs.items() if law != "fastsim")]
    return out


def diagnose(path, prm):
    """The creep curves of a family file (tools/data/rolling_diag_families.csv: magnitudes along one
    held-out point's direction): per point ρ, the exact wrench and the base's, |W|/|W_fs| (the exact
    wrench's length in units of the full slip's: > 1 is an overshoot past |W_fs|), its angle to W_fs
    and the linear wrench's, and the exact part perpendicular to W_fs over the linear one's (h)."""
    fam = read([path])
    tags = [l.split(",")[0] for l in pathlib.Path(path).read_text().splitlines()
            if l and l[0] != "#" and not l.startswith("family")]
    p = prepare(fam)
    finish(fam, p, prm)
    sig = spin_share(fam)
    out, cur = [], None
    ang = lambda u, v: math.degrees(math.acos(max(-1.0, min(1.0, u @ v / np.linalg.norm(u) / np.linalg.norm(v)))))
    for i, tag in enumerate(tags):
        name = tag.split("_")[0]
        ref, b, fs, lin = fam["ref"][i], p["base"][i], p["fs"][i], p["lin"][i]
        mf = np.linalg.norm(fs)
        uf = fs / mf
        if name != cur:
            cur = name
            out += ["", f"{name}: a/b = {fam['aob'][i]:.2f}, θ = {math.degrees(fam['theta'][i]):.0f}°, ν = {fam['nu'][i]:.2f}, "
                    f"σ = {sig[i]:.2f}, W_fs = ({fs[0]:+.3f}, {fs[1]:+.3f}, {fs[2]:+.3f}), angle(W_lin, W_fs) = {ang(lin, fs):.0f}°", "",
                    "| ρ | exact F_x, F_y, M_z | base | ΔF / ΔM (base) | exact abs(W)/abs(W_fs) | exact ∠W_fs (°) | h |",
                    "|---|---|---|---|---|---|---|"]
        pl, pe = lin - (lin @ uf) * uf, ref - (ref @ uf) * uf
        out.append(f"| {p['rho'][i]:.2f} | {ref[0]:+.3f}, {ref[1]:+.3f}, {ref[2]:+.3f} | {b[0]:+.3f}, {b[1]:+.3f}, {b[2]:+.3f} | "
                   f"{math.hypot(*(ref - b)[:2]):.3f} / {abs(ref[2] - b[2]):.3f} | {np.linalg.norm(ref) / mf:.3f} | "
                   f"{ang(ref, fs):.1f} | {np.linalg.norm(pe) / max(np.linalg.norm(pl), 1e-300):.4f} |")
    return out


def committed_laws(n):
    """The library's laws on the held-out points (tools/data/rolling_heldout_laws.csv)."""
    rows = [l.split(",") for l in (root / "tools/data/rolling_heldout_laws.csv").read_text().splitlines()
            if l and l[0].isdigit()]
    a = np.array([[float(x) for x in r] for r in rows])[:n]
    return {"table": a[:, 5:8], "fastsim": a[:, 11:14]}


def summary(name, ef, em):
    return (f"| {name} | {ef.max():.3f} | {em.max():.3f} | {np.median(ef):.4f} | {np.median(em):.4f} | "
            f"{np.quantile(ef, 0.95):.3f} | {np.quantile(em, 0.95):.3f} |")


def main():
    train_files = args("--train", [str(root / "tools/data/rolling_ref_train.csv")])
    if "--aligned" in sys.argv:  # + the committed aligned creep-curve files (never the held-out set)
        train_files += [str(p) for p in sorted((root / "tools/data").glob("rolling_ref*.csv"))
                        if p.name not in ("rolling_ref_heldout.csv", "rolling_ref_timing.csv")
                        and "train" not in p.name]
    degree = int(args("--degree", ["3"])[0])
    lam = float(args("--ridge", ["1e-4"])[0])
    tr, ho = read(train_files), read([HELDOUT])
    if "--no-mirror" not in sys.argv:
        tr = mirrored(tr)
    ptr, pho = prepare(tr), prepare(ho)
    prm = fit_base(ptr["lin"], ptr["fs"], tr["ref"])
    for d, p in [(tr, ptr), (ho, pho)]:
        finish(d, p, prm)
    lines = [f"training points: {len(tr['aob'])}, held-out points: {len(ho['aob'])}; base (ρ₀, n, m) = "
             f"({prm[0]:.3f}, {prm[1]:.3f}, {prm[2]:.3f})", "",
             "| law | worst ΔF | worst ΔM | median ΔF | median ΔM | 95 % ΔF | 95 % ΔM |", "|---|---|---|---|---|---|---|"]
    for name, w in [("full slip (quadrature)", pho["fs"]), ("base, held-out", pho["base"])]:
        lines.append(summary(name, *errors(w, ho["ref"])))
    mons = monomials(ptr["x"].shape[1], degree)
    a = design(ptr["x"], ptr["fac"], mons)
    res = tr["ref"] - ptr["base"]
    # ridge on standardised columns
    sc = np.maximum(np.sqrt((a * a).mean(0)), 1e-12)
    an = a / sc
    coef = np.linalg.solve(an.T @ an + lam * len(an) * np.eye(an.shape[1]), an.T @ res) / sc[:, None]
    fit_tr = ptr["base"] + a @ coef
    fit_ho = pho["base"] + design(pho["x"], pho["fac"], mons) @ coef
    lines.append(summary(f"surrogate deg {degree} ({len(mons)} terms × 3), training", *errors(fit_tr, tr["ref"])))
    lines.append(summary(f"surrogate deg {degree}, held-out", *errors(fit_ho, ho["ref"])))
    if "--mlp" in sys.argv:
        h = int(args("--mlp", ["12"])[0])
        wd = float(args("--decay", ["1e-5"])[0])
        theta = mlp_fit(ptr["x"], ptr["fac"], res, h, wd)
        fit_tr = ptr["base"] + ptr["fac"][:, None] * mlp_apply(theta, ptr["x"], h)[0]
        fit_ho = pho["base"] + pho["fac"][:, None] * mlp_apply(theta, pho["x"], h)[0]
        fit_ho, projected = passive(fit_ho, ho)
        nb = passive(pho["base"], ho)[1]
        lines.append(summary(f"MLP {h}×{h} ({mlp_size(ptr['x'].shape[1], h)} weights), training", *errors(fit_tr, tr["ref"])))
        lines.append(summary(f"MLP {h}×{h}, held-out", *errors(fit_ho, ho["ref"])))
        lines.append(f"\nPassivity (W·(ξ, η, φc) ≤ 0): held-out points projected: base {nb}, prototype {projected}.")
        np.savez("/tmp/roll/mlp.npz", theta=theta, h=h)
    if "--families" in sys.argv:
        laws = committed_laws(len(ho["aob"]))
        laws.update({"base": pho["base"], "prototype": fit_ho})
        lines += family_tables(ho, laws)
    if "--diagnose" in sys.argv:
        lines += ["", "## Creep curves through the worst held-out points of the base (diagnosis; never fitted on)"]
        lines += diagnose((args("--diagnose", []) or [str(root / "tools/data/rolling_diag_families.csv")])[0], prm)
    print("\n".join(lines))
    if "--md" in sys.argv:
        title = ["# Rolling surrogate prototype against the held-out set", "",
                 "`" + " ".join(["python3", "tools/fit_rolling_surrogate.py"] + sys.argv[1:]) + "` (see its docstring "
                 "and docs/guide/src/rolling.md). ΔF = |(ΔF_x, ΔF_y)| (fN), ΔM = |ΔM_z| (fNc); per family: worst ΔF / "
                 "worst ΔM (median ΔF / median ΔM); `table`, `fastsim` (32×32): the library's laws "
                 "(tools/data/rolling_heldout_laws.csv); `base`, `prototype`: this script's.", ""]
        pathlib.Path(args("--md", [""])[0]).write_text("\n".join(title + lines) + "\n")
    np.savez("/tmp/roll/last.npz", fit=fit_ho, ref=ho["ref"], rho=pho["rho"], aob=ho["aob"], theta=ho["theta"],
             lin=pho["lin"], fs=pho["fs"], base=pho["base"])
    np.savez("/tmp/roll/surrogate_fit.npz", coef=coef, mons=np.array([str(m) for m in mons]),
             ho_fit=fit_ho, ho_base=pho["base"], ho_ref=ho["ref"])


if __name__ == "__main__":
    main()
