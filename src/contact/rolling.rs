//! The per-step wrench of a rolling contact: the contact's normal law and patch, the tangential
//! part by a rolling law ([`crate::friction::rolling`]) from the slip and the rolling velocity.
//!
//! # Conventions
//!
//! As the crate's ([`crate::guide`]): the contact frame has x along the major axis, y along
//! the minor axis, z the normal from A into B; the slip (v_x, v_y, ω) is body B's velocity
//! relative to A at the patch centre and their relative spin about z; the wrench is on B from
//! A. The rolling velocity V ([`RollingVelocity`]) is the velocity of the contact point over
//! both surfaces, relative to their material, averaged (a wheel rolling forward along +x: V
//! along +x, material flows through the patch towards −x). Creepages are (v_x, v_y, ω)/|V| in
//! the rolling frame, Kalker's signs ([`crate::friction::rolling`]).
//!
//! # Formula
//!
//! Per step: the patch (a ≥ b along the contact frame's x, y; N) from the contact's normal law
//! as in [`Contact::wrench`]; V = (V_x, V_y) sets the **rolling frame**: x_r along V,
//! (c_θ, s_θ) = V/|V| (θ = 0 when V = 0), y_r = z × x_r. In that frame the slip is
//! (c_θ v_x + s_θ v_y, −s_θ v_x + c_θ v_y, ω), the rolling speed |V| ≥ 0, and the rolling law
//! `L` evaluates Kalker's creepages on the **aligned ellipse**
//! ([`crate::friction::rolling::aligned_ellipse`]): semi-axis a_r = ab/√(b²c_θ² + a²s_θ²)
//! along V (the patch's extent in that direction), b_r = ab/a_r across (same area, same
//! c = √(ab)), with the creep shape of a_r/b_r (`blend`'s constants, `table`'s residuals:
//! [`RollingShape`]) and the **patch's own linear theory**: the aligned ellipse's exact
//! coefficients turned into the skewed patch's creep matrix, its diagonal and the couplings
//! K₁₂, K₁₃ ([`crate::friction::rolling::skew_linear`]). The **full-slip part** the law saturates to is the
//! contact's own `best` (δ = 0) on the **real** patch, in the direction of the slip, turned into
//! the rolling frame. The law's (F_x, F_y) are turned back: F = (c_θF_xr − s_θF_yr,
//! s_θF_xr + c_θF_yr); T_z = M_z.
//!
//! # Domain and special cases
//!
//! Every validated input; total (no panic, finite output).
//!
//! - **V along an axis** (V_y = 0 or V_x = 0; every direction for a circle) of a fixed
//!   contact: the aligned ellipse is the patch, the rolling law's own domain, with the creep
//!   shapes of both axes cached at construction: the rolling law's error only
//!   (`RollingContact` on the patch: within 8.7e-16 fN along +x, 1.5e-7 along the other
//!   directions, `host-tests/rolling_wrench.rs`).
//! - **V skewed** (and every step of a varying contact): the creep shape of a_r/b_r per call,
//!   its linear part the patch's own creep matrix: a fixed contact's from one path in ln(a_r/b_r)
//!   of the matrix's entries ([`crate::friction::rolling::skew_linear`]), a varying one's from
//!   its [`ShapePath`] and skew ratios ([`crate::friction::rolling::SkewGrid`]). The linear
//!   limit is the exact reference's table, within its error (K₃₃ 4.7 %, K₁₃ 4.3 %, the rest
//!   ≤ 2 %; the grid's bilinear K₃₃ 6.9 %); a fixed contact within 3.1e-4 fN / fNc of the `f64`
//!   build ([`Rolling::wrench_aligned`], the table's cubic Hermite) at P/Q ≥ 0.025, 7.4e-3 at
//!   P/Q = 0.0025 (a patch 40 times longer than wide; 6e-3 and 0.031 while the skew ratios were
//!   linear in t between 17 nodes). The rest of the aligned ellipse is the approximation (the
//!   laws' nonlinear data are for rolling along an axis): exact along both axes, continuous in
//!   θ. Measured against the exact theory on the skewed patch
//!   (`tools/data/rolling_ref_heldout.csv`, `python3 tools/rolling_heldout.py`,
//!   `bench-results/rolling-heldout.md`): with `table`, 330 random skewed states, worst
//!   0.106 fN / 0.098 fNc for patches with b/a ≥ 0.2 and 0.147 / 0.334 for b/a < 0.2 (0.194 /
//!   0.196 and 0.433 / 0.952 with the aligned-ellipse rule's diagonal alone; FASTSIM 32 × 32
//!   with the same coefficients: 0.243 / 0.162 and 0.281 / 1.002). The full slip stays exact
//!   (the real patch's).
//! - **V = 0** (and creepage → ∞): the full slip of `best` on the real patch, in every
//!   direction (`table`, `blend`: within 6.4e-16 fN of [`Contact::wrench`] with δ = 0; FASTSIM:
//!   its grid's full slip on the patch, 4.8e-2 fN on 16 × 16 at a/b ≈ 4.3).
//! - V < 0 along x is the half-turn of the rolling frame (not `RollingSlip`'s mirror; the
//!   two agree within 1.5e-7 fN, `best`'s own mirror symmetry).
//! - h ≤ 0 (apart), N ≤ 0, f = 0: zero tangential wrench. The contact's δ is not used.
//! - a_r/b_r outside [0.01, 100]: the shape of the nearer end.
//!
//! # Example
//!
//! ```
//! use contensou::contact::{Contact, Rolling};
//! use contensou::friction::rolling::{Elasticity, RollingVelocity, Table};
//! use contensou::friction::{Friction, Slip};
//! use contensou::geometry::Curvatures;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::shape::Newton;
//!
//! // A steel ball (R = 10 mm) in a groove (Q > P), f = 0.1.
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::new(25.0, 100.0)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::new(0.1_f64, 0.0)?,
//! )?;
//! let rolling = Rolling::<_, _, Table>::new(contact, Elasticity::new(80e9, 0.3)?)?;
//! // rolling along the minor axis at 2 m/s with 0.1 % creepage along it
//! let v = RollingVelocity::new(0.0, 2.0)?;
//! let w = rolling.wrench(1e-6, 0.0, Slip::new(0.0, 2e-3, 0.0)?, v);
//! assert!(w.n > 0.0 && w.fy < 0.0 && w.fy.abs() < 0.1 * w.n);
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Cost
//!
//! Cortex-M4F, `f32`, `table`, 64 creep states (`bench-results/qemu.csv`, stage `rolling`):
//! fixed contact, V along an axis **1,167** instructions (1,187 with libm's `logf` for the law's
//! ln m and before the look-up trims below; 1,181 before each residual channel's own order between the direction families, 1,179 with five table shapes) (`RollingContact::wrench` alone: 1,020; 1,037 with `logf`);
//! V skewed **1,500** (1,593 before the hot-path `ln` ([`crate::real::ln_f32_hot`]) for ln m
//! and ln q — the two take 54 instructions where libm's `logf` took 93, 39 saved — and the
//! creep shape's look-up trims — the Hermite path's reads without zero fallbacks, the path and
//! √q clamped together, the shapes' search on |x|, two redundant clamps: 54 saved, measured
//! together (`tools/profile_row.py`); 1,587 before the channel orders, 1,585 with five table shapes, 1,708 with twelve curve views built per call, 1,809 with per-call shared-grid checks and `f32` nodes; the creep shape per call: one `ln`, the creep matrix from one Hermite
//! segment of its path, `blend`'s constants, and `table`'s curves built per call with no grid
//! stored, each look-up computing the one it reads — ≈ 330 to build them and ≈ 135 more in the
//! law than on a cached shape; 2,282 with the ln-coefficients' path, a bisection and five
//! `exp`, and the skew ratios apart; 5,025 while every curve's grid and tails were built per
//! call: 24 `exp`); varying contact **1,990** (2,094 before the hot-path `ln` and the look-up trims, 2,088 before the channel orders, 2,080 with five table shapes, 2,192 with twelve curve views built per call, 2,292 with per-call shared-grid checks and `f32` nodes; 2,766 with the ln-coefficients' path; 5,301).
//! Host (x86-64, criterion's fastest sample, per call, `bench-results/host-ns.csv`): 176 ns,
//! 240 ns, 311 ns (`RollingContact` 148 ns in the same run; 220, 299, 428 and 164 ns in the run
//! before these changes, on another day's load — `blend` and `full-slip`, unchanged, were 21 %
//! and 11 % slower there too; 377 ns, 1.26 µs, 1.55 µs and 338 ns
//! by the mean before the curves read their nodes from flash and before the per-call curves). Per contact: two [`RollingShape`]s (264 bytes each in `f32` on x86-64; 528 while the tables held a view per curve) and the path of the
//! skewed creep matrix (216 numbers) (fixed), a [`ShapePath`] (292 numbers) and a `SkewGrid`
//! (378 numbers) (varying).
//!
//! # References
//!
//! Kalker, *Three-dimensional elastic bodies in rolling contact* (1990): the theory the laws
//! approximate, for rolling along a semi-axis.

