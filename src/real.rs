//! The float core: one sealed [`Real`] trait for `f32` and `f64`.
//!
//! Every numerical routine in the crate is generic over `T: Real`. The trait is sealed (only
//! `f32` and `f64` implement it) and backed by [`libm`] directly, not by `num-traits`' `Float`,
//! whose implementation silently changes with feature unification.
//!
//! # Square root on Cortex-M4F
//!
//! `libm::sqrtf` is a software routine on `thumbv7em-none-eabihf` (≈50 instructions). On every
//! `eabihf` ARM target `f32::sqrt` goes through the private `hw_sqrt` module (`src/hw_sqrt.rs`), which executes the FPU's
//! `vsqrt.f32` (one instruction plus call/return). Elsewhere libm is used (on x86-64 libm itself
//! compiles to `sqrtss`/`sqrtsd`). `f64` is always libm: the M4F has a single-precision FPU only.
//!
//! # Hot-path budget
//!
//! `sqrt`, `abs`, `min`, `max`, `copysign` and the arithmetic operators are cheap everywhere.
//! `ln`, `exp`, `sin`, `cos`, `atan2` cost 100–300 instructions in f32 on the M4F; `cbrt` ≈1,600
//! (libm runs it in f64). Keep them off per-step paths: precompute, or use the fixed-cost
//! approximations in the relevant module.

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use core::str::FromStr;

pub(crate) mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A floating-point scalar: `f32` or `f64` (and, inside the crate, the forward-mode
/// [`Dual`](crate::jacobian::Dual) numbers over them that differentiate the wrench).
///
/// Sealed: the crate's accuracy statements are measured for these types only.
pub trait Real:
    sealed::Sealed
    + Copy
    + Clone
    + Default
    + Debug
    + Display
    + FromStr
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
{
    /// `"f32"` or `"f64"`, for reports and benchmark labels.
    const NAME: &'static str;
    /// `true` for the forward-mode [`Dual`](crate::jacobian::Dual) numbers, whose
    /// derivatives a round trip through `f64` or a bit-level shortcut would drop.
    const DERIVATIVES: bool = false;
    /// The underlying precision: `f32` or `f64` itself (a dual number's: that of its value).
    type Base: Real;
    /// Of a generated table kept in both precisions, the one in `Self::Base`'s: `single` for
    /// `f32`, `double` for `f64`. Resolved at compile time; no per-call conversion, no
    /// fallback. Read an entry with [`Real::from_base`] (the identity for `f32` and `f64`).
    fn of_precision<'a, const W: usize, const C: usize>(
        single: &'a [[f32; W]; C],
        double: &'a [[f64; W]; C],
    ) -> &'a [[Self::Base; W]; C];
    /// A value of the underlying precision as `Self` (the identity for `f32` and `f64`; a
    /// constant for a dual number).
    fn from_base(x: Self::Base) -> Self;
    /// Significand bits including the implicit one: 24 or 53. Use it to pick fixed iteration
    /// counts per precision (`if T::MANTISSA_DIGITS > 24 { .. }` folds at compile time).
    const MANTISSA_DIGITS: u32;
    /// 0
    const ZERO: Self;
    /// 1
    const ONE: Self;
    /// 2
    const TWO: Self;
    /// ½
    const HALF: Self;
    /// π
    const PI: Self;
    /// π/2
    const FRAC_PI_2: Self;
    /// π/4
    const FRAC_PI_4: Self;
    /// Machine epsilon (2⁻²³ or 2⁻⁵²).
    const EPSILON: Self;
    /// Largest finite value.
    const MAX: Self;
    /// Smallest positive normal value.
    const MIN_POSITIVE: Self;

    /// Nearest value of `Self` to `x` (exact for `f64`). Constant-folds for literal `x`.
    fn from_f64(x: f64) -> Self;
    /// `x` in `Self` (exact: identity for `f32`, widening for `f64`).
    fn from_f32(x: f32) -> Self;
    /// Exact widening to `f64`.
    fn to_f64(self) -> f64;
    /// `i as Self` (exact for |i| < 2²⁴).
    fn from_usize(i: usize) -> Self;
    /// Truncate towards zero into `usize`; saturating: NaN and negatives give 0, never panics.
    fn trunc_usize(self) -> usize;

    /// √x; `vsqrt.f32` for `f32` on ARM eabihf. NaN for x < 0.
    fn sqrt(self) -> Self;
    /// |x|
    fn abs(self) -> Self;
    /// Smaller of two values; if one is NaN, the other.
    fn min(self, other: Self) -> Self;
    /// Larger of two values; if one is NaN, the other.
    fn max(self, other: Self) -> Self;
    /// Magnitude of `self` with the sign of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// Natural logarithm on a hot path: `f32` by [`ln_f32_hot`] (within 2.5 ulp, no call),
    /// `f64` by `log` (bit-identical to [`Real::ln`]).
    fn ln_hot(self) -> Self;
    /// eˣ
    fn exp(self) -> Self;
    /// sin x
    fn sin(self) -> Self;
    /// cos x
    fn cos(self) -> Self;
    /// (sin x, cos x)
    fn sin_cos(self) -> (Self, Self);
    /// Four-quadrant arctangent of `self / x`.
    fn atan2(self, x: Self) -> Self;
    /// ∛x. Costly on the M4F (≈1,600 instructions for `f32`): not for hot paths.
    fn cbrt(self) -> Self;
    /// √(x² + y²) without undue overflow.
    fn hypot(self, other: Self) -> Self;
    /// Largest integer value ≤ x.
    fn floor(self) -> Self;
    /// Neither infinite nor NaN.
    fn is_finite(self) -> bool;
    /// `MIN_POSITIVE ≤ x ≤ MAX`: positive, normal and finite (false for 0, subnormals, ∞, NaN
    /// and every negative number). One unsigned compare on the bits: on the M4F four
    /// instructions, where the float range test takes eight.
    fn is_positive_normal(self) -> bool;

    /// x², for readability.
    #[inline(always)]
    fn sq(self) -> Self {
        self * self
    }
    /// `self` limited to `[lo, hi]`; NaN maps to `lo`.
    #[inline(always)]
    fn clamp_to(self, lo: Self, hi: Self) -> Self {
        if self >= lo {
            if self <= hi { self } else { hi }
        } else {
            lo
        }
    }
}

