//! Linear coefficients per grid and extrapolated: `cargo run --release --example linear -- <a/b> <nu> <k>`.
use rolling_exact::reference::Patch;
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let p = Patch::new(a[0], a[1], 1.0, a[2] as usize);
    let sx = p.solve(1.0, 0.0, 0.0, false);
    let se = p.solve(0.0, 1.0, 0.0, false);
    let sp = p.solve(0.0, 0.0, 1.0, false);
    for i in 0..3 {
        println!(
            "k={} C11={:.4} C22={:.4} C23={:.4}/{:.4} C33={:.4} sweeps {} {} {} s {:.3} {:.3} {:.3} build {:.3}",
            p.levels[i].k,
            -sx.levels[i].0.fx,
            -se.levels[i].0.fy,
            se.levels[i].0.mz,
            -sp.levels[i].0.fy,
            -sp.levels[i].0.mz,
            sx.levels[i].1.sweeps,
            se.levels[i].1.sweeps,
            sp.levels[i].1.sweeps,
            sx.levels[i].2,
            se.levels[i].2,
            sp.levels[i].2,
            p.levels[i].build_s
        );
    }
    println!(
        "extrap C11={:.4}±{:.4} C22={:.4}±{:.4} C23={:.4}±{:.4} / {:.4}±{:.4} C33={:.4}±{:.4}",
        -sx.totals.fx,
        sx.err_f,
        -se.totals.fy,
        se.err_f,
        se.totals.mz,
        se.err_m,
        -sp.totals.fy,
        sp.err_f,
        -sp.totals.mz,
        sp.err_m
    );
}
