//! A deep-groove ball bearing (the paper's §5 second scene): the inner ring driven at constant
//! angular velocity and free to translate under a radial (and optional axial) load, the outer
//! ring fixed, [`BALLS`] balls as free rigid spheres in Hertz + friction contact with both
//! raceways. No cage: the balls start equally spaced at the rolling speed and are not checked
//! for ball–ball contact (the example reports the smallest angular spacing). No gravity.
//!
//! # Model
//!
//! - World frame: the bearing axis along z, the outer ring's centre at the origin.
//! - Raceways: tori. A race of groove radius r_g has its groove centre circle at radius
//!   ρ_c = (d_m − D)/2 + r_g (inner, about the inner ring's centre) or (d_m + D)/2 − r_g
//!   (outer), zero clearance. For a ball centre at distance d from that circle in the meridian
//!   plane, the approach is h = d + D/2 − r_g; the unit vector u from the groove centre to the
//!   ball centre gives the contact normal z = −u (from the ring, body A, into the ball, body B)
//!   and the patch centre P = ball centre + (D/2)u.
//! - Contact frame ([`crate::frame`]): reference tangent t₁ the circumferential (rolling)
//!   direction, the race's first principal direction in [`Curvatures::ball_race`]; the major
//!   axis at [`Curvatures::major_angle`] from it (π/2, x = z × t₁ across the groove, when the
//!   groove conforms closely). The curvatures — hence e² and the friction constants — are those
//!   of the nominal contact angle 0, fixed per race (the contact angle that a load develops in
//!   a zero-clearance bearing is a few degrees).
//! - Race laws ([`RaceLaw`]): any contact [`crate::select`] builds — a full-slip
//!   [`Contact`] (the rolling velocity ignored) or, with the motion [`crate::select::Rolls`],
//!   [`crate::contact::Rolling`] over `best` with the default rolling law `table` (the creep
//!   forces and spin moment from the elasticity; needs RK4 steps ≤ 0.1 µs at the 209's loads:
//!   the creep law is a stiff damper, G c² C₁₁/V ≈ 2.2e4 N·s/m at the inner race at 900 N).
//! - Slip: ball minus ring material velocity at P; spin: (ω_ball − ω_ring)·z.
//! - Rolling velocity ([`RaceContact::rolling`], the input of a rolling law): the velocity at
//!   which the contact point moves over both surfaces relative to their material, averaged,
//!   V = v_P − ½(u_A + u_B), tangential components in the contact frame. u_A = v_r + ω_r ẑ ×
//!   (P − c) is the ring's material velocity at P, u_B = v + ω × (r_b u) the ball's. v_P is the
//!   velocity of the geometric contact point P = p + r_b u: the torus is symmetric about the
//!   ring's axis, so P does not move with the ring's rotation, only with the ball's centre
//!   relative to the ring centre, r = p − c, ṙ = v − v_r. With ρ, e_ρ, e_θ the cylindrical
//!   radius and unit vectors of r, g = (ρ − ρ_c)e_ρ + r_z ẑ and u = g/d, d = |g|:
//!   ġ = ṙ − (ρ_c/ρ)(e_θ·ṙ)e_θ (the meridian components of ṙ move g one to one, the
//!   circumferential one turns e_ρ and moves g by (ρ − ρ_c)/ρ of it), u̇ = (ġ − u(u·ġ))/d
//!   (e_θ ⟂ u, so u·ġ = u·ṙ) and v_P = v + r_b u̇. Examples (tested): pure rolling at the
//!   cage speed ω_c, contact angle 0 — outer race V = ω_c(d_m/2 + r_b) along +e_θ, inner race
//!   V = −(ω_i − ω_c)(d_m/2 − r_b) along e_θ (the contact point runs backwards over the faster
//!   inner ring); a ball pivoting in place about the normal: V = 0. P is the ball's surface
//!   point (the slip's point too); the mid-point of the overlap would change V by O(h/r_b).
//! - State ([`N`] scalars): inner ring centre and velocity (6), then per ball centre, velocity
//!   and angular velocity (9; a sphere's attitude does not enter).

use super::integrate::Ode;
use super::rigid::{Quat, Vec3};
use super::step_aware::{Candidate, InvInertia, Site, StepContact, Warm, rigid_w, solve_library};
use crate::contact::{Contact, Rolling, VaryingContact};
use crate::frame::{ContactFrame, Frame, MajorAxis, point_velocity};
use crate::friction::Best;
use crate::friction::rolling::RollingLaw;
use crate::friction::rolling::RollingVelocity;
use crate::geometry::{Curvatures, Race};
use crate::jacobian::State as StepState;
use crate::jacobian::{Jacobian, LinearDamping, LinearLaw, LinearNormal, Linearize};
use crate::select::StepRolling;
use crate::step::Scheme;
use crate::{Error, Real};

/// Number of balls (the 209 bearing has 9).
pub const BALLS: usize = 9;
/// Number of scalars in the state: inner ring (6) + 9 per ball.
pub const N: usize = 6 + 9 * BALLS;
/// The state (see the [module docs](self)).
pub type State<T> = [T; N];

