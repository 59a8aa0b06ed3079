//! Compile-time model selection: declare what a scene has, get the cheapest adequate contact
//! type — and link nothing else.
//!
//! A scene is described by five types in [`Scene`]`<P, G, S, B, T>`:
//!
//! | parameter | choices | meaning |
//! |---|---|---|
//! | `P` patch | [`Circular`], [`Elliptic`] | P = Q (sphere on plane or sphere) or P < Q |
//! | `G` geometry | [`Fixed`], [`Varying`] | curvatures fixed for the contact's life, or new every step |
//! | `S` motion | [`Spin`], [`NoSpin`] | relative spin ω about the normal present, or always 0 |
//! | `B` budget | [`Coarse`], [`ExactGrade`] | friction error bound (below) |
//! | `T` precision | `f32`, `f64` | [`Real`] |
//!
//! [`Select`] resolves it to a law ([`LawOf`]) and a contact type ([`ContactOf`]), and
//! [`Select::build`] constructs it from the geometry kind's input. Everything is decided by
//! types: a firmware that uses one configuration links only that configuration's code.
//!
//! ```
//! use contensou::friction::Friction;
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::select::{Circular, Coarse, Fixed, Scene, Select, Spin};
//!
//! // A 6.35 mm steel ball spinning on a steel plane, friction within 0.25 fN / 0.15 fNa.
//! type Ball = Scene<Circular, Fixed, Spin, Coarse, f32>;
//! let contact = Ball::build(
//!     &Curvatures::sphere_plane(6.35e-3)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::new(0.1, 0.0)?,
//! )?;
//! let w = contact.wrench(1e-6, 0.0, contensou::friction::Slip::new(0.01, 0.0, 50.0)?);
//! assert!(w.n > 0.0 && w.fx < 0.0 && w.tz < 0.0);
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # What is chosen
//!
//! - **Normal law.** [`Circular`] + [`Fixed`]: [`Hertz::circular`] +
//!   [`crate::friction::Constants::circle`] through [`Contact::circular`] — closed forms: **no
//!   elliptic integral, no eccentricity solver and no shape table is linked** (checked by
//!   `tools/flash-bench.sh` on the size probe's line table, inlined code included:
//!   `bench-results/scene-no-elliptic.txt`). [`Elliptic`] + [`Fixed`]: exact-grade Hertz with
//!   the shape from [`Table`] once at construction ([`Contact::hertz`]; constants
//!   precomputed, per step a square root and the friction law). [`crate::shape::Newton`] would
//!   be exact to 1.5e-15 instead of 3.6e-12 (f64), but in `f32` the table is the more accurate
//!   (3.0e-7 against 7.6e-7) and it is 5 KB smaller and 13× cheaper to build, so the table is
//!   the cheapest adequate choice. [`Elliptic`] + [`Varying`]: [`VaryingContact`], the shape
//!   from [`Table`] every step (fixed cost, no elliptic integral). N, a and b are exact-grade in
//!   every configuration (relative error ≤ [`NORMAL_BOUND`]); `Circular` + `Varying` is not
//!   offered (a circle's shape cannot vary; a changing radius is `Elliptic` + `Varying` at
//!   P = Q).
//! - **Friction law.** [`NoSpin`]: [`Coulomb`] at every budget — with ω = 0 the
//!   Contensou–Erismann integrals reduce exactly to F = −fN·v_P/|v_P|, T_z = 0 (the exact
//!   law's pure-translation limit), which is Coulomb's law for δ = 0 (its g_δ ramp below δ is
//!   the regularization, a modelling choice, not an error). (At ω = 0 [`Ellipsoid`] is also
//!   exact and 18 instructions cheaper per `f32` step, but ignores δ; in `f64` Coulomb is the
//!   cheaper.) [`Spin`]: the budget's law,
//!   [`Budget::SpinLaw`]:
//!   - [`Coarse`] (≤ 0.25 fN, ≤ 0.15 fNa) → [`Ellipsoid`] (measured 0.227 fN, 0.134 fNa
//!     over e² ∈ [0, 0.99]; 34 M4F instructions). The paper's [`crate::friction::Simplified`]
//!     (0.393 fN / 0.354 fNa, 66 instructions) is dominated by it in error *and* cost, so no
//!     budget selects it; build `Contact<_, _, _, Simplified>` directly to reproduce the paper.
//!     The ellipsoidal law ignores δ (Coulomb's sign law at ω = 0).
//!   - [`ExactGrade`] (≤ 5e-4 fN, ≤ 5e-4 fNa) → [`Best`] (measured 5.2e-5 fN / 4.1e-6 fNa in
//!     the per-contact form a [`Fixed`] contact precomputes, 2.0e-6 / 8.7e-7 per call for
//!     [`Varying`]).
//!
//! The friction bounds hold for patches with e² ≤ 0.99 (g = P/Q ≥ 0.0274); beyond that both
//! laws degrade (see [`Best`]'s and [`Ellipsoid`]'s docs).
//!
//! # The table
//!
//! Per step (h, ḣ, v_P, ω → N, F, T_z), measured by `tools/scene-bench.sh` into
//! `bench-results/scenes.csv`: M4F instructions per step (QEMU, stage `scene`, the 64-state
//! mixed set of the `wrench` stage), flash bytes the configuration adds to an empty firmware
//! (construction from curvatures + one step, size probe `firmware/src/bin/probe.rs`; an
//! `f64` row includes the soft-float routines), and the max error on the host against exact
//! Hertz (f64 [`crate::shape::Newton`]) + [`crate::friction::exact`] (N relative; F in fN;
//! T_z in fNa; `examples/scene_error.rs`: 3–11 geometries per kind, 19 slip directions, 40
//! ratios u per decade in [1e-2, 1e2] plus 0 and ∞). Asserted against the bounds by
//! `host-tests/select.rs`.
//!
//! | scene | declaration | contact, normal law, friction law | f32: insns / flash B | f64: insns / flash B | max error N (f32) / F fN / T_z fNa |
//! |---|---|---|---|---|---|
//! | sphere-plane-spin-coarse | `Circular, Fixed, Spin, Coarse` | [`Contact`], `Hertz::circular`, [`Ellipsoid`] | 109 / 1204 | 3518 / 6000 | 1.0e-07 / 1.1e-01 / 8.3e-02 |
//! | sphere-plane-spin-exact | `Circular, Fixed, Spin, ExactGrade` | [`Contact`], `Hertz::circular`, [`Best`] | 209 / 11032 | 7880 / 19920 | 1.0e-07 / 9.3e-07 / 2.5e-07 |
//! | sphere-plane-nospin | `Circular, Fixed, NoSpin, _` | [`Contact`], `Hertz::circular`, [`Coulomb`] | 127 / 1244 | 3348 / 6072 | 1.0e-07 / 2.0e-07 / 0 |
//! | ball-race-spin-coarse | `Elliptic, Fixed, Spin, Coarse` | [`Contact`], Hertz, `Table` once, [`Ellipsoid`] | 109 / 4000 | 3517 / 12064 | 1.7e-07 / 2.2e-01 / 1.3e-01 |
//! | ball-race-spin-exact | `Elliptic, Fixed, Spin, ExactGrade` | [`Contact`], Hertz, `Table` once, [`Best`] | 230 / 14796 | 9192 / 30012 | 1.7e-07 / 4.9e-05 / 3.5e-06 |
//! | ball-race-nospin | `Elliptic, Fixed, NoSpin, _` | [`Contact`], Hertz, `Table` once, [`Coulomb`] | 127 / 3992 | 3338 / 12056 | 1.7e-07 / 1.9e-07 / 0 |
//! | varying-spin-coarse | `Elliptic, Varying, Spin, Coarse` | [`VaryingContact`], Hertz, `Table` per step, [`Ellipsoid`] | 258 / 4136 | 9779 / 11928 | 2.6e-07 / 2.2e-01 / 1.3e-01 |
//! | varying-spin-exact | `Elliptic, Varying, Spin, ExactGrade` | [`VaryingContact`], Hertz, `Table` per step, [`Best`] | 1574 / 12328 | 99308 / 25612 | 2.6e-07 / 2.1e-06 / 7.2e-07 |
//! | varying-nospin | `Elliptic, Varying, NoSpin, _` | [`VaryingContact`], Hertz, `Table` per step, [`Coulomb`] | 265 / 4168 | 9516 / 11896 | 2.6e-07 / 2.9e-07 / 0 |
//!
//! Instructions include the rig's 8-instruction call floor; `f64` is soft float on the M4F.
//! The [`Best`] rows' flash includes its 2.8 KB (`f32`) coefficient table and, for a fixed
//! contact, [`crate::friction::BestContact::new`]. N is exact in closed form for the circle
//! (the `f32` figure is rounding); F and T_z of the `Coarse` rows are the ellipsoidal law's
//! own error, worst at the thinnest patch (e² = 0.989–0.99).
//!
//! # Extending
//!
//! A budget is a type implementing [`Budget`]: its bounds and the cheapest law measured to
//! meet them. MICROMATH: the `micromath` backend (feature `micromath`, `f32` only) will plug
//! in here as a further budget (or as `Coarse`'s law when its measured error fits 0.25 fN /
//! 0.15 fNa) once its laws are measured; nothing here depends on it yet.

