//! One runner for the scenes' step sweeps: one scene, one law, one step, one integrator; one
//! JSON object on stdout.
//!
//! ```sh
//! cargo run --release --features scenes --example scene -- NAME --law L --dt H \
//!     [--integrator rk4|step-aware] [--end T] [--spin ±2] [--geometry 209|paper] \
//!     [--ring start|predicted] [--ramp T] [--delta D]
//! ```
//!
//! NAME: `tippe-top` (laws `best`, `simplified`, `coulomb`; θ₀ = 0.1 rad, 180 rad/s, f = 0.3,
//! δ = 1e-4 m/s; default end 2.5 s), `ball` (`best`, `coulomb`; the guide's steel ball,
//! f = 0.1, δ = 1e-4 m/s; default end 0.9 s), `rattleback` (the sliding laws at their δ → 0
//! limits: `best`, `simplified` δ = 0.1 mm/s (`BEST_DELTA`, `SIMPLIFIED_DELTA`), `coulomb`
//! 0.01 mm/s (`COULOMB_DELTA`), `ellipsoid` (ignores δ); `--delta D` another δ (m/s) for them;
//! or the rolling laws `table`, `blend`; Kane & Levinson's start,
//! `--spin` ω₀ (default −2 rad/s); default end 3 s), `bearing` (`best` full slip, δ = 0.05 m/s,
//! or the creep laws `table`, `blend`; `--geometry 209|paper`; the step-aware integrator's
//! `--ring start|predicted` (where the balls see the inner ring within a step, default `start`:
//! `RingCoupling`); `--ramp T` the load's ramp time (default 5 ms: the reference's own
//! sensitivity); default end 20 ms).
//!
//! Output keys: `scene`, `law`, `integrator`, `dt`, `end`, `steps`, `stable`, `reason` (null
//! when stable), `energy_max_rise`, `energy_split` (the step-aware rattleback: where the energy
//! went over the run, of the start energy — `rotation` (the rotation update's own error),
//! `normal` (the normal force with gravity), `friction`: `Rattleback::step_aware_split`; null
//! otherwise), `events`, `cpu_s` (the run's thread CPU time; per simulated second:
//! `cpu_s / end`). Events (s, rad/s, rad/s², N·m, or relative):
//!
//! - tippe-top: `half` (first θ = π/2), `touch` (the small sphere's first touch-down);
//! - ball: `roll` (pure rolling: slip speed 1e-3·v₀), `spin_rate` (−dω_z/dt over 0.05–0.45 s
//!   after it), with the analytic `roll_analytic`, `spin_rate_analytic`;
//! - rattleback: `reversal`, `stall` (10 % of |ω₀|), `peak_reversed` (largest spin against ω₀);
//! - bearing: `ring_torque` (inner ring, N·m), `spin_moment_inner`, `spin_moment_outer`
//!   (Σ|T_z| over the balls, N·m), `cage` (mean orbital speed / ω_c − 1), means over the last
//!   quarter of the run; `ring_vibration` the RMS speed of the inner ring's centre there (m/s).
//!
//! **Stability** (`stable: false` with a `reason`, and `events` null, instead of figures):
//! a non-finite state; an energy rise — the largest rise of the mechanical energy (incl. the
//! contacts' elastic energy) above its running minimum, relative to the start energy — above
//! [`ENERGY_TOL`] (friction and damping only dissipate, so any rise is the integrator's, not the
//! contact's); for the bearing (driven: its energy is not a check) a step that the stiffest
//! contact mode does not allow on more than 10 % of the sampled states: RK4's bound 2.785 on
//! h × the ball's normal rate √((dN/dh)/m) or h × the tangential creep/friction rate
//! |∂F/∂v|·3.5/m (a sphere's tangential inverse mass at its surface, central differences).

use std::time::Instant;

