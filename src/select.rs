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
//! | `B` budget | [`Rough`], [`Coarse`], [`ExactGrade`] | error bounds on N, a, b and friction (below) |
//! | `T` precision | `f32`, `f64` | [`Precision`] (a [`Real`]) |
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
//!     Friction::with_law(0.1, 0.0)?, // the law is the scene's (here Simplified)
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
//!   (3.7e-7 against 7.6e-7) and it is 5 KB smaller and 13× cheaper to build, so the table is
//!   the cheapest adequate choice. [`Elliptic`] + [`Varying`]: [`VaryingContact`], the shape
//!   from [`Table`] every step (fixed cost, no elliptic integral). N, a and b are exact-grade
//!   (relative error ≤ [`NORMAL_BOUND`]) in every configuration but one: a [`Fixed`] contact
//!   with budget [`Rough`] in `f32` with the feature `micromath` takes the per-step √h from
//!   micromath (`HertzMicromath`, built from the same exact Hertz law through
//!   [`Contact::circular_with`] / [`Contact::hertz_with`], so a sphere on a plane still links
//!   no elliptic code): N, a, b up to 6.07 % high ([`ROUGH_NORMAL_BOUND`] = 6.5 %) for one M4F
//!   instruction less per step (86 against 87; isolated, the twin's patch is 32 against
//!   36). `Circular` + `Varying` is not offered (a circle's shape cannot vary; a changing
//!   radius is `Elliptic` + `Varying` at P = Q).
//! - **Friction law.** [`NoSpin`]: [`Coulomb`] at every budget — with ω = 0 the
//!   Contensou–Erismann integrals reduce exactly to F = −fN·v_P/|v_P|, T_z = 0 (the exact
//!   law's pure-translation limit), which is Coulomb's law for δ = 0 (its g_δ ramp below δ is
//!   the regularization, a modelling choice, not an error). (At ω = 0 [`Ellipsoid`] is also
//!   exact and 18 instructions cheaper per `f32` step, but ignores δ; in `f64` Coulomb is the
//!   cheaper; `CoulombMicromath` is 3 dearer.) [`Spin`]: the budget's law,
//!   [`Budget::SpinLaw`] for a fixed contact (its per-contact form), [`Budget::VaryingSpinLaw`]
//!   for a varying one (per-call form):
//!   - [`Rough`] (≤ 0.25 fN, ≤ 0.17 fNa, N, a, b ≤ 6.5 %) → [`Ellipsoid`], as `Coarse`:
//!     `EllipsoidMicromath` costs 3 instructions more. Its torque bound exceeds `Coarse`'s
//!     because micromath's √h inflates N·a by up to 12.5 % (measured 0.159 fNa at the 209
//!     inner race).
//!   - [`Coarse`] (≤ 0.25 fN, ≤ 0.15 fNa) → [`Ellipsoid`] (measured 0.227 fN, 0.134 fNa
//!     over e² ∈ [0, 0.99]; 34 M4F instructions). The paper's [`crate::friction::Simplified`]
//!     (0.393 fN / 0.354 fNa, 66 instructions) is dominated by it in error *and* cost, so no
//!     budget selects it; build `Contact<_, _, _, Simplified>` directly to reproduce the paper.
//!     The ellipsoidal law ignores δ (Coulomb's sign law at ω = 0).
//!   - [`ExactGrade`] (≤ 5e-4 fN, ≤ 5e-4 fNa) → [`Best`] (measured 5.2e-5 fN / 4.0e-6 fNa in
//!     the per-contact form a [`Fixed`] contact precomputes, 4.7e-5 fN / 3.3e-6 fNa in the
//!     per-step flash-table form a [`Varying`] contact calls, both over every shape the contract
//!     accepts, e² up to 0.99998 at P/Q = 1e-4; 521 M4F instructions per `f32`
//!     wrench on average, 750 on the worst input an input search found, against 1,950 / 3,310
//!     for the per-call series it replaced). The per-step form calls no `ln`, so no micromath
//!     twin pays there any more: with the feature `micromath` a [`Varying`] `f32` contact keeps
//!     [`Best`] too (`BestMicromath`, the series with micromath's `ln`, measured 1,539 per step).
//!
//! The micromath twins are used exactly where the budget admits their measured error *and*
//! they were measured cheaper in the scene (`bench-results/micromath.md` has each twin's
//! figures); the others (its `sqrt` in the friction laws, `HamrockDowsonMicromath`) cost more
//! on the M4F and are never chosen. The choice goes through [`Precision`]: for `f64` (where the
//! twins are libm code) and without the feature every declaration resolves to libm types.
//!
//! [`Best`]'s bounds hold for every accepted patch (g = P/Q ≥ 1e-4, e² ≤ 0.99998);
//! [`Ellipsoid`]'s are measured for e² ≤ 0.99 (g = P/Q ≥ 0.0274) and it degrades beyond (see its
//! docs).
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
//! ratios u per decade in [1e-2, 1e2] plus 0 and ∞, h ∈ {0.1, 1, 2⁻¹⁹ ≈ 1.9, 5} µm).
//! Asserted against the bounds by `host-tests/select.rs`.
//!
//! | scene | declaration | contact, normal law, friction law | f32: insns / flash B | f64: insns / flash B | max error N (f32) / F fN / T_z fNa |
//! |---|---|---|---|---|---|
//! | sphere-plane-spin-coarse | `Circular, Fixed, Spin, Coarse` | [`Contact`], `Hertz::circular`, [`Ellipsoid`] | 87 / 1104 | 3147 / 5728 | 1.0e-07 / 1.1e-01 / 8.3e-02 |
//! | sphere-plane-spin-exact | `Circular, Fixed, Spin, ExactGrade` | [`Contact`], `Hertz::circular`, [`Best`] | 161 / 10984 | 7423 / 19800 | 1.0e-07 / 9.3e-07 / 2.4e-07 |
//! | sphere-plane-nospin | `Circular, Fixed, NoSpin, _` | [`Contact`], `Hertz::circular`, [`Coulomb`] | 107 / 1152 | 3073 / 5920 | 1.0e-07 / 2.0e-07 / 0 |
//! | ball-race-spin-coarse | `Elliptic, Fixed, Spin, Coarse` | [`Contact`], Hertz, `Table` once, [`Ellipsoid`] | 87 / 3828 | 3146 / 11928 | 1.7e-07 / 2.2e-01 / 1.3e-01 |
//! | ball-race-spin-exact | `Elliptic, Fixed, Spin, ExactGrade` | [`Contact`], Hertz, `Table` once, [`Best`] | 182 / 14700 | 8757 / 29908 | 1.7e-07 / 4.9e-05 / 3.4e-06 |
//! | ball-race-nospin | `Elliptic, Fixed, NoSpin, _` | [`Contact`], Hertz, `Table` once, [`Coulomb`] | 107 / 3868 | 3063 / 11904 | 1.7e-07 / 1.9e-07 / 0 |
//! | varying-spin-coarse | `Elliptic, Varying, Spin, Coarse` | [`VaryingContact`], Hertz, `Table` per step, [`Ellipsoid`] | 232 / 3964 | 9422 / 11688 | 2.6e-07 / 2.2e-01 / 1.3e-01 |
//! | varying-spin-exact | `Elliptic, Varying, Spin, ExactGrade` | [`VaryingContact`], Hertz, `Table` per step, [`Best`] (per-step flash table) | 440 / 34248 | 25156 / 44944 | 2.6e-07 / 1.4e-05 / 1.5e-06 |
//! | varying-nospin | `Elliptic, Varying, NoSpin, _` | [`VaryingContact`], Hertz, `Table` per step, [`Coulomb`] | 242 / 4016 | 9268 / 11696 | 2.6e-07 / 2.9e-07 / 0 |
//! | sphere-plane-spin-rough-micromath | `Circular, Fixed, Spin, Rough` | [`Contact`], `HertzMicromath` from `Hertz::circular`, [`Ellipsoid`] | 86 / 1104 | — | 6.1e-02 / 1.2e-01 / 1.3e-01 |
//! | sphere-plane-nospin-rough-micromath | `Circular, Fixed, NoSpin, Rough` | [`Contact`], `HertzMicromath` from `Hertz::circular`, [`Coulomb`] | 106 / 1152 | — | 6.1e-02 / 6.1e-02 / 0 |
//! | ball-race-spin-rough-micromath | `Elliptic, Fixed, Spin, Rough` | [`Contact`], `HertzMicromath`, `Table` once, [`Ellipsoid`] | 86 / 3828 | — | 6.1e-02 / 2.3e-01 / 1.6e-01 |
//! | ball-race-nospin-rough-micromath | `Elliptic, Fixed, NoSpin, Rough` | [`Contact`], `HertzMicromath`, `Table` once, [`Coulomb`] | 106 / 3864 | — | 6.1e-02 / 6.1e-02 / 0 |
//! | varying-spin-exact-micromath | `Elliptic, Varying, Spin, ExactGrade` | [`VaryingContact`], Hertz, `Table` per step, [`Best`] (as without the feature) | 440 / 34248 | — | 2.6e-07 / 1.4e-05 / 1.5e-06 |
//!
//! Instructions include the rig's 8-instruction call floor; `f64` is soft float on the M4F.
//! The [`Best`] rows' flash includes, for a fixed contact, its 2.8 KB (`f32`) coefficient
//! table and [`crate::friction::BestContact::new`], for a varying one the 28.2 KB per-step
//! table (e² interpolated) instead. N is exact in closed form for the circle
//! (the `f32` figure is rounding); F and T_z of the `Coarse` rows are the ellipsoidal law's
//! own error, worst at the thinnest patch (e² = 0.989–0.99). The `-micromath` rows are what
//! an `f32` declaration resolves to with the feature `micromath`, where that differs (`f64`
//! rows are unchanged by it); without it the `Rough` rows are the `Coarse` ones and
//! `varying-spin-exact` is the libm row. The rough rows' N error is micromath's √h bias at
//! its worst (h = 2⁻¹⁹ m); it costs 1 instruction less per step than libm's `vsqrt.f32` —
//! measured, but the whole gain of a 6 % normal-force error (a toy, not a bearing).
//!
//! # Rolling contacts: [`Rolls`]
//!
//! A rolling patch is mostly stuck (Kalker): a full-slip law's force and drilling torque there
//! come from the regularisation speed δ, not from physics. Declaring the motion [`Rolls`] picks
//! the rolling law instead: [`Rolling`]`<T, C, `[`rolling::Table`]`>` over the geometry kind's
//! contact with friction [`Best`] — `Circular, Fixed`: `Rolling<T, Contact<T, Hertz<T>, D,
//! Best>, Table>` (circular Hertz, no elliptic code); `Elliptic, Fixed`: the same with the
//! shape from [`Table`] once; `Elliptic, Varying`: `Rolling<T, VaryingContact<T, D, Best>,
//! Table>`. Per step it takes the rolling velocity besides the slip: [`StepRolling`]
//! (implemented by every scene's contact; the sliding ones ignore V). [`Select::build`] takes
//! the elasticity of quasi-identical bodies of the contact's E*: ν = [`ROLLING_NU`] = 0.3 and
//! G = E*(1 − ν) (E* = E/(2(1 − ν²)), G = E/(2(1 + ν)); steel E* = 1.1429e11 Pa gives G =
//! 80 GPa); [`SelectRolling::build_rolling`] takes any [`Elasticity`] (e.g.
//! [`Elasticity::dissimilar`]).
//!
//! Error: the `table` law's against the exact steady-rolling theory (`tools/rolling_exact`)
//! over Kalker's creep curves, a/b ∈ [0.2, 5]: [`ROLLING_FORCE`] fN, [`ROLLING_TORQUE`] fNc
//! (c = √(ab)); exact `best` at full slip. N, a, b: exact Hertz ([`NORMAL_BOUND`]). Cost:
//! `table`'s (759 M4F f32 instructions per call, `bench-results/qemu.csv`, stage `rolling`)
//! plus the normal law and the frame rotation (`bench-results/qemu.csv`, rows `wrench-*`).
//!
//! ```
//! use contensou::friction::rolling::RollingVelocity;
//! use contensou::friction::{Friction, Slip};
//! use contensou::geometry::{Curvatures, Race};
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::select::{Elliptic, ExactGrade, Fixed, Rolls, StepRolling, Scene, Select};
//!
//! // A ball in the inner race of a 209 bearing, rolling along the groove at 3 m/s.
//! type Race209 = Scene<Elliptic, Fixed, Rolls, ExactGrade, f64>;
//! let curvatures = Curvatures::ball_race(12.7e-3, 6.6e-3, 65e-3, 0.0, Race::Inner)?;
//! let ball = Race209::build(&curvatures, Modulus::new(1.142857e11)?, Undamped, Friction::new(0.07, 0.0)?)?;
//! // the major axis is across the groove: rolling along y, creepage 1e-4 along it
//! let v = RollingVelocity::new(0.0, 3.0)?;
//! let w = ball.step_rolling(&curvatures, 5e-6, 0.0, Slip::new(0.0, 3e-4, 0.0)?, v);
//! assert!(w.fy < 0.0 && w.fy.abs() < 0.07 * w.n);
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Extending
//!
//! A budget is a type implementing [`Budget`]: its bounds (N, a, b; friction with and without
//! spin) and the cheapest laws measured to meet them — the fixed contact's normal law (any
//! [`NormalLaw`] built `From` exact [`Hertz`]), the spin law of a fixed and of a varying
//! contact. A law that depends on the precision (a micromath twin for `f32` only) goes
//! through an associated type of [`Precision`].

