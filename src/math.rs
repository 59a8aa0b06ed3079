//! Math backends: where a method's square roots, logarithms and exponentials come from.
//!
//! A [`Backend`] is a zero-sized type chosen at compile time. [`Libm`] is what [`Real`] does
//! (libm, and the `vsqrt.f32` shim for `f32` square roots on the Cortex-M4F): every method type
//! of the crate uses it. With the feature `micromath`, `Micromath` substitutes the
//! [micromath](https://docs.rs/micromath/2.1.0) crate's fast `f32` approximations, and each
//! method where that can matter gets a twin type named `…Micromath` that implements the same
//! trait ([`crate::elliptic::Method`], [`crate::shape::Eccentricity`],
//! [`crate::normal::NormalLaw`], [`crate::friction::FrictionLaw`]). Without the feature nothing
//! changes: same types, same code, same results.
//!
//! micromath is `f32`-only: for `f64` `Micromath` falls back to libm (the `f64` results of a
//! `…Micromath` type equal its libm twin's), so the twins stay generic over [`Real`] like every
//! other method.
//!
//! # micromath's functions (2.1.0)
//!
//! ```text
//! sqrt(x)  = bits⁻¹((bits(x) + 0x3f80_0000) >> 1)     exact at even powers of 2, ≤ +6.1 % off
//! ln(x)    = e·ln 2 + quartic on the mantissa [1, 2) (1/x first for x < 1; x = 1 → 0)
//! exp(x)   = 2^⌊x/ln 2⌋ · (four Taylor terms of e^f, f = frac(x/ln 2)·ln 2 ∈ [0, ln 2))
//! ```
//!
//! micromath's `ln` takes 1/x for x < 1 by a bit trick that is up to 12 % off (0.118 absolute
//! error in ln x); `Micromath::ln` divides exactly instead (−ln(1/x)), which is both more
//! accurate (6.2e-5) and one instruction cheaper on the M4F.
//!
//! Which functions each twin routes through the backend, its measured error against the same
//! mpmath references as its libm twin (host-tests/micromath.rs), and its cost on the Cortex-M4F
//! (QEMU instructions per call, `bench-results/qemu.csv`, rows ending in `-micromath`):
//!
//! | twin (QEMU key) | routes | libm: max error, M4F insns | micromath: max error, M4F insns | worth it? |
//! |---|---|---|---|---|
//! | `sqrt` alone (`core`) | — | 5.7e-8 rel., 11 (`vsqrt.f32`) | 6.1e-2 rel. (always ≥ √x), 18 | no |
//! | `ln` alone (`core`) | — | 4.9e-7 abs., 59 | 6.2e-5 abs., 44 (micromath's own: 0.118, 45) | yes, alone |
//! | `exp` alone (`core`) | — | 6.2e-8 rel., 67 | 2.4e-3 rel., 94 | no |
//! | `ThetaMicromath` (`elliptic`) | `ln` | 3.4e-7 (K, E, B, D), 122 | 4.7e-5, 117 | barely (Table: 1.1e-7, 45) |
//! | `HamrockDowsonMicromath` (`hertz`, `shape_…`) | `ln`, `exp` | c 1.6e-2 abs., 277 | c 1.65e-2 abs., 295 | no |
//! | `HertzMicromath` (`hertz`, `per_step…`) | `sqrt` | a, b, N, p0 5.0e-7, 36 | 6.1e-2, 32 | only for ≥ 6.1 % budgets |
//! | `SimplifiedMicromath` (`friction`) | `sqrt` | 0.329 fN / 0.335 fNa, 66 | 0.329 / 0.335 (median ×36), 70 | no |
//! | `CoulombMicromath` (`friction`) | `sqrt` | 0.988 fN / 0.589 fNa, 42 | 0.988 / 0.589, 45 | no |
//! | `EllipsoidMicromath` (`friction`) | `sqrt` | 0.227 fN / 0.121 fNa, 34 | 0.211 / 0.121 (median ×3.4), 37 | no |
//! | `BestMicromath` (`friction`, per call) | `ln` | 2.0e-6 fN / 8.8e-7 fNa, 1,324 | 2.6e-6 / 8.9e-7, 1,297 | marginal |
//!
//! Errors: `f32`, max over the sets of host-tests/micromath.rs (functions: 2,000 x from 1e-6 to
//! 1e6, exp on [−20, 20], against `f64` libm; the methods: against mpmath references and the
//! exact friction integrals). Instructions: QEMU per call, including the rig's 8-instruction
//! call floor. Host times (criterion, x86-64) are equal within the shared machine's noise.
//!
//! **Verdict.** On the Cortex-M4F micromath rarely pays. Its bit-trick `sqrt` is up to 6.1 %
//! high and is not even cheaper than the FPU's `vsqrt.f32` (18 against 11 instructions as a
//! call; inlined, 4 fewer than the shim in `HertzMicromath`
//! but 3–4 more in the friction laws, all measured). Its `exp` costs more than libm's. Only `ln` is cheaper (15 instructions
//! per call) — after fixing micromath's reciprocal below 1 —, and every `ln` of the crate is
//! off the per-step path except in [`Best`](crate::friction::Best)'s per-call form. Use
//! `HertzMicromath` only where a 6 % high normal force is
//! acceptable, `BestMicromath` where e² changes every call
//! and a 3e-6 friction error is, `ThetaMicromath` where
//! 5e-5 in K, E, B, D is and the [`Table`](crate::elliptic::Table)'s 12 KB of flash are not.
//! `bench-results/micromath.md` has the same table with medians and host times.

