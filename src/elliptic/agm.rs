//! K, E, B, D by the arithmetic–geometric mean, with a fixed iteration count.
//!
//! # Formula
//!
//! a₀ = 1, b₀ = √m₁, c₀² = m;  a_{n+1} = (a_n + b_n)/2, b_{n+1} = √(a_n b_n),
//! c_{n+1} = (a_n − b_n)/2 = c_n²/(4a_{n+1})  (the right-hand form never cancels relative to
//! c_{n+1}; the left-hand form has the smaller absolute error).
//!
//! K = π/(2a_{N+1}) = π/(a_N + b_N),  K − E = K·Σ_{n≥0} 2^{n−1} c_n²,  so with s_n = c_n²/m (s₀ = 1,
//! s_{n+1} = s_n·c_n²/(16a²_{n+1})):  D = (K − E)/m = K·Σ 2^{n−1} s_n — no division by m.
//!
//! E is not formed as K − m·D: near m = 1 that difference cancels by a factor K/E ≈ 9 (the
//! `f32` error reached 1.7e-6). Since 1 − c₀²/2 − c₁² = a₁²,
//! E = K·(a₁² − Σ_{n≥2} 2^{n−1} c_n²), and (`f32` only; `f64` is accurate enough without
//! it and saves a branch and a division) for m₁ < 0.004, since a₁² − 2c₂² = 2a₂² − b₁² with
//! b₁² = √m₁, E = K·(2a₂² − √m₁ − Σ_{n≥3} 2^{n−1} c_n²), which subtracts only ≈ 20 %.
//! Here c_n = (a_{n−1} − b_{n−1})/2 by the difference: its absolute error is what matters, and
//! the recurrence c_n² = c_{n−1}⁴/(16a_n²) doubles the relative error at every step. For the
//! same reason (`f32` only), for m > ½, D = K·(½ + s₁ + Σ_{n≥2} 2^{n−1}c_n²/m) with the
//! differences; for m ≤ ½ the recurrence for s_n is the accurate one.
//! Then B = E − m₁·D (at small m the subtracted term is ≈ E/2, near m = 1 it vanishes).
//!
//! # Domain and cost
//!
//! Every valid [`Parameter`]: m ∈ [0, 1 − m₁_min]. Fixed count N = 7 (`f64`) or 5 (`f32`),
//! enough for the whole domain: the slowest case is m₁ = m₁_min, where a_N alone would still be
//! 3.4e-7 (`f32`, N = 5) resp. 3.6e-18 (`f64`, N = 7) off the mean; the free half-step
//! (a_N + b_N)/2 brings that to 3e-14 resp. below 1e-30. Each iteration costs one square root
//! and one division (plus one of each to start and to finish).

use super::{Integrals, Method, Parameter};
use crate::Real;

/// Arithmetic–geometric mean with a fixed iteration count (7 for `f64`, 5 for `f32`).
///
/// Domain: every valid [`Parameter`]; m = 0 gives K = E = π/2, B = D = π/4 (rounded).
/// Measured max relative error of K, E, B, D against mpmath (1,408 reference points, m = 0 …
/// 1 − 1e-12, 1,000 of them at m₁ ∈ [1e-12, 1e-9] where the error peaks; `f32` 318 points
/// down to m₁ = 2⁻²⁴): `f64` 1.3e-15 on the set (E and B near m₁ = 1.2e-12), 1.5e-15 over
/// scans of 3,000 and 12,000 m₁ ∈ [1e-12, 1e-8] (`tools/scan_agm_edge.py`, `contact_eval`
/// against mpmath; the error there is rounding noise), `f32` 3.3e-7 (a dense scan of 3,000
/// `f32` points agrees).
///
/// Cost: N + 1 square roots, N + 2 divisions, ≈12N adds/multiplies; host time and ratio to
/// `ellip` in the [module table](super); MCU instructions: see bench-results/qemu.csv.
#[derive(Clone, Copy, Debug, Default)]
pub struct Agm;

impl Agm {
    /// Iterations used for `T`.
    pub const fn iterations<T: Real>() -> usize {
        if T::MANTISSA_DIGITS > 24 { 7 } else { 5 }
    }
}

impl Method for Agm {
    const NAME: &'static str = "agm";

    #[inline]
    fn integrals<T: Real>(p: Parameter<T>) -> Integrals<T> {
        let (m, m1) = (p.m(), p.m1());
        // n = 0 → 1, peeled: a₁ = (1 + √m₁)/2, c₁² = m²/(16a₁²), s₁ = m/(16a₁²).
        let b0 = m1.sqrt();
        let mut a = (T::ONE + b0) * T::HALF;
        let mut b = b0.sqrt();
        let a1_sq = a * a;
        let mut s = m / (T::from_f64(16.0) * a1_sq);
        let mut c2 = m * s;
        let s1 = s;
        let mut weight = T::ONE; // 2^{n−1} at n = 1
        let mut s_sum = T::ZERO; // Σ_{n≥2} 2^{n−1} s_n, by the recurrence (for small m)
        // a₂ and c₂ = (a₁ − b₁)/2 (the loop's first step recomputes them; the compiler merges)
        let a2 = (a + b) * T::HALF;
        let c2d = (a - b) * T::HALF;
        let mut e_rest = T::ZERO; // Σ_{n≥3} 2^{n−1} c_n², by the difference
        let mut e_weight = T::ZERO; // 0 at n = 2 (kept apart), then 2^{n−1}
        for _ in 1..Self::iterations::<T>() {
            let a_next = (a + b) * T::HALF;
            let b_next = (a * b).sqrt();
            let inv = T::ONE / (T::from_f64(16.0) * a_next * a_next);
            s = s * c2 * inv;
            c2 = c2 * c2 * inv;
            weight *= T::TWO;
            s_sum += weight * s;
            // c_{n+1} by the difference, not the recurrence: the recurrence doubles the relative
            // error at every step (1e-6 in f32 E near m = 1).
            let c = (a - b) * T::HALF;
            e_rest += e_weight * c * c;
            e_weight = weight * T::TWO;
            a = a_next;
            b = b_next;
        }
        // a_{N+1} = (a_N + b_N)/2 for free: at m₁ = 2⁻²⁴ it cuts the f32 truncation error of
        // K from 3.4e-7 to 3e-14.
        let k = T::PI / (a + b);
        // For m > ½ the difference-based tail e_sum/m is the accurate one; for small m only the
        // recurrence keeps relative accuracy (c_n by difference is then pure rounding noise).
        let e_sum = T::TWO * c2d * c2d + e_rest; // Σ_{n≥2} 2^{n−1} c_n²
        // f32 only (compile-time): the f64 rounding is small enough for the plain forms.
        let narrow = T::MANTISSA_DIGITS <= 24;
        let tail = if narrow && m > T::HALF {
            e_sum / m
        } else {
            s_sum
        };
        let d = k * (T::HALF + s1 + tail);
        // E/K = a₁² − Σ_{n≥2} 2^{n−1}c_n² = 2a₂² − b₁² − Σ_{n≥3} 2^{n−1}c_n² (b₁² = √m₁): for
        // m₁ < 0.004 the second form subtracts less (≈ 20 % instead of up to 55 % at m₁ → 0),
        // above it the first does (nothing at m = 0, 10 % at m₁ = 0.01).
        let e_over_k = if narrow && m1 < T::from_f64(0.004) {
            T::TWO * a2 * a2 - b0 - e_rest
        } else {
            a1_sq - e_sum
        };
        let e = k * e_over_k;
        let bb = e - m1 * d;
        Integrals { k, e, b: bb, d }
    }
}