/// The bearing's geometry, loads and masses (SI).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry<T> {
    /// Ball diameter D (m).
    pub ball_diameter: T,
    /// Inner groove radius (m).
    pub inner_groove: T,
    /// Outer groove radius (m).
    pub outer_groove: T,
    /// Pitch diameter d_m (m).
    pub pitch_diameter: T,
    /// Ball mass (kg).
    pub ball_mass: T,
    /// Inner ring (+ shaft) mass (kg).
    pub ring_mass: T,
    /// Inner ring angular velocity ω_i about +z (rad/s).
    pub omega_inner: T,
    /// Radial load on the inner ring along −y (N).
    pub radial_load: T,
    /// Axial load on the inner ring along +z (N).
    pub axial_load: T,
    /// The loads ramp up linearly over this time (s) (> 0).
    pub ramp: T,
}

impl<T: Real> Geometry<T> {
    /// The 209 deep-groove bearing: D = 12.7 mm, groove radii 6.6 mm (0.52 D), d_m = 65 mm,
    /// steel balls (7,800 kg/m³, 8.4 g), inner ring + shaft 0.5 kg; ω_i = 200 rad/s,
    /// 2,000 N radial and 200 N axial over a 5 ms ramp.
    pub fn bearing_209() -> Self {
        let c = T::from_f64;
        let d = 12.7e-3;
        Geometry {
            ball_diameter: c(d),
            inner_groove: c(6.6e-3),
            outer_groove: c(6.6e-3),
            pitch_diameter: c(65e-3),
            ball_mass: c(7800.0 * core::f64::consts::PI / 6.0 * d * d * d),
            ring_mass: c(0.5),
            omega_inner: c(200.0),
            radial_load: c(2000.0),
            axial_load: c(200.0),
            ramp: c(5e-3),
        }
    }

    /// The 209 bearing with a shallow inner groove (13.18 mm = 1.04 D) such that the inner
    /// race contact has P/Q = 0.4172, i.e. the paper's e² = 0.687 (exact Hertz); outer groove
    /// 6.6 mm as in the 209.
    pub fn paper_e2() -> Self {
        let d: f64 = 12.7e-3;
        let dm: f64 = 65e-3;
        // P/Q = (2/D − 1/r_g)/(2/D + 2/(d_m − D)) = 0.41721.
        let q = 2.0 / d + 2.0 / (dm - d);
        let rg = 1.0 / (2.0 / d - 0.41721 * q);
        Geometry {
            inner_groove: T::from_f64(rg),
            ..Self::bearing_209()
        }
    }

    /// The curvatures of one race at contact angle 0.
    ///
    /// Errors: those of [`Curvatures::ball_race`].
    pub fn curvatures(&self, race: Race) -> Result<Curvatures<T>, Error> {
        let rg = match race {
            Race::Inner => self.inner_groove,
            Race::Outer => self.outer_groove,
        };
        Curvatures::ball_race(self.ball_diameter, rg, self.pitch_diameter, T::ZERO, race)
    }

    /// Kinematic cage speed ω_c = (ω_i/2)(1 − D/d_m) (contact angle 0, fixed outer ring).
    pub fn cage_speed(&self) -> T {
        self.omega_inner * T::HALF * (T::ONE - self.ball_diameter / self.pitch_diameter)
    }
}

/// One race with its contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Raceway<T, C> {
    /// Radius of the groove centre circle (m).
    centre_radius: T,
    groove: T,
    /// The major axis, from the rolling direction.
    axis: MajorAxis<T>,
    /// The curvatures at contact angle 0.
    curvatures: Curvatures<T>,
    contact: C,
}

/// One ball–race contact at a state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RaceContact<T> {
    /// Approach h (m), ≤ 0 when apart.
    pub h: T,
    /// Normal force (N).
    pub n: T,
    /// e² of the patch.
    pub e2: T,
    /// Friction force along the major axis x (N): across the groove when it conforms closely.
    pub fx: T,
    /// Friction force along the minor axis y (N): then along the rolling direction.
    pub fy: T,
    /// Drilling torque (N·m).
    pub tz: T,
    /// Slip (v_x, v_y) of the ball relative to the ring at P in the contact frame (m/s).
    pub slip: [T; 2],
    /// Relative spin (ω_ball − ω_ring)·z (rad/s).
    pub spin: T,
    /// Relative rolling speed |ω_ball − ω_ring| in the contact plane (rad/s).
    pub roll: T,
    /// Rolling velocity V = v_P − ½(u_A + u_B) in the contact frame (x = major axis) (m/s):
    /// see the [module docs](self).
    pub rolling: [T; 2],
    /// Torque about the bearing axis through the ring's centre on the ring from this contact
    /// (N·m): the friction forces' moment plus the drilling torque's axial part.
    pub ring_torque: T,
    /// The drilling torque's part of [`RaceContact::ring_torque`], −ẑ·(T_z z) (N·m): the rest
    /// is the friction forces' moment.
    pub ring_torque_spin: T,
    /// Force on the ball, world frame (N).
    pub force: Vec3<T>,
    /// Torque on the ball about its centre, world frame (N·m).
    pub torque: Vec3<T>,
}

/// A per-step contact law for the races: any contact [`crate::select`] builds, through
/// [`StepRolling`] — [`Contact`] with any normal law (exact Hertz, the G* shape, the volumetric
/// law), damping and friction law but the reference `Exact` (full slip: the rolling velocity
/// is ignored), or [`crate::contact::Rolling`] over `best` (what [`crate::select::Rolls`]
/// resolves to: the rolling velocity drives the creep law), fixed or varying. The race's
/// curvatures at contact angle 0 are passed every step (read by a varying contact only).
pub trait RaceLaw<T: Real>: StepRolling<T> {
    /// The wrench and its Jacobian at `s` and the curvatures `curv` (read by a varying
    /// contact only): the library's analytic [`Linearize`] (forward-mode dual numbers), what
    /// the large step ([`Bearing::step_aware`]) linearises with. Zero at h ≤ 0.
    fn race_linearize(&self, curv: &Curvatures<T>, s: &StepState<T>) -> Jacobian<T>;
}

