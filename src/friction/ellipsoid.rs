//! The ellipsoidal law of Leine & Glocker / Möller (MuJoCo's elliptic friction cone): force and
//! torque normalised together on an ellipsoidal limit surface.
//!
//! # Formula
//!
//! ```text
//! F = −fN·v_P/√(v² + R̄²ω²),    T_z = −fN·R̄²ω/√(v² + R̄²ω²)
//! ```
//!
//! with the effective radius R̄ = C·a, C = (3/8)E(m) the exact pure-spin torque coefficient
//! ([`Constants::spin_torque`]). For a circle that is the classical R̄ = (3π/16)a; for an
//! ellipse it keeps pure spin exact for every e² (T_z = −C·fNa), which is what the law's
//! one spin-related constant can match. (Matching the small-u slopes instead is impossible:
//! the law is isotropic, slope 1/C' for any R̄ = C'a, while the exact slopes A ≠ B differ.)
//! Dimensionless, with r = R̄/a = C: X = −x/√(v² + r²w²), T = −r²w/√(v² + r²w²).
//!
//! # Domain and special cases
//!
//! Every [`SlipState`]; ignores δ (at ω = 0 it is Coulomb's sign law, 0 at v = 0). Pure
//! translation and pure spin exact. Passive by construction (it is the gradient of the
//! dissipation √(v² + R̄²ω²)), and (F/(fN))² + (T/(fNR̄))² = 1 off rest, so |F| ≤ fN.
//! Smooth for ω ≠ 0. Symmetries as for [`Simplified`](super::Simplified), bit-exact.
//!
//! # Error
//!
//! Against the exact integrals, max over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]: **0.227 fN**,
//! **0.134 fNa** (circle: 0.111 fN, 0.083 fNa): the most accurate of the fast laws, though
//! isotropic. Scaling R̄ by λ trades one error for the other (measured, max over e²:
//! λ = 0.9: 0.250 fN / 0.108 fNa; 1.1: 0.213 / 0.158; 1.2: 0.206 / 0.189); λ = 1 is the
//! only choice that keeps pure spin exact, hence R̄ = C·a.
//!
//! # Cost
//!
//! One square root, one division. Cortex-M4F `f32`: 34 instructions per call (incl. the
//! 8-instruction call floor); `f64` ≈1,300. Host: ≈3–7 ns.

use super::law::Smooth;
use super::{Constants, SlipState, Traction};
use crate::Real;
use crate::math::Backend;

/// The Leine–Glocker/Möller ellipsoidal law with R̄ = C·a (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ellipsoid;

impl Ellipsoid {
    /// Measured max error against the exact integrals over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (`f64`): (|F − F_exact|/(fN), |T_z − T_exact|/(fNa)).
    pub const ERROR: (f64, f64) = (0.22720, 0.13357);
}

super::twin::libm_and_micromath! {
    Ellipsoid: "ellipsoid", Smooth, maximally_dissipative true,
    /// [`Ellipsoid`] with micromath's square root of v² + R̄²ω² (feature `micromath`; `f32` only,
    /// libm for `f64`).
    ///
    /// Formula, domain: as [`Ellipsoid`]; `f64` is [`Ellipsoid`]. The direction of (F, T_z/R̄) is
    /// right, its length 1/(1 + ε) with the square root's error ε ∈ [0, 6.07 %]: |F| ≤ fN still
    /// holds, passivity too. Measured (`f32`, the 4,329 states of host-tests/micromath.rs, asserted
    /// there): against [`Ellipsoid`] 5.7e-2 fN / 2.1e-2 fNa; against the exact integrals
    /// **0.211 fN / 0.121 fNa** max ([`Ellipsoid`]: 0.227 / 0.121 on the same set: the shortfall
    /// happens to offset the law's overshoot there), median 4.0e-2 fN / 7.8e-3 fNa (vs 1.2e-2 /
    /// 3.6e-3). Cost: M4F **37** instructions (`f32`; [`Ellipsoid`] 34), host ≈ 6 ns. Not worth
    /// using.
    twin EllipsoidMicromath
}

/// The ellipsoidal law with √ from the backend `B`.
#[inline(always)]
fn traction<B: Backend, T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Smooth) {
    let (x, y, w) = (s.x(), s.y(), s.w());
    let r = k.spin_torque();
    let rw = r * w;
    let n2 = x * x + y * y + rw * rw;
    if n2 == T::ZERO {
        // Off rest n2 ≥ min(1, r²)/9 > 0 (max(|x|, |y|, |w|) ≥ 1/3).
        return (Traction::default(), Smooth::Rest);
    }
    let inv = T::ONE / B::sqrt(n2);
    (
        Traction {
            fx: -x * inv,
            fy: -y * inv,
            tz: -r * rw * inv,
        },
        Smooth::Slip,
    )
}
