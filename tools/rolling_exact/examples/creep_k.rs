//! The library's linear creep matrix (`contensou::friction::rolling::CreepMatrix`, the linear
//! theory within 1 % of the exact reference for any patch and skew) for the cases of a
//! reference file, in the reference's rolling frame: reads `a_over_b theta_deg nu` per line
//! on stdin (a₀/b₀ of the patch, its a₀ axis at θ from the rolling direction x), writes
//! `k11,k12,k13,k21,k22,k23,k31,k32,k33` with (F_x, F_y, M_z/c)/(Gc²) = −K·(ξ, η, cφ).
//! Used by tools/fit_rolling_surrogate.py (the surrogate prototype's base law).
//!
//! `cargo run --release --example creep_k < cases.txt`
use contensou::friction::rolling::CreepMatrix;
use std::io::{BufRead, Write};

fn main() {
    let stdin = std::io::stdin();
    let mut out = std::io::BufWriter::new(std::io::stdout());
    for line in stdin.lock().lines() {
        let line = line.expect("stdin");
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|x| x.parse().expect("number"))
            .collect();
        let (aob, theta, nu) = (v[0], v[1].to_radians(), v[2]);
        // library frame: x along the major axis; the rolling direction x at −ψ from it,
        // ψ the major axis' angle from the rolling direction
        let (r, psi) = if aob >= 1.0 {
            (aob, theta)
        } else {
            (1.0 / aob, theta + std::f64::consts::FRAC_PI_2)
        };
        let (a, b) = (r.sqrt(), 1.0 / r.sqrt());
        let k = CreepMatrix::<f64>::new(a, b, psi.cos(), -psi.sin(), nu).k;
        let row: Vec<String> = k.iter().flatten().map(|x| format!("{x:e}")).collect();
        writeln!(out, "{}", row.join(",")).expect("stdout");
    }
}
