#!/usr/bin/env python3
"""The long-patch asymptote of steady rolling, as a base for patches long along the rolling
direction (prototype, Python; measured, not a library law).

For a patch much longer along the rolling direction x than across (semi-extents a ≫ b), the
tangential displacement at (x, y) is dominated by the traction within a few widths of the same
cross-section: integrating the Boussinesq–Cerruti kernel along x gives 2·ln(a/b)·q(x) with
q(x) = ∫ τ(x, y) dy the cross-section's resultant, the same across the width. To leading order
each cross-section moves as a rigid body, u(x) = Λ∘q(x) (Λ = (Λ_x, Λ_y) flexibilities, u_x from
q_x with the factor 1, u_y from q_y with 1 − ν), and the steady slip s = w − ∂u/∂x is a 1-D
problem along x with
- the creepage w(x) = (ξ − φ·ȳ(x), η + φ·x) (ȳ the cross-section's centroid: 0 on an aligned patch),
- the bound Q(x) = ∫ f·p dy = (3fN/4a)(1 − x²/a²) (the marginal of the Hertz pressure over any
  line is a parabola in the projected coordinate, for any ellipse and skew),
- adhesion from the leading edge x = +a: q(x) = −(1/Λ)∘∫ₓᵃ w, until abs(q) reaches Q; then slip.

It is FASTSIM with one strip along the whole patch and a parabolic bound. For translation it is
closed form: F = fN·(1 − (1 − ρ_F/3)³) (Johnson–Vermeulen's cubic, ρ_F = abs(F_lin)/(fN)) and
M_z = (1 − ρ_F/3)³·M_z,lin (derived: the moment of the ramp/bound split about the centre). Spin
enters as a lateral creepage varying along x: the case the reach base gets wrong on long patches
(the pole within a semi-major axis of the patch, outside its width).

Calibration: Λ_x = 2a²/K₁₁, Λ_y = 2a²/K₂₂ (the 1-D model's linear F_x, F_y from ξ, η equal the
exact creep matrix'); its C₂₃ is a·C₂₂/3 and its C₃₃ ≈ 0 (the exact C₃₃ is a small difference on long
patches, ≈ 0.48 against C₂₃²/C₂₂ ≈ 53 at a/b = 20). Both limits made exact by the defects:

    W = W_1D + (1 − λ)·(W_lin − W_1D,lin) + λ·(W_fs − W_1D,fs),  λ = 3u² − 2u³, u = min(ρ_F/3, 1)

(W_1D,lin, W_1D,fs: the model's own linear and full-slip wrenches; W_lin, W_fs the exact ones;
ρ_F = abs(F_1D,lin)/abs(F_fs)). Small creepage: W_1D = W_1D,lin + O(ρ²) and λ = O(ρ²), so
W = W_lin + O(ρ²) (the linear theory is the exact tangent); creepage → ∞: λ = 1 from ρ_F = 3 on and
W_1D → W_1D,fs, so W → W_fs.

    "$(tools/venv.sh)" tools/rolling_strip1d.py [--steps N] [--md OUT]
"""
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import fit_rolling_long as L  # noqa: E402
import fit_rolling_reach as R  # noqa: E402
import fit_rolling_surrogate as F  # noqa: E402


def geometry(d):
    """a (semi-extent along x, c = 1) and the centroid slope k: ȳ(x) = k·x on the sheared ellipse."""
    a0 = np.sqrt(d["aob"])
    ct, st = np.cos(d["theta"]), np.sin(d["theta"])
    aa = ct * ct / a0 ** 2 + st * st * a0 ** 2
    bb = st * ct * (1 / a0 ** 2 - a0 ** 2)
    cc = st * st / a0 ** 2 + ct * ct * a0 ** 2
    # chord at fixed x: A x² + 2B xy + C y² ≤ 1 → midpoint ȳ = −B x / C
    return 1.0 / np.sqrt(aa), -bb / cc


SPIN_LEVER = "--no-spin-lever" not in sys.argv