use crate::Real;

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Libm {}
    #[cfg(feature = "micromath")]
    impl Sealed for super::Micromath {}
}

/// Where square roots, logarithms and exponentials come from (sealed: [`Libm`], `Micromath`).
pub trait Backend:
    sealed::Sealed + Copy + core::fmt::Debug + Default + PartialEq + Eq + Send + Sync + 'static
{
    /// `"libm"` or `"micromath"`.
    const NAME: &'static str;
    /// √x
    fn sqrt<T: Real>(x: T) -> T;
    /// ln x
    fn ln<T: Real>(x: T) -> T;
    /// eˣ
    fn exp<T: Real>(x: T) -> T;
}

/// The crate's default: exactly [`Real::sqrt`], [`Real::ln`], [`Real::exp`] (libm; `vsqrt.f32`
/// for `f32` square roots on ARM `eabihf`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Libm;

impl Backend for Libm {
    const NAME: &'static str = "libm";
    #[inline(always)]
    fn sqrt<T: Real>(x: T) -> T {
        x.sqrt()
    }
    #[inline(always)]
    fn ln<T: Real>(x: T) -> T {
        x.ln()
    }
    #[inline(always)]
    fn exp<T: Real>(x: T) -> T {
        x.exp()
    }
}

/// micromath's `f32` approximations (feature `micromath`); libm for `f64`.
///
/// Edge behaviour (`f32`): `sqrt(0)` is 5.4e-20, not 0, and `sqrt(+∞)` is finite; `ln(1) = 0`
/// exactly; `exp` saturates to 0 below ≈ −88 and to +∞ above ≈ 88. The twins only call these
/// where the argument is positive and finite.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Micromath;

/// `f` on `f32` values (the round trip through `f64` folds away), `fallback` for `f64`.
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[inline(always)]
fn on_f32<T: Real>(
    x: T,
    f: impl FnOnce(micromath::F32) -> micromath::F32,
    fallback: fn(T) -> T,
) -> T {
    // A dual number takes the fallback (libm), whose derivative the round trip would drop.
    if T::MANTISSA_DIGITS == f32::MANTISSA_DIGITS && !T::DERIVATIVES {
        T::from_f64(f64::from(f(micromath::F32(x.to_f64() as f32)).0))
    } else {
        fallback(x)
    }
}

/// micromath's `ln`, its argument kept ≥ 1 (see `Micromath::ln`).
#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
#[inline(always)]
fn ln_f32(x: micromath::F32) -> micromath::F32 {
    if x.0 < 1.0 {
        -micromath::F32(1.0 / x.0).ln()
    } else {
        x.ln()
    }
}

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl Backend for Micromath {
    const NAME: &'static str = "micromath";
    #[inline(always)]
    fn sqrt<T: Real>(x: T) -> T {
        on_f32(x, micromath::F32::sqrt, T::sqrt)
    }
    /// micromath's `ln` on [1, ∞); below 1, −ln(1/x) with an exact division, because micromath
    /// takes 1/x there by its bit-trick reciprocal (up to 12 % off: 0.118 absolute error in ln).
    #[inline(always)]
    fn ln<T: Real>(x: T) -> T {
        on_f32(x, ln_f32, T::ln)
    }
    #[inline(always)]
    fn exp<T: Real>(x: T) -> T {
        on_f32(x, micromath::F32::exp, T::exp)
    }
}

#[cfg(all(test, feature = "micromath"))]
mod tests {
    use super::{Backend, Libm, Micromath};

    #[test]
    fn f64_falls_back_to_libm() {
        for &x in &[1e-10f64, 0.3, 1.0, 2.0, 77.0] {
            assert_eq!(Micromath::sqrt(x), Libm::sqrt(x));
            assert_eq!(Micromath::ln(x), Libm::ln(x));
            assert_eq!(Micromath::exp(-x), Libm::exp(-x));
        }
    }

    #[test]
    fn f32_is_micromath() {
        assert_eq!(Micromath::sqrt(2.0f32), 1.5);
        assert_eq!(Micromath::ln(1.0f32), 0.0);
        assert!((Micromath::exp(1.5f32) / 4.481689 - 1.0).abs() < 2e-3);
    }
}
