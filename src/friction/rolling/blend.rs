//! `blend`: the default rolling law — Kalker's linear theory and the exact full-slip law joined
//! by a cubic saturation that is exact at both ends by construction.
//!
//! # Formula
//!
//! With W_lin = (F_x, F_y, M_z/c)/(fN) of Kalker's linear theory ([`super::Linear`]), split
//! into its gyroscopic pair W_g = (0, −κC₂₃cφ, κC₂₃η) (the φ → F_y and η → M_z cross terms,
//! whose power cancels) and the dissipative rest W_d = W_lin − W_g, and W_fs the full-slip
//! Contensou–Erismann traction in the direction of (ξ, η, cφ) (`best`, [`super::FullSlip`]):
//!
//! W = A(t)·W_d + A_s(t)·W_g + B(t)·W_fs, then |F| ≤ fN by scaling W back,
//! A = (1 − t)ⁿ, B = 1 − (1 − t)ⁿ(1 + nt) for t < 1, A = 0 and B = 1 beyond,
//! A_s = 1/(1 + (σt)²) (the spin-induced lateral force decays like 1/creepage, as in the
//! exact theory, instead of vanishing at a finite creepage),
//!
//! t² = (κC₁₁ξ/α_ξ)² + (κC₂₂η/α_η)² + (κC₂₃cφ/α_φ)² + (M_z,lin/(fNc·α_M))², κ = Gc²/(fN).
//!
//! For pure longitudinal creepage with α = n + 1 this is the Vermeulen–Johnson form
//! |F|/(fN) = 1 − (1 − t)ⁿ⁺¹. In general:
//!
//! - t → 0: W = W_lin + O(t): Kalker's linear theory (its coefficients, [`super::Kalker`]).
//! - V → 0 (t → ∞): W = W_fs exactly (`best`'s error only, 2.9e-5 fN measured); at a large
//!   finite creepage W − W_fs = A_s·W_g = O(1/creepage), like the exact theory's elastic
//!   correction.
//! - Passive by construction: W_d and W_fs are passive (Kalker's C₁₁, C₂₂, C₃₃ > 0), W_g has
//!   zero power, A, B, A_s ≥ 0, and the final scaling is positive.
//! - Continuous (C⁰ at t = 1 for n = 1).
//!
//! n ([`Blend::ORDER`]), α ([`Blend::ALPHA`]), α_M ([`Blend::ALPHA_M`]) and σ
//! ([`Blend::SIGMA`]) were fitted to the exact steady-rolling reference
//! (`tools/data/rolling_ref.csv`) by `python3 tools/fit_rolling_blend.py` (minimax of
//! max(|ΔF|/3 %, |ΔM_z|/5 %) over its creep-curve families): n = 1, α = (2.5, 2.5, 3.31),
//! α_M = 3.15, σ = 2. **The form is too poor for the aim**: 0.198 fN on F and 0.329 fNc
//! on M_z at worst ([`Blend::REF_ERROR`], asserted by `host-tests/rolling_ref.rs`); pure ξ
//! and η within 0.06 fN, the misses are spin-dominated (the exact spin moment and spin force
//! approach full slip asymptotically over two decades of creepage; one saturation variable
//! cannot follow both that and the finite saturation of pure creepage). [`super::Fastsim`]
//! is 0.085 fN / 0.06 fNc on the same set at ≈ 130× the cost.
//!
//! # Domain and special cases
//!
//! Every input: rest → 0; N ≤ 0 or f = 0 → 0; V = 0 → full slip (no division: t ≥ 1 is
//! tested as t·V/S ≥ V/S); V < 0 by the mirror ([`super::RollingSlip`]).
//!
//! # Error and cost
//!
//! Linear limit: Kalker's coefficients, deviation O(t) (`host-tests/rolling.rs`: ≤ 1e-4
//! relative at 1e-6 of saturation); full slip: `best`'s error (2.9e-5 fN, 2.0e-6 fNc
//! measured); against the exact reference: [`Blend::REF_ERROR`] and the README's rolling
//! section. Cost (M4F, f32, stage `rolling` of the firmware rig, 64 creep-curve states):
//! 368 instructions per dimensional call on average (273 … 412; f64: 16,423), of which `best`'s full-slip
//! call ≈ 110; `RollingContact::new` once per contact (f64 table interpolation, `best`'s
//! per-contact tables). Flash of a probe with the contact built and one call: 29.4 KB (f32).