use core::marker::PhantomData;

use super::{Contact, VaryingContact, Wrench};
use crate::friction::rolling::{
    Creep, CreepMatrix, Elasticity, Input, RollingLaw, RollingShape, RollingSlip, RollingVelocity,
    ShapePath, SkewGrid, aligned_ellipse,
    skew::aligned_ratio,
    skew_linear::{SkewPath, skewed},
};
use crate::friction::{Best, Constants, Explicit, FrictionLaw, Slip, SlipState};
use crate::geometry::Curvatures;
use crate::normal::{Damping, Hertz, NormalLaw, Patch};
use crate::shape::{self, Eccentricity, Ratio};
use crate::{Error, Real};

/// A contact the rolling laws drive ([`Contact`] or [`VaryingContact`] with [`Best`]): what
/// [`Rolling`] keeps besides it.
pub trait RollingBase<T: Real> {
    /// The per-contact creep shapes (fixed contact: rolling along x and along y; varying: none).
    type Cache: Clone + Copy + core::fmt::Debug + PartialEq;
    /// Builds the cache for these elastic constants.
    fn cache(&self, elasticity: &Elasticity<T>) -> Self::Cache;
}

/// A fixed contact's creep shapes: rolling along x (a/b) and along y (b/a), and the path
/// of the patch's creep matrix between them for a skewed rolling velocity
/// ([`crate::friction::rolling::skew_linear`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedShapes<T> {
    pub(crate) axes: [RollingShape<T>; 2],
    pub(crate) skew: SkewPath<T>,
}