use core::marker::PhantomData;

use crate::contact::{Contact, VaryingContact, Wrench};
use crate::friction::{Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Slip};
use crate::geometry::Curvatures;
use crate::normal::{Damping, Hertz, Modulus, NormalLaw};
use crate::shape::Table;
use crate::{Error, Real};

/// Relative error bound on N, a and b in every configuration (measured ≤ 2.6e-7 in `f32`,
/// ≤ 6.1e-13 in `f64`; `bench-results/scenes.csv`).
pub const NORMAL_BOUND: f64 = 2e-6;

/// Friction error bound (fN and fNa) without spin: [`Coulomb`] is the exact law there, so
/// only rounding remains (measured ≤ 3.0e-7 in `f32`, the normal force's rounding included).
pub const NOSPIN_BOUND: f64 = 1e-6;

mod sealed {
    pub trait Sealed {}
}

/// Patch kind: P = Q (sphere on plane, sphere on sphere). No elliptic code is linked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Circular;
/// Patch kind: P < Q, an elliptic patch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Elliptic;
/// Geometry: the curvatures are fixed (constants precomputed at construction).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Fixed;
/// Geometry: the curvatures change every step (shape from a table per step).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Varying;
/// Motion: the bodies spin relative to each other about the normal (ω ≠ 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Spin;
/// Motion: ω = 0 always (pure sliding or rolling without spin): the plain Coulomb law is exact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoSpin;
/// Budget: friction within 0.25 fN in force and 0.15 fNa in torque → [`Ellipsoid`] (measured
/// 0.227 fN / 0.134 fNa; 109 M4F instructions per `f32` step of a fixed contact).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Coarse;
/// Budget: friction within 5e-4 fN in force and 5e-4 fNa in torque ("exact-grade") → [`Best`]
/// (measured 4.9e-5 fN / 3.5e-6 fNa; 209–230 M4F instructions per `f32` step of a fixed
/// contact, 1,574 of a varying one).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExactGrade;

