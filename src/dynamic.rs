//! The wrench contract with the friction law and the contact form chosen **at run time**: the
//! one definition that `contact_eval wrench`, the C API (`capi/`) and the Python package
//! (`python/`) share, so that each can be checked against the others bit for bit.
//!
//! Everything else in the crate picks methods by generics, so that a program links only what
//! it uses. A shell that reads the law from a command line, a C call or a Python string cannot:
//! [`DynContact`] holds one of the generic contacts in an enum and dispatches per call (one
//! `match`; the arm is the generic code itself, so the numbers are those of the generic call).
//! It links every law. Firmware that knows its law at compile time uses
//! [`crate::contact::Contact`] directly.
//!
//! # The contract
//!
//! | columns | meaning (crate conventions, SI) |
//! |---|---|
//! | `P,Q` | relative surface z = P x² + Q y², **0 < P ≤ Q** so that x is the major axis (P > Q is [`Error::CurvaturesNotOrdered`], never swapped); P/Q ≥ 1e-4 ([`Error::CurvatureRatioOutOfRange`], never clamped) |
//! | `estar` | effective modulus E* (Pa) |
//! | `cd` | Hunt–Crossley c_d (s/m), N = k_H h^{3/2}(1 + (3/2)c_d ḣ); 0 = undamped (bit for bit) |
//! | `f,delta` | friction coefficient, regularization speed δ (m/s, 0 allowed) |
//! | `h,hdot` | approach (m; ≤ 0 is contact loss) and its rate (m/s; > 0 compression) |
//! | `vx,vy,omega` | slip of B relative to A at the patch centre in the contact frame (m/s), spin about z (rad/s) |
//! | → `N,Fx,Fy,Tz,a,b,e2` | normal force, friction force, drilling torque on B from A; semi-axes; e² |
//! | optional: `G,nu` | rolling laws: combined shear modulus (Pa; default E*·(1 − ν): quasi-identical bodies of the contact's E*), Poisson ratio (default 0.3) ([`RollingSpec`]) |
//! | optional: `vrx,vry` | rolling laws: the contact's rolling velocity in the contact frame (m/s; default 0: full slip) ([`RollingStep`], [`RollingVelocity`]) |
//!
//! Forms ([`Form`]): `fixed` builds a [`Contact`] with the exact eccentricity
//! ([`shape::Newton`]) once; `varying` is a [`VaryingContact`], the eccentricity and every
//! shape constant by [`shape::Table`] at each step. Laws ([`Law`]): `best` (the default),
//! `simplified`, `pade`, `ellipsoid`, `coulomb` (sliding: the optional columns are neither read
//! nor checked, so every existing input gives the same bits); rolling ([`Rolling`] over the
//! form's contact with friction `best`, its δ unused): `table`, `blend`, `fastsim`,
//! `fastsim-16`. Errors of the optional columns name them: `G` ≤ 0
//! [`Error::ShearModulusNotPositive`], `nu` outside [0, 0.5]
//! [`Error::RollingPoissonRatioOutOfRange`], NaN or ±∞ [`Error::NonFinite`].
//! [`DynContact::wrench_many`] runs a rolling law as a scalar loop at V = 0;
//! [`DynContact::wrench_many_rolling`] takes the `vrx, vry` columns (a scalar loop, every law).
//!
//! # Example
//!
//! ```
//! use contensou::dynamic::{DynContact, Form, Law, Spec, Step};
//!
//! let spec = Spec { p: 50.0_f64, q: 50.0, estar: 1.15e11, cd: 0.0, f: 0.1, delta: 1e-4 };
//! let contact = DynContact::new(&spec, Law::from_name("best").unwrap(), Form::Fixed)?;
//! let w = contact.wrench(&Step { h: 1e-6, hdot: 0.0, vx: 0.01, vy: 0.0, omega: 50.0 })?;
//! assert!(w.n > 0.0 && w.fx < 0.0 && w.tz < 0.0);
//!
//! // Every invalid input names its column.
//! let bad = Spec { p: 60.0, ..spec };
//! let e = DynContact::new(&bad, Law::Best, Form::Fixed).unwrap_err();
//! assert_eq!((e.column, e.error), ("P", contensou::Error::CurvaturesNotOrdered));
//! # Ok::<(), contensou::dynamic::Invalid>(())
//! ```

