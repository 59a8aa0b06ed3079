//! The stiffness bounds of `best`'s ramped law (for the stable explicit steps).
//!
//! Below c·δ (c = 3/8) the wrapper scales the core by p/(c·δ), p = −(F·v_P + T_z·ω)/(fN) the
//! full-slip law's own dissipation per unit fN
//! ([`FrictionLaw::RAMP_BELOW_DELTA`](crate::friction::FrictionLaw::RAMP_BELOW_DELTA)). For the
//! exact law p = D(v_P, aω) = ∫σ|v_M| dA/N, convex and homogeneous of degree one, and the core
//! is −∇D; so the ramped law is the gradient F = −(fN/(cδ))·∇_v G,
//! T_z/a = −(fN/(cδ))·∂G/∂(aω) of G = D²/2, and its stiffness matrix
//! −∂(F, T_z/a)/∂(v_P, aω) = (fN/δ)·(8/3)·∇²G is symmetric positive semidefinite and depends
//! on the slip direction only. While the instantaneous
//! centre (IC) (X, Y) = (−v_Py, v_Px)/(aω) lies inside the ellipse, D = a|ω|·Ψ(X, Y) with Ψ
//! the exact quartic (`best` is exact there), so G = (aω)²Ψ²/2:
//!
//! - the translational block is the Hessian of g = Ψ²/2 in (Y, X):
//!   g_XX = Ψ_X² + Ψ·Ψ_XX, g_YY = Ψ_Y² + Ψ·Ψ_YY, g_XY = Ψ_X·Ψ_Y + Ψ·Ψ_XY;
//! - the spin entry is ∂²G/∂(aω)² = (1 − E)(2 − E)·g, E = X∂_X + Y∂_Y (Euler's operator):
//!   with Ψ = C + Q₂ + Q₄ (its homogeneous parts),
//!   k_T = C² + 3(Q₂² + 2C·Q₄) + 20·Q₂Q₄ + 21·Q₄².
//!
//! κ and κ_T are 8/3 times their maxima over the inside region, found by `maximise` (a grid and pattern searches). With the IC
//! outside the ellipse, and past the ramp (p ≥ δ: fN/p times the core's own stiffness, whose
//! sup is lower), the stiffness is smaller: checked on the whole direction sphere, for the
//! exact law and for `best` (`host-tests/stability.rs`).

use super::quartic::Quartic;
use crate::Real;
use crate::friction::law::RAMP_GAIN;
use crate::friction::{Constants, larger};

/// Grid points over ρ and θ, and pattern-search moves, of [`maximise`].
const GRID_RHO: usize = 32;
const GRID_THETA: usize = 64;
const MOVES: usize = 200;

/// The quartic's value and derivatives at the IC (X, Y) (first quadrant):
/// (Q₂, Q₄, Ψ, Ψ_X, Ψ_Y, Ψ_XX, Ψ_YY, Ψ_XY).
fn parts<T: Real>(q: &Quartic<T>, x: T, y: T) -> [T; 8] {
    let (x2, y2) = (x * x, y * y);
    let three = T::from_f64(3.0);
    let q2 = q.hb * x2 + q.ha * y2;
    // c₄₀ = k40/4, c₂₂ = k22/2: Q₄ = c₄₀(X⁴ + Y⁴/m₁) + c₂₂X²Y² = (t40·X⁴ + t22·X²Y² + t40m·Y⁴)/3
    let q4 = (x2 * (q.t40 * x2 + q.t22 * y2) + q.t40m * y2 * y2) / three;
    let px = x * (q.b + q.k40 * x2 + q.k22 * y2);
    let py = y * (q.a + q.k40m * y2 + q.k22 * x2);
    let pxx = q.b + three * q.k40 * x2 + q.k22 * y2;
    let pyy = q.a + three * q.k40m * y2 + q.k22 * x2;
    let pxy = T::TWO * q.k22 * x * y;
    [q2, q4, q.c + q2 + q4, px, py, pxx, pyy, pxy]
}

