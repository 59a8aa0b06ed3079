//! A contact in your own loop (the guide's worked example, [`contensou::guide`]): a steel ball
//! launched sliding and spinning on a steel plane, integrated by semi-implicit Euler with the
//! default friction law, against the analytic results.
//!
//! ```sh
//! cargo run --release --example ball_on_plane   # prints analytic and measured figures
//! ```
//!
//! Ball: R = 10 mm, E = 2.1e11 Pa, ν = 0.3, ρ = 7,800 kg/m³ (m = 32.7 g, I = (2/5)mR²); the
//! plane the same steel, at rest (body A; the ball is body B). f = 0.1, δ = 1e-4 m/s, `Best`.
//! Start: resting at its static approach h₀ (N = mg), sliding at v₀ = 1 m/s along x, spinning
//! at 100 rad/s about the vertical. With Coulomb friction (the spin barely changes the force
//! while the slip is much faster than aω ≈ 3 mm/s):
//!
//! - the slip v_P = v − Rω_y falls at (7/2)·f·g (the centre decelerates at fg, the rolling
//!   speed Rω_y rises at (5/2)fg): pure rolling at **t = (2/7)·v₀/(f g)** with **v = (5/7)·v₀**;
//! - then v_P = 0 and the spin decays at the constant rate of the pure-spin Contensou torque on
//!   the Hertz circle, T = (3π/16)·f·N·a: **dω_z/dt = −(3π/16)·f·N·a/I**, with
//!   a = (3NR/(4E*))^{1/3}.
//!
//! The step is half the smallest of the library's stable steps: the slip's
//! ([`Contact::stable_step`] with the rolling ball's effective mass 2m/7), the spin's
//! ([`Contact::stable_spin_step`]) and the vertical contact oscillation's (2/ω_n,
//! ω_n² = (dN/dh)/m). `host-tests/ball_on_plane.rs` asserts the figures within 1 %.

use contensou::contact::Contact;
use contensou::frame::{ContactFrame, Frame, MajorAxis, point_velocity};
use contensou::friction::{Explicit, Friction};
use contensou::geometry::Curvatures;
use contensou::normal::{Material, Modulus, NormalLaw, Undamped};
use contensou::shape::Newton;
use std::f64::consts::PI;

/// Ball radius R (m).
pub const RADIUS: f64 = 10e-3;
/// Steel density (kg/m³).
pub const DENSITY: f64 = 7800.0;
/// Friction coefficient f.
pub const F: f64 = 0.1;
/// Regularization speed δ (m/s).
pub const DELTA: f64 = 1e-4;
/// Gravity g (m/s²).
pub const G: f64 = 9.81;
/// Launch speed v₀ (m/s) and spin (rad/s).
pub const V0: f64 = 1.0;
/// Initial spin about the vertical (rad/s).
pub const SPIN0: f64 = 100.0;
/// Pure rolling is declared when the slip speed |v_P| first falls to this fraction of v₀.
pub const ROLLING: f64 = 1e-3;
/// The spin decay is measured over this time after pure rolling starts (s).
pub const SPIN_WINDOW: (f64, f64) = (0.05, 0.45);

/// Analytic and measured figures of one run.
#[derive(Debug)]
pub struct Outcome {
    /// Step (s) and the number of steps taken.
    pub dt: f64,
    /// Steps integrated.
    pub steps: usize,
    /// (2/7)·v₀/(f g) (s).
    pub t_roll_analytic: f64,
    /// First time with |v_P| = `ROLLING`·v₀ (s), located between steps (linear interpolation).
    pub t_roll: f64,
    /// Centre speed at `t_roll` (m/s, interpolated the same way); analytic (5/7)·v₀.
    pub v_roll: f64,
    /// (3π/16)·f·N·a/I (rad/s²).
    pub spin_rate_analytic: f64,
    /// −Δω_z/Δt over `SPIN_WINDOW` after `t_roll` (rad/s²).
    pub spin_rate: f64,
}

/// Builds the contact, picks the step (half the smallest stable step) and integrates
/// (semi-implicit Euler).
pub fn run() -> Result<Outcome, contensou::Error> {
    run_at(0.5)
}

