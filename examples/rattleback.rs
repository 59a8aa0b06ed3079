//! The rattleback (Kane & Levinson's body, `contensou::scenes::rattleback`) with each friction
//! law — the full-slip laws `best`, `simplified`, `ellipsoid`, `coulomb` and the rolling laws
//! `table`, `blend` (Kalker's creep from the contact's rolling velocity, polymer on glass:
//! `Params::elasticity`) — spun both ways: spin reversal or stall, peak rocking, peak reversed
//! spin, final spin and energy.
//!
//! ```sh
//! cargo run --release --features scenes --example rattleback         # into out/
//! cargo run --release --features scenes --example rattleback -- DIR  # into DIR
//! ```
//!
//! `RATTLEBACK_H` (s), `RATTLEBACK_ESTAR` (Pa), `RATTLEBACK_SAMPLE` (s, the output
//! interval, default 10 ms), `RATTLEBACK_DELTA` (m/s, the full-slip laws' δ, default each
//! law's converged δ, below) and `RATTLEBACK_T` (s, default 20) override the step (for every
//! law), E* (the rolling laws' G scales with it), the sampling, δ and the run's length (docs/guide/src/rattleback.md: step, stiffness, sampling and δ checks);
//! `RATTLEBACK_LAWS=table,blend` runs only the named laws (`fastsim`, `fastsim-16`: FASTSIM
//! on a 32 × 32 or 16 × 16 grid as a cross-check of the creep laws, run only when named); `RATTLEBACK_STIFFNESS=1` prints
//! h × the friction's tangential rate against RK4's bound (before / after the event).
//!
//! Writes `rattleback_summary.csv` (`law,direction,reversal_s,stall_s,peak_rock_rad,
//! final_spin,energy_start,energy_end,reversal_sampled_s,stall_sampled_s,peak_reversed_spin`,
//! empty fields when
//! there is none) and one labelled PNG of ω·ẑ(t) per law (`rattleback_<law>.png`, both
//! directions). `reversal_s`, `stall_s`: located between the RK4 steps on every step
//! ([`SpinEvents`], Hermite interpolant + bisection), independent of the output sampling;
//! `*_sampled_s`: the first output sample past the threshold (the figures before event
//! location, for comparison).
//!
//! Start (Kane & Levinson 1982): roll = pitch = 0.5°, rolling (the contact point at rest),
//! the static approach. Spin ω₀ = ∓2 rad/s instead of their 5 rad/s: with the compliant contact
//! and f = 0.3, rolling at 5 rad/s needs more than f (the friction ratio saturates within
//! 0.1 s and the body slides), at 2 rad/s the peak |F_t|/N is 0.23–0.25 < f (printed per
//! run; the `Ellipsoid` law touches f briefly).
//! Friction f = 0.3; each full-slip law at the δ → 0 limit of its events
//! (bench-results/rattleback-delta.md): `best` and `simplified` δ = 0.1 mm/s (`BEST_DELTA`,
//! `SIMPLIFIED_DELTA`), RK4 h = 10 µs; `coulomb` δ = 0.01 mm/s (`COULOMB_DELTA`), h = 2 µs;
//! `ellipsoid` (ignores δ) h = 25 µs; the rolling laws (no δ) h = 0.1 ms — each step gives the
//! same events to ≤ 1 µs at half of it. 20 s; ≈ 1 min in all.
//!
//! - **reversal**: the first time the spin has turned and reached 10 % of |ω₀| the other way;
//! - **stall**: no reversal within the run, and the spin was braked to below 10 % of |ω₀|:
//!   the first time it got there (the spin wobbles with the rocking: the first dip counts).

use std::fmt::Write as _;

use contensou::friction::rolling::{Blend, FastsimGrid, RollingLaw, Table};
use contensou::friction::{Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Simplified};
use contensou::scenes::integrate::rk4;
use contensou::scenes::rattleback::{
    BEST_DELTA, COULOMB_DELTA, Creeping, FloorLaw, Params, Probe, Rattleback, SIMPLIFIED_DELTA,
    SpinEvents,
};
use plotters::prelude::*;
use plotters::style::{FontStyle, register_font};