impl<T: Real, N: LinearNormal<T>, D: LinearDamping<T>, L: LinearLaw> RaceLaw<T>
    for Contact<T, N, D, L>
{
    #[inline]
    fn race_linearize(&self, _: &Curvatures<T>, s: &StepState<T>) -> Jacobian<T> {
        Linearize::linearize(self, s)
    }
}

impl<T: Real, D: LinearDamping<T>, L: LinearLaw> RaceLaw<T> for VaryingContact<T, D, L> {
    #[inline]
    fn race_linearize(&self, curv: &Curvatures<T>, s: &StepState<T>) -> Jacobian<T> {
        self.at(curv).linearize(s)
    }
}

impl<T: Real, N: LinearNormal<T>, D: LinearDamping<T>, L: RollingLaw> RaceLaw<T>
    for Rolling<T, Contact<T, N, D, Best>, L>
{
    #[inline]
    fn race_linearize(&self, _: &Curvatures<T>, s: &StepState<T>) -> Jacobian<T> {
        Linearize::linearize(self, s)
    }
}

impl<T: Real, D: LinearDamping<T>, L: RollingLaw> RaceLaw<T>
    for Rolling<T, VaryingContact<T, D, Best>, L>
{
    #[inline]
    fn race_linearize(&self, curv: &Curvatures<T>, s: &StepState<T>) -> Jacobian<T> {
        self.at(curv).linearize(s)
    }
}

impl<T: Real, C: RaceLaw<T>> Raceway<T, C> {
    /// For the ball centre at `rel` from the ring's centre: its cylindrical radius ρ, the
    /// radial unit vector e_ρ (not finite when ρ = 0), the vector g from the groove centre
    /// circle to the ball centre in the meridian plane and its length d.
    #[inline(always)]
    fn torus(&self, rel: Vec3<T>) -> (T, Vec3<T>, Vec3<T>, T) {
        let rho = (rel.x * rel.x + rel.y * rel.y).sqrt();
        let e_rho = Vec3::new(rel.x / rho, rel.y / rho, T::ZERO);
        let g = e_rho * (rho - self.centre_radius) + Vec3::new(T::ZERO, T::ZERO, rel.z);
        (rho, e_rho, g, g.norm())
    }

    /// The contact frame and the velocities at P from the torus data of [`Raceway::torus`]
    /// (d > 0), the ring's velocity and spin, the ball's velocity and angular velocity.
    #[inline(always)]
    fn kin(
        &self,
        (rel, rho, e_rho, g, d): (Vec3<T>, T, Vec3<T>, Vec3<T>, T),
        (vr, wr): (Vec3<T>, T),
        (v, w): (Vec3<T>, Vec3<T>),
        rb: T,
    ) -> Kin<T> {
        let u = g * (T::ONE / d);
        let z = -u;
        let e_theta = Vec3::new(-e_rho.y, e_rho.x, T::ZERO);
        let frame = Frame::new(z.into(), e_theta.into(), self.axis);
        let arm = u * rb;
        let ring_w = Vec3::new(T::ZERO, T::ZERO, wr);
        let ball_p: Vec3<T> = point_velocity(v.into(), w.into(), arm.into()).into();
        let ring_p: Vec3<T> = point_velocity(vr.into(), ring_w.into(), (rel + arm).into()).into();
        // Rolling velocity (module docs): v_P = v + r_b u̇ with the torus' u̇.
        let rdot = v - vr;
        let g_dot = rdot - e_theta * (self.centre_radius / rho * e_theta.dot(rdot));
        let u_dot = (g_dot - u * u.dot(rdot)) * (T::ONE / d);
        let v_contact = v + u_dot * rb;
        Kin {
            z,
            frame,
            arm,
            ring_w,
            ball_p,
            ring_p,
            rolling_world: v_contact - (ball_p + ring_p) * T::HALF,
        }
    }

    /// The contact of a ball (centre `p`, velocity `v`, angular velocity `w`, radius `rb`)
    /// with this race on a ring at `c` moving with `vr`, spinning at `wr` about z.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn eval(
        &self,
        c: Vec3<T>,
        vr: Vec3<T>,
        wr: T,
        p: Vec3<T>,
        v: Vec3<T>,
        w: Vec3<T>,
        rb: T,
    ) -> RaceContact<T> {
        let rel = p - c;
        let (rho, e_rho, g, d) = self.torus(rel);
        if rho <= T::ZERO {
            return RaceContact::default();
        }
        let h = d + rb - self.groove;
        if h <= T::ZERO || d <= T::ZERO {
            return RaceContact {
                h,
                ..RaceContact::default()
            };
        }
        let Kin {
            z,
            frame,
            arm,
            ring_w,
            ball_p,
            ring_p,
            rolling_world,
        } = self.kin((rel, rho, e_rho, g, d), (vr, wr), (v, w), rb);
        let vp = (ball_p - ring_p).into();
        let w_rel = w - ring_w;
        let slip = frame.slip(vp, w_rel.into()).unwrap_or_default();
        let [vrx, vry, _] = frame.to_contact(rolling_world.into());
        // A non-finite V (never from a finite state) falls back to full slip.
        let rolling = RollingVelocity::new(vrx, vry).unwrap_or(RollingVelocity::ZERO);
        let wrench =
            self.contact
                .step_rolling(&self.curvatures, h, frame.approach_rate(vp), slip, rolling);
        let load = frame.on_b(&wrench, arm.into());
        let force: Vec3<T> = load.force.into();
        let ring_torque_spin = -z.z * wrench.tz;
        let ring_torque = ring_torque_spin - (rel + arm).cross(force).z;
        RaceContact {
            h,
            n: wrench.n,
            e2: wrench.patch.e2,
            fx: wrench.fx,
            fy: wrench.fy,
            tz: wrench.tz,
            slip: [slip.vx(), slip.vy()],
            spin: slip.omega(),
            roll: (w_rel - z * slip.omega()).norm(),
            rolling: [vrx, vry],
            ring_torque,
            ring_torque_spin,
            force,
            torque: load.torque.into(),
        }
    }
}

