//! The Hertz patch and its damping lane by lane (`Hertz::patch_with` +
//! `NormalLaw::damped_patch`, src/normal.rs).

use super::lanes::Lanes;
use crate::Real;
use crate::normal::{CompressionDamping, Damping, Hertz, HuntCrossley, NormalLaw, Undamped};

/// The Hertz coefficients of a few contacts: a = a_c√h, b = b_c√h, N = k_H·h·√h.
#[derive(Clone, Copy, Debug)]
pub struct HertzLanes<V> {
    pub a_coef: V,
    pub b_coef: V,
    pub k_h: V,
    pub e2: V,
}

/// One Hertz law's coefficients, read exactly through its patch at h = 1 (√1 = 1, x·1 = x).
#[inline(always)]
pub(crate) fn coefficients<T: Real>(hertz: &Hertz<T>) -> [T; 4] {
    let p = hertz.patch(T::ONE);
    [p.a, p.b, p.n, p.e2]
}

impl<V: Lanes> HertzLanes<V> {
    /// From [`coefficients`] per lane.
    #[inline(always)]
    pub(crate) fn of(c: &[[V::T; super::lanes::MAX_LANES]; 4]) -> Self {
        HertzLanes {
            a_coef: V::from_array(&c[0]),
            b_coef: V::from_array(&c[1]),
            k_h: V::from_array(&c[2]),
            e2: V::from_array(&c[3]),
        }
    }

    /// The same law in every lane.
    #[inline(always)]
    pub(crate) fn splat(hertz: &Hertz<V::T>) -> Self {
        let [a, b, k, e2] = coefficients(hertz);
        HertzLanes {
            a_coef: V::splat(a),
            b_coef: V::splat(b),
            k_h: V::splat(k),
            e2: V::splat(e2),
        }
    }

    /// (a, b, N) of the damped patch; h ≤ 0 gives the empty patch (+0).
    #[inline(always)]
    pub(crate) fn patch<D: BatchDamping<V::T>>(&self, d: &D, h: V, hdot: V) -> (V, V, V) {
        let zero = V::splat(V::T::ZERO);
        let contact = h.gt(zero);
        let sh = h.sqrt();
        let a = V::select(contact, self.a_coef * sh, zero);
        let b = V::select(contact, self.b_coef * sh, zero);
        let mut n = V::select(contact, self.k_h * h * sh, zero);
        if !D::ELASTIC {
            // `!patch.is_empty()`: a ≠ 0 (a can underflow to 0 at h > 0: undamped then).
            let damped = d.force_lanes(n, h, hdot).max_real(zero);
            n = V::select(a.eq(zero), n, damped);
        }
        (a, b, n)
    }
}

/// A damping law with a lane form (`Damping::force` lane by lane). Implemented for
/// [`Undamped`], [`HuntCrossley`] and [`CompressionDamping`].
pub trait BatchDamping<T: Real>: Damping<T> + super::sealed::Sealed {
    /// `Damping::force(elastic, h, ḣ)` of a few contacts.
    #[doc(hidden)]
    #[allow(private_bounds)]
    fn force_lanes<V: Lanes<T = T>>(&self, elastic: V, h: V, hdot: V) -> V;
}

impl<T: Real> BatchDamping<T> for Undamped {
    #[inline(always)]
    fn force_lanes<V: Lanes<T = T>>(&self, elastic: V, _h: V, _hdot: V) -> V {
        elastic
    }
}

impl<T: Real> BatchDamping<T> for HuntCrossley<T> {
    #[inline(always)]
    fn force_lanes<V: Lanes<T = T>>(&self, elastic: V, _h: V, hdot: V) -> V {
        elastic * (V::splat(T::ONE) + V::splat(self.three_halves_cd()) * hdot)
    }
}

impl<T: Real> BatchDamping<T> for CompressionDamping<T> {
    #[inline(always)]
    fn force_lanes<V: Lanes<T = T>>(&self, elastic: V, h: V, hdot: V) -> V {
        elastic + V::splat(self.coefficient()) * h * hdot.max_real(V::splat(T::ZERO))
    }
}
