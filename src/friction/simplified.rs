//! The paper's simplified anisotropic Contensou model (Kosenko & Aleksandrov 2009, §3), with the
//! switch to the regularized Coulomb law g_δ made continuous.
//!
//! # Formula
//!
//! With u = v/(a|ω|), α = cos ψ, β = sin ψ (crate conventions) and the patch [`Constants`]
//! A, B, C:
//!
//! ```text
//! X = −α·min(A u, 1)        Y = −β·min(B u, 1)
//! T = −sgn(ω)·min(C, |T₁|/u),   T₁ = −(1 − e²β²)/5      (plateau −C up to u_z* = |T₁|/C)
//! ```
//!
//! in units of fN and fNa. In dimensional speeds the force pieces are −α·v/max(v, aω·u_x*, δ)
//! and −β·v/max(v, aω·u_y*, δ) (u_x* = 1/A, u_y* = 1/B): each axis follows the spin-induced
//! linear law while its width aω·u* exceeds δ and the regularized Coulomb law g_δ(v) = min(v/δ, 1)
//! below it. The torque is multiplied by min(1, aω·u_T/δ) with u_T = 1/(5C), the largest u_z*.
//!
//! The paper switches all three components to plain g_δ Coulomb (with no torque) at once when
//! aω·u_x*, aω·u_y*, aω·u_z* are all below δ; that jumps (the torque by up to C·fNa, the
//! force wherever v < δ). Switching each component on its own width, as here, equals the paper's
//! Coulomb law for the force wherever all widths are below δ, is continuous everywhere, and
//! fades the spin torque out linearly as aω → 0. With δ = 0 it is exactly the paper's model
//! (up to the 1e-38-relative floor of [`SlipState::d`]).
//!
//! # Domain and special cases
//!
//! Every [`SlipState`]. Pure translation (ω = 0): F = −fN·g_δ(v)·v_P/v, T = 0 (exact Coulomb
//! for δ → 0). Pure spin (v = 0): F = 0, T = −C·fNa·sgn ω (exact for δ → 0). Rest: zero.
//! Passive by construction (each component opposes its own velocity), |F| ≤ fN, continuous
//! (kinked at the switches). Symmetries: ψ → −ψ maps (F_x, F_y, T_z) to (F_x, −F_y, T_z),
//! ψ → ψ + π to (−F_x, −F_y, T_z), ω → −ω to (F_x, F_y, −T_z), all bit-exact.
//!
//! # Error
//!
//! Against the exact integrals ([`Exact`](super::Exact)), δ = 0, max over e² ∈ [0, 0.99], all
//! ψ, u ∈ [0, ∞] (`cargo bench --bench friction`, dense grid through every knee):
//! **0.393 fN** in force (at e² = 0.99, ψ = 0, the knee u = 1/A) and **0.354 fNa** in torque
//! (e² = 0.99, ψ = π/2, u ≈ 0.11, where |T₁| = (1 − e²)/5 makes the plateau end far too
//! early); for a circle (e² = 0) 0.180 fN and 0.073 fNa. `f32` adds < 4e-7.
//!
//! # Cost
//!
//! One square root, three divisions in `f32` (four in `f64`, where the soft-float division is
//! cheaper than the cross-multiplied torque test; a fifth only while the spin is regularized),
//! no transcendental functions. Cortex-M4F, `f32`, patch constants given: **69 instructions**,
//! ≈174 cycles per call including the 8-instruction call floor of the QEMU rig (stage
//! `friction`, `bench-results/cycles.csv`); `f64` (soft float) ≈2,300. Host (x86-64): ≈6–12 ns.
//! The dimensional call [`Friction::tangential`](super::Friction::tangential) (normalisation +
//! core + scaling): 124 instructions (`f32`).

use super::{Constants, SlipState, Traction, larger as max};
use crate::Real;
use crate::math::Backend;

/// The paper's simplified anisotropic model (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Simplified;

/// Which piece of an axis' force law is active.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zone {
    /// v ≥ aω·u* and v ≥ δ: saturated, −α (resp. −β), Coulomb's value.
    Sliding,
    /// aω·u* > v and aω·u* ≥ δ: the spin-induced linear law −αAu (resp. −βBu).
    Spin,
    /// δ > v and δ > aω·u*: the regularized Coulomb slope −α·v/δ (resp. −β·v/δ).
    Regularized,
}

/// Which piece of the torque law is active.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TorqueZone {
    /// u ≤ u_z*: the pure-spin plateau −C.
    Plateau,
    /// u > u_z*: the hyperbola T₁/u.
    Hyperbola,
}

/// The branch of [`Simplified`]: the piece used for each component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Branch {
    /// F_x piece (slope A).
    pub x: Zone,
    /// F_y piece (slope B).
    pub y: Zone,
    /// T_z piece.
    pub tz: TorqueZone,
    /// T_z is scaled by aω·u_T/δ < 1 (spin slower than the regularization speed).
    pub tz_regularized: bool,
}

