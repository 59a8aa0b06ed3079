//! Kalker's linear creep matrix by the exact theory over the whole domain, the reference of the
//! library's linear theory (`contensou::friction::rolling::linear`):
//! `nice cargo run --release --example linear_table -- MODE [OUT]` (from tools/rolling_exact),
//! MODE:
//! - `aligned`: a/b = 20^(2i/16 − 1), i = 0 … 16 (log-uniform over [1/20, 20]) at ν = 0, ¼, ½,
//!   rolling along an axis (θ = 0) → `../data/rolling_linear_aligned.csv`;
//! - `skewed`: the patch's own ratio r = 20^(i/6), i = 1 … 6, rolled at the angles whose aligned
//!   ellipse has ln(a_r/b_r) = u_j = ln r·(1 − j/4), j = 1 … 7 (between the two axes; θ = 0 and
//!   90° are the aligned rows), ν = 0, ¼, ½ → `../data/rolling_linear_skewed.csv`;
//! - `check`: 40 points drawn at random (seed 2929, ν uniform in [0, ½]; the first 12 aligned
//!   with a/b log-uniform in [1/20, 20], the others r log-uniform in [1, 20] and θ uniform in
//!   [0°, 90°]) → `../data/rolling_linear_check.csv` (held out: the
//!   tests of the library's linear theory).
//!
//! Grids: ≈ 1,024 elements on the finest (2,048 for aligned ratios beyond 5), n/m of
//! `elements_ratio`; k/2, 3k/4, k extrapolated as everywhere. Columns: the matrix K of
//! `CreepMatrix` ((F_x, F_y, M_z/c)/(Gc²) = −K (ξ, η, cφ)), row-major, then the extrapolation's
//! error estimate per entry, the grids and the seconds.
use rolling_exact::cases::uniform;
use rolling_exact::reference::{Patch, elements_ratio, finest_k, skew};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mode = args.first().map(String::as_str).unwrap_or("aligned");
    let out = args
        .get(1)
        .cloned()
        .unwrap_or(format!("../data/rolling_linear_{mode}.csv"));
    let mut cases: Vec<(f64, f64, f64)> = Vec::new(); // (own a/b, θ rad, ν)
    let nus = [0.0, 0.25, 0.5];
    match mode {
        "aligned" => {
            // in this order the long shapes (slow) come last
            for i in 0..=16 {
                let r = 20f64.powf(2.0 * i as f64 / 16.0 - 1.0);
                cases.extend(nus.iter().map(|&nu| (r, 0.0, nu)));
            }
        }
        "skewed" => {
            for i in 1..=6 {
                let r = 20f64.powf(i as f64 / 6.0);
                for j in 1..=7 {
                    let u = r.ln() * (1.0 - j as f64 / 4.0);
                    // e^{−u} = 1/r + sin²θ (r − 1/r) (the aligned ellipse's A, c = 1)
                    let s2 = ((-u).exp() - 1.0 / r) / (r - 1.0 / r);
                    let th = s2.clamp(0.0, 1.0).sqrt().asin();
                    cases.extend(nus.iter().map(|&nu| (r, th, nu)));
                }
            }
        }
        "check" => {
            let mut state = 2929u64;
            for i in 0..40 {
                // the first 12 aligned (θ = 0, r over [1/20, 20]), the others skewed
                let r = 20f64.powf(
                    uniform(&mut state) * if i < 12 { 2.0 } else { 1.0 }
                        - if i < 12 { 1.0 } else { 0.0 },
                );
                let t = uniform(&mut state);
                let th = if i < 12 {
                    0.0
                } else {
                    std::f64::consts::FRAC_PI_2 * t
                };
                let nu = 0.5 * uniform(&mut state);
                cases.push((r, th, nu));
            }
        }
        _ => panic!("mode: aligned, skewed or check"),
    }
    let started = Instant::now();
    let mut line = rolling_exact::line_writer(&out);
    line(&format!(
        "# Kalker's linear creep matrix by the exact theory, mode `{mode}` of tools/rolling_exact/examples/linear_table.rs (see there)."
    ));
    line(
        "# (F_x, F_y, M_z/c)/(G c^2) = -K (xi, eta, c phi); theta_deg: rolling direction x to the patch's a axis (a/b = a_over_b, c = 1).",
    );
    line(
        "a_over_b,theta_deg,nu,k11,k12,k13,k21,k22,k23,k31,k32,k33,e11,e12,e13,e21,e22,e23,e31,e32,e33,grids,seconds",
    );
    for (r, th, nu) in cases {
        let t = Instant::now();
        let (a, b, _) = skew(r, th);
        let nm = elements_ratio(a / b);
        // the long side converges slowly (full adhesion along long strips): finer there
        let target = if a / b > 5.0 { 2048 } else { 1024 };
        let patch = Patch::skewed_on(r, th, nu, 1.0, finest_k(nm, target), nm);
        let m = patch.creep_matrix();
        let dims = patch.grid_dims();
        let k: Vec<String> = m.k.iter().flatten().map(|v| format!("{v:.7e}")).collect();
        let e: Vec<String> = m.err.iter().flatten().map(|v| format!("{v:.2e}")).collect();
        line(&format!(
            "{r:.10},{:.10},{nu},{},{},{},{:.1}",
            th.to_degrees(),
            k.join(","),
            e.join(","),
            dims.join(" "),
            t.elapsed().as_secs_f64()
        ));
    }
    eprintln!("wrote {out} in {:.1} s", started.elapsed().as_secs_f64());
}
