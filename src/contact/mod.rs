//! The per-step wrench: approach h, its rate ḣ, slip v_P and spin ω → normal force N, friction
//! force (F_x, F_y) and drilling torque T_z, on body B from body A in the contact frame (crate
//! conventions).
//!
//! This is where the data flow closes: geometry → shape → normal law (+ damping) → friction
//! law. Two forms, by what changes between steps:
//!
//! - [`Contact`]: **fixed geometry** (e.g. a ball on a plane, a ball in a given raceway). The
//!   shape, the Hertz constants and the friction constants are computed once at construction;
//!   a step is the normal law's square root plus the friction law.
//! - [`VaryingContact`]: the curvatures change every step (e.g. a body whose contact point
//!   wanders over a non-spherical surface). Each step solves the eccentricity with
//!   [`shape::Table`] (no elliptic integral, fixed cost) and rebuilds the constants.
//!
//! - [`Rolling`] ([`rolling`]): either form with a rolling law (Kalker's creep,
//!   [`crate::friction::rolling`]) for the tangential part, from the slip and the contact's
//!   rolling velocity.
//!
//! All are total: validated inputs in, finite wrench out. h ≤ 0 (contact loss) and N ≤ 0
//! (a damped rebound) give the zero wrench.
//!
//! # Example
//!
//! ```
//! use contensou::contact::Contact;
//! use contensou::friction::{Friction, Simplified, Slip};
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::shape::Newton;
//!
//! // A 6.35 mm steel ball on a steel plane, f = 0.1.
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::sphere_plane(6.35e-3)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::<f64, Simplified>::with_law(0.1, 0.0)?,
//! )?;
//! let w = contact.wrench(1e-6, 0.0, Slip::new(0.01, 0.0, 50.0)?);
//! assert!(w.n > 0.0 && w.fx < 0.0 && w.tz < 0.0);
//! # Ok::<(), contensou::Error>(())
//! ```

pub mod rolling;
pub use rolling::{FixedShapes, Rolling, RollingBase, VaryingShapes};

use crate::friction::law::{PerCall, PerContact};
use crate::friction::{Best, Constants, Explicit, Friction, FrictionLaw, Slip, Tangential};
use crate::geometry::Curvatures;
use crate::normal::{Damping, Hertz, Modulus, NormalLaw, Patch};
use crate::shape::{self, Eccentricity, Ratio, Shape};
use crate::{Error, Real};

/// The contact wrench on body B from body A, in the contact frame (SI): x the major axis, y the
/// minor axis, z the normal from A into B. N, F_x, F_y act at the patch centre P; T_z is a couple
/// about z. Body A receives the opposite. [`crate::frame`] turns it into a world force and a
/// torque about each body's centre of mass (see [`crate::guide`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wrench<T, B> {
    /// Normal force N ≥ 0 (N), along +z (from A into B).
    pub n: T,
    /// Friction force along x, the major axis (N).
    pub fx: T,
    /// Friction force along y, the minor axis (N).
    pub fy: T,
    /// Drilling torque about z (N·m).
    pub tz: T,
    /// The contact patch the wrench was integrated over (semi-axes, peak pressure, e²).
    pub patch: Patch<T>,
    /// Which branch of the friction law produced the tangential part.
    pub branch: B,
}

/// The wrench from the step's patch and its friction (shared by both contact forms; the
/// calls are made inline by each form, no closure, so that the friction core inlines).
#[inline(always)]
fn wrench_of<T: Real, B>(patch: Patch<T>, t: Tangential<T, B>) -> Wrench<T, B> {
    Wrench {
        n: patch.n,
        fx: t.fx,
        fy: t.fy,
        tz: t.tz,
        patch,
        branch: t.branch,
    }
}