use core::fmt;

use crate::contact::{Contact, Rolling, VaryingContact, Wrench};
use crate::error::finite;
use crate::friction::rolling::row::RowLaw;
use crate::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, RollingLaw, RollingVelocity, Table,
};
use crate::friction::{Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Pade, Simplified, Slip};
use crate::geometry::Curvatures;
use crate::normal::{Hertz, HuntCrossley, Modulus};
use crate::shape::{self, Ratio};
use crate::{Error, Real};

/// The contract's input columns, in order (contact columns, then step columns).
pub const INPUTS: [&str; 11] = [
    "P", "Q", "estar", "cd", "f", "delta", "h", "hdot", "vx", "vy", "omega",
];

/// The contract's optional rolling columns, in order: contact `G, nu` ([`RollingSpec`]), step
/// `vrx, vry` ([`RollingStep`]). Absent: the defaults (see the module docs).
pub const ROLLING_INPUTS: [&str; 4] = ["G", "nu", "vrx", "vry"];

/// The contract's output columns, in order ([`Output::to_array`]).
pub const OUTPUTS: [&str; 7] = ["N", "Fx", "Fy", "Tz", "a", "b", "e2"];

/// A friction law, by name ([`FrictionLaw::NAME`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Law {
    /// [`Best`], the exact-grade default.
    #[default]
    Best,
    /// [`Simplified`], the paper's model.
    Simplified,
    /// [`Pade`].
    Pade,
    /// [`Ellipsoid`].
    Ellipsoid,
    /// [`Coulomb`] (point contact: no drilling torque).
    Coulomb,
    /// Rolling: [`Table`], the default rolling law.
    Table,
    /// Rolling: [`Blend`].
    Blend,
    /// Rolling: [`Fastsim`] (FASTSIM, 32 × 32).
    Fastsim,
    /// Rolling: [`FastsimGrid`]`<16, 16>`.
    Fastsim16,
}

impl Law {
    /// Every law: the sliding laws (the default first), then the rolling laws.
    pub const ALL: [Law; 9] = [
        Law::Best,
        Law::Simplified,
        Law::Pade,
        Law::Ellipsoid,
        Law::Coulomb,
        Law::Table,
        Law::Blend,
        Law::Fastsim,
        Law::Fastsim16,
    ];

    /// The sliding laws (full slip everywhere; the rolling columns are ignored).
    pub const SLIDING: [Law; 5] = [
        Law::Best,
        Law::Simplified,
        Law::Pade,
        Law::Ellipsoid,
        Law::Coulomb,
    ];

    /// The rolling laws ([`crate::contact::Rolling`]: the rolling columns are read).
    pub const ROLLING: [Law; 4] = [Law::Table, Law::Blend, Law::Fastsim, Law::Fastsim16];

    /// The law's name: `"best"`, `"simplified"`, `"pade"`, `"ellipsoid"`, `"coulomb"`;
    /// rolling: `"table"`, `"blend"`, `"fastsim"`, `"fastsim-16"` (as `contact_eval rolling
    /// --law`).
    pub const fn name(self) -> &'static str {
        match self {
            Law::Best => Best::NAME,
            Law::Simplified => Simplified::NAME,
            Law::Pade => Pade::NAME,
            Law::Ellipsoid => Ellipsoid::NAME,
            Law::Coulomb => Coulomb::NAME,
            Law::Table => Table::NAME,
            Law::Blend => Blend::NAME,
            Law::Fastsim => Fastsim::NAME,
            Law::Fastsim16 => "fastsim-16",
        }
    }

    /// Whether the law is maximally dissipative ([`FrictionLaw::MAXIMALLY_DISSIPATIVE`]; the
    /// rolling laws count as `true`: their full-slip limit is `best`'s).
    pub const fn maximally_dissipative(self) -> bool {
        match self {
            Law::Simplified => Simplified::MAXIMALLY_DISSIPATIVE,
            Law::Pade => Pade::MAXIMALLY_DISSIPATIVE,
            Law::Best => Best::MAXIMALLY_DISSIPATIVE,
            Law::Ellipsoid => Ellipsoid::MAXIMALLY_DISSIPATIVE,
            Law::Coulomb => Coulomb::MAXIMALLY_DISSIPATIVE,
            Law::Table | Law::Blend | Law::Fastsim | Law::Fastsim16 => true,
        }
    }

    /// A rolling law ([`Law::ROLLING`])?
    pub const fn is_rolling(self) -> bool {
        matches!(
            self,
            Law::Table | Law::Blend | Law::Fastsim | Law::Fastsim16
        )
    }

    /// The law of that name ([`Law::name`]), the default rolling law for `"rolling"`
    /// ([`RowLaw::ALIAS`], resolved by [`RowLaw::resolve`]); `None` for any other string.
    pub fn from_name(name: &str) -> Option<Self> {
        let name = RowLaw::resolve(name);
        Law::ALL.into_iter().find(|l| l.name() == name)
    }
}