use contensou::contact::{Contact, Rolling};
use contensou::friction::rolling::{Blend, RollingLaw, Table};
use contensou::friction::{Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Simplified};
use contensou::geometry::Race;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::scenes::ball::{Ball, BallEvents};
use contensou::scenes::bearing::{BALLS, Bearing, Geometry, RaceLaw, RingCoupling};
use contensou::scenes::integrate::{Ode, rk4_step};
use contensou::scenes::rattleback::{
    BEST_DELTA, COULOMB_DELTA, Creeping, FloorLaw, Params, Rattleback, SIMPLIFIED_DELTA, SpinEvents,
};
use contensou::scenes::step_aware::Warm;
use contensou::scenes::tippe_top::{Events, Params as TopParams, TippeTop};
use contensou::select::{Elliptic, ExactGrade, Fixed, Rolls, Scene, Select, rolling_elasticity};
use contensou::shape::Newton;

/// The largest energy rise above its running minimum, relative to the start energy, that a
/// run may show and still count as stable.
const ENERGY_TOL: f64 = 1e-3;

/// RK4 runs: h × the stiffest contact rate above this on more than 10 % of the sampled states
/// (one per ms) is a mode the step does not follow (RK4 is stable to 2.785 on the negative real
/// axis, but no longer accurate there).
const MODE_BOUND: f64 = 2.0;

#[derive(Clone, Copy, PartialEq)]
enum Integrator {
    Rk4,
    StepAware,
}

struct Args {
    name: String,
    law: String,
    dt: f64,
    integrator: Integrator,
    end: Option<f64>,
    spin: f64,
    geometry: String,
    ring: RingCoupling,
    ramp: Option<f64>,
    delta: Option<f64>,
}

fn parse() -> Result<Args, String> {
    let mut it = std::env::args().skip(1);
    let name = it.next().ok_or("usage: scene NAME --law L --dt H [--integrator rk4|step-aware] [--end T] [--spin ±2] [--geometry 209|paper] [--ring start|predicted] [--ramp T] [--delta D]")?;
    let mut a = Args {
        name,
        law: "best".into(),
        dt: f64::NAN,
        integrator: Integrator::Rk4,
        end: None,
        spin: -2.0,
        geometry: "209".into(),
        ring: RingCoupling::Start,
        ramp: None,
        delta: None,
    };
    while let Some(k) = it.next() {
        let v = it.next().ok_or(format!("{k} needs a value"))?;
        let num = || v.parse::<f64>().map_err(|e| format!("{k} {v}: {e}"));
        match k.as_str() {
            "--law" => a.law = v.clone(),
            "--dt" => a.dt = num()?,
            "--end" => a.end = Some(num()?),
            "--spin" => a.spin = num()?,
            "--geometry" => a.geometry = v.clone(),
            "--ramp" => a.ramp = Some(num()?),
            "--delta" => a.delta = Some(num()?),
            "--ring" => {
                a.ring = match v.as_str() {
                    "start" => RingCoupling::Start,
                    "predicted" => RingCoupling::Predicted,
                    _ => return Err(format!("unknown ring coupling {v}")),
                }
            }
            "--integrator" => {
                a.integrator = match v.as_str() {
                    "rk4" => Integrator::Rk4,
                    "step-aware" => Integrator::StepAware,
                    _ => return Err(format!("unknown integrator {v}")),
                }
            }
            _ => return Err(format!("unknown option {k}")),
        }
    }
    if !(a.dt > 0.0 && a.dt.is_finite()) {
        return Err("--dt must be a positive step (s)".into());
    }
    Ok(a)
}

/// Non-finite states and the energy's largest rise above its running minimum.
struct Watch {
    e0: f64,
    min: f64,
    rise: f64,
    finite: bool,
    /// Sampled states, and those where h × the contact rate exceeds [`MODE_BOUND`].
    modes: (usize, usize),
}

