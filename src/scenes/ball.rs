//! A steel ball launched sliding and spinning on a steel plane (the guide's worked example,
//! `examples/ball_on_plane.rs`) as a scene: RK4 through [`Ode`] and the large-step
//! [`Ball::step_aware`] ([`super::step_aware`]), with the analytic figures to compare against.
//!
//! Ball: R = 10 mm, E = 2.1e11 Pa, ν = 0.3, ρ = 7,800 kg/m³ (m = 32.7 g, I = (2/5)mR²), the
//! plane the same steel, at rest (body A). Hertz, undamped; friction f = 0.1, δ = 1e-4 m/s.
//! Start: resting at its static approach (N = mg), sliding at v₀ = 1 m/s along x, spinning at
//! 100 rad/s about the vertical. Analytic (Coulomb while sliding): pure rolling at
//! t = (2/7)·v₀/(f g), then the spin decays at (3π/16)·f·N·a/I ([`Ball::analytic`]).
//!
//! State (9 scalars): G (m), Ġ (m/s), ω (rad/s, world; a sphere's attitude does not enter).

use super::integrate::Ode;
use super::rigid::Vec3;
use super::step_aware::{Candidate, InvInertia, Site, Warm, rigid_w, solve_library};
use crate::contact::Contact;
use crate::frame::{ContactFrame, WorldAxes, point_velocity};
use crate::friction::{Friction, FrictionLaw};
use crate::geometry::Curvatures;
use crate::normal::{Hertz, Material, Modulus, NormalLaw, Undamped};
use crate::shape::Newton;
use crate::step::Scheme;
use crate::{Error, Real};

/// Number of scalars in the state.
pub const N: usize = 9;

/// The state [G (3), Ġ (3), ω world (3)].
pub type State<T> = [T; N];

/// Launch speed v₀ (m/s).
pub const V0: f64 = 1.0;
/// Launch spin about the vertical (rad/s).
pub const SPIN0: f64 = 100.0;
/// Pure rolling is declared when the slip speed first falls to this fraction of v₀.
pub const ROLLING: f64 = 1e-3;
/// The spin decay is measured over this window after pure rolling starts (s).
pub const SPIN_WINDOW: (f64, f64) = (0.05, 0.45);

/// The ball on the plane with friction law `L`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball<T: Real, L: FrictionLaw> {
    radius: T,
    mass: T,
    inertia: T,
    gravity: T,
    estar: T,
    friction: T,
    contact: Contact<T, Hertz<T>, Undamped, L>,
}

/// The analytic figures (Coulomb sliding, Hertz circle's pure-spin torque).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Analytic {
    /// (2/7)·v₀/(f g) (s).
    pub t_roll: f64,
    /// (3π/16)·f·m g·a/I with a = (3 m g R/(4E*))^{1/3} (rad/s²).
    pub spin_rate: f64,
}

impl<T: Real, L: FrictionLaw> Ball<T, L> {
    /// The steel ball of the module docs with friction coefficient f and ramp δ.
    ///
    /// Errors: those of [`Friction::with_law`] and the contact's construction.
    pub fn new(f: T, delta: T) -> Result<Self, Error> {
        let c = T::from_f64;
        let steel = Material::new(c(2.1e11), c(0.3))?;
        let estar = Modulus::of(steel, steel)?;
        let radius = c(10e-3);
        let mass = c(7800.0 * 4.0 / 3.0 * core::f64::consts::PI * 1e-6);
        let contact = Contact::hertz::<Newton>(
            &Curvatures::sphere_plane(radius)?,
            estar,
            Undamped,
            Friction::<T, L>::with_law(f, delta)?,
        )?;
        Ok(Ball {
            radius,
            mass,
            inertia: c(0.4) * mass * radius * radius,
            gravity: c(9.81),
            estar: estar.get(),
            friction: f,
            contact,
        })
    }

    /// The analytic pure-rolling time and spin decay rate (f64, independent of the crate's
    /// contact code: Hertz's circle radius in closed form).
    pub fn analytic(&self) -> Analytic {
        let (m, g, f, r) = (
            self.mass.to_f64(),
            self.gravity.to_f64(),
            self.friction.to_f64(),
            self.radius.to_f64(),
        );
        let w = m * g;
        let a = libm::cbrt(3.0 * w * r / (4.0 * self.estar.to_f64()));
        Analytic {
            t_roll: 2.0 / 7.0 * V0 / (f * g),
            spin_rate: 3.0 * core::f64::consts::PI / 16.0 * f * w * a / (0.4 * m * r * r),
        }
    }