/// How the shape is obtained: once at construction, or by table at every step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Form {
    /// A [`Contact`]: exact eccentricity ([`shape::Newton`]) solved once.
    #[default]
    Fixed,
    /// A [`VaryingContact`]: eccentricity and shape constants by [`shape::Table`] each step.
    Varying,
}

impl Form {
    /// Both forms, the default first.
    pub const ALL: [Form; 2] = [Form::Fixed, Form::Varying];

    /// `"fixed"` or `"varying"`.
    pub const fn name(self) -> &'static str {
        match self {
            Form::Fixed => "fixed",
            Form::Varying => "varying",
        }
    }

    /// The form of that name ([`Form::name`]); `None` for any other string.
    pub fn from_name(name: &str) -> Option<Self> {
        Form::ALL.into_iter().find(|f| f.name() == name)
    }
}

/// The contact columns `P,Q,estar,cd,f,delta` (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spec<T> {
    /// P (1/m), 0 < P ≤ Q.
    pub p: T,
    /// Q (1/m).
    pub q: T,
    /// E* (Pa).
    pub estar: T,
    /// Hunt–Crossley c_d (s/m) ≥ 0; 0 = undamped.
    pub cd: T,
    /// Friction coefficient f ≥ 0.
    pub f: T,
    /// Regularization speed δ (m/s) ≥ 0.
    pub delta: T,
}

/// The step columns `h,hdot,vx,vy,omega` (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Step<T> {
    /// Approach h (m).
    pub h: T,
    /// ḣ (m/s), > 0 compression.
    pub hdot: T,
    /// v_Px (m/s), along the major axis.
    pub vx: T,
    /// v_Py (m/s).
    pub vy: T,
    /// ω (rad/s) about the normal.
    pub omega: T,
}

/// The contact and the step of a row of the contract's [`INPUTS`] columns, in that order.
///
/// ```
/// use contensou::dynamic::{INPUTS, from_inputs};
///
/// let (spec, step) = from_inputs(core::array::from_fn(|i| i as f64));
/// assert_eq!((INPUTS[0], INPUTS[5], INPUTS[6], INPUTS[10]), ("P", "delta", "h", "omega"));
/// assert_eq!((spec.p, spec.delta, step.h, step.omega), (0.0, 5.0, 6.0, 10.0));
/// ```
pub fn from_inputs<T: Copy>(row: [T; 11]) -> (Spec<T>, Step<T>) {
    let [p, q, estar, cd, f, delta, h, hdot, vx, vy, omega] = row;
    (
        Spec {
            p,
            q,
            estar,
            cd,
            f,
            delta,
        },
        Step {
            h,
            hdot,
            vx,
            vy,
            omega,
        },
    )
}

impl<T: Real> Step<T> {
    /// `h, hdot` and the slip, each finite (any NaN or ±∞ is [`Error::NonFinite`] naming the
    /// column).
    #[inline]
    pub(crate) fn validated(&self) -> Result<(T, T, Slip<T>), Invalid> {
        let h = at("h", finite(self.h, "h"))?;
        let hdot = at("hdot", finite(self.hdot, "hdot"))?;
        let vx = at("vx", finite(self.vx, "vx"))?;
        let vy = at("vy", finite(self.vy, "vy"))?;
        let omega = at("omega", finite(self.omega, "omega"))?;
        Ok((h, hdot, at("vx", Slip::new(vx, vy, omega))?))
    }
}

