//! The friction-law interface: a dimensionless core chosen by generics, and the dimensional
//! wrapper that scales it by fN and fNa.

use core::fmt::Debug;
use core::marker::PhantomData;

use super::{Constants, Slip, SlipState, Traction};
use crate::error::finite;
use crate::{Error, Real};

/// A friction law over the Hertz ellipse: a zero-sized type, chosen by generics so that only the
/// laws a program uses are linked.
///
/// Every law here is passive by construction (F·v_P + T_z·ω ≤ 0), bounded (|F| ≤ fN) and
/// continuous across its own branch switches; the only jump left is dry friction's own, at
/// v_P = 0 with ω = 0 and δ = 0 (F = 0 there, −fN·v_P/|v_P| beside it). See each law's docs
/// for its formula, error and cost.
pub trait FrictionLaw: Copy + Debug + PartialEq {
    /// Short name used by the evaluator CLI and the benchmark labels (`"simplified"`, …).
    const NAME: &'static str;
    /// Which formula piece produced a traction (for diagnostics, tests and plots).
    type Branch: Copy + Debug + PartialEq;

    /// Whether the dimensional wrapper regularizes the law near rest: for δ > 0 it scales the
    /// traction by min(1, S/δ), S = |v_Px| + |v_Py| + a|ω| (S/δ = 1/d of the normalised
    /// [`SlipState`]). A non-negative factor keeps passivity, |F| ≤ fN, continuity and every
    /// symmetry; δ = 0 (or S ≥ δ) changes nothing. It replaces dry friction's jump at rest by
    /// a ramp of width δ, for laws whose core ignores δ (`best`); laws with their own g_δ
    /// switch (`simplified`, `coulomb`) leave it `false`.
    const RAMP_BELOW_DELTA: bool = false;

    /// What the law precomputes once per contact shape (e² fixed). For most laws it is the
    /// [`Constants`] themselves (then `traction_prepared` is `traction`);
    /// [`crate::friction::Best`] builds its tables into [`crate::friction::BestContact`].
    type Prepared<T: Real>: Copy + Debug + PartialEq;

    /// The dimensionless core: the slip state (homogeneous form, see [`SlipState`]) →
    /// F/(fN), T_z/(fNa) on body B from body A, and the branch. Total: finite output for every
    /// state. This is the form for a shape that changes every call (nothing precomputed).
    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Self::Branch);

    /// Precompute the per-contact form from the shape constants (once per contact). Total.
    fn prepare<T: Real>(k: &Constants<T>) -> Self::Prepared<T>;

    /// The dimensionless core with the per-contact form: same result as
    /// [`FrictionLaw::traction`] up to the law's stated error, usually cheaper. Total.
    fn traction_prepared<T: Real>(
        p: &Self::Prepared<T>,
        s: &SlipState<T>,
    ) -> (Traction<T>, Self::Branch);
}

/// Implements the per-contact items of [`FrictionLaw`] for a law that precomputes nothing
/// beyond the [`Constants`]: `Prepared = Constants`, `traction_prepared = traction`.
macro_rules! constants_are_prepared {
    () => {
        type Prepared<T: $crate::Real> = $crate::friction::Constants<T>;

        #[inline(always)]
        fn prepare<T: $crate::Real>(k: &$crate::friction::Constants<T>) -> Self::Prepared<T> {
            *k
        }

        #[inline(always)]
        fn traction_prepared<T: $crate::Real>(
            p: &Self::Prepared<T>,
            s: &$crate::friction::SlipState<T>,
        ) -> ($crate::friction::Traction<T>, Self::Branch) {
            Self::traction(p, s)
        }
    };
}
pub(crate) use constants_are_prepared;

/// Friction force and drilling torque on body B from body A, in the contact frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tangential<T, B> {
    /// F_x (N), along the major axis.
    pub fx: T,
    /// F_y (N), along the minor axis.
    pub fy: T,
    /// T_z (N·m), about the common normal.
    pub tz: T,
    /// The law's branch that produced it.
    pub branch: B,
}