/// The larger eigenvalue of the translational block ∇²g at the IC (X, Y).
fn slip_block<T: Real>(q: &Quartic<T>, x: T, y: T) -> T {
    let [_, _, psi, px, py, pxx, pyy, pxy] = parts(q, x, y);
    let gxx = px * px + psi * pxx;
    let gyy = py * py + psi * pyy;
    let gxy = px * py + psi * pxy;
    let half = T::HALF * (gxx - gyy);
    T::HALF * (gxx + gyy) + (half * half + gxy * gxy).sqrt()
}

/// The spin entry k_T at the IC (X, Y).
fn spin_entry<T: Real>(q: &Quartic<T>, x: T, y: T) -> T {
    let [q2, q4, ..] = parts(q, x, y);
    let c = q.c;
    c * c
        + T::from_f64(3.0) * (q2 * q2 + T::TWO * c * q4)
        + T::from_f64(20.0) * q2 * q4
        + T::from_f64(21.0) * q4 * q4
}

/// The maximum of `f(X, Y)` over the first quadrant of the inside region X² + Y²/m₁ ≤ 1,
/// parametrised X = ρ cos θ, Y = γρ sin θ, (ρ, 2θ/π) ∈ [0, 1]²: a 33 × 65 grid, then a
/// pattern search (eight neighbours at a step halved whenever none improves; 200 moves, from
/// the grid's spacing down to ≈ 1e-13 of the square) from the grid's best point, and a
/// search along each axis (θ = 0, π/2; two neighbours) from its best grid point — where the
/// maxima of thin patches lie. A fixed amount of work.
fn maximise<T: Real>(k: &Constants<T>, f: impl Fn(T, T) -> T) -> T {
    let gamma = k.m1().sqrt();
    let at = |r: T, t: T| {
        let (s, c) = (t * T::FRAC_PI_2).sin_cos();
        f(r * c, gamma * r * s)
    };
    let (nr, nt) = (T::from_usize(GRID_RHO), T::from_usize(GRID_THETA));
    let origin = (T::ZERO, T::ZERO, at(T::ZERO, T::ZERO));
    // [overall, on θ = 0, on θ = π/2]
    let mut starts = [origin; 3];
    for i in 0..=GRID_RHO {
        for j in 0..=GRID_THETA {
            let (r, t) = (T::from_usize(i) / nr, T::from_usize(j) / nt);
            let v = at(r, t);
            let slot = [true, j == 0, j == GRID_THETA];
            for (start, on) in starts.iter_mut().zip(slot) {
                if on && v > start.2 {
                    *start = (r, t, v);
                }
            }
        }
    }
    let clamp = |x: T| larger(x, T::ZERO).min(T::ONE);
    let one = T::ONE;
    let moves = [
        (one, T::ZERO),
        (-one, T::ZERO),
        (T::ZERO, one),
        (T::ZERO, -one),
        (one, one),
        (-one, -one),
        (one, -one),
        (-one, one),
    ];
    let mut top = origin.2;
    // The axis starts search along their axis only: near an axis the maxima of the thin
    // patches sit on a ridge X ≈ const that curves in (ρ, θ), which a pattern search would
    // follow only with ever smaller steps.
    for (n, mut best) in starts.into_iter().enumerate() {
        let mut step = T::ONE / nr;
        let dirs = if n == 0 { &moves[..] } else { &moves[..2] };
        for _ in 0..MOVES {
            let mut moved = false;
            for &(dr, dt) in dirs {
                let (r, t) = (clamp(best.0 + dr * step), clamp(best.1 + dt * step));
                let v = at(r, t);
                if v > best.2 {
                    best = (r, t, v);
                    moved = true;
                    break;
                }
            }
            if !moved {
                step = T::HALF * step;
            }
        }
        top = larger(top, best.2);
    }
    top
}

