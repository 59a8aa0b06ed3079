//! K, E, B, D by the arithmetic–geometric mean, with a fixed iteration count.
//!
//! # Formula
//!
//! a₀ = 1, b₀ = √m₁, c₀² = m;  a_{n+1} = (a_n + b_n)/2, b_{n+1} = √(a_n b_n),
//! c_{n+1} = (a_n − b_n)/2 = c_n²/(4a_{n+1})  (the right-hand form never cancels).
//!
//! K = π/(2a_N),  K − E = K·Σ_{n≥0} 2^{n−1} c_n²,  so with s_n = c_n²/m (s₀ = 1,
//! s_{n+1} = s_n·c_n²/(16a²_{n+1})):  D = (K − E)/m = K·Σ 2^{n−1} s_n — no division by m.
//! Then E = K − m·D and B = E − m₁·D (neither cancels: at small m the subtracted terms are
//! O(m), near m = 1 B → 1 while m₁D → 0).
//!
//! # Domain and cost
//!
//! Every valid [`Parameter`]: m ∈ [0, 1 − m₁_min]. Fixed count N = 7 (`f64`) or 5 (`f32`),
//! enough for the whole domain (the slowest case, m₁ = m₁_min, needs them all). Each iteration
//! costs one square root and one division.

use super::{Integrals, Method, Parameter};
use crate::Real;

/// Arithmetic–geometric mean with a fixed iteration count (7 for `f64`, 5 for `f32`).
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
        let mut a = T::ONE;
        let mut b = m1.sqrt();
        let mut c2 = m; // c_n²
        let mut s = T::ONE; // c_n²/m
        let mut weight = T::HALF; // 2^{n−1}
        let mut sum = T::HALF; // Σ 2^{n−1} s_n, n = 0 term
        for _ in 0..Self::iterations::<T>() {
            let a_next = (a + b) * T::HALF;
            let b_next = (a * b).sqrt();
            let denom = T::from_f64(16.0) * a_next * a_next;
            s = s * c2 / denom;
            c2 = c2 * c2 / denom;
            weight *= T::TWO;
            sum += weight * s;
            a = a_next;
            b = b_next;
        }
        let k = T::FRAC_PI_2 / a;
        let d = k * sum;
        let e = k - m * d;
        let bb = e - m1 * d;
        Integrals { k, e, b: bb, d }
    }
}
