//! Complete elliptic integrals K(m), E(m) and the cancellation-free pair B(m), D(m).
//!
//! **Parameter convention: m = k² = e²** (never the modulus k). With it
//!
//! ```text
//! K(m) = ∫₀^{π/2} dθ/√(1 − m sin²θ)          B(m) = ∫₀^{π/2} cos²θ/√(1 − m sin²θ) dθ
//! E(m) = ∫₀^{π/2} √(1 − m sin²θ) dθ          D(m) = ∫₀^{π/2} sin²θ/√(1 − m sin²θ) dθ
//! K = B + D,   E = B + (1 − m)·D,   K − E = m·D,   E − (1 − m)·K = m·B
//! ```
//!
//! Hertz needs D/B and friction needs (K − E)/m = D: computing them from K and E cancels
//! catastrophically at small m (in `f32` already at m ≈ 1e-3), so every method here returns all
//! four, each computed without cancellation.
//!
//! Methods (all fixed-cost, no data-dependent loops) are zero-sized types implementing
//! [`Method`]: [`Agm`]. Inputs are validated once into a [`Parameter`].

mod agm;
mod table;
mod table_data;
mod theta;

pub use agm::Agm;
pub use table::Table;
pub use theta::{Theta, ThetaTerms, paper_k_e};

use crate::{Error, Real};

/// K, E, B, D at one parameter m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Integrals<T> {
    /// K(m), complete integral of the first kind.
    pub k: T,
    /// E(m), complete integral of the second kind.
    pub e: T,
    /// B(m) = (E − (1 − m)K)/m.
    pub b: T,
    /// D(m) = (K − E)/m.
    pub d: T,
}

/// A validated elliptic parameter: m and its complement m₁ = 1 − m, each held exactly.
///
/// Domain: m ∈ [0, 1 − m₁_min] with m₁_min = 1e-12 (`f64`) or 2⁻²⁴ (`f32`). Near m = 1 the
/// integrals depend on m₁ logarithmically, so callers who know m₁ = (b/a)² directly should build
/// with [`Parameter::from_complement`]: forming 1 − m in floating point loses that information.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parameter<T> {
    m: T,
    m1: T,
}

impl<T: Real> Parameter<T> {
    /// Smallest supported m₁ = 1 − m: 1e-12 for `f64`, 2⁻²⁴ for `f32`.
    pub fn min_complement() -> T {
        if T::MANTISSA_DIGITS > 24 {
            T::from_f64(1e-12)
        } else {
            T::from_f64(5.960464477539063e-8)
        }
    }

    /// From m ∈ [0, 1 − m₁_min]; otherwise [`Error::EllipticParameterOutOfDomain`]
    /// (or [`Error::NonFinite`]).
    pub fn new(m: T) -> Result<Self, Error> {
        let m = crate::error::finite(m, "m")?;
        let m1 = T::ONE - m;
        if m >= T::ZERO && m1 >= Self::min_complement() {
            Ok(Parameter { m, m1 })
        } else {
            Err(Error::EllipticParameterOutOfDomain)
        }
    }

    /// From the complement m₁ = 1 − m ∈ [m₁_min, 1] (e.g. m₁ = (b/a)²), kept exactly.
    pub fn from_complement(m1: T) -> Result<Self, Error> {
        let m1 = crate::error::finite(m1, "m1")?;
        if m1 >= Self::min_complement() && m1 <= T::ONE {
            Ok(Parameter { m: T::ONE - m1, m1 })
        } else {
            Err(Error::EllipticParameterOutOfDomain)
        }
    }

    /// m
    #[inline(always)]
    pub fn m(self) -> T {
        self.m
    }
    /// m₁ = 1 − m
    #[inline(always)]
    pub fn m1(self) -> T {
        self.m1
    }
}

/// A method for the complete elliptic integrals: a zero-sized type, chosen by generics so that
/// only the methods a program uses are linked.
pub trait Method {
    /// Short name used by the evaluator CLI and the benchmark labels (`"agm"`, …).
    const NAME: &'static str;
    /// K, E, B, D at a validated parameter. Total: finite for every valid parameter.
    fn integrals<T: Real>(p: Parameter<T>) -> Integrals<T>;
}