/// A contact of fixed geometry: everything that depends only on geometry and materials is
/// precomputed; [`Contact::wrench`] is the per-step call.
///
/// The friction law defaults to [`Best`] (exact-grade, per-contact tables built here once:
/// 182 M4F instructions per `f32` wrench, 1,404 bytes of tables). `Best`'s per-step form, which needs no
/// build, would cost 521 here, so a fixed contact keeps the per-contact tables.
///
/// Cost per step (f32, Cortex-M4F, Hertz + undamped): `bench-results/qemu.csv`, stage `wrench`,
/// method `fixed` ([`crate::friction::Simplified`]) and `fixed-best` ([`Best`]).
///
/// The wrench comes back in the contact frame (x the major axis, z from A into B, on body B;
/// see [`crate::guide`]); [`crate::frame::Frame`] turns it into world loads.
///
/// # Example
///
/// ```
/// use contensou::contact::Contact;
/// use contensou::friction::{Friction, Slip};
/// use contensou::geometry::Curvatures;
/// use contensou::normal::{HuntCrossley, Material, Modulus};
///
/// // A 5 mm steel ball on a steel plate: a circle, so no eccentricity method is linked.
/// let steel = Material::new(2.1e11, 0.3)?;
/// let contact = Contact::circular(
///     &Curvatures::sphere_plane(5e-3)?,
///     Modulus::of(steel, steel)?,
///     HuntCrossley::new(1.0)?, // restitution ≈ 1 − c_d·v
///     Friction::<f64>::new(0.2, 1e-4)?, // the default law, `Best`
/// )?;
/// // Per step: approach 1 µm, compressing at 1 mm/s, sliding along x at 5 cm/s, no spin.
/// let w = contact.wrench(1e-6, 1e-3, Slip::new(0.05, 0.0, 0.0)?);
/// assert!(w.n > 0.0 && (w.fx + 0.2 * w.n).abs() < 1e-9 * w.n); // F = −fN: full sliding
/// assert_eq!((w.fy, w.tz), (0.0, 0.0));
/// assert_eq!(contact.wrench(-1e-6, 0.0, Slip::new(0.05, 0.0, 0.0)?).n, 0.0); // apart
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contact<T: Real, N, D, L: FrictionLaw = Best> {
    normal: N,
    damping: D,
    friction: Friction<T, L>,
    prepared: L::Prepared<T>,
    constants: Constants<T>,
}

impl<T: Real, D: Damping<T>, L: FrictionLaw> Contact<T, Hertz<T>, D, L> {
    /// Exact Hertz on the given curvatures, the eccentricity solved once by method `M`
    /// ([`shape::Newton`] for the exact shape). A circle (P = Q) takes the circular fast path
    /// and evaluates no elliptic integral.
    /// That test is a runtime branch, so `M`'s elliptic code is still linked; for a patch
    /// known to be circular, [`Contact::circular`] links none.
    ///
    /// Errors: [`Error::CurvatureRatioOutOfRange`] if P/Q is below the solver's range.
    pub fn hertz<M: Eccentricity>(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
        damping: D,
        friction: Friction<T, L>,
    ) -> Result<Self, Error> {
        Self::hertz_with::<M>(curvatures, estar, damping, friction)
    }

    /// A circular patch (P = Q: sphere on plane, sphere on sphere, ball in a spherical cup)
    /// built with no eccentricity method at all: [`Hertz::circular`] + [`Constants::circle`].
    /// Unlike [`Contact::hertz`], whose circle test is a runtime branch (so the elliptic code
    /// is still linked), nothing of [`crate::elliptic`] or [`crate::shape`]'s solvers is
    /// reachable from here: the firmware size probe `scene,sphere-plane-*` links no AGM,
    /// theta, elliptic table or shape table (see [`crate::select`]).
    ///
    /// Exact Hertz (a = b = √(Rh), N = (4/3)E*√R·h^{3/2}, R = 1/(2P)). Errors:
    /// [`Error::CurvatureRatioOutOfRange`] if P ≠ Q (the patch is not a circle).
    pub fn circular(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
        damping: D,
        friction: Friction<T, L>,
    ) -> Result<Self, Error> {
        Self::circular_with(curvatures, estar, damping, friction)
    }
}

