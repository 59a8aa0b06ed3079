//! Step limits: what the plain (explicit) path needs, for each of the contact's stiff modes,
//! and what the step-aware path tolerates.
//!
//! # The plain path: three stiff modes
//!
//! An explicit integrator calling the plain wrench every (sub)step is stable only while each
//! of the contact's modes is: the step must stay below the **smallest** of
//!
//! | mode | rate | limit (this module) |
//! |---|---|---|
//! | Hertz normal mode, k_n = dN/dh = (3/2)·N/h = (3/2)·k_H^{2/3}·N^{1/3} | ω = √(k_n/m_n), an undamped oscillation | [`normal_step`]: limit_osc/ω (RK4 2√2, semi-implicit Euler 2, forward Euler 0: it grows every undamped oscillation) |
//! | regularised friction, F = −κ·fN·v/δ below δ | fN·κ/(δ·m_t), a decay | [`crate::contact::Contact::stable_step`] (and `stable_spin_step` for the spin) |
//! | creep (Kalker's linear theory), F = −G·c²·C₁₁·v/V | G·c²·max(C₁₁, C₂₂)/(V·m_t), a decay | [`creep_step`]: limit/rate (Euler 2, RK4 2.785) |
//!
//! m_n, m_t are the effective masses at the contact point along the normal and the tangent
//! (1/W_nn, 1/W_xx of [`super::InverseMass`]: 2m/7 for a ball rolling on its surface along
//! the tangent). Measured where the issue that introduced them was filed (RK4, the scenes'
//! own setups): the bearing's creep contact needs ≈ 0.2 µs, the tippe top's normal mode
//! ≈ 0.15 ms.
//!
//! # The step-aware path
//!
//! [`super::step_wrench`] takes the contact's stiffness into the step (linearly implicit
//! backward Euler, normal direction included): **no stability limit from the contact's own
//! modes** (normal, friction ramp, creep), for any Δt, given a W that is the bodies' true inverse
//! mass at the contact (a W too small by a factor r is a mass r× too large: the step then
//! over-damps, never explodes). What it does not remove:
//!
//! - **Accuracy is first order** (backward Euler): the normal mode is resolved only for
//!   Δt ≲ T_n/10 ([`normal_period`]); above that the oscillation is damped numerically (an
//!   undamped mode's amplitude × 1/√(1 + (ωΔt)²) per step): a bounce loses energy, a resting
//!   contact settles at once. The contact's force is still right on average (momentum).
//! - **The slip's own change within the step** is the caller's u_free: a contact point running
//!   fast over a curved surface or a gyroscopic turn of ω that the caller leaves out of u_free
//!   is an error of order Δt·(that rate) in the friction's direction.
//! - **The rigid body's own update** (e.g. a fast-spinning top needs an exact torque-free
//!   rotation at 1 ms).
//! - **The Newton part** has a fixed count ([`super::LINEARISATIONS`],
//!   [`super::PREDICTOR_STEPS`]): measured on a ball under gravity at 5 ms (h_free ≈ 3,000×
//!   the static approach), N within 1.8e-9 of the nonlinear backward-Euler step.

use crate::Real;
use crate::friction::Explicit;
use crate::friction::rolling::{Elasticity, Kalker};
use crate::normal::NormalLaw;

/// The stability limit h·ω of an explicit scheme on an undamped oscillation (the imaginary
/// axis): forward Euler 0 (|1 + iωh| > 1 for every h > 0), RK4 2√2 = 2.8284.
/// Semi-implicit (symplectic) Euler, not an [`Explicit`] variant, has 2.
pub const fn oscillation_limit(scheme: Explicit) -> f64 {
    match scheme {
        Explicit::Euler => 0.0,
        Explicit::Rk4 => 2.828_427_124_746_190_3,
    }
}

/// The angular frequency ω = √(k_n/m) of the normal mode of a mass `mass` (kg; the effective
/// mass 1/W_nn at the contact) resting on `normal` at load `n` (N): k_n = (3/2)·k_H^{2/3}·n^{1/3}.
/// Host/construction use (a `cbrt`). 0 for n ≤ 0 or mass ≤ 0 (no mode).
pub fn normal_omega<T: Real, N: NormalLaw<T>>(normal: &N, mass: T, n: T) -> T {
    if !(n > T::ZERO && mass > T::ZERO) {
        return T::ZERO;
    }
    let h = normal.approach(n);
    if !(h > T::ZERO) {
        return T::ZERO;
    }
    let kn = T::from_f64(1.5) * n / h;
    let w = (kn / mass).sqrt();
    if w.is_finite() { w } else { T::ZERO }
}

/// The period 2π/ω of the normal mode ([`normal_omega`]); `T::MAX` where there is no mode.
pub fn normal_period<T: Real, N: NormalLaw<T>>(normal: &N, mass: T, n: T) -> T {
    let w = normal_omega(normal, mass, n);
    if w > T::ZERO {
        T::TWO * T::PI / w
    } else {
        T::MAX
    }
}

/// The largest stable step of an explicit `scheme` for the undamped normal mode at load `n`
/// (see the [module docs](self)): [`oscillation_limit`]/ω; 0 for forward Euler (no stable
/// step); `T::MAX` with no mode (n ≤ 0). Damping (Hunt–Crossley) moves the mode off the
/// imaginary axis and does not enlarge RK4's limit by more than its real-axis margin; use this
/// as the bound. For semi-implicit Euler multiply [`normal_period`] by 1/π (2/ω).
pub fn normal_step<T: Real, N: NormalLaw<T>>(normal: &N, mass: T, n: T, scheme: Explicit) -> T {
    let w = normal_omega(normal, mass, n);
    if w > T::ZERO {
        T::from_f64(oscillation_limit(scheme)) / w
    } else {
        T::MAX
    }
}

/// The largest stable step of an explicit `scheme` for the creep of a rolling contact (Kalker's
/// linear theory, the stiffest part of every rolling law here): the creep force
/// F = −G·c²·C·v/V (c = √(ab), C = max(C₁₁, C₂₂) for the patch a/b along the rolling direction)
/// is a damper of rate G·c²·C/(V·m) on the slip of an effective mass `mass` (kg, 1/W_xx);
/// the step is [`Explicit::limit`]·m·V/(G·c²·C). `speed` = |V| (m/s), `a_along`, `b_across`
/// the patch's semi-axes along and across V (m). 0 for V = 0 (no creep: then the full-slip
/// law's own ramp, [`crate::contact::Contact::stable_step`]); `T::MAX` for a point patch; 0 for
/// `mass` ≤ 0. Host/construction use (Kalker's coefficients in `f64`).
pub fn creep_step<T: Real>(
    elasticity: &Elasticity<T>,
    a_along: T,
    b_across: T,
    speed: T,
    mass: T,
    scheme: Explicit,
) -> T {
    if !(mass > T::ZERO) || !(speed > T::ZERO) {
        return T::ZERO;
    }
    if !(a_along > T::ZERO && b_across > T::ZERO) {
        return T::MAX;
    }
    let ratio = (a_along / b_across).clamp_to(T::from_f64(0.01), T::from_f64(100.0));
    let k = Kalker::new(ratio, elasticity.nu());
    let c2 = a_along * b_across;
    let rate = elasticity.g() * c2 * k.c11.max(k.c22) / (speed * mass);
    let h = T::from_f64(scheme.limit()) / rate;
    if h.is_finite() && h > T::ZERO {
        h
    } else {
        T::MAX
    }
}
