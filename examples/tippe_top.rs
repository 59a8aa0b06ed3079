//! The paper's tippe top (§5) on the host: θ(t), both normal forces, energy and Jellett's
//! quantity as CSV, θ(t) as a PNG, and the cost of Contensou against Coulomb friction with the
//! adaptive integrator.
//!
//! ```sh
//! cargo run --release --example tippe_top            # writes out/tippe_top_*.csv, out/tippe_top.png
//! cargo run --release --example tippe_top -- DIR     # … into DIR instead of out/
//! ```
//!
//! The PNG is drawn like the report's charts (its renderer, `examples/report/plot.rs`, and the
//! committed font): θ (rad) against t (s), one labelled curve per law with its δ, the line
//! θ* = arccos(−10/13) where both spheres touch, legend and title.
//!
//! Events — t(θ = π/2), the inversion θ = θ* and the small sphere's touch-down — are located
//! between the RK4 steps on every step ([`Events`]: Hermite interpolant + bisection), not read
//! off the 2 ms output; the sampled inversion (first output row with θ ≥ θ*) is printed beside
//! it. `TIPPE_H` (s) and `TIPPE_SAMPLE` (s) override the step and the output interval.
//!
//! Runs (f64, fixed-step RK4, h = 10 µs ≈ 1/68 of the 1.5 kHz contact period, T = 8 s):
//! `simplified` (the paper's simplified Contensou law, δ = 1e-4 m/s), `coulomb-steep`
//! (δ = 1e-4 m/s) and `coulomb-gentle` (δ = 1e-2 m/s). Then the cost comparison: Dormand–Prince
//! 5(4) at a fixed tolerance over the first second, simplified vs steep Coulomb.

use std::fmt::Write as _;
use std::time::Instant;

use contensou::friction::{Best, Coulomb, FrictionLaw, Simplified};
use contensou::scenes::integrate::{dopri45, rk4};
use contensou::scenes::tippe_top::{Events, Probe};

/// The paper's top as the tests start it (θ₀, spin, f; the adaptive tolerance).
#[path = "../host-tests/common/paper_top.rs"]
mod paper_top;
use paper_top::{F, SPIN, THETA0, paper_top, tolerance};

/// The report's chart renderer (plotters with the committed font); only `lines` is used here.
#[path = "report/plot.rs"]
#[allow(dead_code)]
mod plot;

const T_END: f64 = 8.0;
/// `name` (s) from the environment, or `default`.
fn env_or(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|h| h.parse().ok())
        .unwrap_or(default)
}
/// RK4 step (s); `TIPPE_H` overrides it (the step-halving check in the guide).
fn step() -> f64 {
    env_or("TIPPE_H", 1e-5)
}
/// Output interval (s); `TIPPE_SAMPLE` overrides it (the sampling check in the guide).
fn sample() -> f64 {
    env_or("TIPPE_SAMPLE", 2e-3)
}
/// Both spheres touch at θ* = arccos(−10/13).
fn theta_star() -> f64 {
    (-10.0f64 / 13.0).acos()
}

struct Run {
    name: &'static str,
    delta: f64,
    rows: Vec<(f64, Probe<f64>)>,
    events: Events<f64>,
    wall: f64,
}

impl Run {
    /// First output sample with θ ≥ θ* (the figure before event location).
    fn sampled_inversion(&self) -> Option<f64> {
        self.rows
            .iter()
            .find(|(_, p)| p.theta >= theta_star())
            .map(|(t, _)| *t)
    }
    /// Share of the last second spent with the big sphere off the floor.
    fn on_head_last_second(&self) -> f64 {
        let last: Vec<_> = self.rows.iter().filter(|(t, _)| *t > T_END - 1.0).collect();
        last.iter()
            .filter(|(_, p)| p.n_big == 0.0 && p.n_small > 0.0)
            .count() as f64
            / last.len().max(1) as f64
    }
    fn last(&self) -> Probe<f64> {
        self.rows.last().map(|r| r.1).unwrap_or_default()
    }
}

fn fixed<L: FrictionLaw>(name: &'static str, delta: f64) -> Run {
    let (top, y0) = paper_top::<f64, L>(delta);
    let steps = (T_END / step()).round() as usize;
    let every = ((sample() / step()).round() as usize).max(1);
    let mut rows = vec![(0.0, top.probe(&y0))];
    let mut events = Events::new(&top, 0.0, &y0);
    let start = Instant::now();
    rk4(&top, 0.0, y0, step(), steps, |i, t, y| {
        events.update(&top, t, y);
        if i % every == 0 {
            rows.push((t, top.probe(y)));
        }
    });
    Run {
        name,
        delta,
        rows,
        events,
        wall: start.elapsed().as_secs_f64(),
    }
}