/// `Real` constructors `name(x: From) -> Self` that convert with `as` into `$t`.
macro_rules! from_as {
    ($t:ident: $($name:ident($from:ty)),*) => {$(
        #[inline(always)]
        fn $name(x: $from) -> Self {
            x as $t
        }
    )*};
}

/// `Real` methods that forward to a libm function: `name(argument) -> return = function;`
/// (the argument, if any, is a second `Self`).
macro_rules! libm_forward {
    ($($name:ident($($arg:ident)?) -> $ret:ty = $f:ident;)*) => {$(
        #[inline(always)]
        fn $name(self $(, $arg: Self)?) -> $ret {
            libm::$f(self $(, $arg)?)
        }
    )*};
}

macro_rules! impl_real {
    ($t:ident, $bits:ident, $name:literal, $own:tt, $sqrt:path,
     $abs:ident, $copysign:ident, $ln:ident, $ln_hot:path, $exp:ident, $sin:ident,
     $cos:ident, $sincos:ident, $atan2:ident, $cbrt:ident, $hypot:ident, $floor:ident) => {
        impl Real for $t {
            const NAME: &'static str = $name;
            type Base = $t;
            const MANTISSA_DIGITS: u32 = $t::MANTISSA_DIGITS;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const PI: Self = core::$bits::consts::PI;
            const FRAC_PI_2: Self = core::$bits::consts::FRAC_PI_2;
            const FRAC_PI_4: Self = core::$bits::consts::FRAC_PI_4;
            const EPSILON: Self = $t::EPSILON;
            const MAX: Self = $t::MAX;
            const MIN_POSITIVE: Self = $t::MIN_POSITIVE;

            #[inline(always)]
            fn of_precision<'a, const W: usize, const C: usize>(
                single: &'a [[f32; W]; C],
                double: &'a [[f64; W]; C],
            ) -> &'a [[Self; W]; C] {
                (single, double).$own
            }
            #[inline(always)]
            fn from_base(x: Self) -> Self {
                x
            }
            from_as!($t: from_f64(f64), from_f32(f32), from_usize(usize));
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn trunc_usize(self) -> usize {
                self as usize
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                // Branch form: on the M4F a compare + select, cheaper than libm's fminf call.
                if other < self || self != self {
                    other
                } else {
                    self
                }
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                if other > self || self != self {
                    other
                } else {
                    self
                }
            }
            #[inline(always)]
            fn ln_hot(self) -> Self {
                $ln_hot(self)
            }
            libm_forward! {
                abs() -> Self = $abs;
                copysign(sign) -> Self = $copysign;
                ln() -> Self = $ln;
                exp() -> Self = $exp;
                sin() -> Self = $sin;
                cos() -> Self = $cos;
                sin_cos() -> (Self, Self) = $sincos;
                atan2(x) -> Self = $atan2;
                cbrt() -> Self = $cbrt;
                hypot(other) -> Self = $hypot;
                floor() -> Self = $floor;
            }
            #[inline(always)]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline(always)]
            fn is_positive_normal(self) -> bool {
                // The positive normal numbers are the bit patterns from MIN_POSITIVE up to
                // MAX; every other value wraps or lands at or past +∞'s pattern.
                let lo = $t::MIN_POSITIVE.to_bits();
                self.to_bits().wrapping_sub(lo) < $t::INFINITY.to_bits() - lo
            }
        }
    };
}

