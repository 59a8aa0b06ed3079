//! `best`: an exact-grade fast Contensou–Erismann law — the exact quartic while the
//! instantaneous centre (IC) lies inside the ellipse, and outside the exact confocal structure
//! with seven fitted one-dimensional coefficients.
//!
//! # Formula
//!
//! Slip state (x, y, w) (see [`SlipState`]); the exact law's symmetries (F_x odd in x, F_y
//! odd in y, T_z odd in w, even otherwise) are built in: every formula below takes x² and y²,
//! and the signs come from the signed x (in cos ν or Y), y (sin ν or X) and w (τ, or w/|w|).
//! The IC is (X₀, Y₀) = (−y, x)/w.
//!
//! - **IC inside** (x² + m₁y² ≤ m₁w²): the exact quartic
//!   Ψ = C + (B/2)X₀² + (A/2)Y₀² + c₄₀(X₀⁴ + Y₀⁴/m₁) + c₂₂X₀²Y₀²,
//!   c₄₀ = −[(2−m)E − 2m₁K]/(8m²) = −(B − m₁A)/(12m) (Taylor series in m for m < 0.05),
//!   c₂₂ = −(A + 12c₄₀)/2: F_x = −∂Ψ/∂Y₀, F_y = ∂Ψ/∂X₀, T_z = −Ψ + X₀Ψ_X + Y₀Ψ_Y.
//! - **IC outside**: confocal coordinates a_c ≥ 1, ν of the IC (X₀ = −a_c sin ν,
//!   Y₀ = b_c cos ν, b_c² = a_c² − m), q = sin²ν, τ = (1 + γ)/(a_c + b_c) ∈ (0, 1]:
//!   F_x = −cos ν·(a_x + b_x q), F_y = −sin ν·(a_y + b_y q), T_z = τ·(a_T + b_T q + c_T q²).
//!   This structure is exact (re-verified to 2e-14 by `tools/gen_best_table.py`); only the
//!   seven coefficients, smooth functions of (e², z), z = √(1 − τ) ∈ [0, 1], are fitted:
//!   tensor Chebyshev series in (ln γ, z) of degree (8, 10) from the exact integrals
//!   (`best/table.rs`), plus a correction in z² that makes them exact at z = 0 (the ellipse,
//!   from the quartic) and at z = 1 (u = ∞: F = −v_P/|v_P|, T_z = T₁/u). The torque
//!   polynomial is clamped to its passive sign. The exact coefficients leave the ellipse like
//!   z² (they are smooth in a_c); the fit keeps that zero slope in z, so the law has no √-like
//!   onset at the boundary.
//!
//! [`BestContact`] (per contact, e² fixed) interpolates the series once into 8 cubic pieces in z
//! (Chebyshev–Lobatto nodes), so a call outside is four square roots, four or five divisions
//! and seven cubics, and inside one division and the quartic. [`Best`], the [`FrictionLaw`] (e² may change every call), sums the series per call.
//!
//! # Domain and special cases
//!
//! Every [`SlipState`] and every e². The fit covers e² ∈ [0, 0.99]; above that it uses
//! e² = 0.99's shape between exact ends (still exact inside, on the ellipse and at u = ∞), and
//! the error outside grows: measured (`f64`) 3.3e-2 fN / 3.0e-3 fNa at e² = 0.995, 9.3e-2 /
//! 8.1e-3 at 0.999, 0.19 / 1.4e-2 as e² → 1. Everywhere |F| is scaled back onto |F| ≤ 1 where
//! the fit would overshoot it (by up to 4e-4 past 0.99, by rounding below). The dimensionless core ignores δ; the dimensional
//! wrapper ramps it to zero below the slip scale δ ([`FrictionLaw::RAMP_BELOW_DELTA`]). Rest
//! gives zero, pure translation −v_P/|v_P| exactly, pure spin −C·sgn ω exactly.
//! Exact (to rounding) inside the ellipse, on its boundary and as u → ∞; continuous across the
//! boundary and between the cubic pieces (to a few rounding steps); symmetries bit-exact;
//! passive: each component opposes its own velocity (the torque by a clamp; the force brackets
//! a + b·q stay ≥ 0.3 over the table, and the quartic's by its structure), checked on random
//! states with |F| ≤ 1.
//!
//! # Error
//!
//! Against [`exact::traction`](super::exact::traction), max over a dense independent set
//! (`host-tests/friction_best.rs`: 32 values of e² ∈ [0, 0.99] clustered towards 0.99, 29 ψ in
//! all quadrants and on the axes, ≈90 u per direction: log grid 0.01 … 3e2, u_b(1 ± δ) for
//! δ = 1e-9 … 0.3, u ≈ 1, 1e4, 1e7, ∞):
//!
//! | form | force (fN) f64 / f32 | torque (fNa) f64 / f32 |
//! |---|---|---|
//! | [`BestContact`] | 5.2e-5 / 5.2e-5 | 4.0e-6 / 4.1e-6 |
//! | [`Best`] | 1.8e-6 / 2.0e-6 | 7.4e-7 / 8.7e-7 |
//!
//! worst at e² = 0.99 just outside the ellipse (u ≈ 1.03–1.1·u_b), where the coefficients vary
//! fastest in z (there the first cubic piece of [`BestContact`], which keeps the exact zero
//! slope in z at the ellipse, dominates).
//!
//! # Cost
//!
//! Cortex-M4F, `f32`, QEMU stage `friction` (mixed set: u log-uniform in [0.01, 100], ψ uniform,
//! e² = 0.5; the rig's 8-instruction call floor included):
//! [`BestContact::traction`] **107 instructions** on average (63 inside … 172 outside;
//! `simplified`: 66, so 1.62× on average, 2.6× worst on the set; 125 on the same set at
//! e² = 0.99, worst 174); the dimensional `Friction::<f32, Best>::tangential_prepared` 144
//! (`simplified`'s `tangential` 122); the full wrench `Contact::wrench` with fixed geometry 182
//! (144 with `simplified`); [`BestContact::new`] ([`FrictionLaw::prepare`]) 19,281 once per
//! contact; the per-call form [`Best`]`::traction` (e² changing every call) 1,324 on average,
//! 3,103 worst (the 693-term series is summed per call). `f64` (soft float): 5,931 / 87,114 per
//! call. Flash: the table is 7 × 9 × 11 `f32` = 2,772 bytes (+ 64 bytes of series);
//! RAM per contact: `BestContact<f32>` 948 bytes. Host (criterion, x86-64, mixed set): ≈20 ns
//! per call (`BestContact`), ≈100 ns (`Best`); `bench-results/friction.csv`.

