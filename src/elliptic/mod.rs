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
//! [`Method`], generic over `f32`/`f64`: [`Agm`], [`Theta`], [`Table`]. Inputs are validated
//! once into a [`Parameter`]; near m = 1 build it from m₁ = 1 − m
//! ([`Parameter::from_complement`], e.g. m₁ = (b/a)²), which every method uses directly.
//!
//! ```
//! use contensou::elliptic::{Method, Parameter, Table, Theta};
//!
//! // b/a = 1e-3: m₁ = 1e-6 exactly, m = 1 − 1e-6
//! let p = Parameter::from_complement(1e-6f32)?;
//! let i = Table::integrals(p);
//! assert!((i.k / 8.294051463601063 - 1.0).abs() < 5e-7);
//! assert!((i.d / Theta::integrals(p).d - 1.0).abs() < 1e-6);
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Accuracy and cost
//!
//! Max relative error of K, E, B and D (worst of the four) against mpmath at 60 digits
//! (tools/gen_elliptic_ref.py → tools/data/elliptic_ref.csv: 1,408 points, m = 0, m from 1e-12,
//! uniform, m₁ down to 1e-12 with 1,000 of them at m₁ ∈ [1e-12, 1e-9] where the `f64` errors
//! peak; `f32`: the 318 points exact in `f32`, m₁ down to 2⁻²⁴), asserted
//! by host-tests/elliptic.rs. Host time per call for K and E on x86-64 (criterion, fastest
//! sample, 64 fixed m incl. near 1, shared machine: ±20 %), beside the `ellip` crate in the
//! same run (ratio ours/ellip in brackets); bench-results/host-elliptic.md has the full table (`tools/host-bench.sh`).
//!
//! | method | `f64` error | `f32` error | host ns `f64` | host ns `f32` | M4F instructions |
//! |---|---|---|---|---|---|
//! | [`Agm`] (7 / 5 iterations) | 1.5e-15 (dense scan near m₁ = 1e-12; 1.3e-15 on the set) | 3.3e-7 | 29 (0.72×) | 15 (0.47×) | 141 `f32` / 12,163 `f64` |
//! | [`Theta`] (complementary nome for m > ½) | 7.0e-16 | 3.3e-7 | 49 (1.20×) | 27 (0.87×) | 122 `f32` / 9,089 `f64` |
//! | [`Table`] (12,320 B `f32`, 20,608 B `f64`) | 1.2e-11 | 1.1e-7 | 8.2 (0.20×) | 4.2 (0.13×) | 45 `f32` / 2,279 `f64` |
//! | `ellip` 1.2 (peer; no B, taken as K − D; its K, E, D: 5.2e-15, 2.6e-7) | 1.4e-14 | 1.6e-6 | 40 (1×) | 31 (1×) | — |
//!
//! [`paper_k_e`] keeps the paper's unfixed theta form for comparison only: its `f64` error is
//! 4.4e-15 up to m = 0.87, 3.2e-8 at m = 0.99 and 0.32 at m = 1 − 1e-12.
//!
//! # Stability
//!
//! - **Near m = 1**: every [`Method`] takes m₁ from [`Parameter`] and stays accurate to
//!   m₁_min; the paper's theta form does not (see [`paper_k_e`]).
//! - **Small m**: the quotient (K − E)/m formed from K and E loses everything in `f32`
//!   (measured with [`Agm`]'s K, E: 1.7e-3 relative at m = 1e-4, 100 % at m = 1e-8; `f64`: 3e-12
//!   at 1e-4, 5e-6 at 1e-11), so every method returns D itself: `f32` D ≤ 2.8e-7 for m from 1e-11
//!   to 0.42 by all three methods (chart `docs/report/stability/d_cancellation.csv`, mpmath
//!   `tools/data/stability_elliptic.csv`, asserted in `host-tests/stability.rs`).

mod agm;
mod table;
mod table_data;
mod theta;

pub use agm::Agm;
pub use table::Table;
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
pub use theta::ThetaMicromath;
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