/// [`run`] with the step `fraction` × the smallest stable step (the step-halving check).
pub fn run_at(fraction: f64) -> Result<Outcome, contensou::Error> {
    let steel = Material::new(2.1e11, 0.3)?;
    let estar = Modulus::of(steel, steel)?;
    let contact = Contact::hertz::<Newton>(
        &Curvatures::sphere_plane(RADIUS)?,
        estar,
        Undamped,
        Friction::<f64>::new(F, DELTA)?, // the default law, `Best`
    )?;
    let mass = DENSITY * 4.0 / 3.0 * PI * RADIUS.powi(3);
    let inertia = 0.4 * mass * RADIUS * RADIUS;
    let weight = mass * G;

    // At rest on the plane: the approach that carries the weight.
    let h0 = contact.normal().approach(weight);
    let a0 = contact.normal().patch(h0).a;

    // The step: `fraction` of the smallest stable step (slip with the rolling ball's effective
    // mass 2m/7, spin, and the vertical contact oscillation, stiffness dN/dh = (3/2)N/h).
    let dt_slip = contact.stable_step(2.0 * mass / 7.0, weight, Explicit::Euler);
    let dt_spin = contact.stable_spin_step(a0, inertia, weight, Explicit::Euler);
    let omega_n = (1.5 * weight / h0 / mass).sqrt();
    let dt = fraction * dt_slip.min(dt_spin).min(2.0 / omega_n);

    // Body B = the ball (centre G, velocity v, angular velocity w, world frame); body A = the
    // plane, at rest. Contact frame: normal up (A → B), x along the world x (a circle: any
    // tangent is a major axis).
    let frame = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::ALONG);
    let mut g = [0.0, 0.0, RADIUS - h0];
    let mut v = [V0, 0.0, 0.0];
    let mut w = [0.0, 0.0, SPIN0];

    let t_roll_analytic = 2.0 / 7.0 * V0 / (F * G);
    let t_end = 1.1 * t_roll_analytic + SPIN_WINDOW.1;
    let (mut t, mut steps) = (0.0, 0);
    let mut roll: Option<(f64, f64)> = None;
    // The previous state's (t, slip speed, speed), for locating pure rolling between steps.
    let mut before: Option<(f64, f64, f64)> = None;
    let mut spin_at: [Option<(f64, f64)>; 2] = [None; 2];
    while t < t_end {
        // The patch centre P: the plane's point under the centre; arm = P − G.
        let h = RADIUS - g[2];
        let arm = [0.0, 0.0, -g[2]];
        let v_rel = point_velocity(v, w, arm); // minus the plane's (zero) velocity at P
        let slip = frame.slip(v_rel, w)?;
        let wrench = contact.wrench(h, frame.approach_rate(v_rel), slip);
        let load = frame.on_b(&wrench, arm); // force at P, torque about G

        // Pure rolling: the slip speed at this state (time t) falls through ROLLING·v₀. Located
        // between this state and the previous one by linear interpolation — semi-implicit
        // Euler's own dense output (velocities are linear in t over a step); not the step's end.
        let slip_speed = slip.vx().hypot(slip.vy());
        let speed = v[0].hypot(v[1]);
        if roll.is_none()
            && let Some((t0, s0, u0)) = before
            && slip_speed <= ROLLING * V0
        {
            let s = (s0 - ROLLING * V0) / (s0 - slip_speed);
            roll = Some((t0 + s * (t - t0), u0 + s * (speed - u0)));
        }
        before = Some((t, slip_speed, speed));

        // Semi-implicit Euler: velocities first, then the position with the new velocity.
        for i in 0..3 {
            v[i] += dt * load.force[i] / mass;
            w[i] += dt * load.torque[i] / inertia; // a sphere: I isotropic, no gyroscopic term
        }
        v[2] -= dt * G;
        for i in 0..3 {
            g[i] += dt * v[i];
        }
        t += dt;
        steps += 1;
        if let Some((t_r, _)) = roll {
            for (k, at) in [SPIN_WINDOW.0, SPIN_WINDOW.1].into_iter().enumerate() {
                if spin_at[k].is_none() && t >= t_r + at {
                    spin_at[k] = Some((t, w[2]));
                }
            }
        }
    }
    let (t_roll, v_roll) = roll.unwrap_or((f64::NAN, f64::NAN));
    let spin_rate = match spin_at {
        [Some((t1, w1)), Some((t2, w2))] => -(w2 - w1) / (t2 - t1),
        _ => f64::NAN,
    };
    // Independent of the library: Hertz's circle radius and the pure-spin torque (3π/16)fNa.
    let a = (3.0 * weight * RADIUS / (4.0 * estar.get())).cbrt();
    Ok(Outcome {
        dt,
        steps,
        t_roll_analytic,
        t_roll,
        v_roll,
        spin_rate_analytic: 3.0 * PI / 16.0 * F * weight * a / inertia,
        spin_rate,
    })
}

fn main() -> Result<(), contensou::Error> {
    let o = run()?;
    let pct = |got: f64, want: f64| 100.0 * (got - want) / want;
    println!(
        "semi-implicit Euler, dt = {:.3e} s ({} steps), default law (Best), f = {F}, δ = {DELTA} m/s",
        o.dt, o.steps
    );
    println!(
        "pure rolling at  t = {:.5} s   (analytic (2/7)·v₀/(f g) = {:.5} s, {:+.3} %)",
        o.t_roll,
        o.t_roll_analytic,
        pct(o.t_roll, o.t_roll_analytic)
    );
    println!(
        "rolling speed    v = {:.5} m/s (analytic (5/7)·v₀ = {:.5} m/s, {:+.3} %)",
        o.v_roll,
        5.0 / 7.0 * V0,
        pct(o.v_roll, 5.0 / 7.0 * V0)
    );
    println!(
        "spin decay  −dω/dt = {:.5} rad/s² (analytic (3π/16)·f·N·a/I = {:.5} rad/s², {:+.3} %)",
        o.spin_rate,
        o.spin_rate_analytic,
        pct(o.spin_rate, o.spin_rate_analytic)
    );
    Ok(())
}
