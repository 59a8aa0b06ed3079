//! The tippe top of the paper's §5 (parameters of Leine & Glocker 2003 / Friedl 1997): a
//! rigid body bounded by two spheres on the symmetry axis, on a rigid, fixed floor, with the
//! unbounded contact problem — at each sphere that touches the floor, Hertz normal force with
//! Hunt–Crossley damping and a friction law of the library, chosen by the type parameter `L`.
//!
//! # Model
//!
//! - Body frame: principal axes at the centre of mass G, e₃ the symmetry axis pointing from G
//!   towards the small sphere ("stem"). The big sphere (radius R) has its centre at
//!   G + ε_R·e₃, the small one (radius r) at G + ε_r·e₃ (paper: ε_R = 3 mm, ε_r = 16 mm).
//! - State (13 scalars): G (m), Ġ (m/s), attitude q (body → world), ω in the body frame (rad/s)
//!   — the order of [`State`].
//! - Each sphere: penetration h = radius − (centre height); the patch centre P is the point of
//!   the floor below the centre; the slip is the velocity of the top's material point at P
//!   (the floor is at rest), the spin the world-vertical component of ω; ḣ = −(vertical
//!   velocity of P). Contact frame: z the world vertical (floor = body A, top = body B), x, y
//!   the world x, y (the patch is a circle, so any horizontal x axis is a major axis).
//!   [`Contact::wrench`] gives N, F_x, F_y, T_z; the force acts at P, the drilling torque about
//!   the vertical. The slip, ḣ and the load about G come from [`crate::frame`] (see
//!   [`crate::guide`]).
//! - Damping: Hunt–Crossley N = k_H h^{3/2}(1 + (3/2)c_d ḣ), clamped ≥ 0.
//!
//! # Diagnostics
//!
//! - θ: the angle between e₃ and the world vertical (θ = 0 stem up, θ = π inverted; both spheres
//!   touch at θ* = arccos((r − R)/(ε_r − ε_R)) = arccos(−10/13) ≈ 2.448 rad).
//! - Energy: ½m|Ġ|² + ½ωᵀIω + m g G_z + Σ (2/5)k_H h^{5/2}. Friction and damping only dissipate,
//!   so it is non-increasing (up to integration error).
//! - Jellett's quantity J = L_G·(ẑ − (ε_R/R)·e₃) (N·m·s), L_G the angular momentum about G.
//!   For a point contact on the big sphere it is conserved by any friction force (the force's
//!   moment about G is perpendicular to G − P = Rẑ − ε_R e₃); the Contensou drilling torque and
//!   contact on the small sphere change it.

use super::event::{Crossing, Direction};
use super::integrate::Ode;
use super::rigid::{Quat, Vec3, euler_rate_inv};
use super::step_aware::{
    Candidate, InvInertia, Site, Warm, rigid_w, solve_library, symmetric_free,
};
use crate::contact::Contact;
use crate::frame::{ContactFrame, WorldAxes, point_velocity};
use crate::friction::{Friction, FrictionLaw};
use crate::geometry::Curvatures;
use crate::normal::{Hertz, HuntCrossley, Modulus, NormalLaw};
use crate::shape::Newton;
use crate::step::Scheme;
use crate::{Error, Real};

/// Number of scalars in the state.
pub const N: usize = 13;

/// The state [G (3), Ġ (3), q = (w, x, y, z) (4), ω body (3)].
pub type State<T> = [T; N];

/// The top's physical parameters (SI).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params<T> {
    /// Mass m (kg).
    pub mass: T,
    /// Equatorial moment of inertia about G (kg·m²).
    pub inertia_eq: T,
    /// Polar moment of inertia (kg·m²).
    pub inertia_polar: T,
    /// Big sphere radius R (m).
    pub big_radius: T,
    /// Small sphere radius r (m).
    pub small_radius: T,
    /// Signed distance along e₃ from G to the big sphere's centre (m).
    pub big_offset: T,
    /// Signed distance along e₃ from G to the small sphere's centre (m).
    pub small_offset: T,
    /// Effective modulus E* (Pa).
    pub estar: T,
    /// Hunt–Crossley damping c_d (s/m).
    pub damping: T,
    /// Gravity g (m/s²).
    pub gravity: T,
}