use core::marker::PhantomData;

use crate::contact::{Contact, Rolling, VaryingContact, Wrench};
use crate::friction::rolling::{self, Elasticity, RollingVelocity};
use crate::friction::{Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Slip};
use crate::geometry::Curvatures;
use crate::normal::{Damping, Hertz, Modulus, NormalLaw};
use crate::shape::Table;
use crate::{Error, Real};

/// Relative error bound on N, a and b of the [`Coarse`] and [`ExactGrade`] budgets, in every
/// configuration (measured ≤ 2.6e-7 in `f32`, ≤ 6.1e-13 in `f64`; `bench-results/scenes.csv`).
/// [`Rough`] has its own ([`ROUGH_NORMAL_BOUND`]); a scene's is [`Select::NORMAL`].
pub const NORMAL_BOUND: f64 = 2e-6;

/// Friction error bound (fN and fNa) without spin for the [`Coarse`] and [`ExactGrade`]
/// budgets: [`Coulomb`] is the exact law there, so only rounding remains (measured ≤ 3.0e-7
/// in `f32`, the normal force's rounding included). A scene's is [`Select::FORCE`].
pub const NOSPIN_BOUND: f64 = 1e-6;

/// [`Rough`]'s relative error bound on N, a and b: micromath's √h is never below the true
/// root and at most 6.07 % above it, so N, a, b (and p0) are biased high by up to that
/// factor (measured 6.07e-2 in every rough `f32` scene with the feature, at h = 2⁻¹⁹ m;
/// `bench-results/scenes.csv`). Without the feature, in `f64` and for varying geometry `Rough`
/// resolves to exact-grade Hertz and meets [`NORMAL_BOUND`].
pub const ROUGH_NORMAL_BOUND: f64 = 0.065;

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
    impl Sealed for super::Spin {}
    impl Sealed for super::NoSpin {}
    impl Sealed for super::Rolls {}
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
/// Motion: the patch rolls — the contact point travels over both surfaces (a ball in a race,
/// a wheel, a rocking body) with small creepage, and spin. Resolves to
/// [`Rolling`]`<T, C, `[`rolling::Table`]`>` (the default rolling law) over the geometry
/// kind's contact with [`Best`] (the full-slip part): the tangential wrench from Kalker's creep
/// theory and the bodies' elasticity, exact `best` at full slip or V → 0, δ not used (see
/// [`Rolls`'s section](self#rolling-contacts-rolls)). Every budget resolves to the same types.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rolls;
/// Budget: N, a, b within 6.5 % ([`ROUGH_NORMAL_BOUND`]); friction within 0.25 fN and
/// 0.17 fNa with spin, 0.065 fN without → [`Ellipsoid`] (with spin) and, for a fixed contact in
/// `f32` with the feature `micromath`, micromath's √h in Hertz (`HertzMicromath`): measured
/// N 6.07e-2, friction 0.233 fN / 0.159 fNa (ball–race; the N and a bias adds to the
/// ellipsoidal law's 0.222 / 0.133, so [`Coarse`]'s torque bound 0.15 would not hold), 86
/// M4F instructions per step (`Coarse`: 87). Without the feature, in `f64` and for
/// [`Varying`] geometry it resolves to [`Coarse`]'s types, within the same bounds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rough;
/// Budget: friction within 0.25 fN in force and 0.15 fNa in torque → [`Ellipsoid`] (measured
/// 0.227 fN / 0.134 fNa; 87 M4F instructions per `f32` step of a fixed contact); N, a, b
/// within [`NORMAL_BOUND`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Coarse;
/// Budget: friction within 5e-4 fN in force and 5e-4 fNa in torque ("exact-grade") → [`Best`]
/// (measured 4.9e-5 fN / 3.5e-6 fNa; 161–182 M4F instructions per `f32` step of a fixed
/// contact; a varying one takes `Best`'s per-step flash-table form: 4.7e-5 fN / 3.3e-6 fNa
/// over every accepted shape (e² to 0.99998),
/// 521 instructions per wrench on the `wrench` set); N, a, b within [`NORMAL_BOUND`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExactGrade;