/// The optional contact columns `G, nu` of the rolling laws (`None`: absent, the default).
///
/// - `G` (Pa), the pair's combined shear modulus: default E*·(1 − ν) (quasi-identical
///   bodies of the contact's E*: E* = E/(2(1 − ν²)), G = E/(2(1 + ν))). G ≤ 0:
///   [`Error::ShearModulusNotPositive`].
/// - `nu`, the Poisson ratio of the tangential problem: default 0.3; outside [0, 0.5]:
///   [`Error::RollingPoissonRatioOutOfRange`].
///
/// Non-finite: [`Error::NonFinite`]. Read (and validated) by the rolling laws only.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollingSpec<T> {
    /// G (Pa); `None`: E*·(1 − ν).
    pub g: Option<T>,
    /// ν; `None`: 0.3.
    pub nu: Option<T>,
}

impl<T: Real> RollingSpec<T> {
    /// The default ν (0.3).
    pub const NU: f64 = 0.3;

    /// The elastic constants for a contact of effective modulus `estar` (Pa), the defaults
    /// filled in; errors name the column (`G`, `nu`).
    pub fn elasticity(&self, estar: T) -> Result<Elasticity<T>, Invalid> {
        let nu = match self.nu {
            Some(nu) => at("nu", finite(nu, "nu"))?,
            None => T::from_f64(Self::NU),
        };
        if !(nu >= T::ZERO && nu <= T::HALF) {
            return Err(Invalid {
                column: "nu",
                error: Error::RollingPoissonRatioOutOfRange,
            });
        }
        let g = match self.g {
            Some(g) => at("G", finite(g, "G"))?,
            None => estar * (T::ONE - nu),
        };
        at(
            if self.g.is_some() { "G" } else { "estar" },
            Elasticity::new(g, nu),
        )
    }
}

/// The optional step columns `vrx, vry` of the rolling laws: the contact's rolling velocity in
/// the contact frame (m/s; [`RollingVelocity`]); default 0 (no rolling: full slip).
/// Non-finite: [`Error::NonFinite`] naming the column. Read (and validated) by the rolling laws
/// only.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollingStep<T> {
    /// V_x (m/s), along the major axis.
    pub vrx: T,
    /// V_y (m/s).
    pub vry: T,
}

impl<T: Real> RollingStep<T> {
    /// The validated rolling velocity; errors name the column (`vrx`, `vry`).
    pub fn velocity(&self) -> Result<RollingVelocity<T>, Invalid> {
        let vx = at("vrx", finite(self.vrx, "vrx"))?;
        let vy = at("vry", finite(self.vry, "vry"))?;
        at("vrx", RollingVelocity::new(vx, vy))
    }
}

/// The rolling columns of a batch ([`DynContact::wrench_many_rolling`]), each as long as `h`.
#[derive(Clone, Copy, Debug)]
pub struct RollingSteps<'a, T> {
    /// V_x (m/s).
    pub vrx: &'a [T],
    /// V_y (m/s).
    pub vry: &'a [T],
}

/// The output columns `N,Fx,Fy,Tz,a,b,e2`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Output<T> {
    /// N (N).
    pub n: T,
    /// F_x (N).
    pub fx: T,
    /// F_y (N).
    pub fy: T,
    /// T_z (N·m).
    pub tz: T,
    /// Major semi-axis a (m); 0 without contact.
    pub a: T,
    /// Minor semi-axis b (m).
    pub b: T,
    /// e² of the patch (also without contact: the geometry's).
    pub e2: T,
}

impl<T: Copy> Output<T> {
    /// The values in [`OUTPUTS`] order.
    pub fn to_array(&self) -> [T; 7] {
        [self.n, self.fx, self.fy, self.tz, self.a, self.b, self.e2]
    }
}

impl<T: Copy, B> From<Wrench<T, B>> for Output<T> {
    fn from(w: Wrench<T, B>) -> Self {
        Output {
            n: w.n,
            fx: w.fx,
            fy: w.fy,
            tz: w.tz,
            a: w.patch.a,
            b: w.patch.b,
            e2: w.patch.e2,
        }
    }
}