impl<T: Real> Params<T> {
    /// The paper's top: m = 6 g, I = 8e-7 / 7e-7 kg·m², R = 15 mm, r = 5 mm, ε_R = 3 mm,
    /// ε_r = 16 mm, E* = 5e9 Pa (wood, E = 9.1e9 Pa, ν = 0.3); g = 9.81 m/s²; c_d = 5 s/m (our
    /// choice: restitution ≈ 1 − c_d·v for small impact speeds v, a damping ratio of ≈0.4 % for
    /// the 1.5 kHz vertical vibration at rest).
    pub fn paper() -> Self {
        let c = T::from_f64;
        Params {
            mass: c(6e-3),
            inertia_eq: c(8e-7),
            inertia_polar: c(7e-7),
            big_radius: c(15e-3),
            small_radius: c(5e-3),
            big_offset: c(3e-3),
            small_offset: c(16e-3),
            estar: c(5e9),
            damping: c(5.0),
            gravity: c(9.81),
        }
    }
}

/// One sphere of the top with its floor contact.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Sphere<T: Real, L: FrictionLaw> {
    offset: T,
    radius: T,
    contact: Contact<T, Hertz<T>, HuntCrossley<T>, L>,
}

/// What one sphere's contact does at a state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SphereContact<T> {
    /// Penetration h (m), negative when apart.
    pub h: T,
    /// Normal force N (N).
    pub n: T,
    /// Force on the top, world frame (N).
    pub force: Vec3<T>,
    /// Torque on the top about G, world frame (N·m).
    pub torque: Vec3<T>,
    /// Elastic energy (J).
    pub energy: T,
}

impl<T: Real, L: FrictionLaw> Sphere<T, L> {
    fn new(offset: T, radius: T, p: &Params<T>, friction: Friction<T, L>) -> Result<Self, Error> {
        let contact = Contact::hertz::<Newton>(
            &Curvatures::sphere_plane(radius)?,
            Modulus::new(p.estar)?,
            HuntCrossley::new(p.damping)?,
            friction,
        )?;
        Ok(Sphere {
            offset,
            radius,
            contact,
        })
    }

    /// The contact at G = `r`, Ġ = `v`, attitude `q`, world angular velocity `w`.
    #[inline]
    fn eval(&self, r: Vec3<T>, v: Vec3<T>, q: Quat<T>, w: Vec3<T>) -> SphereContact<T> {
        let to_centre = q.rotate(Vec3::new(T::ZERO, T::ZERO, self.offset));
        let h = self.radius - (r.z + to_centre.z);
        if h <= T::ZERO {
            return SphereContact {
                h,
                ..SphereContact::default()
            };
        }
        // G → P, P the floor point under the centre; the floor is at rest.
        let arm = [to_centre.x, to_centre.y, -r.z];
        let vp = point_velocity(v.into(), w.into(), arm);
        // The floor's contact frame is the world's: z up (floor = body A, top = body B), x the
        // world x (the patch is a circle: any tangent is a major axis).
        let floor = WorldAxes;
        // Non-finite only if the state is: then no friction (the step is rejected anyway).
        let slip = floor.slip(vp, w.into()).unwrap_or_default();
        let wr = self.contact.wrench(h, floor.approach_rate(vp), slip);
        let load = floor.on_b(&wr, arm);
        SphereContact {
            h,
            n: wr.n,
            force: load.force.into(),
            torque: load.torque.into(),
            energy: self.contact.normal().energy(h),
        }
    }
}

/// The tippe top with friction law `L` (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TippeTop<T: Real, L: FrictionLaw> {
    mass: T,
    gravity: T,
    inertia: Vec3<T>,
    /// 1/m and 1/I, so the right-hand side multiplies instead of dividing.
    inv_mass: T,
    inv_inertia: Vec3<T>,
    big: Sphere<T, L>,
    small: Sphere<T, L>,
}

/// Diagnostics of a state (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Probe<T> {
    /// Tilt θ of the symmetry axis from the vertical (rad).
    pub theta: T,
    /// Normal force at the big sphere (N).
    pub n_big: T,
    /// Normal force at the small sphere (N).
    pub n_small: T,
    /// Total mechanical energy (J), incl. elastic energy of the contacts.
    pub energy: T,
    /// Jellett's quantity L_G·(ẑ − (ε_R/R)e₃) (N·m·s).
    pub jellett: T,
    /// Spin about the symmetry axis, ω·e₃ (rad/s).
    pub spin: T,
    /// Height of G (m).
    pub height: T,
}