/// A scene's precision (sealed: `f32`, `f64`) and the micromath twins it admits. With the
/// feature `micromath`, `f32` names the twins measured to pay in some scene; `f64` (where the
/// twins are libm code) and every precision without the feature name the libm types.
pub trait Precision: Real + sealed::Sealed {
    /// [`Hertz`] with micromath's √h per step (`HertzMicromath<f32>`), or [`Hertz`].
    type FastHertz: NormalLaw<Self> + From<Hertz<Self>> + Copy + core::fmt::Debug + PartialEq;
    /// The spin law of a varying exact-grade contact: [`Best`] (its per-step flash-table form
    /// calls no `ln`, so `BestMicromath`, the series with micromath's `ln`, no longer pays).
    type FastBest: FrictionLaw;
}

#[cfg(feature = "micromath")]
#[cfg_attr(docsrs, doc(cfg(feature = "micromath")))]
impl Precision for f32 {
    type FastHertz = crate::normal::HertzMicromath<f32>;
    type FastBest = Best;
}

#[cfg(not(feature = "micromath"))]
impl Precision for f32 {
    type FastHertz = Hertz<f32>;
    type FastBest = Best;
}

impl Precision for f64 {
    type FastHertz = Hertz<f64>;
    type FastBest = Best;
}

/// An error budget: its bounds (max over e² ≤ 0.99 — for [`ExactGrade`]'s [`Best`] over every
/// accepted e², to 0.99998 —, all slip directions and ratios, δ = 0, against exact Hertz and
/// the exact integrals) and the cheapest laws measured to meet them.
pub trait Budget {
    /// Short name used in benchmark keys.
    const NAME: &'static str;
    /// Bound on the relative error of N, a and b.
    const NORMAL: f64;
    /// Bound on |F − F_exact| in units of fN, with spin.
    const FORCE: f64;
    /// Bound on |T_z − T_exact| in units of fNa, with spin.
    const TORQUE: f64;
    /// Bound on |F − F_exact| (fN) and |T_z − T_exact| (fNa) without spin ([`Coulomb`]).
    const NOSPIN: f64;
    /// The normal law of a fixed contact (built from exact Hertz by `From`).
    type Normal<T: Precision>: NormalLaw<T> + From<Hertz<T>> + Copy + core::fmt::Debug + PartialEq;
    /// The friction law of a spinning fixed contact (its per-contact form is used).
    type SpinLaw: FrictionLaw;
    /// The friction law of a spinning varying contact (its per-call form is used).
    type VaryingSpinLaw<T: Precision>: FrictionLaw;
}