/// A rejected input: the contract column it came from and the crate's error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Invalid {
    /// The column ([`INPUTS`]) whose value was rejected.
    pub column: &'static str,
    /// Why.
    pub error: Error,
}

impl fmt::Display for Invalid {
    /// `"<column>: <reason>"` (the reason is [`Error::as_str`]).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.column, self.error.as_str())
    }
}

impl core::error::Error for Invalid {}

/// Tags an error with the column it came from.
pub(crate) fn at<V>(column: &'static str, r: Result<V, Error>) -> Result<V, Invalid> {
    r.map_err(|error| Invalid { column, error })
}

type Fixed<T, L> = Contact<T, Hertz<T>, HuntCrossley<T>, L>;
type Varying<T, L> = VaryingContact<T, HuntCrossley<T>, L>;

/// One law's contact in either form.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Formed<T: Real, L: FrictionLaw> {
    Fixed(Fixed<T, L>),
    Varying(Varying<T, L>),
}

impl<T: Real, L: FrictionLaw> Formed<T, L> {
    fn new(
        form: Form,
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
        damping: HuntCrossley<T>,
        friction: Friction<T, L>,
    ) -> Result<Self, Invalid> {
        Ok(match form {
            Form::Fixed => Formed::Fixed(at(
                "P",
                Contact::hertz::<shape::Newton>(curvatures, estar, damping, friction),
            )?),
            Form::Varying => Formed::Varying(VaryingContact::new(estar, damping, friction)),
        })
    }

    #[inline]
    fn wrench(&self, curvatures: &Curvatures<T>, h: T, hdot: T, slip: Slip<T>) -> Output<T> {
        match self {
            Formed::Fixed(c) => c.wrench(h, hdot, slip).into(),
            Formed::Varying(c) => c.wrench(curvatures, h, hdot, slip).into(),
        }
    }
}

/// One rolling law's contact in either form.
#[derive(Clone, Copy, Debug)]
pub(crate) enum RollingFormed<T: Real, L> {
    Fixed(Rolling<T, Fixed<T, Best>, L>),
    Varying(Rolling<T, Varying<T, Best>, L>),
}

// By hand: the law `L` is a marker (no `PartialEq` bound on it).
impl<T: Real, L> PartialEq for RollingFormed<T, L> {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (RollingFormed::Fixed(a), RollingFormed::Fixed(b)) => a == b,
            (RollingFormed::Varying(a), RollingFormed::Varying(b)) => a == b,
            _ => false,
        }
    }
}

impl<T: Real, L: RollingLaw> RollingFormed<T, L> {
    /// The `best` contact `formed` rolling with `elasticity`.
    fn new(formed: Formed<T, Best>, elasticity: Elasticity<T>) -> Result<Self, Invalid> {
        Ok(match formed {
            Formed::Fixed(c) => RollingFormed::Fixed(at("P", Rolling::new(c, elasticity))?),
            Formed::Varying(c) => RollingFormed::Varying(at("P", Rolling::new(c, elasticity))?),
        })
    }

    #[inline]
    fn wrench(
        &self,
        curvatures: &Curvatures<T>,
        h: T,
        hdot: T,
        slip: Slip<T>,
        v: RollingVelocity<T>,
    ) -> Output<T> {
        match self {
            RollingFormed::Fixed(c) => c.wrench(h, hdot, slip, v).into(),
            RollingFormed::Varying(c) => c.wrench(curvatures, h, hdot, slip, v).into(),
        }
    }
}

/// The contact of each law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ByLaw<T: Real> {
    Best(Formed<T, Best>),
    Simplified(Formed<T, Simplified>),
    Pade(Formed<T, Pade>),
    Ellipsoid(Formed<T, Ellipsoid>),
    Coulomb(Formed<T, Coulomb>),
    Table(RollingFormed<T, Table>),
    Blend(RollingFormed<T, Blend>),
    Fastsim(RollingFormed<T, Fastsim>),
    Fastsim16(RollingFormed<T, FastsimGrid<16, 16>>),
}

/// A validated contact of the contract, its law and form chosen at run time. Per step,
/// [`DynContact::wrench`] validates the step columns and returns exactly what the generic
/// contact returns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DynContact<T: Real> {
    spec: Spec<T>,
    rolling: RollingSpec<T>,
    pub(crate) curvatures: Curvatures<T>,
    law: Law,
    form: Form,
    pub(crate) contact: ByLaw<T>,
}

