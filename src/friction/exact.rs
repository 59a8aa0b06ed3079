//! The exact Contensou–Erismann integrals (reference path): the paper's (1.3)–(1.4) over the
//! Hertz ellipse, to ≈1e-14 in f64.
//!
//! # Formula
//!
//! τ = −fσ v_M/|v_M| with the Hertz pressure σ ∝ √(1 − x²/a² − y²/b²) and
//! v_M = (v_Px − ωy, v_Py + ωx) (crate conventions); F = ∬τ dA, T_z = ∬(xτ_y − yτ_x) dA.
//! The slip field is a rotation about the instantaneous centre (IC)
//! (X₀, Y₀) = (−v_Py, v_Px)/(aω) = u(−sin ψ, cos ψ). Two branches:
//!
//! - **IC inside** the ellipse (vy² + vx²/m₁ ≤ (aω)²): the quartic polynomial in (X₀, Y₀) of
//!   `inside` (closed form; K, E, B, D by [`Agm`]).
//! - **IC outside**: polar coordinates about the IC with closed-form radial integrals and a
//!   Gauss–Legendre rule of 64–96 nodes (up to 192 when e² > 0.9999) over the ray angle
//!   (`outside`).
//! - **u > 1e5** (aω < 1e-5·|v_P|, including aω = 0): the large-u series
//!   F = −w + F₂/u², T_z = T₁/u (paper §2: F₂ = −(1/5){−w/2 − e²[((3/2)α² − 1/2)w − α i]},
//!   T₁ = −(1 − e²β²)/5), whose next terms are O(u⁻⁴) and O(u⁻³) < 1e-15.
//!
//! Symmetries are applied exactly, by reduction to v_Px, v_Py, aω ≥ 0: F_x is odd in v_Px,
//! F_y odd in v_Py, T_z odd in ω, and every other dependence on those signs is even
//! (mirror images of the patch about its axes).
//!
//! # Domain and special cases
//!
//! Any [`Parameter`] (e² up to 1 − 1e-12; accuracy measured to m₁ = 1 − e² = 1.5e-12) and any finite
//! (vx, vy, a_omega); the result is homogeneous of degree 0 (the inputs are scaled by their
//! largest magnitude first, so no overflow or underflow). All three zero → zero traction.
//! Non-finite inputs → zero traction (validate before; the dimensional wrapper does).
//! Pure spin: F = 0, T_z = −(3/8)E(m)·sign ω; pure translation: F = −v_P/|v_P|, T_z = 0.
//! Continuous across the ellipse boundary (the two branches agree there to ≈1e-15).
//!
//! # Error
//!
//! Measured against the independent brute-force reference `tools/data/friction_ref.csv` and
//! `friction_ref_random.csv` (`tools/gen_friction_ref.py`: 2-D tanh-sinh over the patch in
//! 80-bit arithmetic, converged to 1.7e-15; 561 structured points — e² ∈ {0, 0.3, 0.687, 0.9,
//! 0.99, 0.9999, 1 − 1e-8, 1 − 1.5e-12}, ψ in all quadrants, u ∈ {0} ∪ [1e-3, 1e3] ∪
//! {u_b(1 ± 1e-6), ∞} — plus 300 random ones with u ∈ [1e-2, 1e2]): max abs error 5.0e-15 in fN
//! and fNa (`f64`), 6.6e-7 (`f32`, with e² and the inputs rounded to `f32`). Jump across the
//! ellipse boundary (u_b(1 ± 1e-12)): 1.1e-12, i.e. the slope times the step. Checked in
//! `host-tests/friction_exact.rs`.
//!
//! # Precision and cost
//!
//! Computed internally in `f64` for both `f32` and `f64` (reference path; the `f32` result is
//! the rounded `f64` one). Cost on the host (x86-64, release, criterion, e² = 0.687): ≈75 ns
//! inside (mostly the AGM for K, E), ≈5 µs (u = 30) to ≈10 µs (u = 1.5) outside (each node two
//! `sincos`, a square root and a `sinh`/`cosh` pair), 50 ns in the large-u branch; `f32` the
//! same plus conversions. Not for the per-step hot path. Cortex-M4F (QEMU, the friction
//! stage's 64-state mixed set at e² = 0.5): 424,014 instructions per call on average (`f32`;
//! 424,118 `f64`: the same f64 soft-float code), against 107 for [`super::BestContact`].

mod gauss;
mod inside;
mod outside;

use super::Traction;
use crate::Real;
use crate::elliptic::{Agm, Method, Parameter};