def march(d, s, steps=64, lin_only=False):
    """The 1-D model's wrench (F_x, F_y)/(fN), M_z/(fNc) for creepages s = (ξ, η, φc) (c = 1).
    Default (`--no-spin-lever` to drop it): the spin's lateral creepage φ·x scaled by K₂₃/(a·K₂₂/3), so that the model's own
    C₂₃ is the exact one (its lever arm a/3 is the long-patch limit's)."""
    a, k = geometry(d)
    kk = d["k"]
    lx, ly = 2 * a * a / kk[:, 0, 0], 2 * a * a / kk[:, 1, 1]
    if SPIN_LEVER:
        s = s.copy()
        s[:, 2] = s[:, 2] * kk[:, 1, 2] / (a * kk[:, 1, 1] / 3)
    nl = d["nl"]
    dx = 2 * a / steps
    qx = np.zeros(len(a))
    qy = np.zeros(len(a))
    fx = np.zeros(len(a))
    fy = np.zeros(len(a))
    mz = np.zeros(len(a))
    xi, eta, phi = s[:, 0], s[:, 1], s[:, 2]
    for j in range(steps):
        x = a - (j + 0.5) * dx
        ybar = k * x
        qx = qx - (xi - phi * ybar) * dx / lx
        qy = qy - (eta + phi * x) * dx / ly
        if not lin_only:
            bound = 0.75 * nl / a * (1 - (x / a) ** 2)
            n = np.hypot(qx, qy)
            sc = np.where(n > bound, bound / np.maximum(n, 1e-300), 1.0)
            qx, qy = qx * sc, qy * sc
        fx += qx * dx
        fy += qy * dx
        mz += (x * qy - ybar * qx) * dx
    return np.column_stack([fx, fy, mz]) / nl[:, None]


OWN_AXIS = "--x-axis" not in sys.argv


def march_own(d, s, steps=64, lin_only=False, lever=None):
    """The same model along the patch's OWN major axis (unit e, at ψ from x; semi-axis A): the
    slender-body cross-sections are perpendicular to the long axis, not to x. With u uniform across
    a section, ∂u/∂x = cos ψ·∂u/∂s, so the adhesion ramp is (1/Λ)∘∫ w ds/abs(cos ψ) from the leading end
    (s·cos ψ > 0); w = (ξ − φy, η + φx) on the centre line (x, y) = s·e; Λ in the own frame from the
    diagonal of the exact translational creep matrix turned to that frame; the spin's creepage scaled
    (`lever`) so that the model's linear F from φ matches the exact K's third column."""
    aob = d["aob"]
    big = aob >= 1.0
    r = np.where(big, aob, 1.0 / aob)
    psi = np.where(big, d["theta"], d["theta"] + 0.5 * np.pi)
    big_a = np.sqrt(r)
    ex, ey = np.cos(psi), np.sin(psi)
    sg = np.where(ex >= 0, 1.0, -1.0)  # march from the end that leads along +x
    ex, ey = ex * sg, ey * sg
    cpsi = np.maximum(ex, 0.05)
    kk = d["k"]
    kss = ex * ex * kk[:, 0, 0] + ex * ey * (kk[:, 0, 1] + kk[:, 1, 0]) + ey * ey * kk[:, 1, 1]
    knn = ey * ey * kk[:, 0, 0] - ex * ey * (kk[:, 0, 1] + kk[:, 1, 0]) + ex * ex * kk[:, 1, 1]
    ls, ln = 2 * big_a ** 2 / (cpsi * kss), 2 * big_a ** 2 / (cpsi * knn)
    nl = d["nl"]
    ds = 2 * big_a / steps
    xi, eta, phi = s[:, 0], s[:, 1], s[:, 2] * (1.0 if lever is None else lever)
    qs = np.zeros(len(r))
    qn = np.zeros(len(r))
    out = np.zeros((len(r), 3))
    for j in range(steps):
        sc_ = big_a - (j + 0.5) * ds
        x, y = sc_ * ex, sc_ * ey
        wx, wy = xi - phi * y, eta + phi * x
        qs = qs - (wx * ex + wy * ey) * ds / (cpsi * ls)
        qn = qn - (-wx * ey + wy * ex) * ds / (cpsi * ln)
        if not lin_only:
            bound = 0.75 * nl / big_a * (1 - (sc_ / big_a) ** 2)
            n = np.hypot(qs, qn)
            f = np.where(n > bound, bound / np.maximum(n, 1e-300), 1.0)
            qs, qn = qs * f, qn * f
        qx, qy = qs * ex - qn * ey, qs * ey + qn * ex
        out[:, 0] += qx * ds
        out[:, 1] += qy * ds
        out[:, 2] += (x * qy - y * qx) * ds
    return out / nl[:, None]