impl sealed::Sealed for Spin {}
impl sealed::Sealed for NoSpin {}

/// An error budget for the friction of a spinning contact: its bounds (max over e² ≤ 0.99,
/// all slip directions and ratios, δ = 0, against the exact integrals) and the cheapest law
/// measured to meet them.
pub trait Budget {
    /// Short name used in benchmark keys.
    const NAME: &'static str;
    /// Bound on |F − F_exact| in units of fN.
    const FORCE: f64;
    /// Bound on |T_z − T_exact| in units of fNa.
    const TORQUE: f64;
    /// The cheapest law (in measured instructions per call) within the bounds.
    type SpinLaw: FrictionLaw;
}

impl Budget for Coarse {
    const NAME: &'static str = "coarse";
    const FORCE: f64 = 0.25;
    const TORQUE: f64 = 0.15;
    type SpinLaw = Ellipsoid;
}

impl Budget for ExactGrade {
    const NAME: &'static str = "exact";
    const FORCE: f64 = 5e-4;
    const TORQUE: f64 = 5e-4;
    type SpinLaw = Best;
}

// MICROMATH: a micromath-backed budget goes here (feature `micromath`, f32 only), e.g.
// `#[cfg(feature = "micromath")] impl Budget for Micro { … type SpinLaw = <its law>; }`,
// with bounds from its measured error — not assumed.

/// Whether the contact spins: [`Spin`] takes the budget's law, [`NoSpin`] plain Coulomb.
pub trait Motion: sealed::Sealed {
    /// Short name used in benchmark keys.
    const NAME: &'static str;
    /// Whether ω ≠ 0 occurs.
    const SPINS: bool;
    /// The friction law for budget `B`.
    type Law<B: Budget>: FrictionLaw;
}

impl Motion for Spin {
    const NAME: &'static str = "spin";
    const SPINS: bool = true;
    type Law<B: Budget> = B::SpinLaw;
}

impl Motion for NoSpin {
    const NAME: &'static str = "nospin";
    const SPINS: bool = false;
    type Law<B: Budget> = Coulomb;
}

/// A scene declaration: patch `P`, geometry `G`, motion `S`, budget `B`, precision `T`. A
/// zero-sized marker; see [`Select`] and the [module docs](self).
#[derive(Debug)]
pub struct Scene<P, G, S, B, T>(PhantomData<Markers<P, G, S, B, T>>);

/// The marker parameters, held by function pointer so that `Scene` is `Send + Sync + Copy`
/// whatever they are.
type Markers<P, G, S, B, T> = fn() -> (P, G, S, B, T);

