//! [`Linearize`] for the sliding contacts: [`Contact`] (fixed geometry) and [`VaryingContact`]
//! at a step's curvatures ([`At`]).

use super::lift::{DualCore, LinearDamping, LinearLaw, LinearNormal};
use super::{D5, Dual, Jacobian, Linearize, State, input};
use crate::Real;
use crate::contact::{Contact, VaryingContact};
use crate::friction::law::PerCall;
use crate::friction::{FrictionLaw, Slip};
use crate::geometry::Curvatures;
use crate::normal::{Damping, Hertz, NormalLaw, Patch};
use crate::shape::{self, Eccentricity, Ratio};

/// The per-step inputs as the five independent variables.
pub(crate) struct Inputs<T: Real> {
    pub(crate) h: D5<T>,
    pub(crate) hdot: D5<T>,
    pub(crate) slip: Slip<D5<T>>,
}

impl<T: Real> Inputs<T> {
    #[inline(always)]
    pub(crate) fn of(s: &State<T>) -> Self {
        let v = Dual::variable;
        Inputs {
            h: v(s.h, input::H),
            hdot: v(s.hdot, input::HDOT),
            // the validated slip as it is (`or_rest` would give rest where finite components
            // overflow their sum, near `T::MAX`, and the value would differ from the wrench's)
            slip: Slip::from_valid(
                v(s.slip.vx(), input::VX),
                v(s.slip.vy(), input::VY),
                v(s.slip.omega(), input::OMEGA),
            ),
        }
    }
}

/// Values and derivatives of (N, F_x, F_y, T_z), the derivatives made finite: one that
/// overflowed saturates at ±`T::MAX`, a NaN (zero times an overflowed intermediate derivative:
/// out of contact, f = 0, a slip speed near the float's smallest normal) is 0.
#[inline(always)]
pub(crate) fn pack<T: Real>(w: [D5<T>; 4]) -> Jacobian<T> {
    let mut jac = Jacobian {
        value: w.map(|x| x.v),
        d: w.map(|x| x.d),
    };
    // one test on the sum (finite exactly when every term is, unless finite terms overflow
    // it, which only sends them through `finite` unchanged)
    if !jac
        .d
        .iter()
        .flatten()
        .fold(T::ZERO, |acc, &x| acc + x)
        .is_finite()
    {
        saturate(&mut jac);
    }
    jac
}

/// Every derivative through [`finite`] (off the common path).
#[cold]
#[inline(never)]
fn saturate<T: Real>(jac: &mut Jacobian<T>) {
    for x in jac.d.iter_mut().flatten() {
        *x = finite(*x);
    }
}

/// ±∞ → ±`T::MAX`, NaN → 0, anything else unchanged.
#[inline(always)]
#[allow(clippy::eq_op)] // `x != x`: the NaN test
fn finite<T: Real>(x: T) -> T {
    if x.is_finite() {
        x
    } else if x != x {
        T::ZERO
    } else {
        T::MAX.copysign(x)
    }
}

/// At exact rest (v_P = 0, ω = 0) the dual pass gives a zero slip block (the slip state is
/// all zero there, its derivatives too). For a law with a ramp below δ > 0 ([`LinearLaw::RAMP`])
/// the slip columns are replaced by the slopes along each axis, w(η·eⱼ)/η with η = δ/4
/// inside the ramp (ω: η/a), where the law is homogeneous of degree one: the derivative itself
/// for `coulomb` and `simplified`; for `best`, whose ramp is not differentiable at rest (its
/// slope depends on the direction), the slope along each axis, which is also what central
/// differences along that axis give (F is odd). Three plain wrench calls, at rest only.
#[cold]
#[inline(never)]
fn rest_columns<T: Real>(
    jac: &mut Jacobian<T>,
    a: T,
    delta: T,
    wrench: impl Fn(Slip<T>) -> [T; 4],
) {
    let eta = T::from_f64(0.25) * delta;
    let steps = [
        (eta, T::ZERO, T::ZERO),
        (T::ZERO, eta, T::ZERO),
        (T::ZERO, T::ZERO, eta / a),
    ];
    for (k, (vx, vy, w)) in steps.into_iter().enumerate() {
        let e = vx + vy + w;
        let col = wrench(Slip::or_rest(vx, vy, w));
        // N does not depend on the slip; the friction rows take the slope
        for (row, &x) in jac.d.iter_mut().zip(col.iter()).skip(1) {
            if let Some(d) = row.get_mut(input::VX + k) {
                *d = finite(x / e);
            }
        }
    }
}

/// Whether [`rest_columns`] applies: exact rest, a ramp law, δ > 0, a > 0 (in contact).
#[inline(always)]
fn at_rest<T: Real, L: LinearLaw>(s: &State<T>, a: T, delta: T) -> bool {
    L::RAMP
        && s.slip.vx() == T::ZERO
        && s.slip.vy() == T::ZERO
        && s.slip.omega() == T::ZERO
        && delta > T::ZERO
        && a > T::ZERO
}