mod contact;
mod quartic;
mod series;
mod stiffness;
mod table;
mod varying;
mod varying_table;

pub use contact::BestContact;
#[cfg(feature = "micromath")]
pub use series::BestMicromath;
pub use series::BestSeries;
pub use stiffness::{ramp_stiffness, spin_stiffness};

use super::{Constants, FrictionLaw, SlipState, Traction, larger};
use crate::Real;
use quartic::Quartic;

/// The `best` law with e² read per call (see the [module docs](self)); the per-contact form,
/// much cheaper per call, is [`BestContact`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Best;

/// Where the IC lies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// No slip: zero traction.
    Rest,
    /// IC inside or on the ellipse: the exact quartic.
    Inside,
    /// IC outside (including pure translation): the confocal form.
    Outside,
}

/// Confocal coordinates of the IC for x, y, w (IC outside or pure translation):
/// (cos ν, sin ν, τ, 1 − |τ|), with the signs of x and y on cos ν and sin ν and that of w on τ.
#[inline(always)]
fn confocal<T: Real>(m: T, g1: T, x: T, y: T, w: T) -> (T, T, T, T) {
    let p = x * x + y * y;
    let w2 = w * w;
    let mw2 = m * w2;
    let dlt = p - mw2;
    let mx2w2 = mw2 * x * x;
    let r = (dlt * dlt + T::from_f64(4.0) * mx2w2).sqrt();
    // (a_c w)², (b_c w)² without cancellation
    let a2 = T::HALF * (p + mw2 + r);
    let b2 = if dlt >= T::ZERO {
        T::HALF * (dlt + r)
    } else {
        T::TWO * mx2w2 / (r - dlt)
    };
    let (ac, bc) = (a2.sqrt(), larger(b2.sqrt(), T::MIN_POSITIVE));
    let tau = g1 * w / (ac + bc);
    (x / bc, y / ac, tau, T::ONE - tau.abs())
}

