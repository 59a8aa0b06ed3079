//! The exact quartic of `best` inside the ellipse, and the outside coefficients it gives on
//! the boundary.

use core::ops::{Add, Mul, Neg};

use crate::Real;
use crate::friction::Constants;

/// The quartic's constants (first quadrant, X = |X₀|, Y = |Y₀|).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quartic<T> {
    pub(crate) a: T,
    pub(crate) b: T,
    pub(crate) c: T,
    /// 2c₂₂
    pub(crate) k22: T,
    /// 4c₄₀
    pub(crate) k40: T,
    /// 4c₄₀/m₁
    pub(crate) k40m: T,
    /// B/2, A/2
    pub(crate) hb: T,
    pub(crate) ha: T,
    /// 3c₄₀, 3c₂₂, 3c₄₀/m₁
    pub(crate) t40: T,
    pub(crate) t22: T,
    pub(crate) t40m: T,
    pub(crate) m1: T,
}

/// c₄₀(m) = −[(2−m)E − 2(1−m)K]/(8m²), Taylor coefficients (m < 0.05: error < 1e-13).
pub(crate) const C40_SERIES: [f64; 8] = [
    -0.07363107781851078,
    -0.018407769454627694,
    -0.008628641931856732,
    -0.00503337446024976,
    -0.003303151989538905,
    -0.0023358003354596543,
    -0.001739684624847555,
    -0.0013461845311320366,
];

impl<T: Copy> Quartic<T> {
    /// Every constant through `f` (the dual form of the Jacobian).
    #[inline(always)]
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Quartic<U> {
        Quartic {
            a: f(self.a),
            b: f(self.b),
            c: f(self.c),
            k22: f(self.k22),
            k40: f(self.k40),
            k40m: f(self.k40m),
            hb: f(self.hb),
            ha: f(self.ha),
            t40: f(self.t40),
            t22: f(self.t22),
            t40m: f(self.t40m),
            m1: f(self.m1),
        }
    }
}

impl<T: Copy + Add<Output = T> + Mul<Output = T> + Neg<Output = T>> Quartic<T> {
    /// (−F_x, −F_y, T_z) for X = y/|w|, Y = x/|w| (T_z for w > 0): F_x is odd in Y and even in
    /// X, F_y the reverse, T_z even in both. Scalar or lane-wise (src/batch/best.rs): the arithmetic alone.
    #[inline(always)]
    pub(crate) fn eval(&self, x: T, y: T) -> (T, T, T) {
        let (x2, y2) = (x * x, y * y);
        let fx = y * (self.a + self.k22 * x2 + self.k40m * y2);
        let fy = x * (self.b + self.k40 * x2 + self.k22 * y2);
        // −Ψ + XΨ_X + YΨ_Y: the quadratic terms once, the quartic ones three times.
        let tz = -self.c
            + x2 * (self.hb + self.t40 * x2 + self.t22 * y2)
            + y2 * (self.ha + self.t40m * y2);
        (fx, fy, tz)
    }
}

impl<T: Real> Quartic<T> {
    #[inline(always)]
    pub(crate) fn new(k: &Constants<T>) -> Self {
        let (m, m1, a, b) = (k.m(), k.m1(), k.slope_x(), k.slope_y());
        let c40 = if m < T::from_f64(0.05) {
            C40_SERIES
                .iter()
                .rev()
                .fold(T::ZERO, |acc, &c| acc * m + T::from_f64(c))
        } else {
            // B(m) − m₁D(m) = (2/3)(B − m₁A); c₄₀ = −(B(m) − m₁D(m))/(8m)
            -(b - m1 * a) / (T::from_f64(12.0) * m)
        };
        let c22 = -T::HALF * (a + T::from_f64(12.0) * c40);
        let k40 = T::from_f64(4.0) * c40;
        let three = T::from_f64(3.0);
        let t40 = three * c40;
        let im1 = T::ONE / m1;
        Quartic {
            a,
            b,
            c: k.spin_torque(),
            k22: T::TWO * c22,
            k40,
            k40m: k40 * im1,
            hb: T::HALF * b,
            ha: T::HALF * a,
            t40,
            t22: three * c22,
            t40m: t40 * im1,
            m1,
        }
    }

    /// The seven outside coefficients on the boundary (a_c = 1, τ = 1), from the quartic at
    /// (X₀, Y₀) = (−sin ν, γ cos ν).
    pub(crate) fn boundary(&self, gamma: T) -> [T; 7] {
        let (a, b, c, m1) = (self.a, self.b, self.c, self.m1);
        let c40 = T::from_f64(0.25) * self.k40;
        let c22 = T::HALF * self.k22;
        let three = T::from_f64(3.0);
        [
            gamma * (a + self.k40),
            gamma * (self.k22 - self.k40),
            b + self.k22 * m1,
            self.k40 - self.k22 * m1,
            -c + T::HALF * a * m1 + three * c40 * m1,
            T::HALF * (b - a * m1) + three * m1 * (c22 - T::TWO * c40),
            three * (c40 * (T::ONE + m1) - c22 * m1),
        ]
    }
}
