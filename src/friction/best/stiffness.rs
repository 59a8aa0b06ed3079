//! The stiffness bounds of `best`'s ramped law (for the stable explicit steps).

use super::quartic::Quartic;
use crate::Real;
use crate::friction::{Constants, larger};

/// κ(e²): the largest stiffness of `best`'s ramped law in units of fN/δ — the supremum, over
/// every slip direction and every spin ratio aω/δ ∈ [0, ∞), of the largest eigenvalue of the
/// translational Jacobian −(δ/fN)·∂F/∂v_P. The stable explicit step
/// ([`Friction::stable_step`](crate::friction::Friction::stable_step) for `Best`) is limit·mδ/(κ·fN).
///
/// # Formula
///
/// With D′ = (A − B)/m = −2c₂₂ (the quartic's coefficient; 3π/32 at m = 0), γ = √m₁:
///
/// ```text
/// ρ* = A/(D′ + √(D′² + 3AD′)),   κ_axis = (1 + ρ*)(A − D′ρ*²),
/// κ = κ_axis·(1 + γ^{3/2}·(0.3861 + 0.0259γ))
/// ```
///
/// # Why
///
/// Below the slip scale (s = |v_Px| + |v_Py| + a|ω| < δ) the wrapper scales the core by s/δ,
/// so F = −(fN/δ)·s·P(v, aω) with P the core's (−F_x, −F_y)/(fN): homogeneous of degree one,
/// its Jacobian K = s·∂P/∂v + P·σᵀ (σ = the signs of v_P, from ∂s/∂v) depends on the direction
/// of (v_P, aω) only. While the instantaneous centre lies inside the ellipse, P is the exact
/// quartic's gradient, so K is a polynomial matrix in (X₀, Y₀) = (−v_Py, v_Px)/(aω). At rest
/// with spin K = diag(A, B); without spin (pure translation) its eigenvalues are
/// |cos ψ| + |sin ψ| ≤ √2 (the ℓ¹ slip scale). Neither is the maximum: s grows with the slip
/// while the core's slope falls off slowly, and their product peaks in between — for a circle
/// with the IC at 0.66a on a diagonal (κ = 2.5135 = 2.13·A), moving onto the major axis as
/// e² → 1. On that axis (v_Px = 0) K is triangular and its first eigenvalue is
/// (1 + ρ)(A − D′ρ²) at |X₀| = ρ, maximal at ρ*: the closed form κ_axis, the exact sup in the
/// limit e² → 1 (≈ (32/27)·A once A ≫ B). The fitted factor 1 + γ^{3/2}·(0.3861 + 0.0259γ)
/// bounds the excess of the off-axis maximum (0 as e² → 1, 40.7 % at the circle). With the IC
/// outside the ellipse, and past the ramp (s ≥ δ: fN/s times the core's own stiffness, whose
/// sup is lower), the stiffness is smaller: checked on the whole direction sphere, for the
/// exact law and for `best` (`host-tests/stability.rs`, e² from the circle to the contract's
/// end m₁ = 1.70e-5: sup 10.694 against κ = 10.709 there; complex eigenvalue pairs, small, are
/// counted by Euler's |λ|²/Re λ). `best` is exact inside the ellipse, so its κ is the exact
/// law's.
///
/// # Domain and accuracy
///
/// Every valid e² (m₁ ∈ [m₁_min, 1]); finite and ≥ 2.51. Against the maximisation of
/// `tools/gen_best_stiffness.py` (mpmath; `tools/data/best_stiffness.csv`, m₁ from 1 to 1e-12):
/// never below it (`f64`; `f32` to rounding), at most 0.35 % above (conservative). Values:
/// 2.522 (circle; exact sup 2.5135), 2.694 (e² = 0.5), 3.492 (0.9), 5.187 (0.99), 7.131 (0.999),
/// 25.48 (m₁ = 1e-12). Cost: three square roots, four divisions (three in the quartic's
/// constants) and a few multiplications — construction or host use, not per step; not yet
/// measured on the Cortex-M4F.
pub fn ramp_stiffness<T: Real>(k: &Constants<T>) -> T {
    let q = Quartic::new(k);
    let a = q.a;
    // D′ = −k₂₂ = −2c₂₂ > 0 (c₂₂: the quartic's X₀²Y₀² coefficient), free of cancellation at
    // small m.
    let dp = -q.k22;
    let rho = a / (dp + (dp * dp + T::from_f64(3.0) * a * dp).sqrt());
    let axis = (T::ONE + rho) * (a - dp * rho * rho);
    let gamma = k.m1().sqrt();
    let fit = T::from_f64(0.3861) + T::from_f64(0.0259) * gamma;
    axis * (T::ONE + gamma * gamma.sqrt() * fit)
}

