//! Creep curves off the families of tools/data/rolling_ref.csv, for the direction tables of the
//! default rolling law (`tools/fit_rolling_table.py`): η with φ of opposite signs, and ξ at 45°
//! to the η–φ plane with η and φ at 0° (same sign), 90° (φ alone) and 135° (opposite signs).
//! Directions are unit vectors d of the linear forces l = (C₁₁ξ, C₂₂η, C₂₃φc)/nl (Table E3,
//! ν = 0.25), the magnitude |l| = 3q with q on the spin magnitudes of rolling_ref.csv
//! (`cases::magnitudes(true)`), same shapes, ν, load ratio, grids and format as rolling_ref.csv.
//!
//! `nice cargo run --release --example directions -- MODE [OUT [a/b …]]` (from
//! tools/rolling_exact), MODE:
//! - `nodes`: the 15 magnitudes and their 14 geometric midpoints per curve (the tables' nodes),
//!   `../data/rolling_ref_dir.csv` (580 cases);
//! - `quarter`: the geometric midpoints of the 29 (¼ and ¾ in ln q of rolling_ref.csv's
//!   intervals, as rolling_ref_quarter.csv), `../data/rolling_ref_dir_quarter.csv` (560 cases;
//!   held out but in the knee window);
//! - `quarter-knee`: the same inside the knee window only (`KNEE`; a/b = 2, 5 by default),
//!   `../data/rolling_ref_dir_quarter_knee.csv` (64 cases: nodes of the knee window);
//! - `random`: 6 directions per shape, uniform on the sphere, at magnitudes log-uniform in
//!   q ∈ [0.01, 10] (deterministic seed), `../data/rolling_ref_dir_random.csv` (30 cases; held
//!   out: between the tables' directions);
//! - `knee`: extra nodes where the spin force's knee is sharp (a/b = 2 and 5): on pure φ, η with
//!   φ (same sign, as in rolling_ref.csv) and the four curves above, the points at ¼ and ¾ (in
//!   ln q) of the intervals `KNEE` between the 29 node magnitudes (with the ½ points of the
//!   quarter files, nodes ¼ of the spacing apart there), `../data/rolling_ref_knee.csv` (192
//!   cases); `knee-held`: one point in every other interval of the same, at ⅛ and ⅝
//!   alternately, `../data/rolling_ref_knee_held.csv` (48 cases; held out);
//! - `half-held`: at a/b = 1, where the knee window holds the ½ points of the quarter files as
//!   nodes, one point per window interval at ¼ and ¾ alternately (the same six curves),
//!   `../data/rolling_ref_half_held.csv` (48 cases; held out);
//! - `plane`: the η–φ directions halfway between the plane's curves (u = 1½, 2½, 3½) at
//!   a/b = 2 and 5, on the node magnitudes from the 11th (q ≥ 0.04) on,
//!   `../data/rolling_ref_plane.csv` (114 cases);
//! - `ends`: the shapes at the ends of the domain, a/b = 1/20 and 20 by default (beyond Table
//!   E3: laid out with the exact reference's own linear coefficients at ν = 0.25,
//!   `../data/rolling_linear_aligned.csv`), all nine curves of the tables on their 29 node
//!   magnitudes: ξ, η, φ, η with φ and ξ with η as in rolling_ref.csv (families `xi`, `eta`,
//!   `phi`, `combined`) and the four curves above, on the grids of the held-out set (elements
//!   elongated along the long axis, `reference::elements_ratio`),
//!   `../data/rolling_ref_ends.csv` (522 cases).
//!
//! With a/b arguments only those shapes are computed (to split the work; concatenate the rows).
use rolling_exact::cases::{NL, SHAPES, magnitudes, uniform};
use rolling_exact::kalker;
use rolling_exact::reference::{CSV_COLUMNS, Patch, finest_k};
use std::time::Instant;

/// The intervals of the 29 node magnitudes (spin) refined in the `knee` modes (q ≈ 0.1 … 1.6).
const KNEE: std::ops::Range<usize> = 12..20;

/// The `plane` mode's curves: name and u.
const PLANE_HALF: [(&str, f64); 3] = [
    ("plane_u1.5", 1.5),
    ("plane_u2.5", 2.5),
    ("plane_u3.5", 3.5),
];

/// The direction curves: name and unit direction of the linear forces.
fn curves() -> Vec<(&'static str, [f64; 3])> {
    let r = std::f64::consts::FRAC_1_SQRT_2;
    vec![
        ("etaphi_opp", [0.0, -r, r]),
        ("xi_etaphi", [r, 0.5, 0.5]),
        ("xi_phi", [r, 0.0, r]),
        ("xi_etaphi_opp", [r, -0.5, 0.5]),
    ]
}

