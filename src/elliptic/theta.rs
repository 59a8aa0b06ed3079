//! K, E, B, D by the theta/nome series (the paper's §4 method), fixed for m > ½.
//!
//! # Formula
//!
//! For a parameter μ ≤ ½ with complement μ₁ = 1 − μ and k' = √μ₁ (μ is m itself when m ≤ ½,
//! and m₁ when m > ½):
//!
//! ```text
//! ε = ½(1 − √k')/(1 + √k') = μ / (2(1 + k')(1 + √k')²)        (no cancelling difference)
//! q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + …                              (nome of μ, q ≤ 0.0433)
//! θ₃ = 1 + 2(q + q⁴ + q⁹ + …),   K(μ) = (π/2)·θ₃²
//! S = Σ q²ⁿ/(1 − q²ⁿ)² = Σ σ₁(j)·q²ʲ = x + 3x² + 4x³ + 7x⁴ + 6x⁵ + 12x⁶ + …   (x = q²)
//! D(μ) = (K − E)/μ = π/(6θ₃²) · [(θ₃⁴ − 1)/μ + θ₃⁴ + 24·S/μ]
//! ```
//!
//! The last line is the paper's E = ((2 − μ)/3)K + (π²/K)(1/12 − 2S) rearranged so that every
//! term is positive; (θ₃⁴ − 1)/μ and S/μ are formed from q/μ = ε/μ·(1 + 2ε⁴ + …), so nothing is
//! divided by μ and D(0) = π/4 exactly. Likewise
//! B(μ) = K − D = π/(6θ₃²)·[2θ₃⁴ − (θ₃⁴ − 1)/μ − 24·S/μ] (the bracket is ≥ 1.4 and cancels by
//! at most a factor 1.5), and E = B + μ₁D (a sum of positive terms).
//!
//! For m > ½ the same series run on the complementary parameter m₁ (taken from
//! [`Parameter::m1`], never formed as 1 − m), giving K' = K(m₁), D' = D(m₁), E' = K' − m₁D'
//! and the complementary nome q'. Then
//!
//! ```text
//! K = K'·ln(1/q')/π,         E = (π/2 + K·m₁D')/K'          (Legendre's relation)
//! B = (E − m₁K)/m = (π/2 − m₁·K·B')/(m·K'),   D = K − B
//! ```
//!
//! evaluated as K = θ₃'²L/2, E = (1 + m₁Lδ'/6)/θ₃'², B = (1 − m₁Lβ'/6)/(mθ₃'²) with
//! L = ln(1/q'), β' = 6θ₃'²B'/π, δ' = 6θ₃'²D'/π (fewer roundings; π cancels).
//!
//! The subtraction in B cancels by at most a factor 2 (at m = ½), the one in D by at most 1.9
//! (at m = ½; near m = 1, D ≈ K ≫ B).
//!
//! Fixed term counts ([`Theta::terms`]): `f64` 4 nome terms, 3 θ₃ terms, 6 S terms; `f32`
//! 2, 2, 3.
//!
//! # The paper's form fails near m = 1
//!
//! The paper uses the nome of m itself on the whole range, with ε = ½(1 − m₁^¼)/(1 + m₁^¼). As m
//! → 1 the nome approaches 1, its five-term series and the θ₃ and S sums stop converging, and
//! 1 − m₁^¼ cancels. That form is kept, clearly labelled, as [`paper_k_e`] for the stability
//! map; its measured error is stated there.

use super::{Integrals, Method, Parameter};
use crate::Real;
use crate::math::{Backend, Libm};

/// Theta/nome series with the complementary-nome fix for m > ½ (fixed term counts).
///
/// Domain: every valid [`Parameter`] (m ∈ [0, 1 − m₁_min]). Special cases: m = 0 gives
/// K = E = π/2, B = D = π/4 exactly (up to rounding of π).
///
/// Measured max relative error of K, E, B, D against mpmath (tools/data/elliptic_ref.csv,
/// 1,408 points from m = 0 to 1 − 1e-12; `f32` 318 points to m₁ = 2⁻²⁴; asserted in
/// host-tests/elliptic.rs): `f64` 7.0e-16, `f32` 3.3e-7 (a dense scan of 3,000 `f32` points
/// agrees).
///
/// Cost: m ≤ ½: two square roots, two divisions, ≈40 adds/multiplies (`f64`; ≈30 `f32`);
/// m > ½: the same plus one `ln` (libm) and two more divisions. Host time and ratio to `ellip`
/// in the [module table](super); MCU instructions: see bench-results/qemu.csv.
#[derive(Clone, Copy, Debug, Default)]
pub struct Theta;