/// Puts the signs back and clamps the coefficients to their passive signs.
#[inline(always)]
fn assemble<T: Real>(c: T, sn: T, tau: T, k: &[T; 7]) -> Traction<T> {
    let q = sn * sn;
    // a + b·q ≥ 0.3 over the fitted domain (tested): no clamp needed for the forces, whose
    // signs come from c = cos ν and sn = sin ν (computed from the signed x and y).
    // τ carries the sign of w; the polynomial is clamped to its passive sign (≤ 0).
    let t = k[4] + q * (k[5] + k[6] * q);
    Traction {
        fx: -c * (k[0] + k[1] * q),
        fy: -sn * (k[2] + k[3] * q),
        tz: tau * if t < T::ZERO { t } else { T::ZERO },
    }
}

/// |F| ≤ 1: past the fitted range (e² > 0.99) the fit can overshoot it by up to 4e-4 (inside
/// the range only by rounding); scale back onto the unit disk (a positive factor: passivity
/// and continuity are kept). One compare on the common path.
#[inline(always)]
fn bounded<T: Real>(t: Traction<T>) -> Traction<T> {
    let f2 = t.fx * t.fx + t.fy * t.fy;
    if f2 > T::ONE { rescale(t, f2) } else { t }
}

#[cold]
#[inline(never)]
fn rescale<T: Real>(t: Traction<T>, f2: T) -> Traction<T> {
    let r = T::ONE / f2.sqrt();
    Traction {
        fx: t.fx * r,
        fy: t.fy * r,
        tz: t.tz,
    }
}

/// Inside branch or rest: `None` when the IC is outside. The forces take their signs from the
/// signed x, y (F_x odd in x, F_y odd in y, both even in the rest), the torque from w.
#[inline(always)]
fn inside<T: Real>(q: &Quartic<T>, s: &SlipState<T>) -> Option<(Traction<T>, Branch)> {
    let (x, y, w) = (s.x(), s.y(), s.w());
    if x * x + q.m1 * y * y > q.m1 * w * w {
        return None;
    }
    if w == T::ZERO {
        return Some((Traction::default(), Branch::Rest));
    }
    let iw = T::ONE / w.abs();
    let (fx, fy, tz) = q.eval(y * iw, x * iw);
    // Exact: the brackets of fx, fy are > 0 and tz ≤ −0.003 (e² = 0.99) by the quartic's
    // structure.
    Some((
        Traction {
            fx: -fx,
            fy: -fy,
            // tz < 0; w/|w| = ±1 up to one rounding, exactly odd in w
            tz: tz * (w * iw),
        },
        Branch::Inside,
    ))
}

/// Both per-call forms: the quartic inside the ellipse, the confocal structure outside with
/// the seven coefficients from `coefficients(quartic, γ, z)` (the flash table for [`Best`],
/// the series for [`BestSeries`]).
#[inline(always)]
fn per_call<T: Real>(
    k: &Constants<T>,
    s: &SlipState<T>,
    coefficients: impl FnOnce(&Quartic<T>, T, T) -> [T; 7],
) -> (Traction<T>, Branch) {
    let q = Quartic::new(k);
    if let Some(r) = inside(&q, s) {
        return r;
    }
    let gamma = k.m1().sqrt();
    let g1 = T::ONE + gamma;
    let (c, sn, tau, one_minus) = confocal(k.m(), g1, s.x(), s.y(), s.w());
    let z = larger(one_minus, T::ZERO).sqrt();
    let co = coefficients(&q, gamma, z);
    (bounded(assemble(c, sn, tau, &co)), Branch::Outside)
}

impl Best {
    /// Measured max error of the per-step form ([`FrictionLaw::traction`], the flash table)
    /// against the exact integrals, e² ∈ [0, 0.99], all ψ, u ∈ [0, ∞], both precisions:
    /// (force in fN, torque in fNa), asserted by `host-tests/friction_best.rs` and
    /// `host-tests/friction_best_varying.rs`.
    pub const ERROR: (f64, f64) = (3.0e-5, 1.0e-5);
}

impl FrictionLaw for Best {
    const NAME: &'static str = "best";
    type Branch = Branch;
    type Prepared<T: Real> = BestContact<T>;
    const RAMP_BELOW_DELTA: bool = true;

    /// The per-step form (e² may change every call): the seven outside coefficients
    /// interpolated in the flash table over (m₁^¼, z) (see the [module docs](self)).
    #[inline(always)]
    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        per_call(k, s, varying::coefficients)
    }

    /// Build the per-contact tables ([`BestContact::new`]).
    fn prepare<T: Real>(k: &Constants<T>) -> BestContact<T> {
        BestContact::new(k)
    }

    /// The per-contact form: [`BestContact::traction`].
    #[inline(always)]
    fn traction_prepared<T: Real>(p: &BestContact<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        p.traction(s)
    }
}
