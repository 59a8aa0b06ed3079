//! The parts of a contact in dual form: each normal law, damping law and friction law says how
//! its per-step call runs on [`Dual`] numbers, its constants lifted (derivative zero) at the
//! call, nothing stored.

use super::{D5, Dual};
use crate::Real;
use crate::friction::law::Core;
use crate::friction::{
    Best, BestSeries, Constants, Coulomb, Ellipsoid, FrictionLaw, Pade, Simplified, SlipState,
    Traction,
};
#[cfg(feature = "micromath")]
use crate::normal::HertzMicromath;
use crate::normal::{
    CompressionDamping, Damping, Fitted, Hertz, HuntCrossley, NormalLaw, Undamped, Volumetric,
};

/// A normal law whose patch can be differentiated: the same law with its constants lifted to
/// [`Dual`] numbers (a few multiplies per call; the law's `patch` then runs on duals).
pub trait LinearNormal<T: Real>: NormalLaw<T> {
    /// The law over dual numbers.
    type Dual: NormalLaw<D5<T>>;
    /// This law's constants as dual constants.
    fn lift(&self) -> Self::Dual;
}

/// A damping law whose force can be differentiated (see [`LinearNormal`]).
pub trait LinearDamping<T: Real>: Damping<T> {
    /// The law over dual numbers.
    type Dual: Damping<D5<T>>;
    /// This law's coefficients as dual constants.
    fn lift(&self) -> Self::Dual;
}

/// A friction law whose per-contact core can be differentiated: the core on a dual slip state.
/// Every law of the crate except the reference [`Exact`](crate::friction::Exact), which
/// computes in `f64` internally (a round trip that drops derivatives).
pub trait LinearLaw: FrictionLaw {
    /// Whether the law is a ramp below δ at rest (homogeneous of degree one there: `best`,
    /// `simplified`, `coulomb`), so that its slope at exact rest along each axis is
    /// F(η·e)/η for any η inside the ramp; `false` for the laws that ignore δ (`pade`,
    /// `ellipsoid`: Coulomb's jump at rest, no slope).
    const RAMP: bool;
    /// [`FrictionLaw::traction_prepared`] on a dual slip state, with the same value bit for bit.
    fn traction_dual<T: Real>(
        p: &Self::Prepared<T>,
        s: &SlipState<D5<T>>,
    ) -> (Traction<D5<T>>, Self::Branch);
}

#[inline(always)]
fn lift<T: Real>(x: T) -> D5<T> {
    Dual::constant(x)
}

/// `impl $tr<T> for $ty<T>`, the law over duals `$ty<D5<T>>` built by `$body` from the
/// receiver (bound to `$s`).
macro_rules! lifted {
    ($($(#[$attr:meta])* $tr:ident for $ty:ident, |$s:ident| $body:expr;)*) => {$(
        $(#[$attr])*
        impl<T: Real> $tr<T> for $ty<T> {
            type Dual = $ty<D5<T>>;
            #[inline(always)]
            fn lift(&self) -> Self::Dual {
                let $s = self;
                $body
            }
        }
    )*};
}

lifted! {
    LinearNormal for Hertz, |s| s.map(lift);
    LinearNormal for Volumetric, |s| Volumetric(s.0.map(lift));
    LinearNormal for Fitted, |s| Fitted(s.0.map(lift));
    /// The derivative is that of the exact √h (a dual number takes libm's square root; the
    /// value part is then exact Hertz, not micromath's, within the law's stated 6.1e-2).
    #[cfg(feature = "micromath")]
    LinearNormal for HertzMicromath, |s| HertzMicromath(s.0.map(lift));
    LinearDamping for HuntCrossley, |s| s.map(lift);
    LinearDamping for CompressionDamping, |s| s.map(lift);
}

impl<T: Real> LinearDamping<T> for Undamped {
    type Dual = Undamped;
    #[inline(always)]
    fn lift(&self) -> Undamped {
        Undamped
    }
}

impl LinearLaw for Best {
    const RAMP: bool = true;
    /// [`crate::friction::BestContact`]'s core with only the piece in use lifted.
    #[inline(always)]
    fn traction_dual<T: Real>(
        p: &Self::Prepared<T>,
        s: &SlipState<D5<T>>,
    ) -> (Traction<D5<T>>, Self::Branch) {
        p.traction_dual(s)
    }
}

/// The laws whose per-contact form is the [`Constants`]: the core on the lifted constants.
macro_rules! by_constants {
    ($($law:ty: $ramp:expr),* $(,)?) => {
        $(
            impl LinearLaw for $law {
                const RAMP: bool = $ramp;
                #[inline(always)]
                fn traction_dual<T: Real>(
                    p: &Constants<T>,
                    s: &SlipState<D5<T>>,
                ) -> (Traction<D5<T>>, Self::Branch) {
                    <$law as FrictionLaw>::traction(&p.map(lift), s)
                }
            }
        )*
    };
}
by_constants!(Simplified: true, Pade: false, Ellipsoid: false, Coulomb: true, BestSeries: true);
#[cfg(feature = "micromath")]
by_constants!(
    crate::friction::SimplifiedMicromath: true,
    crate::friction::CoulombMicromath: true,
    crate::friction::EllipsoidMicromath: false,
    crate::friction::BestMicromath: true,
);

/// The per-contact core on dual numbers (for [`crate::friction::Friction`]'s wrapper).
pub(crate) struct DualCore<'a, T: Real, L: FrictionLaw>(pub(crate) &'a L::Prepared<T>);

impl<T: Real, L: LinearLaw> Core<D5<T>, L> for DualCore<'_, T, L> {
    #[inline(always)]
    fn eval(self, s: &SlipState<D5<T>>) -> (Traction<D5<T>>, L::Branch) {
        L::traction_dual(self.0, s)
    }
}