/// What a [`Scene`] resolves to.
pub trait Select {
    /// The precision.
    type Real: Real;
    /// The friction law chosen.
    type Law: FrictionLaw;
    /// What the constructor needs of the geometry: [`Curvatures`] for a fixed contact,
    /// `()` for a varying one (its curvatures come with every step).
    type Geometry;
    /// The contact type chosen, for damping law `D`; every one steps through [`Step`].
    type Contact<D: Damping<Self::Real>>: Step<Self::Real>;
    /// Short name of the geometry kind (benchmark keys): `sphere-plane`, `ball-race` or
    /// `varying`; the key is `<GEOMETRY>-<Motion::NAME>[-<Budget::NAME>]`.
    const GEOMETRY: &'static str;
    /// Whether the scene spins ([`Motion::SPINS`]).
    const SPINS: bool;
    /// Bound on the friction force error (fN).
    const FORCE: f64;
    /// Bound on the drilling torque error (fNa).
    const TORQUE: f64;

    /// Build the contact. Errors: those of the geometry kind's constructor
    /// ([`Contact::circular`], [`Contact::hertz`]; a varying contact cannot fail).
    fn build<D: Damping<Self::Real>>(
        geometry: &Self::Geometry,
        estar: Modulus<Self::Real>,
        damping: D,
        friction: Friction<Self::Real, Self::Law>,
    ) -> Result<Self::Contact<D>, Error>;

    /// The constructor input of this geometry kind from curvatures: the curvatures themselves
    /// for a fixed contact, `()` for a varying one (for code generic over scenes).
    fn geometry(curvatures: &Curvatures<Self::Real>) -> Self::Geometry;
}

/// One per-step call of any scene's contact: this step's curvatures (read by a varying
/// contact, ignored by a fixed one), approach h (m), its rate ḣ (m/s) and the slip → the
/// wrench on B from A. Total; the contact's own `wrench` under one signature.
pub trait Step<T: Real> {
    /// The friction law's branch.
    type Branch: Copy + core::fmt::Debug + PartialEq;
    /// One step (see the [trait docs](Step)).
    fn step(&self, curv: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, Self::Branch>;
}

impl<T: Real, N: NormalLaw<T>, D: Damping<T>, L: FrictionLaw> Step<T> for Contact<T, N, D, L> {
    type Branch = L::Branch;
    #[inline(always)]
    fn step(&self, _: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, L::Branch> {
        self.wrench(h, hdot, slip)
    }
}

impl<T: Real, D: Damping<T>, L: FrictionLaw> Step<T> for VaryingContact<T, D, L> {
    type Branch = L::Branch;
    #[inline(always)]
    fn step(&self, curv: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, L::Branch> {
        self.wrench(curv, h, hdot, slip)
    }
}

/// The friction law a scene resolves to.
pub type LawOf<S> = <S as Select>::Law;
/// The contact type a scene resolves to, with damping law `D` (default [`Undamped`](crate::normal::Undamped)).
pub type ContactOf<S, D = crate::normal::Undamped> = <S as Select>::Contact<D>;

/// One [`Select`] impl per geometry kind: patch, geometry, key name, constructor input, contact
/// type (for damping law `$d`), the constructor body and the geometry input from curvatures.
macro_rules! select {
    ($p:ty, $g:ty, $name:literal, $geometry:ty,
     |$d:ident| $contact:ty,
     |$geo:pat_param, $estar:ident, $damping:ident, $friction:ident| $build:expr,
     |$c:pat_param| $of:expr) => {
        impl<S: Motion, B: Budget, T: Real> Select for Scene<$p, $g, S, B, T> {
            type Real = T;
            type Law = S::Law<B>;
            type Geometry = $geometry;
            type Contact<$d: Damping<T>> = $contact;
            const GEOMETRY: &'static str = $name;
            const SPINS: bool = S::SPINS;
            const FORCE: f64 = if S::SPINS { B::FORCE } else { NOSPIN_BOUND };
            const TORQUE: f64 = if S::SPINS { B::TORQUE } else { NOSPIN_BOUND };

            fn build<$d: Damping<T>>(
                $geo: &$geometry,
                $estar: Modulus<T>,
                $damping: $d,
                $friction: Friction<T, Self::Law>,
            ) -> Result<Self::Contact<$d>, Error> {
                $build
            }

            #[inline(always)]
            fn geometry($c: &Curvatures<T>) -> $geometry {
                $of
            }
        }
    };
}

select!(Circular, Fixed, "sphere-plane", Curvatures<T>,
    |D| Contact<T, Hertz<T>, D, S::Law<B>>,
    |curvatures, estar, damping, friction| Contact::circular(curvatures, estar, damping, friction),
    |c| *c);

select!(Elliptic, Fixed, "ball-race", Curvatures<T>,
    |D| Contact<T, Hertz<T>, D, S::Law<B>>,
    |curvatures, estar, damping, friction| Contact::hertz::<Table>(curvatures, estar, damping, friction),
    |c| *c);

select!(Elliptic, Varying, "varying", (),
    |D| VaryingContact<T, D, S::Law<B>>,
    |_, estar, damping, friction| Ok(VaryingContact::new(estar, damping, friction)),
    |_| ());