impl Watch {
    fn new(e0: f64) -> Self {
        Watch {
            e0,
            min: e0,
            rise: 0.0,
            finite: e0.is_finite(),
            modes: (0, 0),
        }
    }
    fn mode(&mut self, h_rate: f64) {
        self.modes.0 += 1;
        if h_rate > MODE_BOUND {
            self.modes.1 += 1;
        }
    }
    /// Returns false once the run has failed.
    fn see(&mut self, e: f64, y: &[f64]) -> bool {
        if !e.is_finite() || !y.iter().all(|v| v.is_finite()) {
            self.finite = false;
            return false;
        }
        self.min = self.min.min(e);
        self.rise = self.rise.max((e - self.min) / self.e0.abs());
        self.rise <= ENERGY_TOL
    }
    fn verdict(&self) -> Option<String> {
        if !self.finite {
            Some("non-finite state".into())
        } else if self.rise > ENERGY_TOL {
            Some(format!(
                "energy rose {:.3e} of the start energy above its running minimum (tolerance {ENERGY_TOL:e}): the step is too large",
                self.rise
            ))
        } else if self.modes.1 * 10 > self.modes.0 {
            Some(format!(
                "h × the stiffest contact rate exceeds {MODE_BOUND} on {} of {} sampled states: the step does not follow that mode",
                self.modes.1, self.modes.0
            ))
        } else {
            None
        }
    }
}

