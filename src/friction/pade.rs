//! The fractional-linear (Padé [1/1]) model mentioned by the paper (§3): right limits at u = 0
//! and u = ∞, per axis.
//!
//! # Formula
//!
//! With u = v/(a|ω|), α = cos ψ, β = sin ψ and the patch [`Constants`] A, B, C:
//!
//! ```text
//! X = −α·Au/(1 + Au),   Y = −β·Bu/(1 + Bu),   T = −sgn(ω)·C/(1 + (C/|T₁|)·u),
//! T₁ = −(1 − e²β²)/5
//! ```
//!
//! in units of fN and fNa: the exact small-u slopes A, B and pure-spin torque C, the exact
//! Coulomb limit and the exact 1/u torque tail T₁/u; the approach rates in between are wrong.
//! Computed as X = −x·A/(|w| + A·v) (and alike) in the homogeneous form of [`SlipState`], so
//! u is never formed.
//!
//! # Domain and special cases
//!
//! Every [`SlipState`]; ignores δ (no regularization: at ω = 0 it is Coulomb's sign law, whose
//! value at v = 0 is set to 0). Pure translation and pure spin exact. Passive by construction,
//! |F| ≤ fN, smooth for ω ≠ 0 (no branches). Symmetries as for
//! [`Simplified`](super::Simplified), bit-exact.
//!
//! # Error
//!
//! Against the exact integrals, max over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]: **0.409 fN**,
//! **0.355 fNa** (circle: 0.344 fN, 0.231 fNa) — worse than [`Simplified`](super::Simplified)
//! in force everywhere: the fractional-linear approach to saturation is far too slow.
//!
//! # Cost
//!
//! One square root, three divisions. Cortex-M4F `f32`: 62 instructions per call (incl. the
//! 8-instruction call floor); `f64` ≈2,400. Host: ≈7–10 ns.

use super::law::Smooth;
use super::{Constants, FrictionLaw, SlipState, Traction};
use crate::Real;

/// The fractional-linear model (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pade;

impl Pade {
    /// Measured max error against the exact integrals over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (`f64`): (|F − F_exact|/(fN), |T_z − T_exact|/(fNa)).
    pub const ERROR: (f64, f64) = (0.40937, 0.35474);
}

impl FrictionLaw for Pade {
    const NAME: &'static str = "pade";
    type Branch = Smooth;
    const MAXIMALLY_DISSIPATIVE: bool = false;
    super::law::constants_are_prepared!();

    #[inline]
    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Smooth) {
        let (x, y, w) = (s.x(), s.y(), s.w());
        let aw = w.abs();
        let v2 = x * x + y * y;
        if aw == T::ZERO && v2 == T::ZERO {
            return (Traction::default(), Smooth::Rest);
        }
        let v = v2.sqrt();
        let (a, b, c) = (k.slope_x(), k.slope_y(), k.spin_torque());
        // −αAu/(1 + Au) = −x·A/(|w| + A v); |w| + A v > 0 off rest.
        let fx = -x * a / (aw + a * v);
        let fy = -y * b / (aw + b * v);
        // C/(1 + Cu/|T₁|) = C·q|w|/(q|w| + 5C v³) with q = x² + m₁y² = 5v²|T₁|. At v = 0 both
        // vanish: the limit is C.
        let p = (x * x + k.m1() * y * y) * aw;
        let den = p + c * T::from_f64(5.0) * v2 * v;
        let t = if den > T::ZERO { c * p / den } else { c };
        (
            Traction {
                fx,
                fy,
                tz: -t.copysign(w),
            },
            Smooth::Slip,
        )
    }
}