/// Term counts of the theta method for one precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ThetaTerms {
    /// Terms of the nome series q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³.
    pub nome: usize,
    /// Terms of θ₃ − 1 = 2(q + q⁴ + q⁹).
    pub theta3: usize,
    /// Terms of the Lambert sum S = Σ σ₁(j)q²ʲ.
    pub e_sum: usize,
}

impl Theta {
    /// The fixed term counts used for `T`.
    pub const fn terms<T: Real>() -> ThetaTerms {
        if T::MANTISSA_DIGITS > 24 {
            ThetaTerms {
                nome: 4,
                theta3: 3,
                e_sum: 6,
            }
        } else {
            ThetaTerms {
                nome: 2,
                theta3: 2,
                e_sum: 3,
            }
        }
    }
}

/// The series for μ ∈ [0, ½] (with its exact complement μ₁): returns θ₃², the brackets
/// β = 6θ₃²B/π and δ = 6θ₃²D/π, and the nome q.
#[inline(always)]
fn series<T: Real>(mu: T, mu1: T) -> (T, T, T, T) {
    let wide = T::MANTISSA_DIGITS > 24;
    let c = T::from_f64;
    let kp = mu1.sqrt();
    let skp = kp.sqrt();
    let one_skp = T::ONE + skp;
    // ε/μ and q/μ
    let eps_over = T::ONE / (T::TWO * (T::ONE + kp) * one_skp * one_skp);
    let eps = mu * eps_over;
    let e4 = eps.sq().sq();
    let q_over = if wide {
        eps_over * (T::ONE + e4 * (T::TWO + e4 * (c(15.0) + e4 * c(150.0))))
    } else {
        eps_over * (T::ONE + e4 * T::TWO)
    };
    let q = mu * q_over;
    let x = q * q;
    let q3 = x * q;
    // (θ₃ − 1)/μ
    let th_over = if wide {
        T::TWO * q_over * (T::ONE + q3 * (T::ONE + q3 * q * q))
    } else {
        T::TWO * q_over * (T::ONE + q3)
    };
    let t = mu * th_over;
    // θ₃² = 1 + t(2 + t) and θ₃⁴ = 1 + μ·(θ₃⁴ − 1)/μ: one rounding each, not a chain
    let theta2 = T::ONE + t * (T::TWO + t);
    // (θ₃⁴ − 1)/μ = (θ₃ − 1)/μ · (4 + 6t + 4t² + t³)
    let theta4_m1_over = th_over * (c(4.0) + t * (c(6.0) + t * (c(4.0) + t)));
    let theta4 = T::ONE + mu * theta4_m1_over;
    // 24·S/μ = 24·q/μ · q · (1 + 3x + 4x² + 7x³ + 6x⁴ + 12x⁵)
    let s_poly = if wide {
        T::ONE + x * (c(3.0) + x * (c(4.0) + x * (c(7.0) + x * (c(6.0) + x * c(12.0)))))
    } else {
        T::ONE + x * (c(3.0) + x * c(4.0))
    };
    let s24 = c(24.0) * q_over * q * s_poly;
    let beta = T::TWO * theta4 - theta4_m1_over - s24;
    let delta = theta4_m1_over + theta4 + s24;
    (theta2, beta, delta, q)
}

impl Method for Theta {
    const NAME: &'static str = "theta";

    #[inline]
    fn integrals<T: Real>(p: Parameter<T>) -> Integrals<T> {
        integrals::<Libm, T>(p)
    }
}

/// [`Theta`] with the logarithm of the m > ½ branch, L = ln(1/q'), from
/// [`Micromath`](crate::math::Micromath) (feature `micromath`; `f32` only, libm for `f64`).
/// The square roots stay [`Real::sqrt`]: micromath's is up to 6.1 % off and costs more than
/// `vsqrt.f32` (see [`crate::math`]).
///
/// Formula, domain, special cases: as [`Theta`]; for m ≤ ½ it is [`Theta`] bit for bit, and
/// `f64` is [`Theta`]. Measured max relative error of K, E, B, D (`f32`, the 318 points of
/// tools/data/elliptic_ref.csv, asserted < 5.5e-5 by host-tests/micromath.rs): **4.7e-5**
/// (median 1.5e-7; [`Theta`]: 3.4e-7, median 8.6e-8), from the ln's 6e-5 absolute error on
/// L ≥ 3.1. Cost: M4F **117** instructions (`f32`; [`Theta`] 122), host ≈ 41 ns (as
/// [`Theta`] within noise).
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, Default)]
pub struct ThetaMicromath;

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl Method for ThetaMicromath {
    const NAME: &'static str = "theta-micromath";

    #[inline]
    fn integrals<T: Real>(p: Parameter<T>) -> Integrals<T> {
        integrals::<crate::math::Micromath, T>(p)
    }
}