/// The large-u series F = −w + F₂/u², T_z = T₁/u is used only for u = v/(aω) > this value.
///
/// The series converges only for u > 1 (model.md §3). Measured against this module's
/// quadrature (`examples/stability.rs` → `docs/report/stability/large_u_series.csv`, max over
/// 25 ψ ∈ [0, π/2] and e² ∈ {0, 0.687, 0.99}): the two-term force errs by 11 fN at u = 0.1
/// (it grows like 1/u², past the bound |F| ≤ fN), 3.1e-2 fN at u = 1, 3.4e-4 at u = 3.2,
/// 3.5e-6 at 10, 3.5e-10 at 100, 6.7e-16 at 1e4; the torque T₁/u by 1.6 fNa at u = 0.1,
/// 3.5e-2 at 1, 4.2e-5 at 10, 4.2e-14 at 1e4 (next term O(u⁻³)), so below 1e-16 past the
/// switch. No approximate law evaluates F₂; [`Simplified`](super::Simplified) and
/// [`Pade`](super::Pade) use T₁ as the torque's asymptote by design (the paper's model; their
/// stated model error includes it). Checked in `host-tests/stability.rs` (continuity across the
/// switch; the series alone is far off the reference where the quadrature is used).
pub const SERIES_MIN_U: f64 = 1e5;

/// Exact dimensionless traction (force / fN, torque / fNa) on body B from body A over the
/// Hertz ellipse with semi-axes a (along x) and b = a·√m₁, for a slip state given by the
/// centre's slip velocity (vx, vy) and a·ω (all in the same units; the result is homogeneous of
/// degree 0 in (vx, vy, a_omega); all three zero → zero traction).
///
/// See the [module docs](self) for the method, the measured error (5e-15 vs the reference)
/// and the cost (µs: reference path, not for per-step use).
pub fn traction<T: Real>(p: Parameter<T>, vx: T, vy: T, a_omega: T) -> Traction<T> {
    let (fx, fy, tz) = traction_f64(
        p.m().to_f64(),
        p.m1().to_f64(),
        vx.to_f64(),
        vy.to_f64(),
        a_omega.to_f64(),
    );
    Traction {
        fx: T::from_f64(fx),
        fy: T::from_f64(fy),
        tz: T::from_f64(tz),
    }
}

fn traction_f64(m: f64, m1: f64, vx: f64, vy: f64, w: f64) -> (f64, f64, f64) {
    let scale = vx.abs().max(vy.abs()).max(w.abs());
    if !(vx.is_finite() && vy.is_finite() && w.is_finite() && scale > 0.0) {
        return (0.0, 0.0, 0.0);
    }
    let (x, y, om) = (vx.abs() / scale, vy.abs() / scale, w.abs() / scale);
    let (fx, fy, tz) = first_quadrant(m, m1, x, y, om);
    // exact symmetries: F_x odd in vx, F_y odd in vy, T_z odd in ω
    let odd = |f: f64, s: f64| {
        if s > 0.0 {
            f
        } else if s < 0.0 {
            -f
        } else {
            0.0
        }
    };
    (odd(fx, vx), odd(fy, vy), odd(tz, w))
}

/// vx, vy, w ≥ 0, max = 1.
fn first_quadrant(m: f64, m1: f64, vx: f64, vy: f64, w: f64) -> (f64, f64, f64) {
    let v = libm::hypot(vx, vy);
    if w < v / SERIES_MIN_U {
        return large_u(m, vx / v, vy / v, w / v);
    }
    if vy * vy + vx * vx / m1 <= w * w {
        let i = match Parameter::from_complement(m1) {
            Ok(p) => Agm::integrals(p),
            // unreachable: every valid Parameter<T> has m₁ ∈ [2⁻²⁴, 1] ⊂ the f64 domain
            Err(_) => return (0.0, 0.0, 0.0),
        };
        return inside::Quartic::new(m, m1, &i).traction(-vy / w, vx / w);
    }
    outside::traction(m, m1, vx, vy, w)
}

/// F = −w + F₂/u², T_z = T₁/u (α = cos ψ, β = sin ψ, eps = 1/u ≤ 1e-5).
fn large_u(m: f64, al: f64, be: f64, eps: f64) -> (f64, f64, f64) {
    let e2 = eps * eps;
    let p2 = 1.5 * al * al - 0.5;
    let f2x = 0.2 * (0.5 * al + m * (p2 * al - al));
    let f2y = 0.2 * (0.5 * be + m * p2 * be);
    (
        -al + f2x * e2,
        -be + f2y * e2,
        -0.2 * (1.0 - m * be * be) * eps,
    )
}