/// A varying contact's creep shapes: the path over every aligned ratio and the skew ratios of
/// every patch ratio ([`SkewGrid`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VaryingShapes<T> {
    pub(crate) path: ShapePath<T>,
    pub(crate) skew: SkewGrid<T>,
}

impl<T: Real, N, D> RollingBase<T> for Contact<T, N, D, Best> {
    type Cache = FixedShapes<T>;
    /// The creep shapes for rolling along x (a/b) and along y (b/a) (one for a circle), and
    /// the path of the patch's creep matrix between them.
    fn cache(&self, elasticity: &Elasticity<T>) -> Self::Cache {
        let m1 = self.constants.m1();
        // a/b = 1/√m₁
        let r = T::ONE / m1.sqrt();
        let along_x = RollingShape::new(r, elasticity.nu());
        let along_y = if m1 == T::ONE {
            along_x
        } else {
            RollingShape::new(T::ONE / r, elasticity.nu())
        };
        // the library frame: x the major axis (a ≥ b)
        let major = if r >= T::ONE { r } else { T::ONE / r };
        FixedShapes {
            axes: [along_x, along_y],
            skew: SkewPath::new(major, elasticity.nu()),
        }
    }
}

impl<T: Real, D> RollingBase<T> for VaryingContact<T, D, Best> {
    type Cache = VaryingShapes<T>;
    /// The path over every aligned ratio ([`ShapePath`]) and the skew ratios ([`SkewGrid`]).
    fn cache(&self, elasticity: &Elasticity<T>) -> Self::Cache {
        VaryingShapes {
            path: ShapePath::new(
                T::from_f64(-libm::log(100.0)),
                T::from_f64(libm::log(100.0)),
                elasticity.nu(),
            ),
            skew: SkewGrid::new(elasticity.nu()),
        }
    }
}

/// A rolling contact at the wrench level: a contact `C` ([`Contact`] or [`VaryingContact`],
/// friction [`Best`]), the pair's [`Elasticity`] and the rolling law `L` (see the
/// [module docs](self)).
pub struct Rolling<T: Real, C: RollingBase<T>, L> {
    pub(crate) contact: C,
    pub(crate) elasticity: Elasticity<T>,
    pub(crate) cache: C::Cache,
    law: PhantomData<L>,
}