/// The points at the fractions `at` of each interval of `q`, in ln q.
fn between(q: &[f64], at: &[f64]) -> Vec<f64> {
    q.windows(2)
        .flat_map(|w| at.iter().map(move |t| w[0] * (w[1] / w[0]).powf(*t)))
        .collect()
}

/// The 29 node magnitudes: the 15 of rolling_ref.csv and their geometric midpoints.
fn nodes(spin: bool) -> Vec<f64> {
    let q = magnitudes(spin);
    let mut v: Vec<f64> = q.iter().copied().chain(between(&q, &[0.5])).collect();
    v.sort_by(f64::total_cmp);
    v
}

/// (C₁₁, C₂₂, C₂₃) of the aligned patch a/b at ν = 0.25 from the exact reference's linear table
/// (`../data/rolling_linear_aligned.csv`, tools/rolling_exact's `linear_table` example).
fn exact_coefficients(aob: f64) -> (f64, f64, f64) {
    let text = std::fs::read_to_string("../data/rolling_linear_aligned.csv")
        .expect("../data/rolling_linear_aligned.csv (run from tools/rolling_exact)");
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('a'))
    {
        let f: Vec<f64> = line
            .split(',')
            .take(12)
            .map(|x| x.parse().expect("number"))
            .collect();
        if (f[0] - aob).abs() < 1e-9 * aob && f[1] == 0.0 && f[2] == 0.25 {
            return (f[3], f[7], f[8]);
        }
    }
    panic!("a/b = {aob} at ν = 0.25 is not in rolling_linear_aligned.csv")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mode = args.first().map(String::as_str).unwrap_or("nodes");
    let default_out = match mode {
        "nodes" => "../data/rolling_ref_dir.csv",
        "quarter" => "../data/rolling_ref_dir_quarter.csv",
        "quarter-knee" => "../data/rolling_ref_dir_quarter_knee.csv",
        "random" => "../data/rolling_ref_dir_random.csv",
        "knee" => "../data/rolling_ref_knee.csv",
        "knee-held" => "../data/rolling_ref_knee_held.csv",
        "half-held" => "../data/rolling_ref_half_held.csv",
        "plane" => "../data/rolling_ref_plane.csv",
        "ends" => "../data/rolling_ref_ends.csv",
        _ => panic!("mode: nodes, quarter, random, knee, knee-held, plane or ends"),
    };
    let out = args.get(1).map(String::as_str).unwrap_or(default_out);
    let shapes: Vec<f64> = if args.len() > 2 {
        args[2..].iter().map(|s| s.parse().expect("a/b")).collect()
    } else if mode.starts_with("knee") || mode == "plane" || mode == "quarter-knee" {
        vec![2.0, 5.0]
    } else if mode == "half-held" {
        vec![1.0]
    } else if mode == "ends" {
        vec![0.05, 20.0]
    } else {
        SHAPES.to_vec()
    };
    let started = Instant::now();
    let nu = 0.25;
    let s = 3.0 * NL;
    // rows are written as they are solved (a run cut short keeps what it has); the grids and
    // the time are comments at the end
    let mut line = rolling_exact::line_writer(out);
    line(&format!(
        "# Exact steady-rolling reference, mode `{mode}` of tools/rolling_exact/examples/directions.rs"
    ));
    line(&format!(
        "# (cargo run --release --example directions -- {mode}; see there for the cases); same method,{}",
        if mode == "ends" { "" } else { " grids," }
    ));
    line(if mode == "ends" {
        "# extrapolation and format as rolling_ref.csv (see its header); the grids of the held-out set (below)."
    } else {
        "# extrapolation and format as rolling_ref.csv (see its header)."
    });
    line(CSV_COLUMNS);
    let mut seed = 20u64;
    for aob in shapes {
        let (c11, c22, c23) = if mode == "ends" {
            exact_coefficients(aob)
        } else {
            kalker::coefficients(aob).expect("shape in Table E3")
        };
        let place =
            |d: [f64; 3], q: f64| (s * q * d[0] / c11, s * q * d[1] / c22, s * q * d[2] / c23);
        let mut cases: Vec<(&str, (f64, f64, f64))> = Vec::new();
        match mode {
            "nodes" | "quarter" | "quarter-knee" => {
                let q = match mode {
                    "nodes" => nodes(true),
                    "quarter" => between(&nodes(true), &[0.5]),
                    _ => between(&nodes(true)[KNEE.start..=KNEE.end], &[0.5]),
                };
                for (name, d) in curves() {
                    cases.extend(q.iter().map(|&q| (name, place(d, q))));
                }
            }
            "ends" => {
                let (plain, spin) = (nodes(false), nodes(true));
                let r = std::f64::consts::FRAC_1_SQRT_2;
                cases.extend(plain.iter().map(|&q| ("xi", place([1.0, 0.0, 0.0], q))));
                cases.extend(plain.iter().map(|&q| ("eta", place([0.0, 1.0, 0.0], q))));
                cases.extend(spin.iter().map(|&q| ("phi", place([0.0, 0.0, 1.0], q))));
                // as rolling_ref.csv: η with φ at equal shares of 3q (|l| = 3q/√2), ξ with η at
                // |l| = 3q
                cases.extend(
                    spin.iter()
                        .map(|&q| ("combined", place([0.0, 0.5, 0.5], q))),
                );
                cases.extend(plain.iter().map(|&q| ("combined", place([r, r, 0.0], q))));
                for (name, d) in curves() {
                    cases.extend(spin.iter().map(|&q| (name, place(d, q))));
                }
            }
            "random" => {
                for _ in 0..6 {
                    let z = 2.0 * uniform(&mut seed) - 1.0;
                    let t = std::f64::consts::TAU * uniform(&mut seed);
                    let w = (1.0 - z * z).sqrt();
                    let d = [z, w * t.cos(), w * t.sin()];
                    let q = 0.01 * 1000f64.powf(uniform(&mut seed));
                    cases.push(("direction", place(d, q)));
                }
            }
            "plane" => {
                // η–φ directions halfway between the plane's curves (u = 1½, 2½, 3½ of
                // u = 2 − 2d_η/(|d_η| + d_φ)), from the 11th node magnitude on (below it the
                // residual is interpolated between directions)
                let q: Vec<f64> = nodes(true)[10..].to_vec();
                for (name, u) in PLANE_HALF {
                    let y = 1.0 - u / 2.0; // with |y| + p = 1
                    let p = 1.0 - y.abs();
                    let n = y.hypot(p);
                    cases.extend(q.iter().map(|&q| (name, place([0.0, y / n, p / n], q))));
                }
            }
            _ => {
                // the knee window: intervals KNEE of the 29 node magnitudes, on pure φ and η
                // with φ (placed as in rolling_ref.csv) and the direction curves
                let knots = nodes(true);
                let window = &knots[KNEE.start..=KNEE.end];
                let q: Vec<f64> = if mode == "knee" {
                    between(window, &[0.25, 0.75])
                } else if mode == "half-held" {
                    // one point per interval, ¼ and ¾ alternately
                    window
                        .windows(2)
                        .enumerate()
                        .map(|(k, w)| {
                            w[0] * (w[1] / w[0]).powf(if k % 2 == 0 { 0.25 } else { 0.75 })
                        })
                        .collect()
                } else {
                    // every other interval, at ⅛ and ⅝ alternately
                    window
                        .windows(2)
                        .enumerate()
                        .filter(|(k, _)| k % 2 == 0)
                        .map(|(k, w)| {
                            w[0] * (w[1] / w[0]).powf(if k % 4 == 0 { 0.125 } else { 0.625 })
                        })
                        .collect()
                };
                cases.extend(q.iter().map(|&q| ("phi", (0.0, 0.0, s * q / c23))));
                cases.extend(
                    q.iter()
                        .map(|&q| ("combined", (0.0, 0.5 * s * q / c22, 0.5 * s * q / c23))),
                );
                for (name, d) in curves() {
                    cases.extend(q.iter().map(|&q| (name, place(d, q))));
                }
            }
        }
        let patch = if mode == "ends" {
            Patch::heldout_grids(aob, 0.0, nu, NL, 1024)
        } else {
            Patch::new(aob, nu, NL, finest_k(aob, 1024))
        };
        for (family, (xi, eta, phi_c)) in cases {
            let sol = patch.solve(xi, eta, phi_c, true);
            assert!(
                sol.converged,
                "not converged: {family} {aob} {xi} {eta} {phi_c}"
            );
            line(&patch.csv_row(family, [xi, eta, phi_c], &sol));
        }
        line(&patch.grids_comment());
        eprintln!(
            "a/b {aob}: done, {:.1} s so far",
            started.elapsed().as_secs_f64()
        );
    }
    line(&format!(
        "# total generator time {:.1} s",
        started.elapsed().as_secs_f64()
    ));
    eprintln!("wrote {out} in {:.1} s", started.elapsed().as_secs_f64());
}
