//! [`Linearize`] for the rolling contacts ([`Rolling`] over a fixed [`Contact`] or a
//! [`VaryingContact`] at a step's curvatures): the same code as their `wrench` on dual
//! numbers. The rolling velocity V is held fixed (no derivative with respect to it); the creep
//! shape depends on V's direction and on a/b only, so it is built in `T` as the plain call
//! builds it and lifted (per call: 130 values for the shape cached along an axis, 216 for the
//! path of a fixed contact's skewed V, 292 and 378 for a varying contact's path and skew grid
//! — the cost of this form, see the [module docs](super)).

use super::contact::{Inputs, pack};
use super::lift::{LinearDamping, LinearNormal};
use super::{At, D5, Dual, Jacobian, Linearize, State};
use crate::Real;
use crate::contact::rolling::{Shapes, Step, direction, tangential};
use crate::contact::{Contact, Rolling, VaryingContact};
use crate::friction::rolling::RollingLaw;
use crate::friction::{Best, Constants, FrictionLaw as _, SlipState};
use crate::normal::{Hertz, NormalLaw as _};
use crate::shape::{self, Eccentricity, Ratio};

#[inline(always)]
fn lift<T: Real>(x: T) -> D5<T> {
    Dual::constant(x)
}

impl<T, N, D, L> Linearize<T> for Rolling<T, Contact<T, N, D, Best>, L>
where
    T: Real,
    N: LinearNormal<T>,
    D: LinearDamping<T>,
    L: RollingLaw,
{
    #[inline]
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        let w = self.wrench(s.h, s.hdot, s.slip, s.rolling);
        [w.n, w.fx, w.fy, w.tz]
    }

    /// As [`Rolling::wrench`] (the creep shape cached along the axes, else the contact's
    /// path), on dual numbers.
    #[inline]
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let (cx, sx, speed) = direction(s.rolling);
        let [along_x, along_y] = &self.cache.axes;
        let one;
        let skew;
        let shapes = if sx == T::ZERO || along_x.rho == T::ONE {
            one = along_x.map(lift);
            Shapes::One(&one)
        } else if cx == T::ZERO {
            one = along_y.map(lift);
            Shapes::One(&one)
        } else {
            skew = self.cache.skew.map(lift);
            Shapes::Skewed(&skew)
        };
        let c = &self.contact;
        let q = Inputs::of(s);
        let patch = c
            .normal()
            .lift()
            .damped_patch(q.h, q.hdot, &c.damping().lift());
        let step = Step::of(patch, lift(c.friction().coefficient()));
        let prepared = c.prepared();
        let full_slip = |st: &SlipState<D5<T>>| prepared.traction_dual(st).0;
        let frame = (lift(cx), lift(sx), lift(speed));
        let elasticity = self.elasticity.map(lift);
        let w = tangential::<D5<T>, L>(&step, shapes, elasticity, frame, q.slip, full_slip);
        pack([w.n, w.fx, w.fy, w.tz])
    }
}

impl<T: Real, D, L> Rolling<T, VaryingContact<T, D, Best>, L>
where
    D: crate::normal::Damping<T>,
{
    /// This contact at this step's curvatures, for [`Linearize`].
    pub fn at(&self, curvatures: &crate::geometry::Curvatures<T>) -> At<'_, Self, T> {
        At {
            contact: self,
            curvatures: *curvatures,
        }
    }
}

impl<T, D, L> Linearize<T> for At<'_, Rolling<T, VaryingContact<T, D, Best>, L>, T>
where
    T: Real,
    D: LinearDamping<T>,
    L: RollingLaw,
{
    #[inline]
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        let w = self
            .contact
            .wrench(&self.curvatures, s.h, s.hdot, s.slip, s.rolling);
        [w.n, w.fx, w.fy, w.tz]
    }

    /// As the varying rolling contact's `wrench`, on dual numbers.
    #[inline]
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let rolling = self.contact;
        let (estar, damping, friction) = rolling.contact.parts();
        let curvatures = &self.curvatures;
        let shape = <shape::Table as Eccentricity>::shape(Ratio::clamped(curvatures.ratio()));
        let normal = Hertz::from_shape(curvatures, &shape, estar).lift();
        let constants = Constants::from_shape(&shape).map(lift);
        let q = Inputs::of(s);
        let patch = normal.damped_patch(q.h, q.hdot, &damping.lift());
        let step = Step::of(patch, lift(friction.coefficient()));
        let full_slip = |st: &SlipState<D5<T>>| Best::traction(&constants, st).0;
        let (cx, sx, speed) = direction(s.rolling);
        let frame = (lift(cx), lift(sx), lift(speed));
        let path = rolling.cache.path.map(lift);
        let skew = rolling.cache.skew.map(lift);
        let elasticity = rolling.elasticity.map(lift);
        let w = tangential::<D5<T>, L>(
            &step,
            Shapes::Path(&path, &skew),
            elasticity,
            frame,
            q.slip,
            full_slip,
        );
        pack([w.n, w.fx, w.fy, w.tz])
    }
}
