//! Forward-mode dual numbers: a value and its K partial derivatives, made a (crate-sealed)
//! [`Real`] so that every generic routine of the crate differentiates itself.
//!
//! x = v + Σ dᵢ εᵢ with εᵢεⱼ = 0. Arithmetic follows the chain rule; the value part is computed
//! by exactly the operations of the plain `T` code (same order, same rounding), so a law
//! evaluated on duals returns the plain law's value bit for bit. Comparisons, branch tests and
//! table indices read the value only: a derivative is that of the branch the value takes
//! (one-sided at a switch).
//!
//! # Non-differentiable points (documented choices)
//!
//! | operation | at | derivative returned |
//! |---|---|---|
//! | √x, ∛x | x = 0 | 0 (the true one is +∞) |
//! | \|x\| | x = ±0 | that of x·sign(x) with sign(+0) = +1, sign(−0) = −1 (one-sided, the side of the zero's sign) |
//! | min, max, clamp | a tie | that of the operand returned |
//! | copysign(x, s) | x = 0 or s = ±0 | ±dx, the sign applied to the value |
//! | floor, trunc | everywhere | 0 |
//! | hypot(x, y) | x = y = 0 | 0 |
//! | atan2(y, x) | x = y = 0 | 0 |
//!
//! `to_f64` returns the value only: a routine that goes through `f64` drops the derivative
//! (audited: only per-shape constants that do not depend on the per-step inputs do, see
//! [`super`]).

use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use core::str::FromStr;

use crate::Real;

/// A value and its K partial derivatives (forward-mode automatic differentiation).
///
/// Equality and order compare the value only (a branch test must not depend on derivatives).
#[derive(Clone, Copy, Debug)]
pub struct Dual<T, const K: usize> {
    /// The value.
    pub v: T,
    /// ∂v/∂qᵢ, i < K.
    pub d: [T; K],
}

impl<T: Real, const K: usize> Dual<T, K> {
    /// A constant, in const context.
    const fn lifted(v: T) -> Self {
        Dual { v, d: [T::ZERO; K] }
    }

    /// A constant (every derivative zero).
    #[inline(always)]
    pub fn constant(v: T) -> Self {
        Dual { v, d: [T::ZERO; K] }
    }

    /// The independent variable number `i` at value `v` (∂v/∂qᵢ = 1); `i ≥ K` gives a
    /// constant.
    #[inline(always)]
    pub fn variable(v: T, i: usize) -> Self {
        let mut d = [T::ZERO; K];
        if let Some(x) = d.get_mut(i) {
            *x = T::ONE;
        }
        Dual { v, d }
    }

    /// f(v) with f′(v) = `slope`: the chain rule.
    #[inline(always)]
    fn chain(self, v: T, slope: T) -> Self {
        Dual {
            v,
            d: self.d.map(|x| x * slope),
        }
    }

    /// `self · k` for a constant `k` (K + 1 multiplies, not 2K + 1).
    #[inline(always)]
    pub fn scale(self, k: T) -> Self {
        self.chain(self.v * k, k)
    }
}

impl<T: Real, const K: usize> Default for Dual<T, K> {
    #[inline(always)]
    fn default() -> Self {
        Self::constant(T::ZERO)
    }
}

impl<T: Real, const K: usize> PartialEq for Dual<T, K> {
    #[inline(always)]
    fn eq(&self, other: &Self) -> bool {
        self.v == other.v
    }
}

/// The order of dual numbers: that of their values.
macro_rules! compare {
    ($($f:ident $op:tt),*) => {$(
        #[inline(always)]
        fn $f(&self, other: &Self) -> bool {
            self.v $op other.v
        }
    )*};
}

impl<T: Real, const K: usize> PartialOrd for Dual<T, K> {
    #[inline(always)]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.v.partial_cmp(&other.v)
    }
    compare!(lt <, le <=, gt >, ge >=);
}

impl<T: Real, const K: usize> fmt::Display for Dual<T, K> {
    /// The value only.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.v, f)
    }
}

impl<T: Real, const K: usize> FromStr for Dual<T, K> {
    type Err = <T as FromStr>::Err;
    /// A constant.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        T::from_str(s).map(Self::constant)
    }
}

