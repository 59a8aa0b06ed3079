//! The creep curves of tools/data/rolling_ref.csv at the geometric midpoints of their
//! magnitudes (14 per curve: √(q_i q_{i+1}) of `cases::magnitudes`), same families, shapes,
//! ν, load ratio, grids and format: the held-out set of the default rolling law's tables
//! (`tools/fit_rolling_table.py`; the tables hold the 15 magnitudes of rolling_ref.csv).
//!
//! `nice cargo run --release --example midpoints` (from tools/rolling_exact) writes
//! `../data/rolling_ref_mid.csv` (≈ 5 min on one core); with the argument `quarter`, the
//! points at ¼ and ¾ of each interval in ln q instead (28 per curve),
//! `../data/rolling_ref_quarter.csv` (≈ 10 min): the held-out set when the tables also hold the
//! midpoints.
use rolling_exact::cases::{NL, SHAPES, magnitudes};
use rolling_exact::kalker;
use rolling_exact::reference::{Patch, csv_file, finest_k};
use std::fmt::Write as _;
use std::time::Instant;

/// The points at the fractions `at` of each interval of the curve's magnitudes, in ln q.
fn between(spin: bool, at: &[f64]) -> Vec<f64> {
    let q = magnitudes(spin);
    q.windows(2)
        .flat_map(|w| at.iter().map(move |t| w[0] * (w[1] / w[0]).powf(*t)))
        .collect()
}

fn main() {
    let quarter = std::env::args().nth(1).as_deref() == Some("quarter");
    let (at, out, what): (&[f64], &str, &str) = if quarter {
        (
            &[0.25, 0.75],
            "../data/rolling_ref_quarter.csv",
            "at 1/4 and 3/4 (in ln q) of the intervals between",
        )
    } else {
        (
            &[0.5],
            "../data/rolling_ref_mid.csv",
            "at the geometric midpoints of",
        )
    };
    let midpoints = |spin: bool| between(spin, at);
    let started = Instant::now();
    let nu = 0.25;
    let s = 3.0 * NL;
    let r = std::f64::consts::FRAC_1_SQRT_2;
    let mut rows = String::new();
    let mut grids = String::new();
    for aob in SHAPES {
        let (c11, c22, c23) = kalker::coefficients(aob).expect("shape in Table E3");
        let mut cases: Vec<(&str, f64, f64, f64)> = Vec::new();
        for q in midpoints(false) {
            cases.push(("xi", s * q / c11, 0.0, 0.0));
        }
        for q in midpoints(false) {
            cases.push(("eta", 0.0, s * q / c22, 0.0));
        }
        for q in midpoints(true) {
            cases.push(("phi", 0.0, 0.0, s * q / c23));
        }
        for q in midpoints(true) {
            cases.push(("combined", 0.0, 0.5 * s * q / c22, 0.5 * s * q / c23));
        }
        for q in midpoints(false) {
            cases.push(("combined", r * s * q / c11, r * s * q / c22, 0.0));
        }
        let patch = Patch::new(aob, nu, NL, finest_k(aob, 1024));
        for (family, xi, eta, phi_c) in cases {
            let sol = patch.solve(xi, eta, phi_c, true);
            assert!(
                sol.converged,
                "not converged: {family} {aob} {xi} {eta} {phi_c}"
            );
            writeln!(rows, "{}", patch.csv_row(family, [xi, eta, phi_c], &sol)).unwrap();
        }
        writeln!(grids, "{}", patch.grids_comment()).unwrap();
        eprintln!(
            "a/b {aob}: done, {:.1} s so far",
            started.elapsed().as_secs_f64()
        );
    }
    let mut text = String::new();
    writeln!(
        text,
        "# Exact steady-rolling reference {what} rolling_ref.csv's creep-curve"
    )
    .unwrap();
    writeln!(text, "# magnitudes (tools/rolling_exact, cargo run --release --example midpoints{}); same method, grids,", if quarter { " -- quarter" } else { "" }).unwrap();
    text.push_str("# extrapolation and format as rolling_ref.csv (see its header). The held-out set of the default\n");
    text.push_str("# rolling law's tables (tools/fit_rolling_table.py).\n");
    let seconds = started.elapsed().as_secs_f64();
    std::fs::write(out, csv_file(&text, &grids, seconds, &rows)).expect("write csv");
    eprintln!("wrote {out} in {:.1} s", started.elapsed().as_secs_f64());
}