/// A ball–race contact's frame and velocities ([`Raceway::kin`]).
struct Kin<T: Real> {
    /// The normal, from the ring into the ball.
    z: Vec3<T>,
    frame: Frame<T>,
    /// Ball centre → P.
    arm: Vec3<T>,
    /// The ring's angular velocity (about z).
    ring_w: Vec3<T>,
    /// The ball's and the ring's material velocities at P.
    ball_p: Vec3<T>,
    ring_p: Vec3<T>,
    /// The rolling velocity V = v_P − ½(u_A + u_B) (world).
    rolling_world: Vec3<T>,
}

/// Where a large step sees a ball and a ring: their centres where the impulse acts, where the
/// velocities are read and at the free end of the step ([`Bearing::step_aware_with`]).
struct Poses<T> {
    ball: [Vec3<T>; 3],
    ring: [Vec3<T>; 3],
}

/// One race contact as the large step sees it: its site where the impulse acts and its candidate.
struct RaceStep<T> {
    site: Site<T>,
    cand: Candidate<T>,
}

impl<T: Real, C: RaceLaw<T>> Raceway<T, C> {
    /// The contact of a ball with this race on a ring moving with `vr`, spinning at `wr`, at
    /// the `poses`: its site (W's rows) and u_free from the ball's velocity `v`, `w` (no
    /// contact) where the impulse acts (the start pose); the same velocities read at the
    /// mid-step pose minus u_free as the drift, so that the law sees the end velocity at
    /// mid-step (see [`Bearing::step_aware_with`]); the gap predicted at the free end pose.
    /// None for a degenerate geometry (a ball centre on the axis or on a
    /// groove's centre circle).
    fn step_site(
        &self,
        poses: &Poses<T>,
        (vr, wr): (Vec3<T>, T),
        (v, w): (Vec3<T>, Vec3<T>),
        rb: T,
    ) -> Option<RaceStep<T>> {
        let [p, p_read, p_end] = poses.ball;
        let [c, c_read, c_end] = poses.ring;
        let rel = p - c;
        let (rho, e_rho, g, d) = self.torus(rel);
        let rel_read = p_read - c_read;
        let read = self.torus(rel_read);
        let h_end = self.torus(p_end - c_end).3 + rb - self.groove;
        if !(rho > T::ZERO
            && d > T::ZERO
            && read.0 > T::ZERO
            && read.3 > T::ZERO
            && h_end.is_finite())
        {
            return None;
        }
        let kin = self.kin((rel, rho, e_rho, g, d), (vr, wr), (v, w), rb);
        let (site, u_free) = kin.free(v, w, wr);
        let kin_read = self.kin(
            (rel_read, read.0, read.1, read.2, read.3),
            (vr, wr),
            (v, w),
            rb,
        );
        let [vrx, vry, _] = kin_read.frame.to_contact(kin_read.rolling_world.into());
        let (_, u_read) = kin_read.free(v, w, wr);
        Some(RaceStep {
            site,
            cand: Candidate {
                h_pred: h_end,
                u_free,
                rolling: RollingVelocity::new(vrx, vry).unwrap_or(RollingVelocity::ZERO),
                drift: [0, 1, 2, 3].map(|i| u_read[i] - u_free[i]),
            },
        })
    }
}

impl<T: Real> Kin<T> {
    /// The step's site and u = (v_n, v_x, v_y, ω) of the ball (velocity `v`, angular velocity
    /// `w`) relative to the ring (spin `wr`) at P in this frame.
    #[inline(always)]
    fn free(&self, v: Vec3<T>, w: Vec3<T>, wr: T) -> (Site<T>, [T; 4]) {
        let (x, y, z) = (
            Vec3::from(self.frame.x()),
            Vec3::from(self.frame.y()),
            self.z,
        );
        let site = Site {
            arm: self.arm,
            axes: [x, y, z],
        };
        let ball_u = site.velocity(v, w);
        let ring_u = [
            z.dot(self.ring_p),
            x.dot(self.ring_p),
            y.dot(self.ring_p),
            z.z * wr,
        ];
        (site, [0, 1, 2, 3].map(|i| ball_u[i] - ring_u[i]))
    }
}