def own_lever(d, steps):
    """The spin scale that matches the model's linear F from φ to the exact −K·(0, 0, 1)/nl."""
    e3 = np.zeros((len(d["aob"]), 3))
    e3[:, 2] = 1.0
    m = march_own(d, e3, steps, lin_only=True)[:, :2]
    ex = -d["k"][:, :2, 2] / d["nl"][:, None]
    return (m * ex).sum(1) / np.maximum((m * m).sum(1), 1e-300)


def strip_base(d, steps=64):
    if OWN_AXIS:
        lev = own_lever(d, steps)
        w1 = march_own(d, d["s"], steps, lever=lev)
        w1l = march_own(d, d["s"], steps, lin_only=True, lever=lev)
        w1f = march_own(d, d["s"] * 1e6, steps, lever=lev)
    else:
        w1 = march(d, d["s"], steps)
        w1l = march(d, d["s"], steps, lin_only=True)
        w1f = march(d, d["s"] * 1e6, steps)
    clock = (F.args("--clock", ["F"]) or ["F"])[0]
    if clock == "W":  # the exact linear and full-slip wrenches, 3-vectors
        rho_f = np.linalg.norm(d["lin"], axis=1) / np.maximum(np.linalg.norm(d["fs"], axis=1), 1e-12)
    elif clock == "W1D":  # the model's own, 3-vectors
        rho_f = np.linalg.norm(w1l, axis=1) / np.maximum(np.linalg.norm(w1f, axis=1), 1e-12)
    else:  # forces: the model's linear against the exact full slip
        rho_f = np.linalg.norm(w1l[:, :2], axis=1) / np.maximum(np.linalg.norm(d["fs"][:, :2], axis=1), 1e-12)
    u = np.minimum(rho_f / 3, 1)
    lam = u * u * (3 - 2 * u)  # O(ρ²): the linear theory stays the exact tangent
    return w1 + (1 - lam)[:, None] * (d["lin"] - w1l) + lam[:, None] * (d["fs"] - w1f), w1


def main():
    steps = int(F.args("--steps", ["64"])[0])
    c = L.reach_cache()
    ho = R.split(c, "ho")
    l2 = L.load_long2()
    prm = np.load(F.args("--prm", ["/tmp/roll/reach_prm.npy"])[0])
    lines = ["| set | σ_M | n | reach base | 1-D strip (raw) | 1-D strip, limits exact |", "|---|---|---|---|---|---|"]
    for name, d in [("long-patch training rows", l2), ("held-out, a/b > 5 along x", ho)]:
        sm = R.sigma_major(d)
        t = L.aligned_t(d)
        rx = (1 + t) / (1 - t)
        b = L.base_of(d, prm)[0]
        w, w1 = strip_base(d, steps)
        for lo, hi in [(0, 0.05), (0.05, 0.2), (0.2, 0.5), (0.5, 0.9), (0.9, 1.01), (0, 1.01)]:
            m = (sm >= lo) & (sm < hi) & (rx > 5)
            if m.sum() < 2:
                continue
            cells = []
            for ww in (b, w1, w):
                ef, em = F.errors(ww[m], d["ref"][m])
                cells.append(f"{ef.max():.3f} / {em.max():.3f} (95 % {np.quantile(ef, .95):.3f} / {np.quantile(em, .95):.3f})")
            lines.append(f"| {name} | {lo}–{hi} | {m.sum()} | " + " | ".join(cells) + " |")
    print("\n".join(lines))
    if "--md" in sys.argv:
        pathlib.Path(F.args("--md", [""])[0]).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