// By hand: the law `L` is a marker (no `Clone`/`PartialEq` bound on it).
impl<T: Real, C: RollingBase<T> + Clone, L> Clone for Rolling<T, C, L> {
    fn clone(&self) -> Self {
        Self {
            contact: self.contact.clone(),
            elasticity: self.elasticity,
            cache: self.cache,
            law: PhantomData,
        }
    }
}

impl<T: Real, C: RollingBase<T> + Copy, L> Copy for Rolling<T, C, L> {}

impl<T: Real, C: RollingBase<T> + PartialEq, L> PartialEq for Rolling<T, C, L> {
    fn eq(&self, other: &Self) -> bool {
        self.contact == other.contact
            && self.elasticity == other.elasticity
            && self.cache == other.cache
    }
}

impl<T: Real, C: RollingBase<T> + core::fmt::Debug, L> core::fmt::Debug for Rolling<T, C, L> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Rolling")
            .field("contact", &self.contact)
            .field("elasticity", &self.elasticity)
            .field("law", &core::any::type_name::<L>())
            .finish_non_exhaustive()
    }
}

impl<T: Real, C: RollingBase<T>, L: RollingLaw> Rolling<T, C, L> {
    /// From a contact ([`Contact`] or [`VaryingContact`], friction [`Best`]; its δ is not
    /// used) and the pair's elastic constants. A fixed contact builds the creep shapes for
    /// rolling along x (a/b) and along y (b/a) once (one for a circle); a varying one builds
    /// nothing. Errors: none today (the `Result` is the contract's: a future shape check).
    pub fn new(contact: C, elasticity: Elasticity<T>) -> Result<Self, Error> {
        Ok(Self {
            cache: contact.cache(&elasticity),
            contact,
            elasticity,
            law: PhantomData,
        })
    }

    /// The contact (normal law, damping, friction coefficient, `best`'s tables).
    pub fn contact(&self) -> &C {
        &self.contact
    }

    /// The pair's elastic constants.
    pub fn elasticity(&self) -> &Elasticity<T> {
        &self.elasticity
    }
}

/// The rolling frame of a rolling velocity: (cos θ, sin θ) of V and |V|; V = 0: θ = 0.
#[inline(always)]
pub(crate) fn direction<T: Real>(v: RollingVelocity<T>) -> (T, T, T) {
    let m = v.vx.abs().max(v.vy.abs());
    if m <= T::ZERO {
        return (T::ONE, T::ZERO, T::ZERO);
    }
    let (ux, uy) = (v.vx / m, v.vy / m);
    let n = (ux * ux + uy * uy).sqrt();
    (ux / n, uy / n, m * n)
}