/// κ_T(e²): the largest torque stiffness of `best`'s ramped law in units of fN·a²/δ — the
/// supremum, over every slip direction and every spin ratio aω/δ, of −(δ/(fN·a²))·∂T_z/∂ω
/// with v_P held fixed. The stable explicit step for the spin
/// ([`Friction::stable_spin_step`](crate::friction::Friction::stable_spin_step) for `Best`) is
/// limit·Iδ/(κ_T·fN·a²).
///
/// # Formula
///
/// With the IC (X, Y) = (−v_Py, v_Px)/(aω) inside the ellipse (X² + Y²/m₁ ≤ 1) and the exact
/// quartic's pieces q₂ = (B/2)X² + (A/2)Y², q₄ = 3[c₄₀(X⁴ + Y⁴/m₁) + c₂₂X²Y²] (torque
/// T_z/(fNa) = −C + q₂ + q₄ for ω > 0):
///
/// ```text
/// k_T(X, Y) = C + q₂ + 3q₄ + (|X| + |Y|)·(2q₂ + 4q₄),     κ_T = max k_T over the ellipse
/// ```
///
/// maximised numerically over X = ρ cos θ, Y = γρ sin θ (ρ ∈ [0, 1], θ ∈ [0, π/2]): along
/// each ray k_T is a quintic in ρ with one maximum (golden-section search, 64 steps); over θ a
/// 65-point grid, then a golden-section search around its best point — a fixed amount of work.
///
/// # Why
///
/// Below the slip scale (s = |v_Px| + |v_Py| + a|ω| < δ) the wrapper gives
/// T_z = fN·a·(s/δ)·τ with τ the core's torque, homogeneous of degree 0 in (v_P, aω). So
/// −∂T_z/∂ω = (fN·a²/δ)·(−sgn ω·τ − s·∂τ/∂(aω)), a function of the slip direction only;
/// with ∂X/∂(aω) = −X/(aω) (and Y alike) and τ = −C + q₂ + q₄ (X·τ_X + Y·τ_Y = 2q₂ + 4q₄)
/// this is k_T. In pure spin k_T = C (the plateau −C·fNa ramped over a|ω| < δ: stiffness
/// C·fN·a²/δ); a slip inside the ramp makes s/|aω| = 1 + |X| + |Y| grow faster than the
/// core's torque falls, and the product peaks in between: κ_T ≈ 1.90–1.97·C (circle:
/// 1.1410 = 1.937·C with the IC at 0.82a on a diagonal). With the IC outside the ellipse, and
/// past the ramp (s ≥ δ: fN·a²/s times the core's own slope), the stiffness is smaller:
/// checked on the whole direction sphere for the exact law and for `best`
/// (`host-tests/stability.rs`). `best` is exact inside the ellipse, so its κ_T is the exact
/// law's. Not covered: the coupling with translation (F depends on ω and T_z on v_P; a body
/// whose v_P and ω both move has a 3 × 3 Jacobian whose largest eigenvalue depends on I/(ma²)).
///
/// # Domain and accuracy
///
/// Every valid e²; finite, ≥ C. Against the maximisation of `tools/gen_spin_stiffness.py`
/// (mpmath; `tools/data/spin_stiffness.csv`, m₁ from 1 to 1e-12): measured within 7.5e-15
/// (`f64`) and 1.9e-7 (`f32`) relative (asserted ≤ 1e-12 and ≤ 1e-6 by
/// `host-tests/stability.rs`). The sphere check covers e² from the circle to the contract's end
/// (m₁ = 1.70e-5: sup 0.73596 against κ_T = 0.73621); below m₁ ≈ 1e-5, reachable only through a
/// `Parameter` built directly, the maximiser lies on the ellipse and the outside is unchecked. Cost: ≈ 9,000 evaluations of a quintic
/// and 133 sine–cosines (host ≈ 26 µs, `f32` or `f64`) — construction or host use, not per
/// step; not measured on the Cortex-M4F.
pub fn spin_stiffness<T: Real>(k: &Constants<T>) -> T {
    /// Grid points over θ; golden-section steps over θ and over ρ.
    const GRID: usize = 64;
    const GOLDEN: usize = 64;
    let q = Quartic::new(k);
    let gamma = k.m1().sqrt();
    let (two, three, four) = (T::TWO, T::from_f64(3.0), T::from_f64(4.0));
    let g = T::from_f64(0.618_033_988_749_894_8);
    // Golden-section search for the maximum of a unimodal `f` on [lo, hi]: (argmax, max).
    let golden = |f: &dyn Fn(T) -> T, mut lo: T, mut hi: T| {
        let mut x1 = hi - g * (hi - lo);
        let mut x2 = lo + g * (hi - lo);
        let (mut f1, mut f2) = (f(x1), f(x2));
        for _ in 0..GOLDEN {
            if f1 < f2 {
                lo = x1;
                (x1, f1) = (x2, f2);
                x2 = lo + g * (hi - lo);
                f2 = f(x2);
            } else {
                hi = x2;
                (x2, f2) = (x1, f1);
                x1 = hi - g * (hi - lo);
                f1 = f(x1);
            }
        }
        // the ends too: the maximum may sit on them (ρ = 1, the ellipse)
        let (fl, fh) = (f(lo), f(hi));
        let mut best = if f1 < f2 { (x2, f2) } else { (x1, f1) };
        for c in [(lo, fl), (hi, fh)] {
            if c.1 > best.1 {
                best = c;
            }
        }
        best
    };
    // Max over ρ ∈ [0, 1] along the ray θ: k_T = C + ρ²(Q₂ + ρ(2LQ₂ + ρ(3Q₄ + 4LQ₄ρ))),
    // unimodal in ρ (its slope over ρ is concave with a positive start).
    let ray = |theta: T| {
        let (s, c) = theta.sin_cos();
        let (cx, cy) = (c, gamma * s);
        let (x2, y2) = (cx * cx, cy * cy);
        let q2 = q.hb * x2 + q.ha * y2;
        let q4 = x2 * (q.t40 * x2 + q.t22 * y2) + q.t40m * y2 * y2;
        let l = cx + cy;
        let (p3, p4, p5) = (two * l * q2, three * q4, four * l * q4);
        let f = |rho: T| q.c + rho * rho * (q2 + rho * (p3 + rho * (p4 + rho * p5)));
        golden(&f, T::ZERO, T::ONE).1
    };
    let n = T::from_usize(GRID);
    let step = T::FRAC_PI_2 / n;
    let mut best = (T::ZERO, ray(T::ZERO));
    for i in 1..=GRID {
        let theta = T::from_usize(i) * step;
        let v = ray(theta);
        if v > best.1 {
            best = (theta, v);
        }
    }
    let lo = larger(best.0 - step, T::ZERO);
    let hi = (best.0 + step).min(T::FRAC_PI_2);
    let refined = golden(&ray, lo, hi).1;
    larger(refined, best.1)
}