/// What a large step applied ([`Bearing::step_aware`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepLoads<T> {
    /// The friction torque on the inner ring about the bearing axis (N·m, as
    /// [`Bearing::inner_ring_torque`]).
    pub ring_torque: T,
    /// The drilling torques' part of [`StepLoads::ring_torque`]: −Σ ẑ_bearing·(T_z z) over the
    /// balls' inner contacts (N·m; the rest is the friction forces' moment).
    pub ring_torque_spin: T,
    /// Σ over balls of |T_z| at the inner and the outer race (N·m).
    pub spin_moment: [T; 2],
}

/// A race contact at fixed curvatures, as the step sees it.
struct RaceContactStep<'a, T, C> {
    contact: &'a C,
    curvatures: &'a Curvatures<T>,
}

impl<T: Real, C: RaceLaw<T>> StepContact<T> for RaceContactStep<'_, T, C> {
    fn wrench4(&self, s: &StepState<T>) -> [T; 4] {
        if s.h <= T::ZERO {
            return [T::ZERO; 4];
        }
        let w = self
            .contact
            .step_rolling(self.curvatures, s.h, s.hdot, s.slip, s.rolling);
        [w.n, w.fx, w.fy, w.tz]
    }

    fn linearize(&self, s: &StepState<T>) -> Jacobian<T> {
        if s.h <= T::ZERO {
            return Jacobian::default();
        }
        self.contact.race_linearize(self.curvatures, s)
    }
}

/// The bearing with race contact law `C` (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bearing<T, C> {
    geometry: Geometry<T>,
    inner: Raceway<T, C>,
    outer: Raceway<T, C>,
    ball_inertia: T,
}

impl<T: Real, C: RaceLaw<T>> Bearing<T, C> {
    /// The bearing `g` with the given inner- and outer-race contact laws (built by the caller
    /// from [`Geometry::curvatures`], e.g. `Contact::hertz::<Newton>`).
    ///
    /// Errors: those of [`Geometry::curvatures`].
    pub fn new(g: &Geometry<T>, inner: C, outer: C) -> Result<Self, Error> {
        let half = T::HALF;
        let (ci, co) = (g.curvatures(Race::Inner)?, g.curvatures(Race::Outer)?);
        Ok(Bearing {
            inner: Raceway {
                centre_radius: (g.pitch_diameter - g.ball_diameter) * half + g.inner_groove,
                groove: g.inner_groove,
                axis: MajorAxis::of(&ci),
                curvatures: ci,
                contact: inner,
            },
            outer: Raceway {
                centre_radius: (g.pitch_diameter + g.ball_diameter) * half - g.outer_groove,
                groove: g.outer_groove,
                axis: MajorAxis::of(&co),
                curvatures: co,
                contact: outer,
            },
            ball_inertia: T::from_f64(0.1) * g.ball_mass * g.ball_diameter * g.ball_diameter,
            geometry: *g,
        })
    }

    /// The geometry.
    pub fn geometry(&self) -> &Geometry<T> {
        &self.geometry
    }

    /// The start: inner ring centred and at rest, balls equally spaced on the pitch circle,
    /// orbiting at the cage speed and rolling without slip (angular velocity −(d_m/D)ω_c about
    /// z), every contact at zero approach.
    pub fn initial_state(&self) -> State<T> {
        let g = &self.geometry;
        let wc = g.cage_speed();
        let rp = g.pitch_diameter * T::HALF;
        let wb = -wc * g.pitch_diameter / g.ball_diameter;
        let mut y = [T::ZERO; N];
        for (i, ball) in y[6..].chunks_exact_mut(9).enumerate() {
            let phi = T::TWO * T::PI * T::from_usize(i) / T::from_usize(BALLS);
            let (s, c) = phi.sin_cos();
            ball.copy_from_slice(&[
                rp * c,
                rp * s,
                T::ZERO,
                -wc * rp * s,
                wc * rp * c,
                T::ZERO,
                T::ZERO,
                T::ZERO,
                wb,
            ]);
        }
        y
    }

    /// Both contacts of ball `i` (< [`BALLS`], else the default) at state `y`: (inner, outer).
    pub fn contacts(&self, y: &State<T>, i: usize) -> (RaceContact<T>, RaceContact<T>) {
        match y[6..].chunks_exact(9).nth(i) {
            Some(b) => self.ball_contacts(ring(y), b),
            None => Default::default(),
        }
    }

    /// The friction torque on the inner ring about the bearing axis at state `y` (N·m): the
    /// sum of every ball's [`RaceContact::ring_torque`] at the inner race (negative: it brakes
    /// the ring, which the drive holds at ω_i).
    pub fn inner_ring_torque(&self, y: &State<T>) -> T {
        let r = ring(y);
        y[6..].chunks_exact(9).fold(T::ZERO, |acc, b| {
            acc + self.ball_contacts(r, b).0.ring_torque
        })
    }

    #[inline(always)]
    fn ball_contacts(
        &self,
        (c, vr): (Vec3<T>, Vec3<T>),
        b: &[T],
    ) -> (RaceContact<T>, RaceContact<T>) {
        let (p, v, w) = ball(b);
        let rb = self.geometry.ball_diameter * T::HALF;
        (
            self.inner
                .eval(c, vr, self.geometry.omega_inner, p, v, w, rb),
            self.outer
                .eval(Vec3::zero(), Vec3::zero(), T::ZERO, p, v, w, rb),
        )
    }
}

