//! Regularized Coulomb point contact g_δ (the paper's §1 baseline): no spin effect, no torque.
//!
//! # Formula
//!
//! ```text
//! F = −fN·(v_P/v)·g_δ(v),   g_δ(v) = min(v/δ, 1),   T_z = 0
//! ```
//!
//! δ = 0 gives Coulomb's sign law (F = −fN·v_P/v for v > 0, F = 0 at v = 0).
//!
//! # Domain and special cases
//!
//! Every [`SlipState`]; ignores ω and the patch. Passive, |F| ≤ fN, continuous for δ > 0
//! (kink at v = δ). Against the exact integrals it is right only for u → ∞ (pure
//! translation); its error is the whole spin effect: 0.9999 fN in force (→ 1 as u → 0) and
//! C = 0.589 fNa in torque (at e² = 0, pure spin), measured over e² ∈ [0, 0.99], all ψ, u.
//!
//! # Cost
//!
//! One square root, three divisions (the direction is renormalised by max(|v_Px|, |v_Py|) so
//! that tiny speeds keep full precision). Cortex-M4F `f32`: 42 instructions per call (incl.
//! the 8-instruction call floor); `f64` ≈1,300. Host: ≈5–12 ns.

use super::{Constants, SlipState, Traction, larger};
use crate::Real;
use crate::math::Backend;

/// Regularized Coulomb point contact (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Coulomb;

/// The branch of [`Coulomb`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// v = 0: zero force.
    Rest,
    /// 0 < v < δ: the linear piece −fN·v_P/δ.
    Regularized,
    /// v ≥ δ: −fN·v_P/v.
    Sliding,
}

impl Coulomb {
    /// Measured max error against the exact integrals over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (δ = 0, `f64`): (|F − F_exact|/(fN), |T_z − T_exact|/(fNa)).
    pub const ERROR: (f64, f64) = (0.99988, 0.58905);
}

super::twin::libm_and_micromath! {
    Coulomb: "coulomb", Branch, maximally_dissipative true,
    slip_ramp
    /// The ramp F = −fN·v_P/δ below δ: κ = 1.
    T::ONE,
    spin_ramp
    /// No drilling torque: κ_T = 0.
    T::ZERO,
    /// [`Coulomb`] with micromath's square root for |v_P| (feature `micromath`; `f32` only, libm
    /// for `f64`).
    ///
    /// Formula, domain, branches: as [`Coulomb`]; `f64` is [`Coulomb`]. The direction is right,
    /// the sliding magnitude is 1/v̂ with v̂ ≥ v at most 6.07 % high: |F| ≤ fN still holds, at most
    /// 5.7 % short of it. Measured (`f32`, the 4,329 states of host-tests/micromath.rs, asserted
    /// there): against [`Coulomb`] 4.4e-2 fN; against the exact integrals 0.988 fN / 0.589 fNa
    /// (the same as [`Coulomb`]: no spin effect). Cost: M4F **45** instructions (`f32`; [`Coulomb`]
    /// 42), host ≈ 10 ns. Not worth using.
    twin CoulombMicromath
}

/// Coulomb's law with √ from the backend `B`.
#[inline(always)]
fn traction<B: Backend, T: Real>(_k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
    let (x, y, d) = (s.x(), s.y(), s.d());
    let mx = larger(x.abs(), y.abs());
    if mx == T::ZERO {
        return (Traction::default(), Branch::Rest);
    }
    // Renormalise by max(|x|, |y|): x, y may be tiny when spin dominates the scale.
    let (xs, ys, ds) = (x / mx, y / mx, d / mx);
    let v = B::sqrt(xs * xs + ys * ys);
    let (den, branch) = if v >= ds {
        (v, Branch::Sliding)
    } else {
        (ds, Branch::Regularized)
    };
    (
        Traction {
            fx: -xs / den,
            fy: -ys / den,
            tz: T::ZERO,
        },
        branch,
    )
}
