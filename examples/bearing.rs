//! The paper's ball bearing (§5) on the host: contact loads, eccentricities, the friction force
//! of one ball at the inner race over time (the paper's Fig. 5.6), the ball's orbital speed
//! against ω_c = (ω_i/2)(1 − D/d_m), the spin-to-roll ratio, and the run time of exact Hertz
//! against the G* and volumetric paths.
//!
//! ```sh
//! cargo run --release --features scenes --example bearing          # writes out/bearing_*.csv, out/bearing_fy.png
//! cargo run --release --features scenes --example bearing -- out rolling   # the guide's creep vs full slip table (≈ 2 min)
//! cargo run --release --features scenes --example bearing -- out rolling table 0.05   # one rolling run to 50 ms
//! cargo run --release --features scenes --example bearing -- out steady step-aware 2e-5 0.4   # steady-state means ± batch-means error
//! ```
//!
//! `steady [rk4|step-aware] [dt] [end] [ramp] [from]` (defaults step-aware, 20 µs, 0.4 s, 5 ms,
//! end/2): the creep bearing's steady state, means over `from`–`end` with their batch-means
//! standard errors (also as one JSON line), and the series in out/bearing_steady_*.csv (RK4 at
//! 0.1 µs to 0.4 s: ≈ 2.5 min).
//!
//! `rolling [best|table|blend|all] [end] [209|paper]`: the 209 (or the paper's e² = 0.687
//! inner groove) with full-slip `best` (δ = 0.05, 0.02 m/s;
//! h = 0.5, 0.25 µs) against the rolling laws `select` picks where the patch rolls
//! (`Scene<Elliptic, Fixed, Rolls, ExactGrade, f64>` → `Rolling<…, Table>`, G = E*(1 − ν) =
//! 80 GPa, ν = 0.3; h = 0.1, 0.05 µs) and `blend`: the inner ring's friction torque, the balls'
//! spin moments, the cage speed and the inner-race slip, means over the last 5 ms to `end`
//! (default 20 ms).
//!
//! f64, RK4 h = 0.5 µs (the ball–race contacts ring at ≈20 kHz), 50 ms simulated, simplified
//! Contensou friction f = 0.07, δ = 0.05 m/s (steeper needs a smaller step: no spin regularizes
//! a contact whose normal is perpendicular to the ball's spin axis), Hunt–Crossley c_d = 0.3 s/m,
//! E* = 1.1429e11 Pa (steel). Loads ramp up over 5 ms.

use std::fmt::Write as _;
use std::time::Instant;

use contensou::contact::{Contact, Rolling};
use contensou::friction::rolling::Blend;
use contensou::friction::{Constants, Friction, Simplified};
use contensou::geometry::Race;
use contensou::normal::{HuntCrossley, Modulus, Volumetric};
use contensou::scenes::bearing::{BALLS, Bearing, Geometry, RaceLaw, State};
use contensou::scenes::integrate::rk4;
use contensou::select::{Elliptic, ExactGrade, Fixed, Rolls, Scene, Select, rolling_elasticity};
use contensou::shape::{Linear, Newton};

const H: f64 = 5e-7;
const T_END: f64 = 0.05;
const SAMPLE: f64 = 1e-4;

fn parts() -> (Modulus<f64>, HuntCrossley<f64>, Friction<f64, Simplified>) {
    (
        Modulus::new(1.142857e11).unwrap(),
        HuntCrossley::new(0.3).unwrap(),
        Friction::with_law(0.07, 0.05).unwrap(),
    )
}

/// Orbital angular velocity of ball `i` about the bearing axis.
fn orbit(y: &State<f64>, i: usize) -> f64 {
    let b = &y[6 + 9 * i..6 + 9 * i + 6];
    (b[0] * b[4] - b[1] * b[3]) / (b[0] * b[0] + b[1] * b[1])
}