impl<T: Real, L: FrictionLaw> TippeTop<T, L> {
    /// The top `p` with the friction law `friction` at both spheres.
    ///
    /// Errors: those of [`Curvatures::sphere_plane`], [`Modulus::new`] and
    /// [`HuntCrossley::new`] for non-positive radii, modulus or negative damping.
    pub fn new(p: &Params<T>, friction: Friction<T, L>) -> Result<Self, Error> {
        let inertia = Vec3::new(p.inertia_eq, p.inertia_eq, p.inertia_polar);
        Ok(TippeTop {
            mass: p.mass,
            gravity: p.gravity,
            inertia,
            inv_mass: T::ONE / p.mass,
            inv_inertia: Vec3::new(T::ONE / inertia.x, T::ONE / inertia.y, T::ONE / inertia.z),
            small: Sphere::new(
                p.small_offset,
                p.small_radius,
                p,
                Friction::with_law(friction.coefficient(), friction.delta())?,
            )?,
            big: Sphere::new(p.big_offset, p.big_radius, p, friction)?,
        })
    }

    /// The paper's start: tilt θ₀ (rad) about the world x axis, spin ω₃ (rad/s) about the
    /// symmetry axis, G at rest, the big sphere touching the floor without penetration.
    pub fn initial_state(&self, theta0: T, spin: T) -> State<T> {
        let q = Quat::about_x(theta0);
        let to_centre = q.rotate(Vec3::new(T::ZERO, T::ZERO, self.big.offset));
        let g = Vec3::new(T::ZERO, T::ZERO, self.big.radius) - to_centre;
        let z = T::ZERO;
        [g.x, g.y, g.z, z, z, z, q.w, q.x, q.y, q.z, z, z, spin]
    }

    /// Both contacts at state `y` (big sphere first).
    #[inline]
    pub fn contacts(&self, y: &State<T>) -> [SphereContact<T>; 2] {
        let (r, v, q, omega) = split(y);
        self.contacts_at(r, v, q.normalized(), omega)
    }

    /// Both contacts at G = `r`, Ġ = `v`, unit attitude `q`, body angular velocity `omega`.
    #[inline(always)]
    fn contacts_at(
        &self,
        r: Vec3<T>,
        v: Vec3<T>,
        q: Quat<T>,
        omega: Vec3<T>,
    ) -> [SphereContact<T>; 2] {
        let w = q.rotate(omega);
        [self.big.eval(r, v, q, w), self.small.eval(r, v, q, w)]
    }

    /// The penetrations h = radius − centre height of both spheres at state `y` (big sphere
    /// first; > 0 in contact): the geometry alone, no force — a cheap touch-down test for a
    /// firmware loop (8 multiply-adds). Takes the attitude q as stored, without normalising
    /// it: [`crate::scenes::integrate::rk4_step`] projects it to unit length after every step.
    #[inline]
    pub fn penetrations(&self, y: &State<T>) -> [T; 2] {
        let (r, _, q, _) = split(y);
        // z component of q·e₃·q*: w² − x² − y² + z².
        let e3z = q.w * q.w - q.x * q.x - q.y * q.y + q.z * q.z;
        [
            self.big.radius - (r.z + self.big.offset * e3z),
            self.small.radius - (r.z + self.small.offset * e3z),
        ]
    }

    /// cos θ = e₃·ẑ at state `y` (θ the tilt of the symmetry axis from the vertical: 1 stem
    /// up, −1 inverted): the event function of [`Events`]' θ crossings — no trigonometry, no
    /// contact evaluation; the attitude is normalised here (the interpolated states between
    /// steps are not unit).
    #[inline]
    pub fn cos_tilt(&self, y: &State<T>) -> T {
        let (_, _, q, _) = split(y);
        let (ww, xx, yy, zz) = (q.w * q.w, q.x * q.x, q.y * q.y, q.z * q.z);
        // z component of q·e₃·q* over |q|².
        (ww - xx - yy + zz) / (ww + xx + yy + zz)
    }

    /// cos θ* = (r − R)/(ε_r − ε_R): at θ* both spheres can touch a flat floor (for the
    /// paper's top −10/13, θ* ≈ 2.448 rad).
    pub fn cos_theta_star(&self) -> T {
        (self.small.radius - self.big.radius) / (self.small.offset - self.big.offset)
    }

    /// θ, both normal forces, energy, Jellett's quantity and the spin at state `y`.
    pub fn probe(&self, y: &State<T>) -> Probe<T> {
        let [big, small] = self.contacts(y);
        let (r, v, q, omega) = split(y);
        let q = q.normalized();
        let e3 = q.rotate(Vec3::unit_z());
        let l = q.rotate(self.inertia.mul_elem(omega));
        let energy = T::HALF * (self.mass * v.dot(v) + omega.dot(self.inertia.mul_elem(omega)))
            + self.mass * self.gravity * r.z
            + big.energy
            + small.energy;
        Probe {
            theta: e3.x.hypot(e3.y).atan2(e3.z),
            n_big: big.n,
            n_small: small.n,
            energy,
            jellett: l.dot(Vec3::unit_z() - e3 * (self.big.offset / self.big.radius)),
            spin: omega.z,
            height: r.z,
        }
    }
}