impl_real!(
    f32,
    f32,
    "f32",
    0,
    crate::hw_sqrt::sqrtf,
    fabsf,
    copysignf,
    logf,
    ln_f32_hot,
    expf,
    sinf,
    cosf,
    sincosf,
    atan2f,
    cbrtf,
    hypotf,
    floorf
);
impl_real!(
    f64,
    f64,
    "f64",
    1,
    libm::sqrt,
    fabs,
    copysign,
    log,
    libm::log,
    exp,
    sin,
    cos,
    sincos,
    atan2,
    cbrt,
    hypot,
    floor
);

/// ln x for `f32` on a hot path (the rolling law's magnitude and shape coordinates).
///
/// **Formula.** x = 2ᵏ·m with m ∈ [1, 2) (the exponent and significand bits); ln m = ln r +
/// 2 artanh s, s = (m − r)/(m + r), r = √2 rounded to `f32` (m − r exact by Sterbenz's lemma),
/// |s| ≤ 0.1716, by the odd series to s⁷: ln x = s·(2 + z·(2/3 + z·(2/5 + z·2/7))) +
/// (k·ln 2 + ln r), z = s² (the series' remainder 2s⁹/9 ≤ 3e-8).
///
/// **Domain.** Positive normal finite x; anything else (0, subnormals, ∞, NaN, negatives)
/// goes to `logf` (one unsigned compare on the bits decides).
///
/// **Error.** Within 2.5 ulp of the exact ln (the result's ulp; for |ln x| < ¼, where that
/// ulp is no measure, 2.5 × 0.6e-7 absolute) on every `f32` in [½, 2] and every 64th bit
/// pattern over the normal range (`ln_hot_is_within_2_5_ulp`): measured worst 2.3 ulp (`logf`:
/// < 1 ulp).
///
/// **Cost.** Inline, one division, no branch on the normal range: 17 M4F instructions fewer
/// than `logf`'s 47 per call (`rolling,table` 1,037 → 1,020 with its one ln,
/// `bench-results/qemu.csv`).
#[inline(always)]
pub fn ln_f32_hot(x: f32) -> f32 {
    if !Real::is_positive_normal(x) {
        return libm::logf(x);
    }
    // x = 2ᵏ·m, m ∈ [1, 2): the exponent and the significand with a zero exponent
    let bits = x.to_bits();
    let k = (bits >> 23) as i32 - 0x7f;
    let m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    // ln m = ln r + 2 artanh s, s = (m − r)/(m + r), r = √2 rounded to f32 (m − r exact by
    // Sterbenz), |s| ≤ 0.1716
    const R: f32 = core::f32::consts::SQRT_2;
    const LN_R: f32 = 0.346_573_6; // ln R (R the f32 √2, not ½ ln 2), rounded
    let s = (m - R) / (m + R);
    let z = s * s;
    let series = s * (2.0 + z * (2.0 / 3.0 + z * (0.4 + z * (2.0 / 7.0))));
    series + (k as f32 * core::f32::consts::LN_2 + LN_R)
}

