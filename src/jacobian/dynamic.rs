//! The Jacobian of the run-time contract ([`DynContact`]): the same validation as
//! [`DynContact::wrench`], then [`Linearize::linearize`] of the generic contact it holds.

use super::{Jacobian, Linearize, State};
use crate::Real;
use crate::dynamic::{ByLaw, DynContact, Formed, Invalid, RollingFormed, RollingStep, Step};
use crate::friction::rolling::{RollingLaw, RollingVelocity};
use crate::geometry::Curvatures;

use super::lift::LinearLaw;

/// The Jacobian of a contact in either form (a varying one at this step's curvatures), for
/// the sliding and the rolling laws.
macro_rules! either_form {
    ($($formed:ident<$law:ident>),*) => {$(
        impl<T: Real, L: $law> $formed<T, L> {
            #[inline]
            fn jacobian(&self, curvatures: &Curvatures<T>, s: &State<T>) -> Jacobian<T> {
                match self {
                    $formed::Fixed(c) => c.linearize(s),
                    $formed::Varying(c) => c.at(curvatures).linearize(s),
                }
            }
        }
    )*};
}

either_form!(Formed<LinearLaw>, RollingFormed<RollingLaw>);

impl<T: Real> DynContact<T> {
    /// The wrench (N, F_x, F_y, T_z) and its Jacobian with respect to (h, ḣ, v_x, v_y, ω) for
    /// one step: the step columns validated as in [`DynContact::wrench`] (the same errors),
    /// the values bit for bit those of `wrench`. A rolling law takes the default rolling step
    /// (V = 0; [`DynContact::jacobian_rolling`]).
    #[inline]
    pub fn jacobian(&self, step: &Step<T>) -> Result<Jacobian<T>, Invalid> {
        self.jacobian_rolling(step, &RollingStep::default())
    }

    /// [`DynContact::jacobian`] with the optional rolling columns `vrx, vry` (read and
    /// validated by the rolling laws only, after the step columns; V is not differentiated).
    #[inline]
    pub fn jacobian_rolling(
        &self,
        step: &Step<T>,
        rolling: &RollingStep<T>,
    ) -> Result<Jacobian<T>, Invalid> {
        let (h, hdot, slip) = step.validated()?;
        let state = |v: RollingVelocity<T>| State {
            h,
            hdot,
            slip,
            rolling: v,
        };
        let c = &self.curvatures;
        Ok(match &self.contact {
            ByLaw::Best(x) => x.jacobian(c, &state(RollingVelocity::ZERO)),
            ByLaw::Simplified(x) => x.jacobian(c, &state(RollingVelocity::ZERO)),
            ByLaw::Pade(x) => x.jacobian(c, &state(RollingVelocity::ZERO)),
            ByLaw::Ellipsoid(x) => x.jacobian(c, &state(RollingVelocity::ZERO)),
            ByLaw::Coulomb(x) => x.jacobian(c, &state(RollingVelocity::ZERO)),
            ByLaw::Table(x) => x.jacobian(c, &state(rolling.velocity()?)),
            ByLaw::Blend(x) => x.jacobian(c, &state(rolling.velocity()?)),
            ByLaw::Fastsim(x) => x.jacobian(c, &state(rolling.velocity()?)),
            ByLaw::Fastsim16(x) => x.jacobian(c, &state(rolling.velocity()?)),
        })
    }
}