impl<T: Real, L: FrictionLaw> TippeTop<T, L> {
    /// One large step of `dt` from `y` on the library's step-aware wrench
    /// ([`crate::step::step_wrenches_with`], [`Scheme::strang`]): a Strang splitting of the
    /// whole pose around the contact impulse, the rotation's free parts exact.
    ///
    /// 1. Free motion over Δt/2: G drifts with Ġ, the attitude turns torque-free with the
    ///    angular momentum L = R I ω ([`symmetric_free`]: the exact motion of the symmetric
    ///    top) — the pose the contacts' geometry (arms, frame, W) is taken at.
    /// 2. Both spheres solved together (W with its cross blocks, an active set); each gap
    ///    predicted at the free end pose (G + ½Δt·(Ġ + Ġ_free), attitude turned over Δt), its
    ///    response to the impulse ½W (the pose moves with the new velocities over the second
    ///    half only); friction by the trapezoidal rule (θ = ½) while the slip keeps its
    ///    direction, backward Euler where it would reverse, with the slip's own change from
    ///    the mid-step to the end pose ([`Candidate::drift`]).
    /// 3. Ġ⁺ = Ġ_free + Δt·ΣF/m, L⁺ = L + Δt·Στ, G⁺ = G_mid + ½Δt·Ġ⁺, the attitude turned
    ///    torque-free over the second Δt/2 with L⁺, ω⁺ = I⁻¹ Rᵀ L⁺.
    ///
    /// Measured against RK4 at 10 µs: θ = π/2 within 0.02 % from 0.1 to 2 ms.
    ///
    /// `warm` carries the solution from step to step ([`Warm::default`] at the start).
    pub fn step_aware(&self, y: &State<T>, dt: T, warm: &mut Warm<T>) -> State<T> {
        let (r, v, q, omega) = split(y);
        let q = q.normalized();
        let l = q.rotate(self.inertia.mul_elem(omega));
        let (i_eq, i_polar) = (self.inertia.x, self.inertia.z);
        let half = T::HALF * dt;
        let v_free = v - Vec3::unit_z() * (self.gravity * dt);
        let sites = |r: Vec3<T>, q: Quat<T>| {
            [&self.big, &self.small].map(|s| {
                let c = r + q.rotate(Vec3::new(T::ZERO, T::ZERO, s.offset));
                let site = Site {
                    arm: Vec3::new(c.x - r.x, c.y - r.y, -r.z),
                    axes: [
                        Vec3::new(T::ONE, T::ZERO, T::ZERO),
                        Vec3::new(T::ZERO, T::ONE, T::ZERO),
                        Vec3::unit_z(),
                    ],
                };
                (site, s.radius - c.z)
            })
        };
        // G drifts with Ġ over the first half-step as the attitude turns with L (the whole
        // pose split around the impulse, as the rattleback's).
        let r_mid = r + v * half;
        let q_mid = symmetric_free(q, l, i_eq, i_polar, half);
        let iw = InvInertia::new(q_mid, self.inv_inertia);
        let w_free = iw.apply(l);
        let [(sb, _), (ss, _)] = sites(r_mid, q_mid);
        let q_end = symmetric_free(q_mid, l, i_eq, i_polar, half);
        let [(eb, hb), (es, hs)] = sites(r_mid + v_free * half, q_end);
        let w_end = InvInertia::new(q_end, self.inv_inertia).apply(l);
        // The slip's own change from the mid-step to the end pose (the contact point running
        // over the sphere as the top turns), tangential and spin components.
        let cand = |site: &Site<T>, end: &Site<T>, h: T| {
            let u_free = site.velocity(v_free, w_free);
            let u_end = end.velocity(v_free, w_end);
            Candidate {
                h_pred: h,
                u_free,
                rolling: Default::default(),
                drift: [0, 1, 2, 3].map(|i| {
                    if i == 0 {
                        T::ZERO
                    } else {
                        u_end[i] - u_free[i]
                    }
                }),
            }
        };
        let wm = rigid_w(self.inv_mass, &iw, &[sb, ss]);
        let sol = solve_library(
            dt,
            &wm,
            &[&self.big.contact, &self.small.contact],
            &[cand(&sb, &eb, hb), cand(&ss, &es, hs)],
            &Scheme::strang(),
            warm,
        );
        let (fb, tb) = sb.load(&sol.w[0]);
        let (fs, ts) = ss.load(&sol.w[1]);
        let v1 = v_free + (fb + fs) * (dt * self.inv_mass);
        let l1 = l + (tb + ts) * dt;
        let r1 = r_mid + v1 * half;
        let q1 = symmetric_free(q_mid, l1, i_eq, i_polar, half);
        let w1 = q1.rotate_inv(l1).mul_elem(self.inv_inertia);
        [
            r1.x, r1.y, r1.z, v1.x, v1.y, v1.z, q1.w, q1.x, q1.y, q1.z, w1.x, w1.y, w1.z,
        ]
    }
}