/// `impl $tr for Dual`: the values and the derivatives entry by entry by `$op` (a sum or a
/// difference).
macro_rules! additive {
    ($($tr:ident, $f:ident, $op:tt, $op_assign:tt;)*) => {$(
        impl<T: Real, const K: usize> $tr for Dual<T, K> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                let mut d = self.d;
                for (x, &y) in d.iter_mut().zip(o.d.iter()) {
                    *x $op_assign y;
                }
                Dual { v: self.v $op o.v, d }
            }
        }
    )*};
}

additive! {
    Add, add, +, +=;
    Sub, sub, -, -=;
}

impl<T: Real, const K: usize> Mul for Dual<T, K> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        let mut d = self.d;
        for (x, &y) in d.iter_mut().zip(o.d.iter()) {
            *x = *x * o.v + self.v * y;
        }
        Dual { v: self.v * o.v, d }
    }
}

impl<T: Real, const K: usize> Div for Dual<T, K> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        let v = self.v / o.v;
        let inv = T::ONE / o.v;
        let mut d = self.d;
        for (x, &y) in d.iter_mut().zip(o.d.iter()) {
            *x = (*x - v * y) * inv;
        }
        Dual { v, d }
    }
}

impl<T: Real, const K: usize> Neg for Dual<T, K> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Dual {
            v: -self.v,
            d: self.d.map(|x| -x),
        }
    }
}

macro_rules! assign {
    ($tr:ident, $f:ident, $op:ident) => {
        impl<T: Real, const K: usize> $tr for Dual<T, K> {
            #[inline(always)]
            fn $f(&mut self, o: Self) {
                *self = (*self).$op(o);
            }
        }
    };
}
assign!(AddAssign, add_assign, add);
assign!(SubAssign, sub_assign, sub);
assign!(MulAssign, mul_assign, mul);
assign!(DivAssign, div_assign, div);

/// The sign of `x` as ±1 (that of its sign bit: +0 → +1, −0 → −1).
#[inline(always)]
fn sign<T: Real>(x: T) -> T {
    T::ONE.copysign(x)
}

/// `Real`'s conversions into a dual number: constants (zero derivatives).
macro_rules! constants {
    ($($f:ident($t:ty)),*) => {$(
        #[inline(always)]
        fn $f(x: $t) -> Self {
            Self::constant(T::$f(x))
        }
    )*};
}

/// `Real`'s reads of a dual number: those of its value.
macro_rules! of_value {
    ($($f:ident -> $t:ty),*) => {$(
        #[inline(always)]
        fn $f(self) -> $t {
            self.v.$f()
        }
    )*};
}

impl<T: Real, const K: usize> crate::real::sealed::Sealed for Dual<T, K> {}

impl<T: Real, const K: usize> Real for Dual<T, K> {
    const NAME: &'static str = "dual";
    const DERIVATIVES: bool = true;
    type Base = T::Base;
    const MANTISSA_DIGITS: u32 = T::MANTISSA_DIGITS;
    const ZERO: Self = Self::lifted(T::ZERO);
    const ONE: Self = Self::lifted(T::ONE);
    const TWO: Self = Self::lifted(T::TWO);
    const HALF: Self = Self::lifted(T::HALF);
    const PI: Self = Self::lifted(T::PI);
    const FRAC_PI_2: Self = Self::lifted(T::FRAC_PI_2);
    const FRAC_PI_4: Self = Self::lifted(T::FRAC_PI_4);
    const EPSILON: Self = Self::lifted(T::EPSILON);
    const MAX: Self = Self::lifted(T::MAX);
    const MIN_POSITIVE: Self = Self::lifted(T::MIN_POSITIVE);

