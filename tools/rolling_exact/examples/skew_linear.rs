//! The linear creep matrix of a skewed patch, per grid level extrapolated:
//! `cargo run --release --example skew_linear -- <a/b> <theta_deg> <nu> <target elements> [β: n/m = (a/b)^β]`.
use rolling_exact::reference::{Patch, finest_k, skew};
use std::time::Instant;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let th = a[1].to_radians();
    let (ga, gb, s) = skew(a[0], th);
    let t = Instant::now();
    // optional 5th argument: the exponent β of n/m = (a/b)^β (1: square elements)
    let nm = (ga / gb).powf(a.get(4).copied().unwrap_or(1.0));
    let p = Patch::skewed_on(a[0], th, a[2], 1.0, finest_k(nm, a[3] as usize), nm);
    let m = p.creep_matrix();
    let dims = p.grid_dims();
    println!(
        "a/b {} theta {}° nu {}: aligned a/b {:.4} shear {:.4}, grids {}, {:.1} s",
        a[0],
        a[1],
        a[2],
        ga / gb,
        s,
        dims.join(" "),
        t.elapsed().as_secs_f64()
    );
    for i in 0..3 {
        println!(
            "  {:>10.5} {:>10.5} {:>10.5}   ± {:.1e} {:.1e} {:.1e}",
            m.k[i][0], m.k[i][1], m.k[i][2], m.err[i][0], m.err[i][1], m.err[i][2]
        );
    }
}