/// κ(e²): the largest stiffness of `best`'s ramped law in units of fN/δ — the supremum, over
/// every slip direction and every spin ratio, of the largest eigenvalue of the translational
/// block −(δ/fN)·∂F/∂v_P (symmetric positive semidefinite: the Hessian of G = D²/2, see
/// [`FrictionLaw::RAMP_BELOW_DELTA`](crate::friction::FrictionLaw::RAMP_BELOW_DELTA)). The stable explicit step
/// ([`Friction::stable_step`](crate::friction::Friction::stable_step) for `Best`) is
/// limit·mδ/(κ·fN).
///
/// # Formula
///
/// κ = (8/3)·max over the IC (X, Y) inside the ellipse of the larger eigenvalue of the
/// Hessian of Ψ²/2 (Ψ the exact quartic), by `maximise` (a grid and pattern searches). Pure translation gives 8/3
/// (G = |v_P|²/2), rest with spin (8/3)·C·diag(A, B); the maximum lies in between, on the
/// minor-axis slip direction (IC on the major axis) once e² > 0: 3.205 for a circle (IC at
/// 0.81a), 3.316 at e² = 0.5, 3.755 at 0.9, 5.317 at 0.99, 10.40 at the contract's end
/// (m₁ = 1.70e-5) — against 2.522, 2.694, 3.492, 5.187, 10.71 for the former ramp by the ℓ¹
/// slip speed (+27 % … −3 %).
/// With the IC outside the ellipse, or past the ramp, the stiffness is smaller (checked on the
/// whole direction sphere, `host-tests/stability.rs`).
///
/// # Domain and accuracy
///
/// Every valid e²; finite and ≥ 8/3. Against the maximisation of `tools/gen_ramp_stiffness.py`
/// (mpmath; `tools/data/best_stiffness.csv`, m₁ from 1 to 1e-12): within 1e-12 (`f64`) and
/// 1e-6 (`f32`) relative, asserted by `host-tests/stability.rs`. Cost: ≈ 2,300 evaluations of
/// the quartic's Hessian (one square root each) and as many sine–cosines, plus three pattern
/// searches (≤ 4,800 more) — construction or host
/// use, not per step; not measured on the Cortex-M4F.
pub fn ramp_stiffness<T: Real>(k: &Constants<T>) -> T {
    let q = Quartic::new(k);
    T::from_f64(RAMP_GAIN) * maximise(k, |x, y| slip_block(&q, x, y))
}

/// κ_T(e²): the largest torque stiffness of `best`'s ramped law in units of fN·a²/δ — the
/// supremum, over every slip direction and every spin ratio, of −(δ/(fN·a²))·∂T_z/∂ω with v_P
/// held fixed (the spin entry of the Hessian of G = D²/2, see [`FrictionLaw::RAMP_BELOW_DELTA`](crate::friction::FrictionLaw::RAMP_BELOW_DELTA)). The
/// stable explicit step for the spin
/// ([`Friction::stable_spin_step`](crate::friction::Friction::stable_spin_step) for `Best`) is
/// limit·Iδ/(κ_T·fN·a²).
///
/// # Formula
///
/// κ_T = (8/3)·max over the IC (X, Y) inside the ellipse of
/// k_T = C² + 3(Q₂² + 2C·Q₄) + 20·Q₂Q₄ + 21·Q₄² (Q₂ = (B/2)X² + (A/2)Y²,
/// Q₄ = c₄₀(X⁴ + Y⁴/m₁) + c₂₂X²Y²), by `maximise` (a grid and pattern searches). Pure spin gives (8/3)·C² (the plateau
/// −C·fNa ramped over C·a|ω| < 3δ/8); the maximum lies with the IC inside the patch at
/// ≈ 0.76–0.81 of the way to its edge: 1.226 for a circle (1.32× pure spin), 1.029 at
/// e² = 0.5, 0.842 at 0.9, 0.775 at 0.99, 0.760 at the contract's end (≈ 2.03× pure spin) —
/// against 1.141, 0.963, 0.810, 0.752, 0.736 for the former ramp (+7 … +3 %).
///
/// # Domain and accuracy
///
/// Every valid e²; finite, ≥ (8/3)·C². Against `tools/gen_ramp_stiffness.py`
/// (`tools/data/spin_stiffness.csv`): within 1e-12 (`f64`) and 1e-6 (`f32`) relative. Cost as
/// [`ramp_stiffness`] (host ≈ 30 µs) — construction or host use.
pub fn spin_stiffness<T: Real>(k: &Constants<T>) -> T {
    let q = Quartic::new(k);
    T::from_f64(RAMP_GAIN) * maximise(k, |x, y| spin_entry(&q, x, y))
}
