//! Per-contact friction constants: everything that depends on the patch shape e² only.
//!
//! Built once per geometry (or per step from tabulated integrals when the eccentricity moves):
//!
//! ```text
//! A = (3/2)·D(m)         small-u slope of F_x/(fN) along the major axis x   (u_x* = 1/A)
//! B = (3/2)·B(m)         small-u slope of F_y/(fN) along the minor axis y   (u_y* = 1/B)
//! C = (3/8)·E(m)         pure-spin torque, T_z = −C·fNa                    (A ≥ B; m = 0: A = B = 3π/8, C = 3π/16)
//! γ = √m₁ = b/a
//! ```
//!
//! with m = e² the elliptic **parameter** and B(m) = (E − m₁K)/m, D(m) = (K − E)/m taken from
//! [`crate::elliptic`] without cancellation. These are the paper's (3.5) slopes: with them
//! F_x ≈ −αAu, F_y ≈ −βBu, T_z ≈ −C as u → 0.

use crate::Real;
use crate::elliptic::{Agm, Integrals, Method, Parameter};
use crate::shape::Shape;

/// The friction constants of one contact shape (see the [module docs](self)).
///
/// Construction costs four multiplications and three divisions given the [`Integrals`]
/// ([`Constants::from_integrals`]: 30 instructions in `f32` on the Cortex-M4F, call included);
/// the friction laws only read the stored fields.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Constants<T> {
    m: T,
    m1: T,
    a: T,
    b: T,
    c: T,
    inv_a: T,
    inv_b: T,
    inv_5c: T,
}

impl<T: Copy> Constants<T> {
    /// Every field through `f` (the dual form of the Jacobian: constants lifted).
    #[inline(always)]
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Constants<U> {
        Constants {
            m: f(self.m),
            m1: f(self.m1),
            a: f(self.a),
            b: f(self.b),
            c: f(self.c),
            inv_a: f(self.inv_a),
            inv_b: f(self.inv_b),
            inv_5c: f(self.inv_5c),
        }
    }
}

impl<T: Real> Constants<T> {
    /// From a validated parameter m = e², computing K, E, B, D with method `M`.
    #[inline]
    pub fn new<M: Method>(p: Parameter<T>) -> Self {
        Self::from_integrals(p, &M::integrals(p))
    }

    /// From a validated parameter m = e² with the default method ([`Agm`]).
    #[inline]
    pub fn from_parameter(p: Parameter<T>) -> Self {
        Self::new::<Agm>(p)
    }

    /// From integrals already computed for `p` (e.g. by the Hertz shape): no elliptic work.
    /// `i` must belong to `p`; only `i.b`, `i.d`, `i.e` are read.
    #[inline]
    pub fn from_integrals(p: Parameter<T>, i: &Integrals<T>) -> Self {
        Self::from_parts(p.m(), p.m1(), i)
    }

    /// From a contact [`Shape`] (c, m₁, K, E, B, D), e.g. solved once for a fixed geometry or
    /// by [`crate::shape::Table`] each step. Total. Cost: 3 divisions, 6 multiplies.
    #[inline]
    pub fn from_shape(shape: &Shape<T>) -> Self {
        Self::from_parts(shape.e2(), shape.m1(), &shape.integrals())
    }

    #[inline(always)]
    fn from_parts(m: T, m1: T, i: &Integrals<T>) -> Self {
        let three_halves = T::from_f64(1.5);
        let a = three_halves * i.d;
        let b = three_halves * i.b;
        let c = T::from_f64(0.375) * i.e;
        Constants {
            m,
            m1,
            a,
            b,
            c,
            inv_a: T::ONE / a,
            inv_b: T::ONE / b,
            inv_5c: T::ONE / (T::from_f64(5.0) * c),
        }
    }

    /// The circular patch (m = 0) in closed form: A = B = 3π/8, C = 3π/16; no elliptic integral
    /// is evaluated or linked.
    #[inline]
    pub fn circle() -> Self {
        let q = T::FRAC_PI_4;
        Self::from_parts(
            T::ZERO,
            T::ONE,
            &Integrals {
                k: T::FRAC_PI_2,
                e: T::FRAC_PI_2,
                b: q,
                d: q,
            },
        )
    }

    /// m = e²
    #[inline(always)]
    pub fn m(&self) -> T {
        self.m
    }
    /// m₁ = 1 − e² = (b/a)²
    #[inline(always)]
    pub fn m1(&self) -> T {
        self.m1
    }
    /// γ = √m₁ = b/a (computed on demand: one square root).
    #[inline]
    pub fn gamma(&self) -> T {
        self.m1.sqrt()
    }
    /// A = (3/2)·D(m): the small-u slope along the major axis x.
    #[inline(always)]
    pub fn slope_x(&self) -> T {
        self.a
    }
    /// B = (3/2)·B(m): the small-u slope along the minor axis y.
    #[inline(always)]
    pub fn slope_y(&self) -> T {
        self.b
    }
    /// C = (3/8)·E(m): the pure-spin torque in units of fNa.
    #[inline(always)]
    pub fn spin_torque(&self) -> T {
        self.c
    }
    /// u_x* = 1/A: where the simplified model's F_x saturates.
    #[inline(always)]
    pub fn knee_x(&self) -> T {
        self.inv_a
    }
    /// u_y* = 1/B: where the simplified model's F_y saturates.
    #[inline(always)]
    pub fn knee_y(&self) -> T {
        self.inv_b
    }
    /// 1/(5C) = u_z* at ψ = 0, the largest u_z* = |T₁|/C over all directions.
    #[inline(always)]
    pub fn knee_z_max(&self) -> T {
        self.inv_5c
    }
}