const F: f64 = 0.3;
/// A full-slip law's regularisation speed δ (m/s): the law's converged `default` (the limit
/// δ → 0: `BEST_DELTA`, `SIMPLIFIED_DELTA`, `COULOMB_DELTA`); `RATTLEBACK_DELTA` overrides it
/// for every law (the guide's δ study; the rolling laws do not use it, `Ellipsoid` ignores it).
fn delta(default: f64) -> f64 {
    env_or("RATTLEBACK_DELTA", default)
}
const TILT_DEG: f64 = 0.5;
const SPIN: f64 = 2.0;
/// RK4 step (s): the law's `default` (small enough for its δ: the same events to 1 µs at half
/// of it); `RATTLEBACK_H` overrides it for every law (the step-size check in the guide).
fn step(default: f64) -> f64 {
    env_or("RATTLEBACK_H", default)
}
/// Simulated time (s); `RATTLEBACK_T` overrides it.
fn t_end() -> f64 {
    env_or("RATTLEBACK_T", 20.0)
}
/// Output interval (s); `RATTLEBACK_SAMPLE` overrides it (the sampling check in the guide).
fn sample() -> f64 {
    env_or("RATTLEBACK_SAMPLE", 1e-2)
}

fn env_or(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|h| h.parse().ok())
        .unwrap_or(default)
}

struct Run {
    law: &'static str,
    direction: &'static str,
    spin0: f64,
    rows: Vec<(f64, Probe<f64>)>,
    events: SpinEvents<f64>,
    /// (t, h·friction rate) per step with `RATTLEBACK_STIFFNESS`.
    stiff: Vec<(f64, f64)>,
}

impl Run {
    /// Located between steps.
    fn reversal(&self) -> Option<f64> {
        self.events.reversal()
    }
    /// Located between steps.
    fn stall(&self) -> Option<f64> {
        self.events.stall()
    }
    /// The first output sample past the reversal threshold.
    fn sampled_reversal(&self) -> Option<f64> {
        let s = self.spin0.signum();
        self.rows
            .iter()
            .find(|(_, p)| p.spin * s <= -0.1 * self.spin0.abs())
            .map(|r| r.0)
    }
    /// The first output sample past the stall threshold.
    fn sampled_stall(&self) -> Option<f64> {
        if self.sampled_reversal().is_some() {
            return None;
        }
        self.rows
            .iter()
            .find(|(_, p)| p.spin.abs() < 0.1 * self.spin0.abs())
            .map(|r| r.0)
    }
    fn peak_rock(&self) -> f64 {
        self.rows
            .iter()
            .map(|(_, p)| p.pitch.abs().max(p.roll.abs()))
            .fold(0.0, f64::max)
    }
    fn peak(&self, f: impl Fn(&Probe<f64>) -> f64) -> f64 {
        self.rows.iter().map(|(_, p)| f(p)).fold(0.0, f64::max)
    }
}

/// Kane & Levinson's body; `RATTLEBACK_ESTAR` overrides E* (Pa) for the stiffness study.
fn params() -> Params<f64> {
    let p = Params::kane_levinson();
    Params {
        estar: env_or("RATTLEBACK_ESTAR", p.estar),
        ..p
    }
}

fn run<L: FloorLaw<f64>>(
    rb: &Rattleback<f64, L>,
    law: &'static str,
    direction: &'static str,
    spin0: f64,
    h: f64,
) -> Run {
    let y0 = rb.initial_state(TILT_DEG.to_radians(), spin0);
    let mut rows = vec![(0.0, rb.probe(&y0))];
    let mut events = SpinEvents::new(rb, 0.0, &y0, spin0, 0.1);
    let every = ((sample() / h).round() as usize).max(1);
    let track = std::env::var("RATTLEBACK_STIFFNESS").is_ok();
    let mut stiff = Vec::new();
    rk4(rb, 0.0, y0, h, (t_end() / h).round() as usize, |i, t, y| {
        events.update(rb, t, y);
        if i % every == 0 {
            rows.push((t, rb.probe(y)));
        }
        if track {
            stiff.push((t, h * friction_rate(rb, y)));
        }
    });
    Run {
        law,
        direction,
        spin0,
        rows,
        events,
        stiff,
    }
}

/// The friction's tangential rate at state `y` (1/s, a diagnostic: `RATTLEBACK_STIFFNESS`):
/// the larger over world x, y of −e·∂u̇_B/∂u_B, u_B the material velocity at P, by central
/// differences of the right-hand side in Ġ (ε = 1e-9 m/s, inside Kalker's linear range).
/// h times it against RK4's bound on the negative real axis, 2.785: above it an explicit step
/// does not resolve the creep force (chatter).
fn friction_rate<L: FloorLaw<f64>>(rb: &Rattleback<f64, L>, y: &[f64; 13]) -> f64 {
    use contensou::scenes::integrate::Ode;
    use contensou::scenes::rigid::{Quat, Vec3};
    let arm = rb.geometry(y).arm;
    let q = Quat {
        w: y[6],
        x: y[7],
        y: y[8],
        z: y[9],
    }
    .normalized();
    let eps = 1e-9;
    let mut rate = 0.0f64;
    for (k, e) in [(3, Vec3::new(1.0, 0.0, 0.0)), (4, Vec3::new(0.0, 1.0, 0.0))] {
        let du = |s: f64| {
            let mut z = *y;
            z[k] += s;
            let f = rb.rhs(0.0, &z);
            let alpha = q.rotate(Vec3::new(f[10], f[11], f[12]));
            Vec3::new(f[3], f[4], f[5]) + alpha.cross(arm)
        };
        let d = (du(eps) - du(-eps)) * (0.5 / eps);
        rate = rate.max(-d.dot(e));
    }
    rate
}