struct Report {
    end: f64,
    steps: usize,
    reason: Option<String>,
    energy_max_rise: f64,
    events: Vec<(&'static str, Option<f64>)>,
    /// The rattleback's step-aware energy split over the run, of E₀: rotation, normal with
    /// gravity, friction (`Rattleback::step_aware_split`).
    split: Option<[f64; 3]>,
}

fn json_num(x: Option<f64>) -> String {
    match x {
        Some(v) if v.is_finite() => format!("{v:.9e}"),
        _ => "null".into(),
    }
}

fn steps_of(end: f64, dt: f64) -> usize {
    (end / dt).round().max(1.0) as usize
}

/// A crossing of g through zero (falling), linear between step ends.
#[derive(Default)]
struct Linear {
    before: Option<(f64, f64)>,
    first: Option<f64>,
}

impl Linear {
    fn see(&mut self, t: f64, g: f64) {
        if let Some((t0, g0)) = self.before
            && self.first.is_none()
            && g0 > 0.0
            && g <= 0.0
        {
            self.first = Some(t0 + (t - t0) * g0 / (g0 - g));
        }
        self.before = Some((t, g));
    }
}

/// Steps from `y` to `end` — RK4 or, with `--integrator step-aware`, `step_aware(y)` (the
/// state after one step) — and `observe(t, y)` sees each step's end and returns its energy.
/// Stops early once the run has failed ([`Watch`]).
fn drive<const N: usize, S: Ode<f64, N>>(
    a: &Args,
    sys: &S,
    end: f64,
    y: &mut [f64; N],
    e0: f64,
    mut step_aware: impl FnMut(&[f64; N]) -> [f64; N],
    mut observe: impl FnMut(f64, &[f64; N]) -> f64,
) -> Driven {
    let mut watch = Watch::new(e0);
    let mut steps = 0;
    let sample = ((1e-3 / a.dt).round() as usize).max(1);
    for i in 0..steps_of(end, a.dt) {
        let t0 = a.dt * i as f64;
        *y = match a.integrator {
            Integrator::Rk4 => rk4_step(sys, t0, y, a.dt),
            Integrator::StepAware => step_aware(y),
        };
        steps += 1;
        if !watch.see(observe(t0 + a.dt, y), y) {
            break;
        }
        if a.integrator == Integrator::Rk4 && i % sample == 0 {
            watch.mode(a.dt * contact_rate(sys, y));
        }
    }
    Driven { end, steps, watch }
}

/// A run [`drive`] has made: its length, its steps and its watch.
struct Driven {
    end: f64,
    steps: usize,
    watch: Watch,
}

impl Driven {
    /// The report of this run with the scene's `events`.
    fn report(self, events: Vec<(&'static str, Option<f64>)>) -> Report {
        Report {
            end: self.end,
            steps: self.steps,
            reason: self.watch.verdict(),
            energy_max_rise: self.watch.rise,
            events,
            split: None,
        }
    }
}

/// The stiffest contact rate at `y` (1/s) for a state [G, Ġ, …]: the larger of the vertical
/// mode's √|∂a_z/∂G_z| and the horizontal damping |∂a_j/∂Ġ_j| (j = x, y), by central
/// differences of the right-hand side (ε = 1e-9 m, 1e-7 m/s). A translational figure: the
/// contact's effective mass with the rotation is smaller (the rate larger) by up to ≈ 3.5×.
fn contact_rate<const N: usize, S: Ode<f64, N>>(sys: &S, y: &[f64; N]) -> f64 {
    let d = |k: usize, out: usize, eps: f64| {
        let (mut p, mut m) = (*y, *y);
        p[k] += eps;
        m[k] -= eps;
        (sys.rhs(0.0, &p)[out] - sys.rhs(0.0, &m)[out]) / (2.0 * eps)
    };
    let normal = d(2, 5, 1e-9).abs().sqrt();
    let tangential = d(3, 3, 1e-7).abs().max(d(4, 4, 1e-7).abs());
    normal.max(tangential)
}

// ---------------------------------------------------------------- tippe top

fn tippe<L: FrictionLaw>(a: &Args, delta: f64) -> Report {
    let top = TippeTop::new(
        &TopParams::paper(),
        Friction::<f64, L>::with_law(0.3, delta).unwrap(),
    )
    .unwrap();
    let end = a.end.unwrap_or(2.5);
    let mut y = top.initial_state(0.1, 180.0);
    let mut events = Events::new(&top, 0.0, &y);
    let (mut half, mut touch) = (Linear::default(), Linear::default());
    half.see(0.0, top.cos_tilt(&y));
    touch.see(0.0, -top.penetrations(&y)[1]);
    let mut warm = Warm::default();
    let e0 = top.probe(&y).energy;
    let run = drive(
        a,
        &top,
        end,
        &mut y,
        e0,
        |y| top.step_aware(y, a.dt, &mut warm),
        |t, y| {
            if a.integrator == Integrator::Rk4 {
                events.update(&top, t, y);
            } else {
                half.see(t, top.cos_tilt(y));
                touch.see(t, -top.penetrations(y)[1]);
            }
            top.probe(y).energy
        },
    );
    let (h, t) = match a.integrator {
        Integrator::Rk4 => (events.half(), events.touch_down()),
        Integrator::StepAware => (half.first, touch.first),
    };
    let p = top.probe(&y);
    run.report(vec![
        ("half", h),
        ("touch", t),
        ("theta_end", Some(p.theta)),
        ("spin_end", Some(p.spin)),
    ])
}

// ---------------------------------------------------------------- ball

fn ball<L: FrictionLaw>(a: &Args) -> Report {
    let b = Ball::<f64, L>::new(0.1, 1e-4).unwrap();
    let end = a.end.unwrap_or(0.9);
    let mut y = b.initial_state();
    let mut ev = BallEvents::default();
    ev.update(&b, 0.0, &y);
    let mut warm = b.initial_warm();
    let e0 = b.energy(&y);
    let run = drive(
        a,
        &b,
        end,
        &mut y,
        e0,
        |y| b.step_aware(y, a.dt, &mut warm),
        |t, y| {
            ev.update(&b, t, y);
            b.energy(y)
        },
    );
    let an = b.analytic();
    run.report(vec![
        ("roll", ev.roll()),
        ("spin_rate", ev.spin_rate()),
        ("roll_analytic", Some(an.t_roll)),
        ("spin_rate_analytic", Some(an.spin_rate)),
    ])
}

// ---------------------------------------------------------------- rattleback

fn rattle<L: FloorLaw<f64>>(a: &Args, rb: &Rattleback<f64, L>) -> Report {
    let end = a.end.unwrap_or(3.0);
    let spin0 = a.spin;
    let mut y = rb.initial_state(0.5f64.to_radians(), spin0);
    let mut events = SpinEvents::new(rb, 0.0, &y, spin0, 0.1);
    let (sign, level) = (spin0.signum(), 0.1 * spin0.abs());
    let (mut rev, mut brake) = (Linear::default(), Linear::default());
    let s0 = rb.spin(&y) * sign;
    rev.see(0.0, s0 + level);
    brake.see(0.0, s0 - level);
    let mut peak: f64 = 0.0;
    let mut warm = Warm::default();
    let e0 = rb.probe(&y).energy;
    let mut split = [0.0; 3];
    let run = drive(
        a,
        rb,
        end,
        &mut y,
        e0,
        |y| {
            let (y1, s) = rb.step_aware_split(y, a.dt, &mut warm);
            for (sum, part) in split.iter_mut().zip([s.rotation, s.normal, s.friction]) {
                *sum += part / e0;
            }
            y1
        },
        |t, y| {
            let s = rb.spin(y) * sign;
            peak = peak.max(-s);
            if a.integrator == Integrator::Rk4 {
                events.update(rb, t, y);
            } else {
                rev.see(t, s + level);
                brake.see(t, s - level);
            }
            rb.probe(y).energy
        },
    );
    let (r, st) = match a.integrator {
        Integrator::Rk4 => (events.reversal(), events.stall()),
        Integrator::StepAware => (
            rev.first,
            if rev.first.is_some() {
                None
            } else {
                brake.first
            },
        ),
    };
    let spin_end = rb.spin(&y);
    let mut report = run.report(vec![
        ("reversal", r),
        ("stall", st),
        ("peak_reversed", Some(peak)),
        ("spin_end", Some(spin_end)),
    ]);
    if a.integrator == Integrator::StepAware {
        report.split = Some(split);
    }
    report
}

fn rattle_law(a: &Args) -> Result<Report, String> {
    let p = Params::<f64>::kane_levinson();
    let sliding = |a: &Args| -> Option<Report> {
        fn go<L: FrictionLaw>(a: &Args, p: &Params<f64>, delta: f64) -> Report {
            let rb = Rattleback::new(p, Friction::<f64, L>::with_law(0.3, delta).unwrap()).unwrap();
            rattle(a, &rb)
        }
        Some(match a.law.as_str() {
            "best" => go::<Best>(a, &p, a.delta.unwrap_or(BEST_DELTA)),
            "simplified" => go::<Simplified>(a, &p, a.delta.unwrap_or(SIMPLIFIED_DELTA)),
            // Ignores δ (Coulomb's sign law at rest).
            "ellipsoid" => go::<Ellipsoid>(a, &p, a.delta.unwrap_or(1e-3)),
            "coulomb" => go::<Coulomb>(a, &p, a.delta.unwrap_or(COULOMB_DELTA)),
            _ => return None,
        })
    };
    if let Some(r) = sliding(a) {
        return Ok(r);
    }
    fn creep<L: RollingLaw>(a: &Args, p: &Params<f64>) -> Report {
        let f = Friction::<f64, Best>::with_law(0.3, 1e-3).unwrap();
        let rb = Rattleback::<f64, Creeping<L>>::rolling(p, f, p.elasticity().unwrap()).unwrap();
        rattle(a, &rb)
    }
    match a.law.as_str() {
        "table" => Ok(creep::<Table>(a, &p)),
        "blend" => Ok(creep::<Blend>(a, &p)),
        l => Err(format!("rattleback: unknown law {l}")),
    }
}

// ---------------------------------------------------------------- bearing

fn bearing_run<C: RaceLaw<f64>>(a: &Args, b: &Bearing<f64, C>) -> Report {
    let end = a.end.unwrap_or(0.02);
    let g = *b.geometry();
    let wc = g.cage_speed();
    let m = g.ball_mass;
    let n = steps_of(end, a.dt);
    let every = ((1e-6 / a.dt).round() as usize).max(1);
    let check_every = ((2e-5 / a.dt).round() as usize).max(1);
    let mut y = b.initial_state();
    let mut warm = [Warm::default(); BALLS];
    let (mut count, mut ring, mut sm_in, mut sm_out, mut cage) = (0.0f64, 0.0, 0.0, 0.0, 0.0);
    // The inner ring's vibration: its centre's mean squared velocity.
    let mut ring_v2 = 0.0f64;
    let (mut checks, mut over) = (0usize, 0usize);
    let mut finite = true;
    let mut done = 0;
    for i in 0..n {
        let t1 = a.dt * (i + 1) as f64;
        let loads = match a.integrator {
            Integrator::Rk4 => {
                y = rk4_step(b, t1 - a.dt, &y, a.dt);
                None
            }
            Integrator::StepAware => {
                let (y1, l) = b.step_aware_with(t1 - a.dt, &y, a.dt, &mut warm, a.ring);
                y = y1;
                Some(l)
            }
        };
        done += 1;
        // A ball off its pitch circle by more than its diameter, or the ring off centre by
        // more than 1 mm: the step has thrown the balls out of the races.
        let escaped = (0..BALLS).any(|k| {
            let r = y[6 + 9 * k].hypot(y[7 + 9 * k]);
            (r - 0.5 * g.pitch_diameter).abs() >= g.ball_diameter
        }) || y[0].hypot(y[1]).hypot(y[2]) >= 1e-3;
        if !y.iter().all(|v| v.is_finite()) || escaped {
            finite = false;
            break;
        }
        if a.integrator == Integrator::Rk4 && (i + 1) % check_every == 0 && t1 > g.ramp {
            checks += 1;
            let mut rate: f64 = 0.0;
            for k in 0..BALLS {
                let (ci, co) = b.contacts(&y, k);
                for c in [ci, co] {
                    if c.h > 0.0 {
                        rate = rate.max((1.5 * c.n / c.h / m).sqrt());
                    }
                }
                // Tangential rate: central differences of the ball's circumferential force in
                // its circumferential velocity.
                let base = 6 + 9 * k;
                let (px, py) = (y[base], y[base + 1]);
                let r = px.hypot(py);
                let e = [-py / r, px / r];
                let eps = 1e-7;
                let force = |s: f64| {
                    let mut z = y;
                    z[base + 3] += s * e[0];
                    z[base + 4] += s * e[1];
                    let (ci, co) = b.contacts(&z, k);
                    (ci.force + co.force).x * e[0] + (ci.force + co.force).y * e[1]
                };
                let d = (force(eps) - force(-eps)) / (2.0 * eps);
                rate = rate.max(d.abs() * 3.5 / m);
            }
            if a.dt * rate > MODE_BOUND {
                over += 1;
            }
        }
        if (i + 1) % every == 0 && t1 >= 0.75 * end {
            count += 1.0;
            let mut orbit = 0.0;
            match loads {
                Some(l) => {
                    ring += l.ring_torque;
                    sm_in += l.spin_moment[0];
                    sm_out += l.spin_moment[1];
                }
                None => {
                    ring += b.inner_ring_torque(&y);
                    for k in 0..BALLS {
                        let (ci, co) = b.contacts(&y, k);
                        sm_in += ci.tz.abs();
                        sm_out += co.tz.abs();
                    }
                }
            }
            for k in 0..BALLS {
                let s = &y[6 + 9 * k..6 + 9 * k + 6];
                orbit += (s[0] * s[4] - s[1] * s[3]) / (s[0] * s[0] + s[1] * s[1]);
            }
            cage += orbit / BALLS as f64 / wc - 1.0;
            ring_v2 += y[3] * y[3] + y[4] * y[4] + y[5] * y[5];
        }
    }
    let reason = if !finite {
        Some("non-finite state, or the balls left the races".to_string())
    } else if checks > 0 && over * 10 > checks {
        Some(format!(
            "h × the stiffest contact rate (normal or creep) exceeds {MODE_BOUND} on {over} of {checks} sampled states: the step does not follow that mode"
        ))
    } else {
        None
    };
    let c = count.max(1.0);
    Report {
        end,
        steps: done,
        reason,
        energy_max_rise: f64::NAN,
        split: None,
        events: vec![
            ("ring_torque", Some(ring / c)),
            ("spin_moment_inner", Some(sm_in / c)),
            ("spin_moment_outer", Some(sm_out / c)),
            ("cage", Some(cage / c)),
            ("ring_vibration", Some((ring_v2 / c).sqrt())),
        ],
    }
}

fn bearing(a: &Args) -> Result<Report, String> {
    let mut g = match a.geometry.as_str() {
        "209" => Geometry::<f64>::bearing_209(),
        "paper" => Geometry::paper_e2(),
        x => return Err(format!("unknown geometry {x}")),
    };
    if let Some(r) = a.ramp {
        if !(r > 0.0 && r.is_finite()) {
            return Err("--ramp must be a positive time (s)".into());
        }
        g.ramp = r;
    }
    let estar = Modulus::new(1.142857e11).unwrap();
    let damping = HuntCrossley::new(0.3).unwrap();
    let best = |race| {
        Contact::hertz::<Newton>(
            &g.curvatures(race).unwrap(),
            estar,
            damping,
            Friction::<f64, Best>::new(0.07, 0.05).unwrap(),
        )
        .unwrap()
    };
    match a.law.as_str() {
        "best" => Ok(bearing_run(
            a,
            &Bearing::new(&g, best(Race::Inner), best(Race::Outer)).unwrap(),
        )),
        "table" => {
            type RollingRace = Scene<Elliptic, Fixed, Rolls, ExactGrade, f64>;
            let table = |race| {
                RollingRace::build(
                    &g.curvatures(race).unwrap(),
                    estar,
                    damping,
                    Friction::new(0.07, 0.05).unwrap(),
                )
                .unwrap()
            };
            Ok(bearing_run(
                a,
                &Bearing::new(&g, table(Race::Inner), table(Race::Outer)).unwrap(),
            ))
        }
        "blend" => {
            let el = rolling_elasticity(estar).unwrap();
            let blend = |race| Rolling::<_, _, Blend>::new(best(race), el).unwrap();
            Ok(bearing_run(
                a,
                &Bearing::new(&g, blend(Race::Inner), blend(Race::Outer)).unwrap(),
            ))
        }
        l => Err(format!("bearing: unknown law {l}")),
    }
}

/// CPU time of this thread (s).
fn cpu() -> f64 {
    // The first field of schedstat: time on the CPU (ns).
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}

fn main() {
    let a = match parse() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("scene: {e}");
            std::process::exit(2);
        }
    };
    let wall = Instant::now();
    let c0 = cpu();
    let r = match a.name.as_str() {
        "tippe-top" => match a.law.as_str() {
            "best" => Ok(tippe::<Best>(&a, 1e-4)),
            "simplified" => Ok(tippe::<Simplified>(&a, 1e-4)),
            "coulomb" => Ok(tippe::<Coulomb>(&a, 1e-4)),
            l => Err(format!("tippe-top: unknown law {l}")),
        },
        "ball" => match a.law.as_str() {
            "best" => Ok(ball::<Best>(&a)),
            "coulomb" => Ok(ball::<Coulomb>(&a)),
            l => Err(format!("ball: unknown law {l}")),
        },
        "rattleback" => rattle_law(&a),
        "bearing" => bearing(&a),
        n => Err(format!(
            "unknown scene {n} (tippe-top, ball, rattleback, bearing)"
        )),
    };
    let r = match r {
        Ok(r) => r,
        Err(e) => {
            eprintln!("scene: {e}");
            std::process::exit(2);
        }
    };
    let mut cpu_s = cpu() - c0;
    if !cpu_s.is_finite() {
        cpu_s = wall.elapsed().as_secs_f64();
    }
    let events = if r.reason.is_some() {
        "null".to_string()
    } else {
        let body: Vec<String> = r
            .events
            .iter()
            .map(|(k, v)| format!("\"{k}\":{}", json_num(*v)))
            .collect();
        format!("{{{}}}", body.join(","))
    };
    println!(
        "{{\"scene\":\"{}\",\"law\":\"{}\",\"integrator\":\"{}\",\"dt\":{:e},\"end\":{},\"steps\":{},\"stable\":{},\"reason\":{},\"energy_max_rise\":{},\"energy_split\":{},\"events\":{},\"cpu_s\":{:.4}}}",
        a.name,
        a.law,
        if a.integrator == Integrator::Rk4 {
            "rk4"
        } else {
            "step-aware"
        },
        a.dt,
        r.end,
        r.steps,
        r.reason.is_none(),
        r.reason
            .as_ref()
            .map_or("null".into(), |s| format!("\"{}\"", s.replace('"', "'"))),
        json_num(Some(r.energy_max_rise)),
        r.split
            .map_or("null".into(), |[rot, normal, friction]| format!(
                "{{\"rotation\":{},\"normal\":{},\"friction\":{}}}",
                json_num(Some(rot)),
                json_num(Some(normal)),
                json_num(Some(friction))
            )),
        events,
        cpu_s
    );
}