/// A friction law with its dimensional parameters: the friction coefficient f and the
/// regularization speed δ (m/s; 0 disables regularization). Validated at construction; the
/// per-step [`Friction::tangential`] is total.
///
/// The law defaults to [`crate::friction::Best`], the exact-grade fast law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Friction<T, L = super::Best> {
    f: T,
    delta: T,
    law: PhantomData<L>,
}

impl<T: Real, L: FrictionLaw> Friction<T, L> {
    /// From the friction coefficient `f` ≥ 0 and the regularization speed `delta` ≥ 0 (m/s).
    /// Errors: [`Error::NonFinite`] (`"f"`, `"delta"`) for NaN or ±∞,
    /// [`Error::FrictionCoefficientNegative`] for f < 0, [`Error::LengthNotPositive`] for
    /// δ < 0 (δ = 0 is allowed and means no regularization).
    pub fn new(f: T, delta: T) -> Result<Self, Error> {
        let f = finite(f, "f")?;
        let delta = finite(delta, "delta")?;
        if f < T::ZERO {
            return Err(Error::FrictionCoefficientNegative);
        }
        if delta < T::ZERO {
            return Err(Error::LengthNotPositive);
        }
        Ok(Friction {
            f,
            delta,
            law: PhantomData,
        })
    }

    /// The friction coefficient f.
    #[inline(always)]
    pub fn coefficient(&self) -> T {
        self.f
    }

    /// The regularization speed δ (m/s).
    #[inline(always)]
    pub fn delta(&self) -> T {
        self.delta
    }

    /// One per-step call: patch constants `k`, major semi-axis `a` (m), normal force `n` (N) and
    /// the slip → force (N) and drilling torque (N·m) on body B from body A.
    ///
    /// N ≤ 0 (or NaN) gives the zero wrench (no contact, no adhesion); `a` ≤ 0 (or NaN) is a
    /// point contact (no spin effect, no torque). Total: finite output for finite `a` and `n`.
    /// Cost: the law's core plus a normalisation (two additions, one division, four
    /// multiplications) and five multiplications: 125 instructions for
    /// `Friction::<f32, Simplified>` on the Cortex-M4F (QEMU stage `friction`, method
    /// `simplified-dimensional`, with the branch; the core alone is 66).
    #[inline(always)]
    pub fn tangential(
        &self,
        k: &Constants<T>,
        a: T,
        n: T,
        slip: Slip<T>,
    ) -> Tangential<T, L::Branch> {
        self.scaled(a, n, slip, |s| L::traction(k, s))
    }

    /// [`Friction::tangential`] with the law's per-contact form `p` (from
    /// [`FrictionLaw::prepare`]): the call a contact of fixed shape makes every step.
    #[inline(always)]
    pub fn tangential_prepared(
        &self,
        p: &L::Prepared<T>,
        a: T,
        n: T,
        slip: Slip<T>,
    ) -> Tangential<T, L::Branch> {
        self.scaled(a, n, slip, |s| L::traction_prepared(p, s))
    }

    /// Normalise the slip, evaluate the dimensionless `core`, scale by fN and fNa.
    #[inline(always)]
    fn scaled(
        &self,
        a: T,
        n: T,
        slip: Slip<T>,
        core: impl FnOnce(&SlipState<T>) -> (Traction<T>, L::Branch),
    ) -> Tangential<T, L::Branch> {
        // `x > 0` is false for NaN: both clamps map NaN to 0.
        let a = if a > T::ZERO { a } else { T::ZERO };
        let mut fn_ = if n > T::ZERO { self.f * n } else { T::ZERO };
        let state = SlipState::from_clamped(slip, a, self.delta);
        if L::RAMP_BELOW_DELTA && state.d() > T::ONE {
            fn_ /= state.d();
        }
        let (t, branch) = core(&state);
        Tangential {
            fx: fn_ * t.fx,
            fy: fn_ * t.fy,
            tz: fn_ * a * t.tz,
            branch,
        }
    }
}

/// The branch of the laws with one smooth formula ([`crate::friction::Pade`],
/// [`crate::friction::Ellipsoid`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Smooth {
    /// No slip: zero traction.
    Rest,
    /// Slipping: the law's single formula.
    Slip,
}