/// Both directions at the RK4 step `h`.
fn both<L: FloorLaw<f64>>(rb: &Rattleback<f64, L>, law: &'static str, h: f64) -> [Run; 2] {
    println!("{law}: RK4 h = {h:e} s");
    // δ > 0 for these parameters: the negative spin is the unstable one.
    [
        run(rb, law, "unstable", -SPIN, h),
        run(rb, law, "steady", SPIN, h),
    ]
}

/// Both directions with the full-slip law `L` at its δ ([`delta`]) and RK4 step ([`step`]).
fn sliding<L: FrictionLaw>(law: &'static str, delta_default: f64, h_default: f64) -> [Run; 2] {
    let d = delta(delta_default);
    println!("{law}: δ = {d:e} m/s");
    let rb = Rattleback::new(&params(), Friction::<f64, L>::with_law(F, d).unwrap()).unwrap();
    both(&rb, law, step(h_default))
}

/// Both directions with the rolling law `L` (Kalker's creep saturating to `Best`'s full slip;
/// the contact's δ is not used) and the polymer-on-glass elasticity ([`Params::elasticity`]).
fn creeping<L: RollingLaw>(law: &'static str) -> [Run; 2] {
    let p = params();
    let friction = Friction::<f64, Best>::with_law(F, delta(1e-3)).unwrap();
    let rb =
        Rattleback::<f64, Creeping<L>>::rolling(&p, friction, p.elasticity().unwrap()).unwrap();
    both(&rb, law, step(1e-4))
}