/// The friction of law `L` with coefficient `f` and regularization speed `delta`; errors name
/// `delta` ([`Error::RegularizationSpeedNegative`]) or `f`.
fn friction_of<T: Real, L: FrictionLaw>(f: T, delta: T) -> Result<Friction<T, L>, Invalid> {
    Friction::with_law(f, delta).map_err(|error| Invalid {
        column: if matches!(error, Error::RegularizationSpeedNegative) {
            "delta"
        } else {
            "f"
        },
        error,
    })
}

impl<T: Real> DynContact<T> {
    /// Validates the contact columns and builds the contact. Errors name the column:
    /// `P`/`Q` ([`Error::NonFinite`], [`Error::CurvaturesNotOrdered`],
    /// [`Error::CurvatureNotPositive`], [`Error::CurvatureRatioOutOfRange`] — the ratio is
    /// reported on `P`), `estar` ([`Error::ModulusNotPositive`]), `cd`
    /// ([`Error::DampingNegative`]), `f` ([`Error::FrictionCoefficientNegative`]), `delta`
    /// ([`Error::RegularizationSpeedNegative`]); any NaN or ±∞ is [`Error::NonFinite`].
    /// A rolling law takes the default rolling columns ([`DynContact::new_rolling`]).
    pub fn new(spec: &Spec<T>, law: Law, form: Form) -> Result<Self, Invalid> {
        Self::new_rolling(spec, &RollingSpec::default(), law, form)
    }

    /// [`DynContact::new`] with the optional rolling columns `G, nu` ([`RollingSpec`]: read
    /// and validated by the rolling laws only; errors name `G` or `nu`).
    pub fn new_rolling(
        spec: &Spec<T>,
        rolling: &RollingSpec<T>,
        law: Law,
        form: Form,
    ) -> Result<Self, Invalid> {
        let curvatures = curvatures_of(spec.p, spec.q)?;
        let estar = at("estar", Modulus::new(spec.estar))?;
        let damping = at("cd", HuntCrossley::new(spec.cd))?;
        let f = at("f", finite(spec.f, "f"))?;
        let delta = at("delta", finite(spec.delta, "delta"))?;
        macro_rules! build {
            ($variant:ident) => {{
                let friction = friction_of(f, delta)?;
                ByLaw::$variant(Formed::new(form, &curvatures, estar, damping, friction)?)
            }};
        }
        macro_rules! roll {
            ($variant:ident) => {{
                let friction = friction_of::<T, Best>(f, delta)?;
                let elasticity = rolling.elasticity(estar.get())?;
                let formed = Formed::new(form, &curvatures, estar, damping, friction)?;
                ByLaw::$variant(RollingFormed::new(formed, elasticity)?)
            }};
        }
        let contact = match law {
            Law::Best => build!(Best),
            Law::Simplified => build!(Simplified),
            Law::Pade => build!(Pade),
            Law::Ellipsoid => build!(Ellipsoid),
            Law::Coulomb => build!(Coulomb),
            Law::Table => roll!(Table),
            Law::Blend => roll!(Blend),
            Law::Fastsim => roll!(Fastsim),
            Law::Fastsim16 => roll!(Fastsim16),
        };
        Ok(DynContact {
            spec: *spec,
            rolling: *rolling,
            curvatures,
            law,
            form,
            contact,
        })
    }

    /// One step: validates `h, hdot, vx, vy, omega` (finite; any NaN or ±∞ is
    /// [`Error::NonFinite`] naming the column) and returns the wrench of the generic contact.
    /// A rolling law takes the default rolling step (V = 0: full slip;
    /// [`DynContact::wrench_rolling`]).
    #[inline]
    pub fn wrench(&self, step: &Step<T>) -> Result<Output<T>, Invalid> {
        self.wrench_rolling(step, &RollingStep::default())
    }