impl<T: Real, L: FrictionLaw> Ode<T, N> for TippeTop<T, L> {
    #[inline]
    fn rhs(&self, _t: T, y: &State<T>) -> State<T> {
        let (r, v, q, omega) = split(y);
        let qn = q.normalized();
        let [big, small] = self.contacts_at(r, v, qn, omega);
        let force = big.force + small.force - Vec3::new(T::ZERO, T::ZERO, self.mass * self.gravity);
        let torque = qn.rotate_inv(big.torque + small.torque);
        let a = force * self.inv_mass;
        let dq = q.derivative(omega);
        let dw = euler_rate_inv(self.inertia, self.inv_inertia, omega, torque);
        [
            v.x, v.y, v.z, a.x, a.y, a.z, dq.w, dq.x, dq.y, dq.z, dw.x, dw.y, dw.z,
        ]
    }

    #[inline]
    fn project(&self, y: &mut State<T>) {
        let q = split(y).2.normalized();
        let [_, _, _, _, _, _, qw, qx, qy, qz, _, _, _] = y;
        (*qw, *qx, *qy, *qz) = (q.w, q.x, q.y, q.z);
    }
}

/// The top's events located between integration steps ([`crate::scenes::event`]): the first
/// time θ reaches π/2 (the axis horizontal), θ reaches θ* ([`TippeTop::cos_theta_star`], where
/// both spheres can touch: the "inversion" of the guide's table, docs/guide/src/tippe-top.md), and the small sphere first
/// reaches the floor (touch-down, [`TippeTop::penetrations`]). The θ events are located on
/// cos θ ([`TippeTop::cos_tilt`], the same roots). Feed it every accepted step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Events<T: Real> {
    cos_star: T,
    half: Crossing<T, N>,
    inversion: Crossing<T, N>,
    touch: Crossing<T, N>,
}

impl<T: Real> Events<T> {
    /// Tracking from the start (t₀, y₀).
    pub fn new<L: FrictionLaw>(top: &TippeTop<T, L>, t0: T, y0: &State<T>) -> Self {
        let cos_star = top.cos_theta_star();
        let mut e = Events {
            cos_star,
            half: Crossing::new(Direction::Falling),
            inversion: Crossing::new(Direction::Falling),
            touch: Crossing::new(Direction::Rising),
        };
        e.half.start(t0, y0, |y| top.cos_tilt(y));
        e.inversion.start(t0, y0, |y| top.cos_tilt(y) - cos_star);
        e.touch.start(t0, y0, |y| top.penetrations(y)[1]);
        e
    }

    /// After an accepted step ending at (t, y). Cost: one cos θ and one penetration
    /// evaluation (≈ 20 flops), plus two right-hand sides and the bisections on a step that
    /// crosses.
    pub fn update<L: FrictionLaw>(&mut self, top: &TippeTop<T, L>, t: T, y: &State<T>) {
        let cos_star = self.cos_star;
        let c = top.cos_tilt(y);
        self.half.update_with(top, t, y, c, |y| top.cos_tilt(y));
        self.inversion
            .update_with(top, t, y, c - cos_star, |y| top.cos_tilt(y) - cos_star);
        self.touch.update(top, t, y, |y| top.penetrations(y)[1]);
    }

    /// First time θ = π/2 (s).
    pub fn half(&self) -> Option<T> {
        self.half.first()
    }

    /// First time θ = θ* (s).
    pub fn inversion(&self) -> Option<T> {
        self.inversion.first()
    }

    /// First time the small sphere touches the floor (s).
    pub fn touch_down(&self) -> Option<T> {
        self.touch.first()
    }
}

/// The state's parts: G, Ġ, q (as stored, not normalised), ω (body).
#[inline(always)]
fn split<T: Real>(y: &State<T>) -> (Vec3<T>, Vec3<T>, Quat<T>, Vec3<T>) {
    let [rx, ry, rz, vx, vy, vz, w, x, y, z, wx, wy, wz] = *y;
    (
        Vec3::new(rx, ry, rz),
        Vec3::new(vx, vy, vz),
        Quat { w, x, y, z },
        Vec3::new(wx, wy, wz),
    )
}
