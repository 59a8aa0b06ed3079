//! The dimensionless cores of `simplified`, `pade`, `ellipsoid` and `coulomb` lane by lane:
//! each is its scalar `traction` (`src/friction/<law>.rs`) with every branch a select, the same
//! operations in the same order.

use super::lanes::Lanes;
use super::state::{State, Tr};
use crate::Real;
use crate::friction::Constants;

/// The shape constants of a few contacts ([`Constants`] lane by lane: one splatted for a
/// fixed contact, one per row for a varying one).
#[derive(Clone, Copy, Debug)]
pub struct Shape<V> {
    pub m: V,
    pub m1: V,
    pub a: V,
    pub b: V,
    pub c: V,
    pub inv_a: V,
    pub inv_b: V,
    pub inv_5c: V,
}

impl<V: Lanes> Shape<V> {
    /// The same constants in every lane.
    #[inline(always)]
    pub(crate) fn splat(k: &Constants<V::T>) -> Self {
        Shape {
            m: V::splat(k.m()),
            m1: V::splat(k.m1()),
            a: V::splat(k.slope_x()),
            b: V::splat(k.slope_y()),
            c: V::splat(k.spin_torque()),
            inv_a: V::splat(k.knee_x()),
            inv_b: V::splat(k.knee_y()),
            inv_5c: V::splat(k.knee_z_max()),
        }
    }

    /// Lane i from `k[i]`.
    #[inline(always)]
    pub(crate) fn of_lanes(k: &[Constants<V::T>]) -> Self {
        let lane = |f: fn(&Constants<V::T>) -> V::T| {
            let mut a = [V::T::ZERO; super::lanes::MAX_LANES];
            for (x, k) in a.iter_mut().zip(k) {
                *x = f(k);
            }
            a
        };
        Shape {
            m: V::from_array(&lane(Constants::m)),
            m1: V::from_array(&lane(Constants::m1)),
            a: V::from_array(&lane(Constants::slope_x)),
            b: V::from_array(&lane(Constants::slope_y)),
            c: V::from_array(&lane(Constants::spin_torque)),
            inv_a: V::from_array(&lane(Constants::knee_x)),
            inv_b: V::from_array(&lane(Constants::knee_y)),
            inv_5c: V::from_array(&lane(Constants::knee_z_max)),
        }
    }
}

/// `simplified::traction` (libm backend).
#[inline(always)]
pub(crate) fn simplified<V: Lanes>(k: &Shape<V>, s: &State<V>) -> Tr<V> {
    let zero = V::splat(V::T::ZERO);
    let (x, y, w, d) = (s.x, s.y, s.w, s.d);
    let aw = w.abs();
    let xx = x * x;
    let v2 = xx + y * y;
    let v = v2.sqrt();
    let vd = v.larger(d);
    let (wx, wy) = (aw * k.inv_a, aw * k.inv_b);
    let q = xx + k.m1 * y * y;
    let five_v3 = V::splat(V::T::from_f64(5.0)) * v2 * v;
    let t = if V::T::MANTISSA_DIGITS <= 24 {
        let hyperbolic = (q * aw).lt(k.c * five_v3);
        let num = V::select(hyperbolic, q, k.c);
        let den = V::select(hyperbolic, five_v3, aw);
        num / den
    } else {
        let plateau = k.c / aw;
        let hyperbola = q / five_v3;
        V::select(hyperbola.lt(plateau), hyperbola, plateau)
    };
    let tz = -w * t;
    let spin = aw * k.inv_5c;
    let regularized = V::select(spin.gt(zero), tz * (spin / d), zero);
    Tr {
        fx: -x / vd.larger(wx),
        fy: -y / vd.larger(wy),
        tz: V::select(spin.lt(d), regularized, tz),
    }
}

/// `pade::traction`.
#[inline(always)]
pub(crate) fn pade<V: Lanes>(k: &Shape<V>, s: &State<V>) -> Tr<V> {
    let zero = V::splat(V::T::ZERO);
    let (x, y, w) = (s.x, s.y, s.w);
    let aw = w.abs();
    let v2 = x * x + y * y;
    let rest = V::and(aw.eq(zero), v2.eq(zero));
    let v = v2.sqrt();
    let (a, b, c) = (k.a, k.b, k.c);
    let fx = -x * a / (aw + a * v);
    let fy = -y * b / (aw + b * v);
    let p = (x * x + k.m1 * y * y) * aw;
    let den = p + c * V::splat(V::T::from_f64(5.0)) * v2 * v;
    let t = V::select(den.gt(zero), c * p / den, c);
    let slip = Tr {
        fx,
        fy,
        tz: -t.copysign(w),
    };
    Tr::select(rest, Tr::zero(), slip)
}

/// `ellipsoid::traction` (libm backend).
#[inline(always)]
pub(crate) fn ellipsoid<V: Lanes>(k: &Shape<V>, s: &State<V>) -> Tr<V> {
    let zero = V::splat(V::T::ZERO);
    let (x, y, w) = (s.x, s.y, s.w);
    let r = k.c;
    let rw = r * w;
    let n2 = x * x + y * y + rw * rw;
    let inv = V::splat(V::T::ONE) / n2.sqrt();
    let slip = Tr {
        fx: -x * inv,
        fy: -y * inv,
        tz: -r * rw * inv,
    };
    Tr::select(n2.eq(zero), Tr::zero(), slip)
}

/// `coulomb::traction` (libm backend).
#[inline(always)]
pub(crate) fn coulomb<V: Lanes>(s: &State<V>) -> Tr<V> {
    let zero = V::splat(V::T::ZERO);
    let (x, y, d) = (s.x, s.y, s.d);
    let mx = x.abs().larger(y.abs());
    let (xs, ys, ds) = (x / mx, y / mx, d / mx);
    let v = (xs * xs + ys * ys).sqrt();
    let den = V::select(v.ge(ds), v, ds);
    let slip = Tr {
        fx: -xs / den,
        fy: -ys / den,
        tz: zero,
    };
    Tr::select(mx.eq(zero), Tr::zero(), slip)
}
