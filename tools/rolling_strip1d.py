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

    W = W_1D + (1 − λ)·(W_lin − W_1D,lin) + λ·(W_fs − W_1D,fs),  λ = 1 − (1 − min(ρ_F/3, 1))³

(W_1D,lin, W_1D,fs: the model's own linear and full-slip wrenches; W_lin, W_fs the exact ones).

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


def march(d, s, steps=64, lin_only=False):
    """The 1-D model's wrench (F_x, F_y)/(fN), M_z/(fNc) for creepages s = (ξ, η, φc) (c = 1)."""
    a, k = geometry(d)
    kk = d["k"]
    lx, ly = 2 * a * a / kk[:, 0, 0], 2 * a * a / kk[:, 1, 1]
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


def strip_base(d, steps=64):
    w1 = march(d, d["s"], steps)
    w1l = march(d, d["s"], steps, lin_only=True)
    w1f = march(d, d["s"] * 1e6, steps)
    rho_f = np.linalg.norm(w1l[:, :2], axis=1) / np.maximum(np.linalg.norm(d["fs"][:, :2], axis=1), 1e-12)
    u = np.minimum(rho_f / 3, 1)
    lam = 1 - (1 - u) ** 3
    return w1 + (1 - lam)[:, None] * (d["lin"] - w1l) + lam[:, None] * (d["fs"] - w1f), w1


def main():
    steps = int(F.args("--steps", ["64"])[0])
    c = dict(np.load(R.CACHE))
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
