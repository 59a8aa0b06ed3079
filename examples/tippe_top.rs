//! The paper's tippe top (§5) on the host: θ(t), both normal forces, energy and Jellett's
//! quantity as CSV, θ(t) as a PNG, and the cost of Contensou against Coulomb friction with the
//! adaptive integrator.
//!
//! ```sh
//! cargo run --release --example tippe_top            # writes out/tippe_top_*.csv, out/tippe_top.png
//! cargo run --release --example tippe_top -- DIR     # … into DIR instead of out/
//! ```
//!
//! Runs (f64, fixed-step RK4, h = 10 µs ≈ 1/68 of the 1.5 kHz contact period, T = 8 s):
//! `simplified` (the paper's simplified Contensou law, δ = 1e-4 m/s), `coulomb-steep`
//! (δ = 1e-4 m/s) and `coulomb-gentle` (δ = 1e-2 m/s). Then the cost comparison: Dormand–Prince
//! 5(4) at a fixed tolerance over the first second, simplified vs steep Coulomb.

use std::fmt::Write as _;
use std::time::Instant;

use contensou::friction::{Coulomb, Friction, FrictionLaw, Simplified};
use contensou::scenes::integrate::{Ode, Tolerance, dopri45, rk4};
use contensou::scenes::tippe_top::{N, Params, Probe, State, TippeTop};

const THETA0: f64 = 0.1;
const SPIN: f64 = 180.0;
const F: f64 = 0.3;
const T_END: f64 = 8.0;
const H: f64 = 1e-5;
const SAMPLE: f64 = 1e-3;
/// Both spheres touch at θ* = arccos(−10/13).
fn theta_star() -> f64 {
    (-10.0f64 / 13.0).acos()
}

struct Run {
    name: &'static str,
    rows: Vec<(f64, Probe<f64>)>,
    wall: f64,
}

impl Run {
    /// First time θ reaches θ* (the small sphere touches down).
    fn inversion(&self) -> Option<f64> {
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
    let top = TippeTop::new(&Params::paper(), Friction::<f64, L>::new(F, delta).unwrap()).unwrap();
    let y0 = top.initial_state(THETA0, SPIN);
    let steps = (T_END / H).round() as usize;
    let every = (SAMPLE / H).round() as usize;
    let mut rows = vec![(0.0, top.probe(&y0))];
    let start = Instant::now();
    rk4(&top, 0.0, y0, H, steps, |i, t, y| {
        if i % every == 0 {
            rows.push((t, top.probe(y)));
        }
    });
    Run {
        name,
        rows,
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
        println!(
            "{:15} inversion (θ ≥ θ*) at {}, θ(T) = {:.3} rad, spin ω·e₃(T) = {:.1} rad/s, on the head {:.0}% of the last second, energy {:.3e} → {:.3e} J, RK4 h = {H:e} s: {:.2} s wall",
            r.name,
            r.inversion()
                .map_or("never".into(), |t| format!("{t:.3} s")),
            last.theta,
            last.spin,
            100.0 * r.on_head_last_second(),
            r.rows[0].1.energy,
            last.energy,
            r.wall
        );
    }
    println!("total {:.1} s", total.elapsed().as_secs_f64());
}