    /// [`DynContact::wrench`] with the optional rolling columns `vrx, vry` ([`RollingStep`]:
    /// read and validated by the rolling laws only, after the step columns).
    ///
    /// Always inlined: a dispatcher (five finiteness tests, one `match` of calls) whose call
    /// frame cost the C API's `contensou_contact_wrench_f32` 34 M4F instructions per call
    /// (`c-fixed-best` 302 → 268, 553 cycles against the Rust row's 513).
    #[inline(always)]
    pub fn wrench_rolling(
        &self,
        step: &Step<T>,
        rolling: &RollingStep<T>,
    ) -> Result<Output<T>, Invalid> {
        let (h, hdot, slip) = step.validated()?;
        let c = &self.curvatures;
        Ok(match &self.contact {
            ByLaw::Best(x) => x.wrench(c, h, hdot, slip),
            ByLaw::Simplified(x) => x.wrench(c, h, hdot, slip),
            ByLaw::Pade(x) => x.wrench(c, h, hdot, slip),
            ByLaw::Ellipsoid(x) => x.wrench(c, h, hdot, slip),
            ByLaw::Coulomb(x) => x.wrench(c, h, hdot, slip),
            ByLaw::Table(x) => x.wrench(c, h, hdot, slip, rolling.velocity()?),
            ByLaw::Blend(x) => x.wrench(c, h, hdot, slip, rolling.velocity()?),
            ByLaw::Fastsim(x) => x.wrench(c, h, hdot, slip, rolling.velocity()?),
            ByLaw::Fastsim16(x) => x.wrench(c, h, hdot, slip, rolling.velocity()?),
        })
    }

    /// New curvatures (same validation as [`DynContact::new`]). For [`Form::Varying`] this is
    /// the per-step update (no rebuild); a [`Form::Fixed`] contact is rebuilt (the construction
    /// cost: an eccentricity solve and, for `best`, its per-contact tables). On error the
    /// contact is unchanged.
    pub fn set_curvatures(&mut self, p: T, q: T) -> Result<(), Invalid> {
        let spec = Spec { p, q, ..self.spec };
        match self.form {
            Form::Varying => {
                self.curvatures = curvatures_of(p, q)?;
                self.spec = spec;
            }
            Form::Fixed => {
                *self = DynContact::new_rolling(&spec, &self.rolling, self.law, self.form)?
            }
        }
        Ok(())
    }

    /// The contact columns it was built from (after [`DynContact::set_curvatures`], the new P, Q).
    pub fn spec(&self) -> &Spec<T> {
        &self.spec
    }

    /// The optional rolling columns it was built from (as given: `None` for a default).
    pub fn rolling_spec(&self) -> &RollingSpec<T> {
        &self.rolling
    }

    /// The friction law.
    pub fn law(&self) -> Law {
        self.law
    }

    /// The form.
    pub fn form(&self) -> Form {
        self.form
    }
}

/// One row of the contract: builds the contact and evaluates one step (the per-row form of
/// `contact_eval wrench`; a loop should build a [`DynContact`] once instead).
pub fn wrench<T: Real>(
    spec: &Spec<T>,
    law: Law,
    form: Form,
    step: &Step<T>,
) -> Result<Output<T>, Invalid> {
    DynContact::new(spec, law, form)?.wrench(step)
}

/// [`wrench`] with the optional rolling columns (the per-row form of `contact_eval wrench`
/// with `G, nu, vrx, vry`).
pub fn wrench_rolling<T: Real>(
    spec: &Spec<T>,
    rolling_spec: &RollingSpec<T>,
    law: Law,
    form: Form,
    step: &Step<T>,
    rolling_step: &RollingStep<T>,
) -> Result<Output<T>, Invalid> {
    DynContact::new_rolling(spec, rolling_spec, law, form)?.wrench_rolling(step, rolling_step)
}

/// Validated, ordered curvatures with P/Q in the solvers' range (both forms: nothing clamped).
pub(crate) fn curvatures_of<T: Real>(p: T, q: T) -> Result<Curvatures<T>, Invalid> {
    let column = if p.is_finite() { "Q" } else { "P" };
    let curvatures = Curvatures::ordered(p, q).map_err(|error| Invalid {
        column: match error {
            Error::NonFinite(_) => column,
            _ => "P",
        },
        error,
    })?;
    at("P", Ratio::of(&curvatures))?;
    Ok(curvatures)
}