/// Smallest angular spacing between neighbouring balls (rad).
fn min_spacing(y: &State<f64>) -> f64 {
    let mut a: Vec<f64> = (0..BALLS)
        .map(|i| y[7 + 9 * i].atan2(y[6 + 9 * i]))
        .collect();
    a.sort_by(f64::total_cmp);
    let mut m = a[0] + std::f64::consts::TAU - a[BALLS - 1];
    for w in a.windows(2) {
        m = m.min(w[1] - w[0]);
    }
    m
}

/// Runs the bearing; returns (wall seconds, CSV rows, final state).
fn run<C: RaceLaw<f64>>(b: &Bearing<f64, C>) -> (f64, String, State<f64>) {
    let y0 = b.initial_state();
    let steps = (T_END / H).round() as usize;
    let every = (SAMPLE / H).round() as usize;
    let mut csv = String::from(
        "t,ring_y_um,n_inner,n_outer,e2_inner,e2_outer,fx_inner,fy_inner,tz_inner,orbit,spin_roll_inner,spin_roll_outer,min_spacing\n",
    );
    let start = Instant::now();
    let mut wall_out = 0.0;
    let y = rk4(b, 0.0, y0, H, steps, |i, t, y| {
        if i % every == 0 {
            let t0 = Instant::now();
            let (ci, co) = b.contacts(y, 0);
            writeln!(
                csv,
                "{t:.5},{:.4},{:.3},{:.3},{:.4},{:.4},{:.5e},{:.5e},{:.5e},{:.4},{:.5},{:.5},{:.4}",
                y[1] * 1e6,
                ci.n,
                co.n,
                ci.e2,
                co.e2,
                ci.fx,
                ci.fy,
                ci.tz,
                orbit(y, 0),
                ci.spin / ci.roll.max(1e-30),
                co.spin / co.roll.max(1e-30),
                min_spacing(y)
            )
            .unwrap();
            wall_out += t0.elapsed().as_secs_f64();
        }
    });
    (start.elapsed().as_secs_f64() - wall_out, csv, y)
}

fn report<C: RaceLaw<f64>>(label: &str, b: &Bearing<f64, C>, dir: &str) -> f64 {
    let (wall, csv, y) = run(b);
    std::fs::write(format!("{dir}/bearing_{label}.csv"), &csv).unwrap();
    let g = b.geometry();
    let loads: Vec<String> = (0..BALLS)
        .map(|i| {
            let (ci, co) = b.contacts(&y, i);
            format!("{:.0}/{:.0}", ci.n, co.n)
        })
        .collect();
    let (ci, co) = (0..BALLS)
        .map(|i| b.contacts(&y, i))
        .max_by(|a, b| a.0.n.total_cmp(&b.0.n))
        .unwrap();
    let orbit_mean: f64 = (0..BALLS).map(|i| orbit(&y, i)).sum::<f64>() / BALLS as f64;
    println!(
        "{label}: {wall:.2} s wall for {T_END} s simulated ({} RK4 steps)",
        (T_END / H) as usize
    );
    println!("  loads inner/outer per ball at T (N): {}", loads.join(" "));
    println!(
        "  most loaded ball: e² inner {:.4}, outer {:.4}; spin/roll inner {:.2e}, outer {:.2e}",
        ci.e2,
        co.e2,
        ci.spin / ci.roll,
        co.spin / co.roll
    );
    println!(
        "  orbital speed (mean over balls) {:.3} rad/s vs ω_c = {:.3} rad/s ({:+.2} %); ring displacement y = {:.2} µm, z = {:.2} µm; min ball spacing {:.4} rad (nominal {:.4})",
        orbit_mean,
        g.cage_speed(),
        100.0 * (orbit_mean / g.cage_speed() - 1.0),
        y[1] * 1e6,
        y[2] * 1e6,
        min_spacing(&y),
        std::f64::consts::TAU / BALLS as f64
    );
    wall
}