/// Where the creep shape of a step comes from.
#[derive(Clone, Copy)]
pub(crate) enum Shapes<'a, T> {
    /// Cached and exact (rolling along an axis, or a circle).
    One(&'a RollingShape<T>),
    /// A fixed contact's skewed V: the patch's creep matrix from its path ([`SkewPath`]) and
    /// the aligned ellipse's per-shape data, per call.
    Skewed(&'a SkewPath<T>),
    /// A varying contact: the aligned ellipse's shape from the contact's path
    /// ([`ShapePath::shape`]) turned into the patch's by its skew ratios ([`SkewGrid`],
    /// [`crate::friction::rolling::skew_linear`]), per call.
    Path(&'a ShapePath<T>, &'a SkewGrid<T>),
    /// The aligned ellipse's own shape, built per call in `f64` ([`RollingShape::new`]).
    Build,
}

/// What one step needs besides the creep shape: the patch, f, E*-free parts.
pub(crate) struct Step<T> {
    patch: Patch<T>,
    /// fN (N), 0 without contact
    fn_: T,
}

impl<T: Real, N: NormalLaw<T>, D: Damping<T>, L: RollingLaw> Rolling<T, Contact<T, N, D, Best>, L> {
    /// The largest stable step of an explicit `scheme` for the **creep** at load `n` (N) and
    /// rolling velocity `v`, for an effective tangential mass `mass` (kg, 1/W_xx): Kalker's
    /// linear creep is a damper of rate G·c²·C/(|V|·m) (C = max(C₁₁, C₂₂) of the aligned
    /// ellipse along V); see [`crate::step::stable::creep_step`]. Host/construction use. The
    /// plain path must also respect [`Contact::stable_normal_step`]; the step-aware path
    /// ([`crate::step`]) has neither limit.
    pub fn stable_creep_step(&self, mass: T, n: T, v: RollingVelocity<T>, scheme: Explicit) -> T {
        let c = &self.contact;
        let patch = c.normal.patch(c.normal.approach(n));
        let (cx, sx, speed) = direction(v);
        let (a, b) = (patch.a, patch.b);
        // the aligned ellipse: a_r = ab/√(b²c² + a²s²) along V, b_r = ab/a_r across
        let a_r = a * b / (b * b * cx * cx + a * a * sx * sx).sqrt();
        let b_r = if a_r > T::ZERO { a * b / a_r } else { T::ZERO };
        crate::step::stable::creep_step(&self.elasticity, a_r, b_r, speed, mass, scheme)
    }

    /// One step: approach h (m), its rate ḣ (m/s, > 0 compression), the slip of B relative to
    /// A and the rolling velocity, both in the contact frame → the wrench on B from A (contact
    /// frame, x the major axis). Total.
    ///
    /// The creep shape: cached along the axes (and for a circle); for a skewed V from the
    /// contact's [`ShapePath`] per call (see the module docs; [`Rolling::wrench_aligned`]
    /// builds it in `f64` instead).
    #[inline]
    pub fn wrench(&self, h: T, hdot: T, slip: Slip<T>, v: RollingVelocity<T>) -> Wrench<T, ()> {
        self.fixed(h, hdot, slip, v, Shapes::Skewed(&self.cache.skew))
    }

    /// [`Rolling::wrench`] with the aligned ellipse's creep shape built per call in `f64`
    /// ([`RollingShape::new`]) for a skewed V (≈ 5 µs on a host, ≈ 3e5 M4F instructions): the
    /// reference [`ShapePath`] is measured against.
    pub fn wrench_aligned(
        &self,
        h: T,
        hdot: T,
        slip: Slip<T>,
        v: RollingVelocity<T>,
    ) -> Wrench<T, ()> {
        self.fixed(h, hdot, slip, v, Shapes::Build)
    }

    /// The fixed contact's step: the cached shape along an axis (or for a circle), else
    /// `skewed`.
    #[inline(always)]
    fn fixed(
        &self,
        h: T,
        hdot: T,
        slip: Slip<T>,
        v: RollingVelocity<T>,
        skewed: Shapes<'_, T>,
    ) -> Wrench<T, ()> {
        let frame = direction(v);
        let (cx, sx, _) = frame;
        let [along_x, along_y] = &self.cache.axes;
        let shapes = if sx == T::ZERO || along_x.rho == T::ONE {
            Shapes::One(along_x)
        } else if cx == T::ZERO {
            Shapes::One(along_y)
        } else {
            skewed
        };
        let c = &self.contact;
        let patch = c.normal.damped_patch(h, hdot, &c.damping);
        let step = Step::of(patch, c.friction.coefficient());
        let prepared = &c.prepared;
        let full_slip = |st: &SlipState<T>| Best::traction_prepared(prepared, st).0;
        tangential::<T, L>(&step, shapes, self.elasticity, frame, slip, full_slip)
    }
}

impl<T: Real, D: Damping<T>, L: RollingLaw> Rolling<T, VaryingContact<T, D, Best>, L> {
    /// One step at this step's curvatures (as [`VaryingContact::wrench`]) with the rolling
    /// velocity (contact frame: x this step's major axis). The creep shape is built per call.
    /// Total.
    #[inline]
    pub fn wrench(
        &self,
        curvatures: &Curvatures<T>,
        h: T,
        hdot: T,
        slip: Slip<T>,
        v: RollingVelocity<T>,
    ) -> Wrench<T, ()> {
        let (estar, damping, friction) = self.contact.parts();
        let shape = shape::Table::shape(Ratio::clamped(curvatures.ratio()));
        let normal = Hertz::from_shape(curvatures, &shape, estar);
        let constants = Constants::from_shape(&shape);
        let patch = normal.damped_patch(h, hdot, damping);
        let step = Step::of(patch, friction.coefficient());
        let full_slip = |st: &SlipState<T>| Best::traction(&constants, st).0;
        let frame = direction(v);
        let shapes = Shapes::Path(&self.cache.path, &self.cache.skew);
        tangential::<T, L>(&step, shapes, self.elasticity, frame, slip, full_slip)
    }
}

impl<T: Real> Step<T> {
    #[inline(always)]
    pub(crate) fn of(patch: Patch<T>, f: T) -> Self {
        let fn_ = if patch.n > T::ZERO && patch.a > T::ZERO && patch.b > T::ZERO {
            f * patch.n
        } else {
            T::ZERO
        };
        Step { patch, fn_ }
    }
}

/// The tangential part (see the module docs): the rolling frame, the creep shape (cached or
/// built), the full slip on the real patch, the law, back to the contact frame.
#[inline(always)]
pub(crate) fn tangential<T: Real, L: RollingLaw>(
    step: &Step<T>,
    shapes: Shapes<'_, T>,
    elasticity: Elasticity<T>,
    (cx, sx, speed): (T, T, T),
    slip: Slip<T>,
    full_slip: impl Fn(&SlipState<T>) -> crate::friction::Traction<T>,
) -> Wrench<T, ()> {
    let patch = step.patch;
    let zero = Wrench {
        n: patch.n,
        fx: T::ZERO,
        fy: T::ZERO,
        tz: T::ZERO,
        patch,
        branch: (),
    };
    if step.fn_ <= T::ZERO {
        return zero;
    }
    let (a, b) = (patch.a, patch.b);
    let c = (a * b).sqrt();
    // the slip in the rolling frame, homogeneous form (V ≥ 0: no mirror)
    let rs = RollingSlip {
        vx: cx * slip.vx() + sx * slip.vy(),
        vy: cx * slip.vy() - sx * slip.vx(),
        omega: slip.omega(),
        v: speed,
    };
    let s = rs.scaled(c);
    let w = c * s.omega;
    let fs = if L::FULL_SLIP {
        // full slip on the real patch: the slip direction back in the contact frame
        let (lx, ly) = (cx * s.vx - sx * s.vy, sx * s.vx + cx * s.vy);
        let major_over_c = (a / b).sqrt();
        let st = SlipState::from_slip(Slip::or_rest(lx, ly, w), major_over_c, T::ZERO);
        let t = full_slip(&st);
        Creep {
            fx: cx * t.fx + sx * t.fy,
            fy: cx * t.fy - sx * t.fx,
            mz: t.tz * major_over_c,
        }
    } else {
        Creep::default()
    };
    let kappa = elasticity.g() * c * c / step.fn_;
    let input = |contact| Input {
        contact,
        kappa: crate::friction::rolling::contact::load_parameter(kappa),
        vx: s.vx,
        vy: s.vy,
        w,
        v: s.v,
        full_slip: fs,
    };
    let cr = match shapes {
        Shapes::One(shape) => L::creep(&input(shape)),
        Shapes::Skewed(path) => {
            let q = aligned_ratio(a, b, cx, sx);
            L::creep(&input(&path.shape_at(q, q.ln_hot(), cx, sx)))
        }
        Shapes::Path(path, grid) => {
            let q = aligned_ratio(a, b, cx, sx);
            let ln_q = q.ln_hot();
            // the aligned ellipse's shape, its coefficients turned into the patch's in place
            // (a new RollingShape would copy its tables)
            let mut shape = path.shape_at(q, ln_q);
            let ratios = grid.at((a / b).ln_hot(), ln_q);
            (shape.kalker, shape.coupling) = skewed(&shape.kalker, ratios, cx, sx);
            L::creep(&input(&shape))
        }
        Shapes::Build => {
            let (ar, br) = aligned_ellipse(a, b, cx, sx);
            let nu = elasticity.nu();
            let k = CreepMatrix::new(a, b, cx, sx, nu).k;
            let [[c11, k12, k13], [_, c22, c23], [_, _, c33]] = k;
            L::creep(&input(&RollingShape {
                kalker: crate::friction::rolling::Kalker { c11, c22, c23, c33 },
                coupling: (k12, k13),
                ..RollingShape::new(ar / br, nu)
            }))
        }
    };
    let (fx, fy) = (cr.fx * step.fn_, cr.fy * step.fn_);
    Wrench {
        fx: cx * fx - sx * fy,
        fy: sx * fx + cx * fy,
        tz: cr.mz * step.fn_ * c,
        ..zero
    }
}