impl<T: Real, C: RaceLaw<T>> Bearing<T, C> {
    /// One large step of `dt` from (`t`, `y`) ([`super::step_aware`]) with the balls seeing
    /// the ring at its start position ([`RingCoupling::Start`]): [`Bearing::step_aware_with`].
    pub fn step_aware(
        &self,
        t: T,
        y: &State<T>,
        dt: T,
        warm: &mut [Warm<T>; BALLS],
    ) -> (State<T>, StepLoads<T>) {
        self.step_aware_with(t, y, dt, warm, RingCoupling::Start)
    }

    /// One large step of `dt` from (`t`, `y`) ([`super::step_aware`]): each ball's two race
    /// contacts solved together (W of the ball, a sphere, over both contacts; an active set),
    /// with the ring where `coupling` puts it over the step ([`RingCoupling`]), each gap
    /// predicted at the free end pose, backward Euler (θ = 1: the creep law is a stiff damper).
    /// Then each ball's kick–drift, v⁺ = v + Δt·F/m, p⁺ = p + Δt·v⁺.
    ///
    /// **Where the impulse acts and where the slip is read.** In that kick–drift the velocities
    /// live half a step off the positions: p⁺ − p = Δt·v⁺ makes v⁺ the chord velocity of the
    /// step, the velocity at mid-step. In the steady state the balls' velocities (v and ω,
    /// whose part in the orbit plane, ≈ 41 rad/s for the 209, turns with the orbit) turn by
    /// ω_c·Δt per step, and the kick v⁺ − v is centred between them — at the start pose p. So
    /// the impulse acts at the start pose (W and the impulse's directions from the contact
    /// frames there) and the law reads the end velocity v⁺, ω⁺ at the mid-step pose
    /// p + ½Δt·v (through the candidate's drift: the start velocities read there minus read at
    /// p). Both at mid-step, as this step did before, turn the balls' centripetal force ahead by
    /// ½ω_c·Δt: a spurious brake m·v·ω_c²·Δt/2 on each ball's orbit (1.4 mN at 20 µs for the
    /// 209) that the inner ring's friction made up — the ring torque came out +0.074 % per µs
    /// of step too large (steady state against RK4 at 0.1 µs: +0.74 / +1.46 / +2.29 % at
    /// 10 / 20 / 30 µs, the cage speed −0.02 / −0.04 / −0.07 %); with the split, +0.03 / +0.30 /
    /// +0.63 % (second order) and −0.004 / −0.008 / −0.017 %. With the impulse at mid-step
    /// and the end velocity read at the end pose, the error has the other sign (−3.5 % per
    /// 10 µs).
    ///
    /// The ring's update, with the balls' reactions F of this step and the
    /// load, linearly implicit in the ring's own displacement:
    /// (M + Δt²·K)(Ṙ⁺ − Ṙ) = Δt(F + load(t + Δt)), R⁺ = R + Δt·Ṙ⁺, K the balls' solved Hertz
    /// tangents 3N/(2h), inner and outer in series, along each inner normal (without K the
    /// ring's radial mode on the balls, ≈ 1.9e4 rad/s for the 209 at 2 kN, is unstable above
    /// ≈ 60 µs with [`RingCoupling::Predicted`]). `warm` carries each ball's solution
    /// ([`Warm::default`] at the start). Also returns the step's [`StepLoads`] (from the
    /// wrenches applied over the step: re-evaluating the plain wrench at the new state would
    /// not give them — a creep force is stiff in the slip).
    pub fn step_aware_with(
        &self,
        t: T,
        y: &State<T>,
        dt: T,
        warm: &mut [Warm<T>; BALLS],
        coupling: RingCoupling,
    ) -> (State<T>, StepLoads<T>) {
        let mut loads = StepLoads::default();
        let g = &self.geometry;
        let (c, vr) = ring(y);
        let rb = g.ball_diameter * T::HALF;
        let inv_m = T::ONE / g.ball_mass;
        let inv_i = T::ONE / self.ball_inertia;
        let iw = InvInertia::new(Quat::identity(), Vec3::new(inv_i, inv_i, inv_i));
        let half = T::HALF * dt;
        // The ring where the impulse acts, where the velocities are read (mid-step) and at
        // the end of the step.
        let (c_kick, c_mid, c_end) = match coupling {
            RingCoupling::Start => (c, c, c),
            RingCoupling::Predicted => (c + vr * half, c + vr * half, c + vr * dt),
        };
        let mut out = *y;
        let mut ring_force = Vec3::zero();
        let mut ring_stiffness = RingStiffness::default();
        for (k, (b, ob)) in y[6..]
            .chunks_exact(9)
            .zip(out[6..].chunks_exact_mut(9))
            .enumerate()
        {
            let (p, v, w) = ball(b);
            let wk = &mut warm[k];
            // The impulse at the start pose, the velocities read at mid-step from the start
            // velocity alone (see above; adding half of the last step's impulse, as this step
            // did before, extrapolates the ball's stiff normal force explicitly: Δt²·k/m ≈ 300
            // at 100 µs, the ball then alternated between its races and the run diverged after
            // 17 steps).
            let p_mid = p + v * half;
            let ball_poses = [p, p_mid, p + v * dt];
            let (si, so) = (
                self.inner.step_site(
                    &Poses {
                        ball: ball_poses,
                        ring: [c_kick, c_mid, c_end],
                    },
                    (vr, g.omega_inner),
                    (v, w),
                    rb,
                ),
                self.outer.step_site(
                    &Poses {
                        ball: ball_poses,
                        ring: [Vec3::zero(); 3],
                    },
                    (Vec3::zero(), T::ZERO),
                    (v, w),
                    rb,
                ),
            );
            let (Some(si), Some(so)) = (si, so) else {
                // A degenerate geometry (never from a finite state): free flight.
                let p1 = p + v * dt;
                ob[..3].copy_from_slice(&[p1.x, p1.y, p1.z]);
                continue;
            };
            let wm = rigid_w(inv_m, &iw, &[si.site, so.site]);
            let inner = RaceContactStep {
                contact: &self.inner.contact,
                curvatures: &self.inner.curvatures,
            };
            let outer = RaceContactStep {
                contact: &self.outer.contact,
                curvatures: &self.outer.curvatures,
            };
            let sol = solve_library(
                dt,
                &wm,
                &[&inner, &outer],
                &[si.cand, so.cand],
                &Scheme::backward_euler(),
                wk,
            );
            let (fi, ti) = si.site.load(&sol.w[0]);
            let (fo, to) = so.site.load(&sol.w[1]);
            let rel_p = p - c_kick + si.site.arm;
            loads.ring_torque -= rel_p.cross(fi).z + si.site.axes[2].z * sol.w[0][3];
            loads.ring_torque_spin -= si.site.axes[2].z * sol.w[0][3];
            loads.spin_moment[0] += sol.w[0][3].abs();
            loads.spin_moment[1] += sol.w[1][3].abs();
            ring_force = ring_force - fi;
            ring_stiffness.add(&sol, si.site.axes[2]);
            let v1 = v + (fi + fo) * (dt * inv_m);
            let w1 = w + (ti + to) * (dt * inv_i);
            let p1 = p + v1 * dt;
            ob.copy_from_slice(&[p1.x, p1.y, p1.z, v1.x, v1.y, v1.z, w1.x, w1.y, w1.z]);
        }
        let ramp = ((t + dt) / g.ramp).clamp_to(T::ZERO, T::ONE);
        let load = Vec3::new(T::ZERO, -g.radial_load, g.axial_load) * ramp;
        let vr1 = vr + ring_stiffness.solve(g.ring_mass, dt, (ring_force + load) * dt);
        let c1 = c + vr1 * dt;
        out[..6].copy_from_slice(&[c1.x, c1.y, c1.z, vr1.x, vr1.y, vr1.z]);
        (out, loads)
    }
}