impl<T: Real, N: NormalLaw<T> + From<Hertz<T>>, D: Damping<T>, L: FrictionLaw> Contact<T, N, D, L> {
    /// [`Contact::hertz`] with the normal law `N` made from the exact Hertz law by
    /// `N::from` (e.g. `HertzMicromath`, feature `micromath`, which keeps Hertz's constants
    /// and takes √h from micromath; `N = Hertz<T>` is [`Contact::hertz`]). Same errors.
    pub fn hertz_with<M: Eccentricity>(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
        damping: D,
        friction: Friction<T, L>,
    ) -> Result<Self, Error> {
        let (normal, shape) = if curvatures.p() == curvatures.q() {
            (Hertz::circular(curvatures.p(), estar), Shape::circle())
        } else {
            let shape = M::shape(Ratio::of(curvatures)?);
            (Hertz::from_shape(curvatures, &shape, estar), shape)
        };
        Ok(Self::from_parts(
            N::from(normal),
            damping,
            friction,
            Constants::from_shape(&shape),
        ))
    }

    /// [`Contact::circular`] with the normal law `N` made from [`Hertz::circular`] by
    /// `N::from` (e.g. `HertzMicromath`). Links no elliptic or shape code either. Same errors.
    pub fn circular_with(
        curvatures: &Curvatures<T>,
        estar: Modulus<T>,
        damping: D,
        friction: Friction<T, L>,
    ) -> Result<Self, Error> {
        if curvatures.p() != curvatures.q() {
            return Err(Error::CurvatureRatioOutOfRange);
        }
        Ok(Self::from_parts(
            N::from(Hertz::circular(curvatures.p(), estar)),
            damping,
            friction,
            Constants::circle(),
        ))
    }
}

impl<T: Real, N: NormalLaw<T>, D: Damping<T>, L: FrictionLaw> Contact<T, N, D, L> {
    /// From parts built separately — e.g. the volumetric or fitted normal law with the friction
    /// constants of the shape it stands for ([`Constants::circle`] for a circular law). The
    /// caller is responsible for `constants` describing the same ellipse as `normal`. Builds
    /// the friction law's per-contact form once ([`FrictionLaw::prepare`]).
    pub fn from_parts(
        normal: N,
        damping: D,
        friction: Friction<T, L>,
        constants: Constants<T>,
    ) -> Self {
        Contact {
            normal,
            damping,
            friction,
            prepared: L::prepare(&constants),
            constants,
        }
    }

    /// One step: approach h (m), its rate ḣ (m/s), slip → the wrench on B from A. Total.
    ///
    /// h > 0 is overlap (h ≤ 0: apart, the zero wrench); **ḣ > 0 is compression** (read only by
    /// the damping law); the slip is B's velocity relative to A at the patch centre P and the
    /// relative spin about the normal, in the contact frame (x the major axis, z from A into B).
    /// From two bodies' states and back to world loads: [`crate::frame`], [`crate::guide`].
    #[inline(always)]
    pub fn wrench(&self, h: T, hdot: T, slip: Slip<T>) -> Wrench<T, L::Branch> {
        let patch = self.normal.damped_patch(h, hdot, &self.damping);
        let core = PerContact::<T, L>(&self.prepared);
        let clamp = !N::NON_NEGATIVE;
        let t = self
            .friction
            .tangential_with(core, clamp, patch.a, patch.n, slip);
        wrench_of(patch, t)
    }

    /// The damping law (for the batch kernels, src/batch/).
    #[inline(always)]
    pub(crate) fn damping(&self) -> &D {
        &self.damping
    }

    /// The normal law (for its stiffness, energy and inverse).
    pub fn normal(&self) -> &N {
        &self.normal
    }

    /// The friction law's per-contact form (for most laws the shape's [`Constants`]).
    pub fn prepared(&self) -> &L::Prepared<T> {
        &self.prepared
    }

    /// The patch shape's friction constants (e², A, B, C, …), for every law.
    pub fn constants(&self) -> &Constants<T> {
        &self.constants
    }

    /// The friction law `L`'s coefficient and regularization speed.
    pub fn friction(&self) -> &Friction<T, L> {
        &self.friction
    }