#[cfg(test)]
mod tests {
    use super::Real;

    #[test]
    fn sqrt_is_correctly_rounded_on_samples() {
        for &x in &[0.0f32, 1.0, 2.0, 1e-30, 3.5e30, 0.1] {
            assert_eq!(Real::sqrt(x), libm::sqrtf(x));
        }
        assert_eq!(Real::sqrt(2.0f64), core::f64::consts::SQRT_2);
    }

    /// |a − b| in units of b's `f32` spacing.
    fn ulps(a: f32, b: f64) -> f64 {
        let bf = (b as f32).abs();
        let spacing = (f32::from_bits(bf.to_bits() + 1) - bf) as f64;
        ((a as f64) - b).abs() / spacing
    }

    #[test]
    fn ln_hot_is_within_2_5_ulp() {
        let mut worst = 0.0f64;
        let mut check = |x: f32| {
            let exact = libm::log(x as f64);
            let got = super::ln_f32_hot(x);
            // near x = 1 the result's own ulp is no measure: 0.6e-7 absolute per ulp there
            let e = if exact.abs() < 0.25 {
                (got as f64 - exact).abs() / 0.6e-7
            } else {
                ulps(got, exact)
            };
            worst = worst.max(e);
            assert!(e <= 2.5, "x = {x:e}: {got:e} against {exact:e} ({e} ulp)");
        };
        // every f32 in [1/2, 2]
        for b in 0.5f32.to_bits()..=2.0f32.to_bits() {
            check(f32::from_bits(b));
        }
        // every 64th bit pattern over the positive normal range
        let mut b = f32::MIN_POSITIVE.to_bits();
        while b < f32::MAX.to_bits() {
            check(f32::from_bits(b));
            b += 64;
        }
        assert!(worst > 2.0, "the check is blind: worst {worst} ulp");
        // off the normal range: logf's own answer
        for x in [0.0f32, -1.0, f32::INFINITY, f32::NAN, 1e-40] {
            let (got, want) = (super::ln_f32_hot(x), libm::logf(x));
            assert!(got == want || (got.is_nan() && want.is_nan()), "{x}");
        }
        assert_eq!(Real::ln_hot(2.5f64), libm::log(2.5));
    }

    #[test]
    fn min_max_ignore_nan() {
        assert_eq!(Real::min(f32::NAN, 1.0), 1.0);
        assert_eq!(Real::max(1.0f64, f64::NAN), 1.0);
        assert_eq!(Real::clamp_to(f64::NAN, 0.0, 1.0), 0.0);
        assert_eq!(Real::trunc_usize(-3.0f32), 0);
        assert_eq!(Real::trunc_usize(f64::NAN), 0);
    }

    #[test]
    fn positive_normal_is_the_normal_range() {
        for x in [f32::MIN_POSITIVE, 1.0, f32::MAX, f32::MIN_POSITIVE * 1.5] {
            assert!(Real::is_positive_normal(x), "{x}");
        }
        let below = f32::from_bits(f32::MIN_POSITIVE.to_bits() - 1);
        for x in [
            0.0,
            -0.0,
            below,
            f32::INFINITY,
            f32::NAN,
            -1.0,
            -f32::MIN_POSITIVE,
        ] {
            assert!(!Real::is_positive_normal(x), "{x}");
        }
        assert!(Real::is_positive_normal(f64::MAX) && Real::is_positive_normal(f64::MIN_POSITIVE));
        assert!(!Real::is_positive_normal(f64::INFINITY) && !Real::is_positive_normal(5e-324));
    }
}