/// Where the balls see the inner ring within a large step ([`Bearing::step_aware_with`]).
///
/// The ring on the balls' Hertz contacts has lightly damped modes: the load's ramp leaves it
/// vibrating axially (≈ 500 Hz, ≈ 35 mm/s), which decays over ≈ 150 ms, and its radial mode is
/// ≈ 3 kHz. Measured in the steady state (creep law `table`, the load ramped over 5 ms, means
/// over 200–400 ms of a 400 ms run against RK4 at 0.1 µs: ring torque −15.074 ± 0.031 N·mm,
/// the ± a batch-means standard error; `examples/bearing.rs`'s `steady`):
///
/// | coupling | step | ring torque | Σ\|T_z\| inner / outer | cage speed |
/// |---|---|---|---|---|
/// | `Start` | 10 µs | +0.01 % | −0.05 / −0.05 % | −0.005 % |
/// | `Start` | 20 µs | +0.28 % | −0.05 / −0.05 % | −0.011 % |
/// | `Start` | 30 µs | +0.66 % | −0.04 / −0.04 % | −0.018 % |
/// | `Start` | 40 µs | +1.30 % | −0.05 / −0.05 % | −0.018 % |
/// | `Start` | 50 µs | +0.14 ± 1.2 % (bursts of the radial mode) | −0.28 / −0.28 % | −0.015 % |
/// | `Predicted` | 20 µs | +0.33 % | −0.03 / −0.03 % | −0.011 % |
/// | `Predicted` | 30 µs | +0.71 % | −0.03 / −0.03 % | −0.018 % |
/// | `Predicted` | 50 µs | −2.9 ± 1.8 % (bursts) | −1.2 / −1.2 % | −0.015 % |
///
/// `Start` diverges from 80 µs, `Predicted` from 70 µs (the runner reports it: the balls
/// leave the races). Before the ring's vibration has decayed the two differ: `Predicted`
/// damps it, `Start` keeps it as RK4 does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RingCoupling {
    /// At its start position R over the whole step: the balls' reactions are the ring's
    /// there, and its update (M + Δt²·K)(Ṙ⁺ − Ṙ) = Δt·F(R), R⁺ = R + Δt·Ṙ⁺ is symplectic in the
    /// ring's displacement (for a linear K exactly: |λ| = 1, stable for any Δt) — the ring's
    /// modes keep their amplitude as in RK4. [`Bearing::step_aware`].
    #[default]
    Start,
    /// Moved with its start velocity (mid-step R + ½Δt·Ṙ for the geometry, R + Δt·Ṙ for the
    /// gaps): the reactions are the ring's at its predicted end position, which damps its modes
    /// (|λ|² = 1/(1 + Δt²K/M) per step for a linear K): while the ring still vibrates after
    /// the load's ramp that shifts the means (the 15–20 ms ones by 2–5 %); in the steady state
    /// the two agree (table above).
    Predicted,
}