/// The budgets' rows: `Budget { NAME, NORMAL, FORCE, TORQUE, NOSPIN, Normal<T>, SpinLaw,
/// VaryingSpinLaw<T> }` (each named in the trait above).
macro_rules! budgets {
    ($($b:ident: $name:literal, $normal:expr, $force:expr, $torque:expr, $nospin:expr,
        $fixed:ty, $spin:ty, $varying:ty;)*) => {$(
        impl Budget for $b {
            const NAME: &'static str = $name;
            const NORMAL: f64 = $normal;
            const FORCE: f64 = $force;
            const TORQUE: f64 = $torque;
            const NOSPIN: f64 = $nospin;
            type Normal<T: Precision> = $fixed;
            type SpinLaw = $spin;
            type VaryingSpinLaw<T: Precision> = $varying;
        }
    )*};
}

budgets! {
    Rough: "rough", ROUGH_NORMAL_BOUND, 0.25, 0.17, ROUGH_NORMAL_BOUND,
        T::FastHertz, Ellipsoid, Ellipsoid;
    Coarse: "coarse", NORMAL_BOUND, 0.25, 0.15, NOSPIN_BOUND,
        Hertz<T>, Ellipsoid, Ellipsoid;
    ExactGrade: "exact", NORMAL_BOUND, 5e-4, 5e-4, NOSPIN_BOUND,
        Hertz<T>, Best, T::FastBest;
}