    /// The largest stable step of an explicit `scheme` for the slip, for an effective `mass`
    /// (kg) at normal force `n` (N): [`Friction::stable_step`] with this contact's shape, the
    /// same call for every law. **`mass` is the effective mass at the contact point**: 2m/7
    /// for a solid ball of mass m rolling on its surface, not m (see
    /// [`Friction::stable_step`]). Host/construction use (for `Best` it evaluates
    /// [`ramp_stiffness`](crate::friction::best::ramp_stiffness)).
    ///
    /// ```
    /// use contensou::contact::Contact;
    /// use contensou::friction::{Explicit, Friction};
    /// use contensou::geometry::Curvatures;
    /// use contensou::normal::{Modulus, Undamped};
    /// use contensou::shape::Newton;
    ///
    /// // A steel ball, R = 10 mm, m = 32.7 g, on a plane: f = 0.1, δ = 1e-4 m/s, N = mg.
    /// let (r, m) = (10e-3, 32.67e-3);
    /// let contact = Contact::hertz::<Newton>(
    ///     &Curvatures::sphere_plane(r)?,
    ///     Modulus::new(1.1538e11)?,
    ///     Undamped,
    ///     Friction::<f64>::new(0.1, 1e-4)?,
    /// )?;
    /// let h_slip = contact.stable_step(2.0 * m / 7.0, m * 9.81, Explicit::Euler);
    /// let a = 2.75e-5; // the patch radius at that load (m)
    /// let h_spin = contact.stable_spin_step(a, 0.4 * m * r * r, m * 9.81, Explicit::Euler);
    /// assert!(h_slip > 1e-5 && h_slip < 3e-5 && h_spin > 1e-3);
    /// # Ok::<(), contensou::Error>(())
    /// ```
    pub fn stable_step(&self, mass: T, n: T, scheme: Explicit) -> T {
        self.friction.stable_step(&self.constants, mass, n, scheme)
    }

    /// The largest stable step of an explicit `scheme` for the contact's **normal mode**: an
    /// effective mass `mass` (kg, along the normal: 1/W_nn) resting at load `n` (N) oscillates
    /// at ω = √(k_n/m), k_n = dN/dh; the step is 2√2/ω for RK4, 0 for forward Euler (it grows
    /// every undamped oscillation; semi-implicit Euler: 2/ω). See
    /// [`crate::step::stable::normal_step`]; host/construction use (a `cbrt`). The smallest of
    /// this, [`Contact::stable_step`] and [`Contact::stable_spin_step`] bounds the plain path;
    /// the step-aware path ([`crate::step`]) has none of these limits.
    pub fn stable_normal_step(&self, mass: T, n: T, scheme: Explicit) -> T {
        crate::step::stable::normal_step(&self.normal, mass, n, scheme)
    }

    /// The largest stable step of an explicit `scheme` for the spin about the normal, for an
    /// effective moment of inertia `inertia` (kg·m², about the normal) at major semi-axis `a`
    /// (m) and normal force `n` (N): [`Friction::stable_spin_step`] with this contact's shape,
    /// the same call for every law. Host/construction use (for `Best` it evaluates
    /// [`spin_stiffness`](crate::friction::best::spin_stiffness), ≈ 26 µs).
    pub fn stable_spin_step(&self, a: T, inertia: T, n: T, scheme: Explicit) -> T {
        self.friction
            .stable_spin_step(&self.constants, a, inertia, n, scheme)
    }
}