impl Simplified {
    /// Measured max error against the exact integrals over e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞]
    /// (δ = 0, `f64`): (|F − F_exact|/(fN), |T_z − T_exact|/(fNa)).
    pub const ERROR: (f64, f64) = (0.39261, 0.35389);
}

/// t·spin/d (0 when spin = 0, where t may be NaN from 0·∞ at rest), out of line: keeps the
/// common path free of the division.
#[cold]
#[inline(never)]
fn regularize<T: Real>(t: T, spin: T, d: T) -> T {
    if spin > T::ZERO {
        t * (spin / d)
    } else {
        T::ZERO
    }
}

/// The zone of one axis, from the same comparisons as its denominator
/// max(max(v, d), width).
#[inline(always)]
fn zone<T: Real>(v: T, width: T, d: T) -> Zone {
    if width > max(v, d) {
        Zone::Spin
    } else if d > v {
        Zone::Regularized
    } else {
        Zone::Sliding
    }
}

super::twin::libm_and_micromath! {
    Simplified: "simplified", Branch, maximally_dissipative false,
    slip_ramp
    /// The ramp of width δ (widened, never steepened, by the spin): κ = 1.
    T::ONE,
    spin_ramp
    /// κ_T = 2/5 (see [`Friction::stable_spin_step`](super::Friction::stable_spin_step)).
    T::from_f64(0.4),
    /// [`Simplified`] with micromath's square root for v = √(x² + y²) (feature `micromath`; `f32`
    /// only, libm for `f64`).
    ///
    /// Formula, domain, branches: as [`Simplified`], with v up to 6.07 % too large (never too
    /// small); each component still opposes its own velocity (passive) and |F| ≤ fN holds; `f64` is
    /// [`Simplified`]. Measured (`f32`, 4,329 states: 9 e² ∈ [0, 0.99], 13 ψ, u log-spaced, around
    /// the ellipse and ∞; asserted by host-tests/micromath.rs): against the exact integrals
    /// **0.329 fN / 0.335 fNa** max, the same as [`Simplified`] (whose model error dominates), but
    /// median 3.1e-2 fN (vs 8.6e-4); against [`Simplified`] itself 5.7e-2 fN / 2.6e-2 fNa. Cost:
    /// M4F **73** instructions (`f32`; [`Simplified`] 69), host ≈ 11 ns. Not worth using.
    twin SimplifiedMicromath
}

/// The simplified law with √ from the backend `B`.
#[inline(always)]
fn traction<B: Backend, T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
    let (x, y, w, d) = (s.x(), s.y(), s.w(), s.d());
    let aw = w.abs();
    let xx = x * x;
    let v2 = xx + y * y;
    let v = B::sqrt(v2);
    // Forces: −x/max(v, d, |w|/A) = −α·min(Au, v/d, 1). d > 0, so no 0/0 even at rest.
    let vd = max(v, d);
    let (wx, wy) = (aw * k.knee_x(), aw * k.knee_y());
    // Torque: T = −w·min(C/|w|, q/(5v³)) with q = x² + m₁y² = 5v²|T₁|: the plateau
    // −C·sgn ω, or the hyperbola −w·q/(5v³) = T₁/u (sign of ω included).
    let q = xx + k.m1() * y * y;
    let five_v3 = T::from_f64(5.0) * v2 * v;
    let (hyperbolic, t) = if T::MANTISSA_DIGITS <= 24 {
        // f32 (the M4F's FPU: a division is 14 cycles, a multiply 1): compared
        // cross-multiplied, q·|w| < C·5v³ (|w|, v ≤ √2: no overflow), and only the chosen
        // quotient divided. At v = 0 both sides are 0 and fail `<`: plateau. At ω = 0 (v > 0):
        // hyperbola (= 0).
        let hyperbolic = q * aw < k.spin_torque() * five_v3;
        let (num, den) = if hyperbolic {
            (q, five_v3)
        } else {
            (k.spin_torque(), aw)
        };
        (hyperbolic, num / den)
    } else {
        // f64 (soft float on the M4F, where the two extra multiplies cost more than the
        // division saved): both quotients. At v = 0 the hyperbola is 0/0 or +∞ and fails
        // `<`: plateau. At ω = 0, C/|w| = +∞: hyperbola (= 0).
        let plateau = k.spin_torque() / aw;
        let hyperbola = q / five_v3;
        let hyperbolic = hyperbola < plateau;
        (hyperbolic, if hyperbolic { hyperbola } else { plateau })
    };
    let tz = -w * t;
    // Spin regularization: × min(1, |w|·u_T/d); d > 0. Rare: divide only when it applies
    // (this also covers rest, where the line above is 0·∞).
    let spin = aw * k.knee_z_max();
    let tz_regularized = spin < d;
    let tz = if tz_regularized {
        regularize(tz, spin, d)
    } else {
        tz
    };
    (
        Traction {
            fx: -x / max(vd, wx),
            fy: -y / max(vd, wy),
            tz,
        },
        Branch {
            x: zone(v, wx, d),
            y: zone(v, wy, d),
            tz: if hyperbolic {
                TorqueZone::Hyperbola
            } else {
                TorqueZone::Plateau
            },
            tz_regularized,
        },
    )
}
