//! Exact steady-rolling totals for arbitrary cases read from stdin, one per line:
//! `a_over_b theta_deg nu xi eta phi_c [tag]` (the held-out set's parametrisation: a₀/b₀ of the
//! patch, c = √(a₀b₀) = 1, its a₀ axis at θ from the rolling direction x, nl = 0.01), written as
//! rows of the held-out file's format (family = tag, default `cases`). Used for the creep-curve
//! families through held-out points (same shape and direction, magnitude varied) and for the
//! surrogate's targeted training points (tools/fit_rolling_surrogate.py; never the held-out
//! points themselves).
//!
//! `nice cargo run --release --example cases -- [ELEMENTS] < cases.txt > out.csv`
//! (ELEMENTS on the finest grid, default 1,024 as the held-out set).
use rolling_exact::reference::skewed_row;
use std::io::{BufRead, Write};

/// Load ratio fN/(Gc²), as the held-out set.
const NL: f64 = 0.01;

fn main() {
    let elements: usize = std::env::args()
        .nth(1)
        .map_or(1024, |s| s.parse().expect("ELEMENTS"));
    let stdin = std::io::stdin();
    let mut out = std::io::stdout();
    writeln!(
        out,
        "family,a_over_b,theta_deg,nu,nl,xi,eta,phi_c,fx,fy,mz,err_f,err_m,converged,seconds"
    )
    .expect("stdout");
    for line in stdin.lock().lines() {
        let line = line.expect("stdin");
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() < 6 || f[0].starts_with('#') {
            continue;
        }
        let v: Vec<f64> = f[..6].iter().map(|x| x.parse().expect("number")).collect();
        let tag = f.get(6).copied().unwrap_or("cases");
        let (aob, theta, nu, xi, eta, phi_c) = (v[0], v[1].to_radians(), v[2], v[3], v[4], v[5]);
        writeln!(
            out,
            "{}",
            skewed_row(tag, aob, theta, nu, NL, [xi, eta, phi_c], elements)
        )
        .and_then(|()| out.flush())
        .expect("stdout");
    }
}
