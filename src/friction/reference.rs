//! The exact integrals ([`super::exact::traction`]) as a [`FrictionLaw`], so that the
//! evaluator, the tests and the benches can put them beside the approximate laws.
//!
//! Reference path: µs per call (see [`super::exact`]), computed in `f64` for both precisions.
//! Ignores δ (no regularization): at ω = 0 it is Coulomb's sign law, 0 at rest.

use super::{Constants, FrictionLaw, SlipState, Traction};
use crate::Real;
use crate::elliptic::Parameter;

/// The exact Contensou–Erismann integrals (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Exact;

/// The branch of [`Exact`]: where the instantaneous centre of rotation (IC) lies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// No slip: zero traction.
    Rest,
    /// IC inside or on the ellipse (u ≤ u_b(ψ)): the quartic polynomial.
    Inside,
    /// IC outside (including pure translation, IC at infinity).
    Outside,
}

impl FrictionLaw for Exact {
    const NAME: &'static str = "exact";
    type Branch = Branch;
    super::law::constants_are_prepared!();

    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Branch) {
        let (x, y, w) = (s.x(), s.y(), s.w());
        if s.is_rest() {
            return (Traction::default(), Branch::Rest);
        }
        // Keep whichever of m, m₁ is small exactly (m₁ carries the log-singular part near 1).
        let p = if k.m() <= T::HALF {
            Parameter::new(k.m())
        } else {
            Parameter::from_complement(k.m1())
        };
        let Ok(p) = p else {
            // Unreachable: `Constants` only holds valid parameters.
            return (Traction::default(), Branch::Rest);
        };
        // IC (X₀, Y₀) = (−y, x)/w inside the ellipse X₀² + Y₀²/m₁ ≤ 1.
        let branch = if x * x + k.m1() * y * y <= k.m1() * w * w {
            Branch::Inside
        } else {
            Branch::Outside
        };
        (super::exact::traction(p, x, y, w), branch)
    }
}