/// Whether the contact spins: [`Spin`] takes the budget's law, [`NoSpin`] plain Coulomb.
pub trait Motion: sealed::Sealed {
    /// Short name used in benchmark keys.
    const NAME: &'static str;
    /// Whether ω ≠ 0 occurs.
    const SPINS: bool;
    /// The friction law, given the budget's law `L` for a spinning contact.
    type Law<L: FrictionLaw>: FrictionLaw;
}

impl Motion for Spin {
    const NAME: &'static str = "spin";
    const SPINS: bool = true;
    type Law<L: FrictionLaw> = L;
}

impl Motion for NoSpin {
    const NAME: &'static str = "nospin";
    const SPINS: bool = false;
    type Law<L: FrictionLaw> = Coulomb;
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
    type Real: Precision;
    /// The normal law chosen (a varying contact rebuilds [`Hertz`] every step).
    type Normal: NormalLaw<Self::Real>;
    /// The friction law chosen.
    type Law: FrictionLaw;
    /// What the constructor needs of the geometry: [`Curvatures`] for a fixed contact,
    /// `()` for a varying one (its curvatures come with every step).
    type Geometry;
    /// The contact type chosen, for damping law `D`; every one steps through [`Step`].
    type Contact<D: Damping<Self::Real>>: Step<Self::Real>;
    /// Short name of the geometry kind (benchmark keys): `sphere-plane`, `ball-race` or
    /// `varying`; the key is `<GEOMETRY>-<Motion::NAME>[-<Budget::NAME>]`, with `-micromath` appended where a
    /// micromath twin was chosen.
    const GEOMETRY: &'static str;
    /// Whether the scene spins ([`Motion::SPINS`]).
    const SPINS: bool;
    /// Bound on the relative error of N, a and b ([`Budget::NORMAL`]).
    const NORMAL: f64;
    /// Bound on the friction force error (fN).
    const FORCE: f64;
    /// Bound on the drilling torque error (fNa).
    const TORQUE: f64;