fn main() {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "out".into());
    std::fs::create_dir_all(&dir).unwrap();
    let total = Instant::now();
    let runs = [
        fixed::<Simplified>("simplified", 1e-4),
        fixed::<Coulomb>("coulomb-steep", 1e-4),
        fixed::<Coulomb>("coulomb-gentle", 1e-2),
        fixed::<Best>("best", 1e-4),
    ];
    for r in &runs {
        let mut csv = String::from("t,theta,n_big,n_small,energy,jellett,spin\n");
        for (t, p) in &r.rows {
            writeln!(
                csv,
                "{t:.4},{:.6},{:.6e},{:.6e},{:.9e},{:.9e},{:.5}",
                p.theta, p.n_big, p.n_small, p.energy, p.jellett, p.spin
            )
            .unwrap();
        }
        std::fs::write(format!("{dir}/tippe_top_{}.csv", r.name), csv).unwrap();
        let last = r.last();
        let at = |t: Option<f64>| t.map_or("never".into(), |t| format!("{t:.6} s"));
        println!(
            "{:15} θ = π/2 at {}, inversion (θ = θ*) at {} (sampled every {} s: {}), small sphere touches at {}, θ(T) = {:.3} rad, spin ω·e₃(T) = {:.1} rad/s, on the head {:.0}% of the last second, energy {:.3e} → {:.3e} J, RK4 h = {:e} s: {:.2} s wall",
            r.name,
            at(r.events.half()),
            at(r.events.inversion()),
            sample(),
            at(r.sampled_inversion()),
            at(r.events.touch_down()),
            last.theta,
            last.spin,
            100.0 * r.on_head_last_second(),
            r.rows[0].1.energy,
            last.energy,
            step(),
            r.wall
        );
    }
    plot(&runs, &format!("{dir}/tippe_top.png"));

    // The MCU's configuration: f32, fixed step. How long may the step be?
    for h in [1e-5f32, 2e-5, 4e-5, 8e-5] {
        let (top, y0) = paper_top::<f32, Simplified>(1e-4);
        let mut events = Events::new(&top, 0.0, &y0);
        let y = rk4(&top, 0.0, y0, h, (4.0 / h).round() as usize, |_, t, y| {
            events.update(&top, t, y)
        });
        let p = top.probe(&y);
        println!(
            "f32 RK4 h = {:2.0} µs ({:4.1} steps per contact period): inversion at {}, θ(4 s) = {:.3}, spin {:.1} rad/s",
            h * 1e6,
            1.0 / (1470.0 * h),
            events
                .inversion()
                .map_or("never".into(), |t| format!("{t:.5} s")),
            p.theta,
            p.spin
        );
    }

    println!(
        "cost to T = {T_COST} s, Dormand–Prince 5(4), rtol = {RTOL:e}, atol = (1e-9 m, 1e-6 m/s, 1e-8, 1e-4 rad/s):"
    );
    let base = adaptive::<Simplified>("simplified", 1e-4);
    let best = adaptive::<Best>("best", 1e-4);
    println!(
        "  best/simplified: rhs evaluations ×{:.2}, wall time ×{:.2}",
        best.0 as f64 / base.0 as f64,
        best.1 / base.1
    );
    for (name, delta) in [("coulomb-steep", 1e-4), ("coulomb-gentle", 1e-2)] {
        let other = adaptive::<Coulomb>(name, delta);
        println!(
            "  {name}/simplified: rhs evaluations ×{:.2}, wall time ×{:.2}",
            other.0 as f64 / base.0 as f64,
            other.1 / base.1
        );
    }
    println!("total {:.1} s", total.elapsed().as_secs_f64());
}

const T_COST: f64 = 3.0;
const RTOL: f64 = 1e-6;

/// Adaptive run to T_COST: (rhs evaluations, wall seconds).
fn adaptive<L: FrictionLaw>(name: &str, delta: f64) -> (usize, f64) {
    let (top, y0) = paper_top::<f64, L>(delta);
    let tol = tolerance(RTOL);
    let start = Instant::now();
    let (t, y, s) = dopri45(
        &top,
        0.0,
        y0,
        T_COST,
        1e-6,
        1e-3,
        &tol,
        50_000_000,
        |_, _| {},
    );
    let wall = start.elapsed().as_secs_f64();
    let p = top.probe(&y);
    println!(
        "  {name:15} δ = {delta:e}: {} rhs evaluations ({} accepted, {} rejected steps), {wall:.2} s wall; t = {t}, θ = {:.4}",
        s.rhs_evals, s.accepted, s.rejected, p.theta
    );
    (s.rhs_evals, wall)
}

/// θ(t) of every run and the θ* line, labelled like the report's charts (its renderer and the
/// committed font).
fn plot(runs: &[Run], path: &str) {
    plot::register();
    let mut series: Vec<plot::Series> = runs
        .iter()
        .map(|r| {
            let label = format!("{} (δ = {:.0e} m/s)", r.name, r.delta);
            (label, r.rows.iter().map(|(t, p)| (*t, p.theta)).collect())
        })
        .collect();
    series.push((
        format!("θ* = {:.3} rad: both spheres touch", theta_star()),
        vec![(0.0, theta_star()), (T_END, theta_star())],
    ));
    let title = format!(
        "Tippe top: tilt θ(t) by friction law (θ₀ = {THETA0} rad, ω₃ = {SPIN} rad/s, f = {F}, RK4 h = {:.0e} s)",
        step()
    );
    let t = plot::Axis {
        title: "t (s)",
        log: false,
    };
    let theta = plot::Axis {
        title: "θ (rad): 0 stem up, π inverted",
        log: false,
    };
    if let Err(e) = plot::lines(std::path::Path::new(path), &title, t, theta, &series, false) {
        eprintln!("tippe_top: {path}: {e}");
    }
}