fn plot(path: &str, series: &[(Vec<(f64, f64)>, plotters::style::RGBColor)]) {
    use plotters::prelude::*;
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.0.iter().map(|p| p.1))
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    let pad = 0.05 * (hi - lo).max(1e-12);
    let root = BitMapBackend::new(path, (900, 500)).into_drawing_area();
    root.fill(&WHITE).unwrap();
    let mut chart = ChartBuilder::on(&root.margin(20, 20, 20, 20))
        .build_cartesian_2d(0.0..T_END, (lo - pad)..(hi + pad))
        .unwrap();
    chart
        .draw_series(LineSeries::new([(0.0, 0.0), (T_END, 0.0)], BLACK))
        .unwrap();
    for (s, c) in series {
        chart
            .draw_series(LineSeries::new(s.iter().copied(), c.stroke_width(2)))
            .unwrap();
    }
    root.present().unwrap();
}

fn column(csv: &str, k: usize) -> Vec<(f64, f64)> {
    csv.lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0], v[k])
        })
        .collect()
}

/// Means over the last [`WINDOW`] of a run (sampled every [`SAMPLE`]).
#[derive(Default)]
struct Summary {
    /// Friction torque on the inner ring about the axis (N·m).
    ring_torque: f64,
    /// Σ over balls of |T_z| at the inner and at the outer race (N·m).
    spin_moment: [f64; 2],
    /// Mean orbital speed relative to ω_c, minus 1.
    cage: f64,
    /// Max over balls loaded > 100 N of the sliding speed |v_P| at the inner race (m/s) and of
    /// the creepage |v_P|/|V| there.
    slip: f64,
    creep: f64,
    finite: bool,
    wall: f64,
}

/// The table's runs end at 20 ms (the load ramps up over 5 ms; `rolling <law> <end>` sets
/// another end) and average over the last 5 ms: a rolling run needs h ≤ 0.1 µs (the creep
/// law's stiffness, below).
const TABLE_END: f64 = 0.02;
const WINDOW: f64 = 0.005;

/// Runs the 209 bearing with race law `C` at step `h` to [`T_END`]: the [`Summary`].
fn summarize<C: RaceLaw<f64>>(b: &Bearing<f64, C>, h: f64, end: f64) -> Summary {
    let steps = (end / h).round() as usize;
    let every = (SAMPLE / h).round() as usize;
    let mut s = Summary::default();
    let mut count = 0.0;
    let wc = b.geometry().cage_speed();
    let start = Instant::now();
    let y = rk4(b, 0.0, b.initial_state(), h, steps, |i, t, y| {
        if i % every != 0 || t < end - WINDOW - 1e-12 {
            return;
        }
        count += 1.0;
        s.ring_torque += b.inner_ring_torque(y);
        let mut orbit_sum = 0.0;
        let (mut slip, mut creep) = (0.0_f64, 0.0_f64);
        for i in 0..BALLS {
            let (ci, co) = b.contacts(y, i);
            s.spin_moment[0] += ci.tz.abs();
            s.spin_moment[1] += co.tz.abs();
            orbit_sum += orbit(y, i);
            if ci.n > 100.0 {
                let v = ci.slip[0].hypot(ci.slip[1]);
                slip = slip.max(v);
                creep = creep.max(v / ci.rolling[0].hypot(ci.rolling[1]));
            }
        }
        s.cage += orbit_sum / BALLS as f64 / wc - 1.0;
        s.slip += slip;
        s.creep += creep;
    });
    s.wall = start.elapsed().as_secs_f64();
    s.ring_torque /= count;
    s.spin_moment = s.spin_moment.map(|m| m / count);
    s.cage /= count;
    s.slip /= count;
    s.creep /= count;
    s.finite = y.iter().all(|v| v.is_finite());
    s
}

fn print_row(label: &str, delta: f64, h: f64, s: &Summary) {
    println!(
        "| {label} | {delta} | {:.3} | {:.1} | {:.2} / {:.2} | {:+.3} | {:.2} | {:.2e} | {} {:.1} s |",
        h * 1e6,
        s.ring_torque * 1e3,
        s.spin_moment[0] * 1e3,
        s.spin_moment[1] * 1e3,
        100.0 * s.cage,
        s.slip * 1e3,
        s.creep,
        if s.finite { "" } else { "NON-FINITE" },
        s.wall
    );
}

