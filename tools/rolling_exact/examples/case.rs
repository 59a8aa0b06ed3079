//! One case on the three grids: `cargo run --release --example case -- <a/b> <nu> <nl> <k> <xi> <eta> <phi_c>`.
use rolling_exact::reference::Patch;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let p = Patch::new(a[0], a[1], a[2], a[3] as usize);
    let s = p.solve(a[4], a[5], a[6], true);
    for (i, l) in s.levels.iter().enumerate() {
        println!(
            "k={:3} N={:5} fx={:+.6} fy={:+.6} mz={:+.6} sweeps {:4} slip {:5} {:.3} s",
            p.levels[i].k,
            p.levels[i].grid.len(),
            l.0.fx,
            l.0.fy,
            l.0.mz,
            l.1.sweeps,
            l.1.slip_elements,
            l.2
        );
    }
    println!(
        "extrap   fx={:+.6} fy={:+.6} mz={:+.6} err_f {:.1e} err_m {:.1e}",
        s.totals.fx, s.totals.fy, s.totals.mz, s.err_f, s.err_m
    );
}
