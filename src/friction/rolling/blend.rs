//! `blend`: the default rolling law — Kalker's linear theory and the exact full-slip law joined
//! by a cubic saturation that is exact at both ends by construction.
//!
//! # Formula
//!
//! With W_lin = (F_x, F_y, M_z/c)/(fN) of Kalker's linear theory ([`super::Linear`]) and W_fs
//! the full-slip Contensou–Erismann traction in the direction of (ξ, η, cφ) (`best`,
//! [`super::FullSlip`]):
//!
//! W = (1 − t)²·W_lin + t²(3 − 2t)·W_fs  for t < 1,   W = W_fs  for t ≥ 1,
//!
//! t = √[(F_x² + F_y²)/α_F² + (M_z/c)²/α_M²]_lin / (fN).
//!
//! For pure creepage on a strip this is the Vermeulen–Johnson saturation
//! |F|/(fN) = 1 − (1 − t)³ (t = |F_lin|/(3fN), α_F = 3): (1 − t)²·3t + t²(3 − 2t) = 1 − (1 − t)³.
//! In general:
//!
//! - t → 0: W = W_lin + O(t²): Kalker's linear theory (its coefficients, [`super::Kalker`]).
//! - t ≥ 1 (large creepage) and V → 0 (t → ∞): W = W_fs exactly (the `best` law's error
//!   only, 2e-5 fN). C¹ at t = 1.
//! - Passive: W_lin is passive (Kalker's matrix has C₁₁, C₂₂, C₃₃ > 0 and antisymmetric C₂₃
//!   cross terms: power −κ(C₁₁ξ² + C₂₂η² + C₃₃c²φ²)·V ≤ 0), W_fs is passive, and the weights
//!   are ≥ 0.
//! - |F| ≤ fN: with α_F ≤ 3, |F| ≤ (1 − t)²·α_F·t + t²(3 − 2t) ≤ 1 − (1 − t)³ ≤ 1.
//!
//! α_F = 3 and α_M are the law's two constants; α_M was chosen on the exact steady-rolling
//! reference (`tools/data/rolling_ref.csv`, see `host-tests/rolling_ref.rs` for the measured
//! error).
//!
//! # Domain and special cases
//!
//! Every input: rest → 0; N ≤ 0 or f = 0 → 0; V = 0 → full slip (no division: t ≥ 1 is
//! tested as √(…) ≥ V/S); V < 0 by the mirror ([`super::RollingSlip`]).
//!
//! # Error and cost
//!
//! See the README's rolling section and `host-tests/rolling*.rs` (linear limit: Kalker's
//! coefficients to rounding; full slip: `best`'s error; against the exact reference: measured).
//! Cost: the linear part ≈ 20 flops, one square root and one division, plus `best`'s
//! per-contact call (107 M4F instructions on average) when t > 0.

use super::contact::{Creep, Input, Linear, RollingLaw};
use crate::Real;

/// The default rolling law (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default)]
pub struct Blend;

impl Blend {
    /// α_F: the force saturation scale (3: Vermeulen–Johnson; ≤ 3 keeps |F| ≤ fN).
    pub const ALPHA_F: f64 = 3.0;
    /// α_M: the spin-moment saturation scale.
    pub const ALPHA_M: f64 = 1.8;
}

impl RollingLaw for Blend {
    const NAME: &'static str = "blend";

    #[inline]
    fn creep<T: Real>(i: &Input<'_, T>) -> Creep<T> {
        let n = Linear::numerators(i);
        let (ia, im) = (
            T::from_f64(1.0 / Blend::ALPHA_F),
            T::from_f64(1.0 / Blend::ALPHA_M),
        );
        let (ux, uy, um) = (n.fx * ia, n.fy * ia, n.mz * im);
        let tv = (ux * ux + uy * uy + um * um).sqrt(); // t·v
        let fs = i.contact.full_slip(i.vx, i.vy, i.w);
        if tv.partial_cmp(&i.v) != Some(core::cmp::Ordering::Less) {
            // t ≥ 1 (or V = 0): full slip
            return fs;
        }
        let r = T::ONE / i.v;
        let t = tv * r;
        let u = T::ONE - t;
        let wl = u * u * r; // (1 − t)²/v: W_lin = numerators/v
        let wf = t * t * (T::from_f64(3.0) - T::TWO * t);
        Creep {
            fx: wl * n.fx + wf * fs.fx,
            fy: wl * n.fy + wf * fs.fy,
            mz: wl * n.mz + wf * fs.mz,
        }
    }
}
