//! Contensou–Erismann dry friction over the Hertz ellipse: the sliding force and the drilling
//! torque, on body B from body A, in the contact frame (crate conventions).
//!
//! The dimensionless core maps the slip state to a [`Traction`]: force / (fN), torque / (fNa).
//! Every law is homogeneous of degree 0 in (v_Px, v_Py, aω): only the direction of that triple
//! matters (u = v/(aω), ψ = atan2(v_Py, v_Px)).
//!
//! # Structure
//!
//! - [`Constants`]: what depends on the patch shape e² only (A, B, C, …), built once.
//! - [`Slip`]: the validated dimensional slip (v_P, ω); [`SlipState`]: its homogeneous form.
//! - [`FrictionLaw`]: a zero-sized law type with a dimensionless core
//!   `(Constants, SlipState) → (Traction, Branch)`; [`Friction`]`<T, L>` adds the friction
//!   coefficient and the regularization speed δ and scales by fN, fNa.
//! - Laws: [`Best`] (exact grade and fast — within 1e-4 fN / 1e-5 fNa of the exact integrals
//!   for every accepted shape, e² to 0.99998 —: the default of [`Friction`], per-contact tables
//!   in [`BestContact`]), [`Simplified`] (the paper's model), [`Pade`], [`Ellipsoid`],
//!   [`Coulomb`], and the reference [`Exact`] (the integrals of [`exact`], µs per call).
//!
//! ```
//! use contensou::elliptic::Parameter;
//! use contensou::friction::{Constants, Friction, Simplified, Slip};
//!
//! let k = Constants::from_parameter(Parameter::new(0.6_f64)?); // once per contact shape
//! let law = Friction::<f64, Simplified>::with_law(0.3, 1e-4)?;       // f = 0.3, δ = 0.1 mm/s
//! // per step: a = 50 µm, N = 0.06 N, v_P = (1, 0.5) mm/s, ω = 30 rad/s
//! let w = law.tangential(&k, 50e-6, 0.06, Slip::new(1e-3, 0.5e-3, 30.0)?);
//! assert!(w.fx < 0.0 && w.fy < 0.0 && w.tz < 0.0);
//! assert!(w.fx.hypot(w.fy) <= 0.3 * 0.06);
//! # Ok::<(), contensou::Error>(())
//! ```

pub mod best;
pub mod constants;
pub mod coulomb;
pub mod ellipsoid;
pub mod exact;
pub mod law;
pub mod pade;
pub mod reference;
pub mod rolling;
pub mod simplified;
pub mod slip;
mod spin_step;
mod twin;

pub use best::{Best, BestContact, BestSeries};
pub use constants::Constants;
pub use coulomb::Coulomb;
pub use ellipsoid::Ellipsoid;
pub use law::{Explicit, Friction, FrictionLaw, Tangential};
pub use pade::Pade;
pub use reference::Exact;
pub use simplified::Simplified;
pub use slip::{Slip, SlipState};
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
pub use {
    best::BestMicromath, coulomb::CoulombMicromath, ellipsoid::EllipsoidMicromath,
    simplified::SimplifiedMicromath,
};

/// Dimensionless friction on body B from body A: `fx`, `fy` in units of fN, `tz` in units of
/// fNa (a = major semi-axis). Contact frame: x along the major axis.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Traction<T> {
    /// F_x/(fN)
    pub fx: T,
    /// F_y/(fN)
    pub fy: T,
    /// T_z/(fNa)
    pub tz: T,
}

/// Larger of two values known not to be NaN: one compare and one select (`Real::max` also
/// tests for NaN, which costs four more instructions on the M4F).
#[inline(always)]
pub(crate) fn larger<T: crate::Real>(a: T, b: T) -> T {
    if b > a { b } else { a }
}