/// The theta method with the logarithm from the backend `B`.
#[inline(always)]
fn integrals<B: Backend, T: Real>(p: Parameter<T>) -> Integrals<T> {
    let (m, m1) = (p.m(), p.m1());
    let sixth = T::ONE / T::from_f64(6.0);
    if m <= T::HALF {
        let (theta2, beta, delta, _) = series(m, m1);
        let k = T::FRAC_PI_2 * theta2;
        let scale = T::PI * sixth / theta2;
        let (b, d) = (scale * beta, scale * delta);
        Integrals {
            k,
            e: b + m1 * d,
            b,
            d,
        }
    } else {
        // Complementary side: θ₃'² and brackets β', δ' of m₁, L = ln(1/q').
        let (theta2, beta, delta, qc) = series(m1, m);
        let l = -B::ln(qc);
        let k = T::HALF * theta2 * l;
        let ml6 = m1 * l * sixth;
        let e = (T::ONE + ml6 * delta) / theta2;
        let b = (T::ONE - ml6 * beta) / (theta2 * m);
        Integrals { k, e, b, d: k - b }
    }
}

/// **Reference only — unstable near m = 1.** K and E by the paper's §4 formulas as printed:
/// the nome of m itself on the whole range, ε = ½(1 − m₁^¼)/(1 + m₁^¼),
/// q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷, K = (π/2)θ₃², θ₃ = 1 + 2Σ_{n=1}^{6} q^{n²},
/// E = ((2 − m)/3)K + (π²/K)(1/12 − 2Σ_{n=1}^{10} q²ⁿ/(1 − q²ⁿ)²).
///
/// Kept for the stability map; use [`Theta`] instead (it is deliberately not a [`Method`], so
/// it cannot be plugged into the contact types). Domain: every valid [`Parameter`], always
/// finite, but accurate only for m ≲ 0.87. Max relative error of K and E against mpmath
/// (`tools/data/stability_elliptic.csv`; chart `docs/report/stability/theta_near_1.csv`):
/// `f64` 5.5e-15 at m₁ = 0.13, 7.8e-14 at m₁ = 0.1, 3.2e-8 at m₁ = 1e-2, 1.8e-5 at 1e-3,
/// 2.3e-2 at 1e-6, 0.32 at m₁ = 1e-12 (the truncated nome series and θ₃/E sums stop
/// converging as q → 1); `f32` above its own rounding (1e-6) from m₁ ≈ 3e-3 (m ≈ 0.997), 6.6e-2
/// at m₁ = 2⁻²⁴. [`Theta`], with the complementary nome for m > ½, stays within 2.8e-16 (`f64`)
/// on the whole domain, asserted in `host-tests/stability.rs`.
/// Cost: two square roots, ≈60 multiply-adds and 11 divisions.
pub fn paper_k_e<T: Real>(p: Parameter<T>) -> (T, T) {
    let c = T::from_f64;
    let (m, m1) = (p.m(), p.m1());
    let r = m1.sqrt().sqrt();
    let eps = T::HALF * (T::ONE - r) / (T::ONE + r);
    let e4 = eps.sq().sq();
    let q = eps * (T::ONE + e4 * (T::TWO + e4 * (c(15.0) + e4 * (c(150.0) + e4 * c(1707.0)))));
    let mut theta = T::ONE;
    let mut sum = T::ZERO;
    let mut qn = T::ONE; // q^{n}
    let mut q2n = T::ONE; // q^{2n}
    let q2 = q * q;
    for n in 1..=10usize {
        qn *= q;
        q2n *= q2;
        if n <= 6 {
            // q^{n²} = (qⁿ)ⁿ by repeated multiplication (n ≤ 6, fixed)
            let mut pw = T::ONE;
            for _ in 0..n {
                pw *= qn;
            }
            theta += T::TWO * pw;
        }
        let den = T::ONE - q2n;
        sum += q2n / (den * den);
    }
    let k = T::FRAC_PI_2 * theta * theta;
    let e = (T::TWO - m) / c(3.0) * k + T::PI * T::PI / k * (T::ONE / c(12.0) - T::TWO * sum);
    (k, e)
}