use super::contact::{Creep, Input, Linear, RollingLaw};
use crate::Real;

/// The default rolling law (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default)]
pub struct Blend;

impl Blend {
    /// n: the saturation's order (A = (1 − t)ⁿ, B = 1 − A(1 + nt)).
    pub const ORDER: u32 = 1;
    /// (α_ξ, α_η, α_φ): the saturation scales of the three linear force shares (fN).
    pub const ALPHA: (f64, f64, f64) = (2.5, 2.5, 3.308);
    /// α_M: the saturation scale of the linear spin moment (fNc).
    pub const ALPHA_M: f64 = 3.15;
    /// σ: the decay scale of the gyroscopic pair's weight A_s = 1/(1 + (σt)²).
    pub const SIGMA: f64 = 2.0;
    /// Measured max error against the exact steady-rolling reference over its creep-curve
    /// families (pure ξ, η, φ, combined, full slip; a/b ∈ {0.2, 0.5, 1, 2, 5}): (|ΔF| in fN,
    /// |ΔM_z| in fNc), asserted by `host-tests/rolling_ref.rs`.
    /// Measured 0.198 fN (pure spin, a/b = 5) and 0.329 fNc (η with φ, a/b = 5): the law
    /// misses the aim (3 %, 5 %) — see the README's rolling section.
    pub const REF_ERROR: (f64, f64) = (0.2, 0.33);
}

impl RollingLaw for Blend {
    const NAME: &'static str = "blend";

    #[inline]
    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        let k = &i.contact.kalker;
        let (ax, ay, ap) = Blend::ALPHA;
        // t·v: the linear force shares over their scales (v = V/S: no division yet)
        let qx = k.c11 * i.vx * T::from_f64(1.0 / ax);
        let qy = k.c22 * i.vy * T::from_f64(1.0 / ay);
        let qp = k.c23 * i.w * T::from_f64(1.0 / ap);
        let n = Linear::numerators(i);
        let qm = n.mz * T::from_f64(1.0 / Blend::ALPHA_M);
        let tv = (i.kappa * i.kappa * (qx * qx + qy * qy + qp * qp) + qm * qm).sqrt();
        let fs = i.contact.full_slip(i.vx, i.vy, i.w);
        // the gyroscopic pair (φ → F_y, η → M_z; zero power) with A_s = 1/(1 + (σt)²),
        // divided by v: v/(v² + σ²(tv)²) (finite at V = 0 unless at rest)
        let gy = (-i.kappa * k.c23 * i.w, i.kappa * k.c23 * i.vy);
        let sg = T::from_f64(Blend::SIGMA) * tv;
        let den = i.v * i.v + sg * sg;
        let ws = if den > T::ZERO { i.v / den } else { T::ZERO };
        let (dy, dm) = (n.fy - gy.0, n.mz - gy.1); // the rest of W_lin (dissipative)
        if tv.partial_cmp(&i.v) != Some(core::cmp::Ordering::Less) {
            // t ≥ 1 (or V = 0): full slip and the decaying gyroscopic pair
            return bounded(Creep {
                fx: fs.fx,
                fy: fs.fy + ws * gy.0,
                mz: fs.mz + ws * gy.1,
            });
        }
        let r = T::ONE / i.v;
        let t = tv * r;
        let u = T::ONE - t;
        let mut a = T::ONE;
        for _ in 0..Blend::ORDER {
            a *= u;
        }
        let b = T::ONE - a * (T::ONE + T::from_f64(Blend::ORDER as f64) * t);
        let wl = a * r; // A·W_lin = A·numerators/v
        bounded(Creep {
            fx: wl * n.fx + b * fs.fx,
            fy: wl * dy + ws * gy.0 + b * fs.fy,
            mz: wl * dm + ws * gy.1 + b * fs.mz,
        })
    }
}

/// |F| ≤ 1 (fN): scales the whole wrench back (a positive factor keeps the power ≤ 0 and the
/// law continuous). One compare on the common path.
#[inline(always)]
fn bounded<T: Real>(w: Creep<T>) -> Creep<T> {
    let f2 = w.fx * w.fx + w.fy * w.fy;
    if f2 > T::ONE {
        let s = T::ONE / f2.sqrt();
        Creep {
            fx: w.fx * s,
            fy: w.fy * s,
            mz: w.mz * s,
        }
    } else {
        w
    }
}