/// A contact whose curvatures change every step: the eccentricity and every shape constant
/// come from [`shape::Table`] per step (fixed cost, no elliptic integral, no iteration).
///
/// Error: that of the table (relative ≤ 4e-7 in f32, ≤ 5e-12 in f64 on c, a, b, N; see
/// [`shape::Table`]) plus the friction law's own. Cost per step (f32, Cortex-M4F, undamped +
/// [`crate::friction::Simplified`]): `bench-results/qemu.csv`, stage `wrench`, method
/// `table_each_step`.
///
/// The friction law defaults to [`Best`], evaluated in its per-step form (nothing precomputed,
/// e² may change every call: the outside coefficients from one flash table with e²
/// interpolated, 34,944 bytes of `f32` table, no RAM; see [`crate::friction::best`]). Measured
/// (`f32`, Cortex-M4F, QEMU): **521** instructions per wrench on the `wrench` set (1.85× the
/// 281 of [`crate::friction::Simplified`]), 750 on the worst input of an input search (row
/// `wrench,table_each_step-best-worst`); friction within 4.7e-5 fN / 3.3e-6 fNa of the exact
/// integrals for every accepted shape (e² to 0.99998 at P/Q = 1e-4). `VaryingContact<f32, Undamped>` is 12 bytes. For a geometry given
/// as two bodies' principal curvatures and their relative angle every step, build the
/// [`Curvatures`] with [`Curvatures::from_bodies_cos_sin`] (no trigonometry, no `f64`: 723
/// instructions per step for both, row `wrench,table_each_step-best-from-bodies`).
///
/// # Example
///
/// A contact point wandering over a body of varying curvature: this step's [`Curvatures`] go
/// into the call, and this step's major axis into the frame (it turns by 90° where P and Q
/// cross; the world force does not jump, see [`crate::frame`]).
///
/// ```
/// use contensou::contact::VaryingContact;
/// use contensou::frame::{ContactFrame, Frame, MajorAxis};
/// use contensou::friction::Friction;
/// use contensou::geometry::Curvatures;
/// use contensou::normal::{Modulus, Undamped};
///
/// let contact = VaryingContact::new(Modulus::new(1.15e11)?, Undamped, Friction::<f64>::new(0.1, 1e-4)?);
/// let (v_rel, w_rel) = ([0.02, 0.01, 0.0], [0.0, 0.0, 30.0]); // world, B relative to A at P
/// let mut previous: Option<[f64; 3]> = None;
/// for step in 0..5 {
///     // Curvature along the world x changes from 40 to 60 1/m; across it stays 50 1/m.
///     let curv = Curvatures::new(40.0 + 5.0 * step as f64, 50.0)?;
///     let frame = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::of(&curv));
///     let w = contact.wrench(&curv, 1e-6, 0.0, frame.slip(v_rel, w_rel)?);
///     let force = frame.force(&w);
///     if let Some(f) = previous {
///         assert!((force[0] - f[0]).abs() < 0.05 * w.n); // no jump at P = Q (step 2)
///     }
///     previous = Some(force);
/// }
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VaryingContact<T, D, L = Best> {
    estar: Modulus<T>,
    damping: D,
    friction: Friction<T, L>,
}

impl<T: Real, D: Damping<T>, L: FrictionLaw> VaryingContact<T, D, L> {
    /// From the effective modulus, a damping law and a friction law. Total (the parts are
    /// validated types).
    pub fn new(estar: Modulus<T>, damping: D, friction: Friction<T, L>) -> Self {
        VaryingContact {
            estar,
            damping,
            friction,
        }
    }

    /// E*, the damping law and the friction law (for the batch kernels, src/batch/).
    #[inline(always)]
    pub(crate) fn parts(&self) -> (Modulus<T>, &D, &Friction<T, L>) {
        (self.estar, &self.damping, &self.friction)
    }

    /// One step at this step's curvatures. P/Q below the table's range (1e-4) is clamped to
    /// it. Total. h, ḣ (> 0: compression) and the slip as in [`Contact::wrench`]; the contact
    /// frame's x is this step's major axis ([`crate::frame::MajorAxis::of`] these curvatures).
    #[inline]
    pub fn wrench(
        &self,
        curvatures: &Curvatures<T>,
        h: T,
        hdot: T,
        slip: Slip<T>,
    ) -> Wrench<T, L::Branch> {
        let shape = shape::Table::shape(Ratio::clamped(curvatures.ratio()));
        let normal = Hertz::from_shape(curvatures, &shape, self.estar);
        let constants = Constants::from_shape(&shape);
        let patch = normal.damped_patch(h, hdot, &self.damping);
        let core = PerCall(&constants);
        let clamp = !<Hertz<T> as NormalLaw<T>>::NON_NEGATIVE;
        let t = self
            .friction
            .tangential_with(core, clamp, patch.a, patch.n, slip);
        wrench_of(patch, t)
    }
}