    #[inline(always)]
    fn of_precision<'a, const W: usize, const C: usize>(
        single: &'a [[f32; W]; C],
        double: &'a [[f64; W]; C],
    ) -> &'a [[Self::Base; W]; C] {
        T::of_precision(single, double)
    }
    constants!(
        from_base(Self::Base),
        from_f64(f64),
        from_f32(f32),
        from_usize(usize)
    );
    of_value!(to_f64 -> f64, trunc_usize -> usize, is_finite -> bool, is_positive_normal -> bool);
    #[inline(always)]
    fn sqrt(self) -> Self {
        let r = self.v.sqrt();
        // d√x = dx/(2√x); 0 at x = 0 (see the module docs)
        let slope = if r > T::ZERO { T::HALF / r } else { T::ZERO };
        self.chain(r, slope)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        self.chain(self.v.abs(), sign(self.v))
    }
    #[inline(always)]
    #[allow(clippy::eq_op)] // `x != x`: the NaN test, as `Real::min` for f32/f64
    fn min(self, other: Self) -> Self {
        if other.v < self.v || self.v != self.v {
            other
        } else {
            self
        }
    }
    #[inline(always)]
    #[allow(clippy::eq_op)]
    fn max(self, other: Self) -> Self {
        if other.v > self.v || self.v != self.v {
            other
        } else {
            self
        }
    }
    #[inline(always)]
    fn copysign(self, s: Self) -> Self {
        let v = self.v.copysign(s.v);
        self.chain(v, sign(self.v) * sign(s.v))
    }
    #[inline(always)]
    fn ln(self) -> Self {
        self.chain(self.v.ln(), T::ONE / self.v)
    }
    #[inline(always)]
    fn ln_hot(self) -> Self {
        self.chain(self.v.ln_hot(), T::ONE / self.v)
    }
    #[inline(always)]
    fn exp(self) -> Self {
        let e = self.v.exp();
        self.chain(e, e)
    }
    #[inline(always)]
    fn sin(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(s, c)
    }
    #[inline(always)]
    fn cos(self) -> Self {
        let (s, c) = self.v.sin_cos();
        self.chain(c, -s)
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        let (s, c) = self.v.sin_cos();
        (self.chain(s, c), self.chain(c, -s))
    }
    #[inline(always)]
    #[allow(clippy::eq_op)]
    fn atan2(self, x: Self) -> Self {
        let v = self.v.atan2(x.v);
        let r2 = self.v * self.v + x.v * x.v;
        if r2 <= T::ZERO || r2 != r2 {
            return Self::constant(v);
        }
        let inv = T::ONE / r2;
        let mut d = self.d;
        for (dy, &dx) in d.iter_mut().zip(x.d.iter()) {
            *dy = (x.v * *dy - self.v * dx) * inv;
        }
        Dual { v, d }
    }
    #[inline(always)]
    fn cbrt(self) -> Self {
        let r = self.v.cbrt();
        let r2 = r * r;
        let slope = if r2 > T::ZERO {
            T::ONE / (T::from_f64(3.0) * r2)
        } else {
            T::ZERO
        };
        self.chain(r, slope)
    }
    #[inline(always)]
    #[allow(clippy::eq_op)]
    fn hypot(self, o: Self) -> Self {
        let h = self.v.hypot(o.v);
        if h <= T::ZERO || h != h {
            return Self::constant(h);
        }
        let (cx, cy) = (self.v / h, o.v / h);
        let mut d = self.d;
        for (x, &y) in d.iter_mut().zip(o.d.iter()) {
            *x = cx * *x + cy * y;
        }
        Dual { v: h, d }
    }
    #[inline(always)]
    fn floor(self) -> Self {
        Self::constant(self.v.floor())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type D = Dual<f64, 2>;

    #[test]
    fn chain_rule_on_samples() {
        let x = D::variable(0.7, 0);
        let y = D::variable(-1.3, 1);
        let f = (x * y).exp() / (x.sq() + y.sq()).sqrt() - y.atan2(x) + x.hypot(y) * x.abs();
        // central differences of the same expression in f64
        let g = |x: f64, y: f64| {
            (x * y).exp() / (x * x + y * y).sqrt() - y.atan2(x) + x.hypot(y) * x.abs()
        };
        let e = 1e-6;
        let dx = (g(0.7 + e, -1.3) - g(0.7 - e, -1.3)) / (2.0 * e);
        let dy = (g(0.7, -1.3 + e) - g(0.7, -1.3 - e)) / (2.0 * e);
        assert_eq!(f.v, g(0.7, -1.3));
        assert!((f.d[0] - dx).abs() < 1e-8 && (f.d[1] - dy).abs() < 1e-8);
    }

    #[test]
    fn kinks_are_finite() {
        let z = D::variable(0.0, 0);
        assert_eq!(z.sqrt().d, [0.0, 0.0]);
        assert_eq!(z.abs().d, [1.0, 0.0]);
        assert_eq!((-z).abs().d, [1.0, 0.0]); // −0: the left side, |x| = −x
        assert_eq!(z.hypot(z).d, [0.0, 0.0]);
        assert_eq!(z.cbrt().d, [0.0, 0.0]);
    }
}