/// The wrench from a dual patch and a friction call (the same steps as the plain wrench).
#[inline(always)]
fn wrench_dual<T: Real, L: FrictionLaw>(
    patch: &Patch<D5<T>>,
    t: crate::friction::Tangential<D5<T>, L::Branch>,
) -> Jacobian<T> {
    pack([patch.n, t.fx, t.fy, t.tz])
}

impl<T, N, D, L> Linearize<T> for Contact<T, N, D, L>
where
    T: Real,
    N: LinearNormal<T>,
    D: LinearDamping<T>,
    L: LinearLaw,
{
    #[inline]
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        let w = self.wrench(s.h, s.hdot, s.slip);
        [w.n, w.fx, w.fy, w.tz]
    }

    /// [`Contact::wrench`]'s N: its normal law alone.
    #[inline]
    fn normal_force(&self, s: &State<T>) -> T {
        self.normal().damped_patch(s.h, s.hdot, self.damping()).n
    }

    /// The law's [`FrictionLaw::MAXIMALLY_DISSIPATIVE`](crate::friction::FrictionLaw).
    #[inline]
    fn maximally_dissipative(&self) -> bool {
        L::MAXIMALLY_DISSIPATIVE
    }

    /// The wrench and its Jacobian, by forward-mode dual numbers through the same code as
    /// [`Contact::wrench`] (value bit for bit that of `wrench`; see the [module docs](super)).
    #[inline]
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let q = Inputs::of(s);
        let patch = self
            .normal()
            .lift()
            .damped_patch(q.h, q.hdot, &self.damping().lift());
        let core = DualCore::<T, L>(self.prepared());
        let clamp = !N::NON_NEGATIVE;
        let t = self
            .friction()
            .map(Dual::constant)
            .tangential_with(core, clamp, patch.a, patch.n, q.slip);
        let mut jac = wrench_dual::<T, L>(&patch, t);
        let delta = self.friction().delta();
        if at_rest::<T, L>(s, patch.a.v, delta) {
            let w = |slip| self.wrench4(&State { slip, ..*s });
            rest_columns(&mut jac, patch.a.v, delta, w);
        }
        jac
    }
}

/// A [`VaryingContact`] at one step's curvatures: what [`Linearize`] needs besides the
/// per-step state (the curvatures are not differentiated: the wrench's dependence on the
/// geometry is not an input of the step).
#[derive(Clone, Copy, Debug)]
pub struct At<'a, C, T> {
    /// The contact.
    pub contact: &'a C,
    /// This step's curvatures.
    pub curvatures: Curvatures<T>,
}

impl<T: Real, D: Damping<T>, L: FrictionLaw> VaryingContact<T, D, L> {
    /// This contact at this step's curvatures, for [`Linearize`].
    pub fn at(&self, curvatures: &Curvatures<T>) -> At<'_, Self, T> {
        At {
            contact: self,
            curvatures: *curvatures,
        }
    }
}

impl<T, D, L> Linearize<T> for At<'_, VaryingContact<T, D, L>, T>
where
    T: Real,
    D: LinearDamping<T>,
    L: LinearLaw,
{
    #[inline]
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        let w = self.contact.wrench(&self.curvatures, s.h, s.hdot, s.slip);
        [w.n, w.fx, w.fy, w.tz]
    }

    /// The law's [`FrictionLaw::MAXIMALLY_DISSIPATIVE`](crate::friction::FrictionLaw).
    #[inline]
    fn maximally_dissipative(&self) -> bool {
        L::MAXIMALLY_DISSIPATIVE
    }

    /// [`VaryingContact::wrench`]'s N: this step's Hertz law alone.
    #[inline]
    fn normal_force(&self, s: &State<T>) -> T {
        let (estar, damping, _) = self.contact.parts();
        let c = &self.curvatures;
        let shape = <shape::Table as Eccentricity>::shape(Ratio::clamped(c.ratio()));
        Hertz::from_shape(c, &shape, estar)
            .damped_patch(s.h, s.hdot, damping)
            .n
    }

    /// As [`VaryingContact::wrench`]: the shape, Hertz's and the friction constants from
    /// [`shape::Table`] in `T` (they depend on the curvatures only), then the per-step part
    /// on dual numbers.
    #[inline]
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let (estar, damping, friction) = self.contact.parts();
        let curvatures = &self.curvatures;
        let shape = <shape::Table as Eccentricity>::shape(Ratio::clamped(curvatures.ratio()));
        let normal = Hertz::from_shape(curvatures, &shape, estar).lift();
        let constants = crate::friction::Constants::from_shape(&shape).map(Dual::constant);
        let q = Inputs::of(s);
        let patch = normal.damped_patch(q.h, q.hdot, &damping.lift());
        let clamp = !<Hertz<T> as NormalLaw<T>>::NON_NEGATIVE;
        let t = friction.map(Dual::constant).tangential_with(
            PerCall(&constants),
            clamp,
            patch.a,
            patch.n,
            q.slip,
        );
        let mut jac = wrench_dual::<T, L>(&patch, t);
        let delta = friction.delta();
        if at_rest::<T, L>(s, patch.a.v, delta) {
            let w = |slip| self.wrench4(&State { slip, ..*s });
            rest_columns(&mut jac, patch.a.v, delta, w);
        }
        jac
    }
}