    /// Build the contact. Errors: those of the geometry kind's constructor
    /// ([`Contact::circular_with`], [`Contact::hertz_with`]; a varying contact cannot fail).
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

/// The normal law a scene resolves to.
pub type NormalOf<S> = <S as Select>::Normal;
/// The friction law a scene resolves to.
pub type LawOf<S> = <S as Select>::Law;
/// The contact type a scene resolves to, with damping law `D` (default [`Undamped`](crate::normal::Undamped)).
pub type ContactOf<S, D = crate::normal::Undamped> = <S as Select>::Contact<D>;

/// One [`Select`] impl per geometry kind: patch, geometry, key name, normal law, friction law
/// for a spinning contact, constructor input, contact type (for damping law `$d`), the
/// constructor body and the geometry input from curvatures.
macro_rules! select {
    ($p:ty, $g:ty, $name:literal, $normal:ty, $spin_law:ty, $geometry:ty,
     |$d:ident| $contact:ty,
     |$geo:pat_param, $estar:ident, $damping:ident, $friction:ident| $build:expr,
     |$c:pat_param| $of:expr) => {
        impl<S: Motion, B: Budget, T: Precision> Select for Scene<$p, $g, S, B, T> {
            type Real = T;
            type Normal = $normal;
            type Law = S::Law<$spin_law>;
            type Geometry = $geometry;
            type Contact<$d: Damping<T>> = $contact;
            const GEOMETRY: &'static str = $name;
            const SPINS: bool = S::SPINS;
            const NORMAL: f64 = B::NORMAL;
            const FORCE: f64 = if S::SPINS { B::FORCE } else { B::NOSPIN };
            const TORQUE: f64 = if S::SPINS { B::TORQUE } else { B::NOSPIN };

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

select!(Circular, Fixed, "sphere-plane", B::Normal<T>, B::SpinLaw, Curvatures<T>,
    |D| Contact<T, B::Normal<T>, D, S::Law<B::SpinLaw>>,
    |curvatures, estar, damping, friction| Contact::circular_with(curvatures, estar, damping, friction),
    |c| *c);

select!(Elliptic, Fixed, "ball-race", B::Normal<T>, B::SpinLaw, Curvatures<T>,
    |D| Contact<T, B::Normal<T>, D, S::Law<B::SpinLaw>>,
    |curvatures, estar, damping, friction| Contact::hertz_with::<Table>(curvatures, estar, damping, friction),
    |c| *c);

select!(Elliptic, Varying, "varying", Hertz<T>, B::VaryingSpinLaw<T>, (),
    |D| VaryingContact<T, D, S::Law<B::VaryingSpinLaw<T>>>,
    |_, estar, damping, friction| Ok(VaryingContact::new(estar, damping, friction)),
    |_| ());

/// Poisson ratio of the elasticity [`Select::build`] gives a [`Rolls`] scene (steel): with
/// G = E*(1 − ν), quasi-identical bodies of the contact's E*.
pub const ROLLING_NU: f64 = 0.3;

/// Bound on |F − F_exact| (fN) of a [`Rolls`] scene: the default rolling law `table` against
/// the exact steady-rolling theory over Kalker's creep curves, a/b ∈ [0.2, 5] (measured 0.045
/// on held-out magnitudes; the user guide, docs/guide/src/rolling.md).
pub const ROLLING_FORCE: f64 = 0.05;

/// Bound on |M_z − M_exact| (fNc, c = √(ab)) of a [`Rolls`] scene, as [`ROLLING_FORCE`]
/// (measured 0.033).
pub const ROLLING_TORQUE: f64 = 0.05;

/// One per-step call of any scene's contact with the rolling velocity V of the contact
/// ([`RollingVelocity`], contact frame): a [`Rolls`] contact reads it, the sliding ones ignore
/// it (their [`Step::step`]). Total.
pub trait StepRolling<T: Real> {
    /// One step: this step's curvatures (read by a varying contact), h (m), ḣ (m/s), the slip
    /// and the rolling velocity → the wrench on B from A (without the law's branch).
    fn step_rolling(
        &self,
        curv: &Curvatures<T>,
        h: T,
        hdot: T,
        slip: Slip<T>,
        v: RollingVelocity<T>,
    ) -> Wrench<T, ()>;
}

/// A wrench without its branch.
#[inline(always)]
fn unbranched<T: Real, B>(w: Wrench<T, B>) -> Wrench<T, ()> {
    Wrench {
        n: w.n,
        fx: w.fx,
        fy: w.fy,
        tz: w.tz,
        patch: w.patch,
        branch: (),
    }
}

/// One [`StepRolling`] impl: generics, type, the call from (self, curvatures, h, ḣ, slip, V).
macro_rules! step_rolling {
    ([$($g:tt)*] $ty:ty, |$s:ident, $curv:pat_param, $h:ident, $hd:ident, $sl:ident, $v:pat_param| $body:expr) => {
        impl<$($g)*> StepRolling<T> for $ty {
            #[inline(always)]
            fn step_rolling(
                &self,
                $curv: &Curvatures<T>,
                $h: T,
                $hd: T,
                $sl: Slip<T>,
                $v: RollingVelocity<T>,
            ) -> Wrench<T, ()> {
                let $s = self;
                $body
            }
        }
    };
}

step_rolling!([T: Real, N: NormalLaw<T>, D: Damping<T>, L: FrictionLaw] Contact<T, N, D, L>,
    |c, _, h, hdot, slip, _| unbranched(c.wrench(h, hdot, slip)));
step_rolling!([T: Real, D: Damping<T>, L: FrictionLaw] VaryingContact<T, D, L>,
    |c, curv, h, hdot, slip, _| unbranched(c.wrench(curv, h, hdot, slip)));
step_rolling!([T: Real, N: NormalLaw<T>, D: Damping<T>, L: rolling::RollingLaw]
    Rolling<T, Contact<T, N, D, Best>, L>,
    |c, _, h, hdot, slip, v| c.wrench(h, hdot, slip, v));
step_rolling!([T: Real, D: Damping<T>, L: rolling::RollingLaw]
    Rolling<T, VaryingContact<T, D, Best>, L>,
    |c, curv, h, hdot, slip, v| c.wrench(curv, h, hdot, slip, v));

/// [`Step`] of a rolling contact without a rolling velocity: its full-slip limit (V = 0,
/// exact `best` with δ = 0). Use [`StepRolling::step_rolling`] to roll.
impl<T: Real, N: NormalLaw<T>, D: Damping<T>, L: rolling::RollingLaw> Step<T>
    for Rolling<T, Contact<T, N, D, Best>, L>
{
    type Branch = ();
    #[inline(always)]
    fn step(&self, _: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, ()> {
        self.wrench(h, hdot, slip, RollingVelocity::ZERO)
    }
}

/// As for the fixed contact: the full-slip limit (V = 0).
impl<T: Real, D: Damping<T>, L: rolling::RollingLaw> Step<T>
    for Rolling<T, VaryingContact<T, D, Best>, L>
{
    type Branch = ();
    #[inline(always)]
    fn step(&self, curv: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, ()> {
        self.wrench(curv, h, hdot, slip, RollingVelocity::ZERO)
    }
}

/// The elasticity [`Select::build`] gives a [`Rolls`] scene: quasi-identical bodies of E*,
/// ν = [`ROLLING_NU`], G = E*(1 − ν). Errors: those of [`Elasticity::new`] (none for a valid
/// E*).
pub fn rolling_elasticity<T: Real>(estar: Modulus<T>) -> Result<Elasticity<T>, Error> {
    let nu = T::from_f64(ROLLING_NU);
    Elasticity::new(estar.get() * (T::ONE - nu), nu)
}

/// A [`Rolls`] scene built with any elasticity.
pub trait SelectRolling: Select {
    /// [`Select::build`] with the pair's elastic constants `elasticity` instead of the
    /// default ([`rolling_elasticity`]). Errors: those of the geometry kind's constructor and
    /// of [`Rolling::new`].
    fn build_rolling<D: Damping<Self::Real>>(
        geometry: &Self::Geometry,
        estar: Modulus<Self::Real>,
        damping: D,
        friction: Friction<Self::Real, Self::Law>,
        elasticity: Elasticity<Self::Real>,
    ) -> Result<Self::Contact<D>, Error>;
}

/// One [`Select`] + [`SelectRolling`] impl per geometry kind for [`Rolls`]: patch, geometry,
/// key name, constructor input, base contact type (damping `$d`), the base constructor, the
/// geometry input from curvatures.
macro_rules! select_rolling {
    ($p:ty, $g:ty, $name:literal, $geometry:ty,
     |$d:ident| $base:ty,
     |$geo:pat_param, $estar:ident, $damping:ident, $friction:ident| $build:expr,
     |$c:pat_param| $of:expr) => {
        impl<B: Budget, T: Precision> Select for Scene<$p, $g, Rolls, B, T> {
            type Real = T;
            type Normal = Hertz<T>;
            type Law = Best;
            type Geometry = $geometry;
            type Contact<$d: Damping<T>> = Rolling<T, $base, rolling::Table>;
            const GEOMETRY: &'static str = $name;
            const SPINS: bool = true;
            const NORMAL: f64 = NORMAL_BOUND;
            const FORCE: f64 = ROLLING_FORCE;
            const TORQUE: f64 = ROLLING_TORQUE;

            fn build<$d: Damping<T>>(
                geometry: &$geometry,
                estar: Modulus<T>,
                damping: $d,
                friction: Friction<T, Best>,
            ) -> Result<Self::Contact<$d>, Error> {
                Self::build_rolling(
                    geometry,
                    estar,
                    damping,
                    friction,
                    rolling_elasticity(estar)?,
                )
            }

            #[inline(always)]
            fn geometry($c: &Curvatures<T>) -> $geometry {
                $of
            }
        }

        impl<B: Budget, T: Precision> SelectRolling for Scene<$p, $g, Rolls, B, T> {
            fn build_rolling<$d: Damping<T>>(
                $geo: &$geometry,
                $estar: Modulus<T>,
                $damping: $d,
                $friction: Friction<T, Best>,
                elasticity: Elasticity<T>,
            ) -> Result<Self::Contact<$d>, Error> {
                Rolling::new($build, elasticity)
            }
        }
    };
}

select_rolling!(Circular, Fixed, "sphere-plane", Curvatures<T>,
    |D| Contact<T, Hertz<T>, D, Best>,
    |curvatures, estar, damping, friction| Contact::circular_with(curvatures, estar, damping, friction)?,
    |c| *c);

select_rolling!(Elliptic, Fixed, "ball-race", Curvatures<T>,
    |D| Contact<T, Hertz<T>, D, Best>,
    |curvatures, estar, damping, friction| Contact::hertz_with::<Table>(curvatures, estar, damping, friction)?,
    |c| *c);

select_rolling!(Elliptic, Varying, "varying", (),
    |D| VaryingContact<T, D, Best>,
    |_, estar, damping, friction| VaryingContact::new(estar, damping, friction),
    |_| ());