/// Creep (rolling laws) against full slip (`best`) on bearing `g` at two δ and two steps:
/// the guide's bearing table (docs/guide/src/bearing.md). `which`: `best`, `table`, `blend` or all; `end`: the runs' end
/// (s). A run at another end than [`TABLE_END`] takes only the first (δ, h).
fn rolling_table(which: Option<&str>, end: f64, g: Geometry<f64>) {
    let first = |runs: &[(f64, f64)]| -> Vec<(f64, f64)> {
        if end == TABLE_END {
            runs.to_vec()
        } else {
            runs[..1].to_vec()
        }
    };
    let (estar, damping, _) = parts();
    println!(
        "| race law | δ (m/s) | h (µs) | inner-ring friction torque (N·mm) | Σ|T_z| balls inner / outer (N·mm) | cage speed vs ω_c (%) | max inner slip (mm/s) | max inner creepage | wall |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let runs = |name: &str| which.is_none_or(|w| w == name || w == "all");
    let best = |delta: f64, race| {
        Contact::hertz::<Newton>(
            &g.curvatures(race).unwrap(),
            estar,
            damping,
            Friction::new(0.07, delta).unwrap(),
        )
        .unwrap()
    };
    if runs("best") {
        for (delta, h) in first(&[(0.05, H), (0.05, H / 2.0), (0.02, H / 2.0)]) {
            let b = Bearing::new(&g, best(delta, Race::Inner), best(delta, Race::Outer)).unwrap();
            print_row("best (full slip)", delta, h, &summarize(&b, h, end));
        }
    }
    // The rolling law `select` picks where the patch rolls: `table` over `best`, elasticity
    // G = E*(1 − ν) = 80 GPa, ν = 0.3 (steel); δ is not used by it. Its creep stiffness
    // G c² C₁₁/V (≈ 2.2e4 N·s/m at the inner race at 900 N) needs h ≤ 0.1 µs with RK4 (at
    // 0.25 µs a numerical limit cycle drives the ring).
    if runs("table") {
        for (delta, h) in first(&[(0.05, H_ROLL), (0.05, H_ROLL / 2.0), (0.02, H_ROLL)]) {
            let b = table_bearing(&g, delta);
            print_row("table (creep)", delta, h, &summarize(&b, h, end));
        }
    }
    if runs("blend") {
        let el = rolling_elasticity(estar).unwrap();
        let blend = |race| Rolling::<_, _, Blend>::new(best(0.05, race), el).unwrap();
        let b = Bearing::new(&g, blend(Race::Inner), blend(Race::Outer)).unwrap();
        print_row("blend (creep)", 0.05, H_ROLL, &summarize(&b, H_ROLL, end));
    }
}

/// RK4 step of the rolling runs (s).
const H_ROLL: f64 = 1e-7;

/// The bearing `g` with the rolling law `select` picks where the patch rolls (`table` over
/// `best`, f = 0.07, slip scale `delta`), both races.
fn table_bearing(g: &Geometry<f64>, delta: f64) -> Bearing<f64, impl RaceLaw<f64>> {
    let (estar, damping, _) = parts();
    let table = |race| {
        let friction = Friction::new(0.07, delta).unwrap();
        Scene::<Elliptic, Fixed, Rolls, ExactGrade, f64>::build(
            &g.curvatures(race).unwrap(),
            estar,
            damping,
            friction,
        )
        .unwrap()
    };
    Bearing::new(g, table(Race::Inner), table(Race::Outer)).unwrap()
}

/// The steady state of the 209 with the creep law `table` (the runner's setup,
/// examples/scene.rs): one run of `integrator` (`rk4` or `step-aware`) at step `dt` to `end`,
/// the load ramped over `ramp`; writes `dir`/bearing_steady_<integrator>_<dt>.csv (every µs or
/// every step: ring torque and its drilling part, Σ|T_z| inner / outer, cage speed / ω_c − 1,
/// the ring's axial speed) and prints the means over `from`–`end` with their
/// standard errors by batch means (20 ms batches: the ring torque's own fluctuation is
/// correlated over milliseconds, so the samples' spread alone would understate it).
fn steady(dir: &str, integrator: &str, dt: f64, end: f64, ramp: f64, from: f64) {
    use contensou::scenes::integrate::rk4_step;
    use contensou::scenes::step_aware::Warm;
    let mut g = Geometry::<f64>::bearing_209();
    g.ramp = ramp;
    let b = table_bearing(&g, 0.05);
    let rk4 = match integrator {
        "rk4" => true,
        "step-aware" => false,
        x => panic!("unknown integrator {x} (rk4, step-aware)"),
    };
    let steps = (end / dt).round() as usize;
    let every = ((1e-6 / dt).round() as usize).max(1);
    let mut y = b.initial_state();
    let mut warm = [Warm::default(); BALLS];
    let mut csv = String::from("t,ring_torque,ring_torque_spin,sm_inner,sm_outer,cage,ring_vz\n");
    // (t, [ring torque, Σ|T_z| inner, outer, cage]) from `from` on.
    let mut rows: Vec<(f64, [f64; 4])> = Vec::new();
    for i in 0..steps {
        let t = dt * (i + 1) as f64;
        let loads = if rk4 {
            y = rk4_step(&b, t - dt, &y, dt);
            None
        } else {
            let (y1, l) = b.step_aware(t - dt, &y, dt, &mut warm);
            y = y1;
            Some(l)
        };
        if (i + 1) % every != 0 {
            continue;
        }
        let (ring, spin, sm) = match loads {
            Some(l) => (l.ring_torque, l.ring_torque_spin, l.spin_moment),
            None => {
                let (mut spin, mut sm) = (0.0, [0.0; 2]);
                for k in 0..BALLS {
                    let (ci, co) = b.contacts(&y, k);
                    sm[0] += ci.tz.abs();
                    sm[1] += co.tz.abs();
                    spin += ci.ring_torque_spin;
                }
                (b.inner_ring_torque(&y), spin, sm)
            }
        };
        let cage =
            (0..BALLS).map(|k| orbit(&y, k)).sum::<f64>() / BALLS as f64 / g.cage_speed() - 1.0;
        writeln!(
            csv,
            "{t:.7},{ring:.6e},{spin:.6e},{:.6e},{:.6e},{cage:.6e},{:.4e}",
            sm[0], sm[1], y[5]
        )
        .unwrap();
        if t > from {
            rows.push((t, [ring, sm[0], sm[1], cage]));
        }
    }
    std::fs::create_dir_all(dir).unwrap();
    let path = format!("{dir}/bearing_steady_{integrator}_{dt:e}.csv");
    std::fs::write(&path, csv).unwrap();
    let batch = 0.02;
    let nb = (((end - from) / batch).floor() as usize).max(2);
    let t0 = from;
    let mut json = Vec::new();
    for (j, name) in [
        "ring torque (N·mm)",
        "Σ|T_z| inner (N·mm)",
        "Σ|T_z| outer (N·mm)",
        "cage speed / ω_c − 1 (%)",
    ]
    .iter()
    .enumerate()
    {
        let scale = if j == 3 { 100.0 } else { 1e3 };
        let mean = rows.iter().map(|r| r.1[j]).sum::<f64>() / rows.len() as f64;
        let bm: Vec<f64> = (0..nb)
            .map(|k| {
                let (a, z) = (t0 + batch * k as f64, t0 + batch * (k + 1) as f64);
                let v: Vec<f64> = rows
                    .iter()
                    .filter(|r| r.0 > a && r.0 <= z)
                    .map(|r| r.1[j])
                    .collect();
                v.iter().sum::<f64>() / v.len().max(1) as f64
            })
            .collect();
        let m = bm.iter().sum::<f64>() / nb as f64;
        let var = bm.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (nb - 1) as f64;
        let key = [
            "ring_torque",
            "spin_moment_inner",
            "spin_moment_outer",
            "cage",
        ][j];
        json.push(format!(
            "\"{key}\":{mean:e},\"{key}_se\":{:e}",
            (var / nb as f64).sqrt()
        ));
        println!(
            "{name}: {:.4} ± {:.4} (mean over {:.0}–{:.0} ms ± batch-means standard error)",
            scale * mean,
            scale * (var / nb as f64).sqrt(),
            1e3 * t0,
            1e3 * end
        );
    }
    println!("series: {path}");
    println!("{{{}}}", json.join(","));
}

fn main() {
    let dir = std::env::args().nth(1).unwrap_or_else(|| "out".into());
    if std::env::args().nth(2).as_deref() == Some("steady") {
        let arg = |i: usize, d: f64| std::env::args().nth(i).map_or(d, |e| e.parse().unwrap());
        let integrator = std::env::args()
            .nth(3)
            .unwrap_or_else(|| "step-aware".into());
        let end = arg(5, 0.4);
        steady(
            &dir,
            &integrator,
            arg(4, 2e-5),
            end,
            arg(6, 5e-3),
            arg(7, 0.5 * end),
        );
        return;
    }
    if std::env::args().nth(2).as_deref() == Some("rolling") {
        let end = std::env::args()
            .nth(4)
            .map_or(TABLE_END, |e| e.parse().unwrap());
        let g = match std::env::args().nth(5).as_deref() {
            Some("paper") => Geometry::paper_e2(),
            _ => Geometry::bearing_209(),
        };
        rolling_table(std::env::args().nth(3).as_deref(), end, g);
        return;
    }
    std::fs::create_dir_all(&dir).unwrap();
    let (estar, damping, friction) = parts();

    let g209 = Geometry::<f64>::bearing_209();
    let hertz = |g: &Geometry<f64>, race| {
        Contact::hertz::<Newton>(&g.curvatures(race).unwrap(), estar, damping, friction).unwrap()
    };
    let b209 = Bearing::new(&g209, hertz(&g209, Race::Inner), hertz(&g209, Race::Outer)).unwrap();
    report("209", &b209, &dir);

    let gp = Geometry::<f64>::paper_e2();
    let exact = Bearing::new(&gp, hertz(&gp, Race::Inner), hertz(&gp, Race::Outer)).unwrap();
    let w_exact = report("paper_exact", &exact, &dir);
    let linear = |race| {
        Contact::hertz::<Linear>(&gp.curvatures(race).unwrap(), estar, damping, friction).unwrap()
    };
    let gstar = Bearing::new(&gp, linear(Race::Inner), linear(Race::Outer)).unwrap();
    let w_gstar = report("paper_gstar", &gstar, &dir);
    let volumetric = |race| {
        Contact::from_parts(
            Volumetric::new(&gp.curvatures(race).unwrap(), estar),
            damping,
            friction,
            Constants::circle(),
        )
    };
    let vol = Bearing::new(&gp, volumetric(Race::Inner), volumetric(Race::Outer)).unwrap();
    let w_vol = report("paper_volumetric", &vol, &dir);
    println!(
        "run time relative to exact Hertz: G* ×{:.2}, volumetric ×{:.2}",
        w_gstar / w_exact,
        w_vol / w_exact
    );

    let csv209 = std::fs::read_to_string(format!("{dir}/bearing_209.csv")).unwrap();
    let csvp = std::fs::read_to_string(format!("{dir}/bearing_paper_exact.csv")).unwrap();
    plot(
        &format!("{dir}/bearing_fy.png"),
        &[
            (column(&csv209, 7), plotters::style::RGBColor(200, 30, 30)),
            (column(&csvp, 7), plotters::style::RGBColor(30, 30, 200)),
        ],
    );
}