    /// At rest on the plane at the static approach, sliding at v₀ along x, spinning at 100 rad/s.
    pub fn initial_state(&self) -> State<T> {
        let h0 = self.contact.normal().approach(self.mass * self.gravity);
        let z = T::ZERO;
        [
            z,
            z,
            self.radius - h0,
            T::from_f64(V0),
            z,
            z,
            z,
            z,
            T::from_f64(SPIN0),
        ]
    }

    /// The step-aware integrator's state at [`Ball::initial_state`]: the floor carries the
    /// weight at the static approach.
    pub fn initial_warm(&self) -> Warm<T> {
        let w = self.mass * self.gravity;
        let mut warm = Warm::default();
        warm.w[0][0] = w;
        warm.h[0] = self.contact.normal().approach(w);
        warm
    }

    /// The floor contact's site at centre height `gz`: arm G → P = (0, 0, −gz), world axes.
    fn site(gz: T) -> Site<T> {
        Site {
            arm: Vec3::new(T::ZERO, T::ZERO, -gz),
            axes: [
                Vec3::new(T::ONE, T::ZERO, T::ZERO),
                Vec3::new(T::ZERO, T::ONE, T::ZERO),
                Vec3::unit_z(),
            ],
        }
    }

    /// Force and torque about G on the ball at state `y` (world).
    fn load(&self, y: &State<T>) -> (Vec3<T>, Vec3<T>) {
        let (g, v, w) = split(y);
        let h = self.radius - g.z;
        if h <= T::ZERO {
            return (Vec3::zero(), Vec3::zero());
        }
        let arm = [T::ZERO, T::ZERO, -g.z];
        let vp = point_velocity(v.into(), w.into(), arm);
        let floor = WorldAxes;
        let slip = floor.slip(vp, w.into()).unwrap_or_default();
        let wr = self.contact.wrench(h, floor.approach_rate(vp), slip);
        let load = floor.on_b(&wr, arm);
        (load.force.into(), load.torque.into())
    }

    /// The slip speed |v_P| at the patch (m/s).
    pub fn slip_speed(&self, y: &State<T>) -> T {
        let (g, v, w) = split(y);
        let vp: Vec3<T> = point_velocity(v.into(), w.into(), [T::ZERO, T::ZERO, -g.z]).into();
        vp.x.hypot(vp.y)
    }

    /// Kinetic + potential + elastic energy (J).
    pub fn energy(&self, y: &State<T>) -> T {
        let (g, v, w) = split(y);
        T::HALF * (self.mass * v.dot(v) + self.inertia * w.dot(w))
            + self.mass * self.gravity * g.z
            + self.contact.normal().energy(self.radius - g.z)
    }

    /// One step-aware step of `dt` from `y` (semi-implicit Euler with the
    /// [`super::step_aware`] wrench: gravity in the free velocity, the gap predicted from the
    /// free motion); `warm` carries the wrench from step to step.
    pub fn step_aware(&self, y: &State<T>, dt: T, warm: &mut Warm<T>) -> State<T> {
        let (g, v, w) = split(y);
        let inv_i = T::ONE / self.inertia;
        let v_free = v - Vec3::unit_z() * (self.gravity * dt);
        // The pose the contact is evaluated at: advanced with the free velocity plus the last
        // step's contact impulse (the free fall alone would lower the centre by g·Δt² — 0.25 mm
        // at 5 ms, a wrong arm for the slip).
        let (fw, tw) = Self::site(g.z).load(&warm.w[0]);
        let v_pred = v_free + fw * (dt / self.mass);
        let w_pred = w + tw * (dt * inv_i);
        let g_pred = g + v_pred * dt;
        let site = Self::site(g_pred.z);
        let iw = InvInertia::new(
            super::rigid::Quat::identity(),
            Vec3::new(inv_i, inv_i, inv_i),
        );
        let wm = rigid_w(T::ONE / self.mass, &iw, &[site]);
        let u_free = site.velocity(v_free, w);
        let u_pred = site.velocity(v_pred, w_pred);
        let cand = [Candidate {
            // The approach the free motion would give, seen from the evaluated pose.
            h_pred: self.radius - g_pred.z + dt * (u_pred[0] - u_free[0]),
            u_free,
            rolling: Default::default(),
            drift: [T::ZERO; 4],
        }];
        let sol = solve_library(
            dt,
            &wm,
            &[&self.contact],
            &cand,
            &Scheme::backward_euler(),
            warm,
        );
        let (f, t) = site.load(&sol.w[0]);
        let v1 = v_free + f * (dt / self.mass);
        let w1 = w + t * (dt * inv_i);
        let g1 = g + v1 * dt;
        [g1.x, g1.y, g1.z, v1.x, v1.y, v1.z, w1.x, w1.y, w1.z]
    }
}