/// A law's two runs (both spin directions), labelled with its name.
type Runs = fn(&'static str) -> [Run; 2];

/// Whether `RATTLEBACK_LAWS` (comma-separated names; default all but the FASTSIM
/// cross-checks) asks for `law`.
fn wanted(law: &str) -> bool {
    std::env::var("RATTLEBACK_LAWS").map_or(!law.starts_with("fastsim"), |l| {
        l.split(',').any(|x| x == law)
    })
}

fn opt(x: Option<f64>) -> String {
    x.map_or(String::new(), |t| format!("{t:.4}"))
}

/// A located time to the µs (the step-halving checks).
fn fine(x: Option<f64>) -> String {
    x.map_or(String::new(), |t| format!("{t:.6}"))
}

fn main() {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "out".into());
    std::fs::create_dir_all(&dir).unwrap();
    static DEJAVU: &[u8] = include_bytes!("../tools/fonts/DejaVuSans.ttf");
    if register_font("sans-serif", FontStyle::Normal, DEJAVU).is_err() {
        eprintln!("rattleback: the committed font did not load; the charts will lack text");
    }
    let p = params();
    println!(
        "Kane–Levinson rattleback: δ = {:.5} rad, I = {:?} kg·m², E* = {:e} Pa, f = {F}, ω₀ = ±{SPIN} rad/s, tilt {TILT_DEG}°, T = {} s, output every {} s",
        p.skew,
        p.inertia,
        p.estar,
        t_end(),
        sample()
    );
    let el = p.elasticity().unwrap();
    println!(
        "rolling laws: G = {:.4e} Pa, ν = {:.4} (polymer on glass, Params::elasticity)",
        el.g(),
        el.nu()
    );
    let all: [(&'static str, Runs); 8] = [
        ("best", |n| sliding::<Best>(n, BEST_DELTA, 1e-5)),
        ("simplified", |n| {
            sliding::<Simplified>(n, SIMPLIFIED_DELTA, 1e-5)
        }),
        ("ellipsoid", |n| sliding::<Ellipsoid>(n, 1e-3, 2.5e-5)),
        ("coulomb", |n| sliding::<Coulomb>(n, COULOMB_DELTA, 2e-6)),
        ("table", creeping::<Table>),
        ("blend", creeping::<Blend>),
        // cross-checks of the creep laws (Kalker's simplified theory on a 32 × 32 and a 16 × 16
        // grid, ≈ 40× and 10× `table`'s cost): only when named in RATTLEBACK_LAWS
        ("fastsim", creeping::<FastsimGrid<32, 32>>),
        ("fastsim-16", creeping::<FastsimGrid<16, 16>>),
    ];
    let laws: Vec<_> = all
        .into_iter()
        .filter(|(name, _)| wanted(name))
        .map(|(name, run)| run(name))
        .collect();
    let mut csv = String::from(
        "law,direction,reversal_s,stall_s,peak_rock_rad,final_spin,energy_start,energy_end,reversal_sampled_s,stall_sampled_s,peak_reversed_spin\n",
    );
    for runs in &laws {
        for r in runs {
            let (first, last) = (r.rows[0].1, r.rows[r.rows.len() - 1].1);
            writeln!(
                csv,
                "{},{},{},{},{:.5},{:.4},{:.6},{:.6},{},{},{:.4}",
                r.law,
                r.direction,
                opt(r.reversal()),
                opt(r.stall()),
                r.peak_rock(),
                last.spin,
                first.energy,
                last.energy,
                opt(r.sampled_reversal()),
                opt(r.sampled_stall()),
                r.peak(|p| -p.spin * r.spin0.signum())
            )
            .unwrap();
            println!(
                "{:10} {:8} ω₀ = {:+.1}: reversal {:>8} s (sampled {:>6}), stall {:>8} s (sampled {:>6}), peak pitch {:.4} / roll {:.4} rad, final spin {:+.3} rad/s, peak reversed spin {:+.3} rad/s, energy {:.6} → {:.6} J, peak |F_t|/N = {:.3}",
                r.law,
                r.direction,
                r.spin0,
                fine(r.reversal()),
                opt(r.sampled_reversal()),
                fine(r.stall()),
                opt(r.sampled_stall()),
                r.peak(|p| p.pitch.abs()),
                r.peak(|p| p.roll.abs()),
                last.spin,
                r.peak(|p| -p.spin * r.spin0.signum()),
                first.energy,
                last.energy,
                r.peak(|p| p.friction_ratio)
            );
            if !r.stiff.is_empty() {
                let event = r.reversal().or(r.stall()).unwrap_or(f64::MAX);
                let share = |before: bool| {
                    let part: Vec<_> = r.stiff.iter().filter(|s| (s.0 < event) == before).collect();
                    let over = part.iter().filter(|s| s.1 > 2.785).count();
                    let peak = part.iter().map(|s| s.1).fold(0.0, f64::max);
                    (100.0 * over as f64 / part.len().max(1) as f64, peak)
                };
                let ((b, pb), (a, pa)) = (share(true), share(false));
                println!(
                    "    h·(friction rate): before the event max {pb:.3}, {b:.2} % of steps > 2.785; after it max {pa:.3}, {a:.2} %"
                );
            }
        }
        plot(runs, &format!("{dir}/rattleback_{}.png", runs[0].law)).unwrap();
    }
    std::fs::write(format!("{dir}/rattleback_summary.csv"), csv).unwrap();
    println!("wrote {dir}/rattleback_summary.csv and {dir}/rattleback_<law>.png");
}

/// ω·ẑ(t) of both directions of one law.
fn plot(runs: &[Run; 2], path: &str) -> Result<(), Box<dyn std::error::Error>> {
    // ±1.1 |ω₀|, or the largest |spin| of the runs (`coulomb` spins up past |ω₀| after the
    // reversal) with the same 10 % margin.
    let top = 1.1
        * runs
            .iter()
            .flat_map(|r| r.rows.iter().map(|(_, p)| p.spin.abs()))
            .fold(SPIN, f64::max);
    let root = BitMapBackend::new(path, (900, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!(
                "Rattleback (Kane–Levinson), {} friction: spin ω·ẑ(t)",
                runs[0].law
            ),
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..t_end(), -top..top)?;
    chart
        .configure_mesh()
        .x_desc("t (s)")
        .y_desc("ω·ẑ (rad/s)")
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .draw()?;
    let colours = [RGBColor(214, 39, 40), RGBColor(31, 119, 180)];
    for (r, c) in runs.iter().zip(colours) {
        chart
            .draw_series(LineSeries::new(
                r.rows.iter().map(|(t, p)| (*t, p.spin)),
                c.stroke_width(2),
            ))?
            .label(format!("ω₀ = {:+.0} rad/s ({})", r.spin0, r.direction))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .draw()?;
    root.present()?;
    Ok(())
}