/// The stiffness K (3 × 3, world) the balls' solved contacts oppose to a displacement of the
/// inner ring within the step: per ball whose two race contacts are both active, the two Hertz
/// tangents k = dN/dh = 3N/(2h) (exact for N ∝ h^{3/2}; at the solved end approach) in series,
/// along the inner contact's normal n: K = Σ k_i k_o/(k_i + k_o)·n nᵀ (a ball touching one
/// race only follows the ring: no stiffness). The ring's update
/// (M + Δt²·K)(Ṙ⁺ − Ṙ) = Δt·F is then backward Euler in the ring's displacement: without it
/// (Ṙ⁺ = Ṙ + Δt·F/M, F taken at the predicted end position) the ring's radial mode on the
/// balls (√(K/M) ≈ 1.9e4 rad/s for the 209 at 2 kN) has |λ|² = 1 − (Δt·ω)² per step and is
/// unstable above Δt·ω ≈ 1.15 (≈ 60 µs). A linearisation (a W-method): the balls' forces
/// themselves are unchanged, K only sets how the ring's velocity responds, so the step stays
/// consistent for any K ≥ 0 and the ring's mode is damped, not amplified.
#[derive(Clone, Copy, Debug, Default)]
struct RingStiffness<T> {
    k: [[T; 3]; 3],
}

impl<T: Real> RingStiffness<T> {
    /// Adds one ball's series stiffness from its solution (contact 0 inner, 1 outer) along
    /// the inner contact's normal `n`.
    fn add(&mut self, sol: &super::step_aware::Solution<T>, n: Vec3<T>) {
        let tangent = |k: usize| {
            let (nk, hk) = (sol.w[k][0], sol.h[k]);
            if nk > T::ZERO && hk > T::ZERO {
                T::from_f64(1.5) * nk / hk
            } else {
                T::ZERO
            }
        };
        let (ki, ko) = (tangent(0), tangent(1));
        let sum = ki + ko;
        if !(ki > T::ZERO && ko > T::ZERO && sum.is_finite()) {
            return;
        }
        let ks = ki * (ko / sum);
        let n = [n.x, n.y, n.z];
        for (row, &na) in self.k.iter_mut().zip(n.iter()) {
            for (x, &nb) in row.iter_mut().zip(n.iter()) {
                *x += ks * na * nb;
            }
        }
    }

    /// Δv with (m·I + Δt²·K)·Δv = `impulse` (Cramer's rule: the matrix is symmetric positive
    /// definite for m > 0; a non-finite result falls back to impulse/m).
    fn solve(&self, m: T, dt: T, impulse: Vec3<T>) -> Vec3<T> {
        let d2 = dt * dt;
        let a: [[T; 3]; 3] = core::array::from_fn(|i| {
            core::array::from_fn(|j| d2 * self.k[i][j] + if i == j { m } else { T::ZERO })
        });
        let col = |j: usize| Vec3::new(a[0][j], a[1][j], a[2][j]);
        let (c0, c1, c2) = (col(0), col(1), col(2));
        let det = c0.dot(c1.cross(c2));
        let x = Vec3::new(
            impulse.dot(c1.cross(c2)),
            c0.dot(impulse.cross(c2)),
            c0.dot(c1.cross(impulse)),
        ) * (T::ONE / det);
        if det > T::ZERO && x.x.is_finite() && x.y.is_finite() && x.z.is_finite() {
            x
        } else {
            impulse * (T::ONE / m)
        }
    }
}

/// Ring centre and velocity.
#[inline(always)]
fn ring<T: Real>(y: &State<T>) -> (Vec3<T>, Vec3<T>) {
    let [x, yy, z, vx, vy, vz, ..] = *y;
    (Vec3::new(x, yy, z), Vec3::new(vx, vy, vz))
}

/// A ball's centre, velocity, angular velocity from its 9 scalars (zeros if fewer).
#[inline(always)]
fn ball<T: Real>(b: &[T]) -> (Vec3<T>, Vec3<T>, Vec3<T>) {
    match *b {
        [px, py, pz, vx, vy, vz, wx, wy, wz, ..] => (
            Vec3::new(px, py, pz),
            Vec3::new(vx, vy, vz),
            Vec3::new(wx, wy, wz),
        ),
        _ => (Vec3::zero(), Vec3::zero(), Vec3::zero()),
    }
}

impl<T: Real, C: RaceLaw<T>> Ode<T, N> for Bearing<T, C> {
    fn rhs(&self, t: T, y: &State<T>) -> State<T> {
        let g = &self.geometry;
        let r = ring(y);
        let mut dy = [T::ZERO; N];
        let mut ring_force = Vec3::zero();
        let inv_m = T::ONE / g.ball_mass;
        let inv_i = T::ONE / self.ball_inertia;
        for (b, db) in y[6..].chunks_exact(9).zip(dy[6..].chunks_exact_mut(9)) {
            let (inner, outer) = self.ball_contacts(r, b);
            let (_, v, _) = ball(b);
            ring_force = ring_force - inner.force;
            let a = (inner.force + outer.force) * inv_m;
            let dw = (inner.torque + outer.torque) * inv_i;
            db.copy_from_slice(&[v.x, v.y, v.z, a.x, a.y, a.z, dw.x, dw.y, dw.z]);
        }
        let ramp = (t / g.ramp).clamp_to(T::ZERO, T::ONE);
        let load = Vec3::new(T::ZERO, -g.radial_load, g.axial_load) * ramp;
        let a = (ring_force + load) * (T::ONE / g.ring_mass);
        let v = r.1;
        dy[..6].copy_from_slice(&[v.x, v.y, v.z, a.x, a.y, a.z]);
        dy
    }
}