impl<T: Real, L: FrictionLaw> Ode<T, N> for Ball<T, L> {
    fn rhs(&self, _t: T, y: &State<T>) -> State<T> {
        let (_, v, _) = split(y);
        let (f, t) = self.load(y);
        let a = f * (T::ONE / self.mass) - Vec3::unit_z() * self.gravity;
        let dw = t * (T::ONE / self.inertia);
        [v.x, v.y, v.z, a.x, a.y, a.z, dw.x, dw.y, dw.z]
    }
}

/// Pure rolling (the slip speed falls to [`ROLLING`]·v₀) and the spin decay rate over
/// [`SPIN_WINDOW`] after it (ω_z interpolated linearly at the window's ends). Feed it every
/// step. The rolling time is located on the step where the slip speed crosses the threshold
/// by extending the slip's fall over the step before it (sliding, the slip falls at a constant
/// rate, (7/2)·f·g: the trajectory's own dense output), or by linear interpolation between the
/// step's ends when that lands outside the step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BallEvents {
    before: Option<(f64, f64, f64)>,
    rate: Option<f64>,
    roll: Option<f64>,
    spin_at: [Option<f64>; 2],
}

impl BallEvents {
    /// After a step ending at (t, y).
    pub fn update<T: Real, L: FrictionLaw>(&mut self, ball: &Ball<T, L>, t: f64, y: &State<T>) {
        let s = ball.slip_speed(y).to_f64();
        let wz = y[8].to_f64();
        let thr = ROLLING * V0;
        if let Some((t0, s0, w0)) = self.before {
            if self.roll.is_none() && s <= thr && s0 > thr {
                let lin = t0 + (t - t0) * (s0 - thr) / (s0 - s);
                let ext = self
                    .rate
                    .filter(|r| *r > 0.0)
                    .map(|r| t0 + (s0 - thr) / r)
                    .filter(|x| *x <= t);
                self.roll = Some(ext.unwrap_or(lin));
            }
            if t > t0 {
                self.rate = Some((s0 - s) / (t - t0));
            }
            if let Some(tr) = self.roll {
                for (i, at) in [SPIN_WINDOW.0, SPIN_WINDOW.1].into_iter().enumerate() {
                    let target = tr + at;
                    if self.spin_at[i].is_none() && t >= target && t0 <= target {
                        let k = if t > t0 {
                            (target - t0) / (t - t0)
                        } else {
                            1.0
                        };
                        self.spin_at[i] = Some(w0 + k * (wz - w0));
                    }
                }
            }
        }
        self.before = Some((t, s, wz));
    }
    /// Pure rolling time (s).
    pub fn roll(&self) -> Option<f64> {
        self.roll
    }
    /// −dω_z/dt over the window (rad/s²).
    pub fn spin_rate(&self) -> Option<f64> {
        match self.spin_at {
            [Some(a), Some(b)] => Some(-(b - a) / (SPIN_WINDOW.1 - SPIN_WINDOW.0)),
            _ => None,
        }
    }
}

#[inline(always)]
fn split<T: Real>(y: &State<T>) -> (Vec3<T>, Vec3<T>, Vec3<T>) {
    (
        Vec3::new(y[0], y[1], y[2]),
        Vec3::new(y[3], y[4], y[5]),
        Vec3::new(y[6], y[7], y[8]),
    )
}
