//! Convergence study: `cargo run --release --example conv -- <a/b> <nu> <nl> <xi> <eta> <phi_c> <coulomb 0|1> k1 k2 ...`
use rolling_exact::{grid::Grid, influence::SlipOperator, solver::*};
fn main() {
    let a: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let (aob, nu, nl) = (a[0], a[1], a[2]);
    let c = Creepage {
        xi: a[3],
        eta: a[4],
        phi: a[5],
    };
    let coulomb = a[6] > 0.0;
    let (sa, sb) = (aob.sqrt(), 1.0 / aob.sqrt());
    for &k in &a[7..] {
        let k = k as usize;
        let (n, m) = if aob >= 1.0 {
            (((k as f64) * aob).round() as usize, k)
        } else {
            (k, ((k as f64) / aob).round() as usize)
        };
        let g = Grid::new(sa, sb, m, n, nl);
        let op = SlipOperator::new(&g, nu);
        let t = std::time::Instant::now();
        let (r, s) = solve(
            &g,
            &op,
            c,
            coulomb,
            Settings {
                tol: 1e-9,
                ..Default::default()
            },
        );
        println!(
            "{k} {:.8} {:.8} {:.8} {} {:.3}",
            r.fx / nl,
            r.fy / nl,
            r.mz / nl,
            s.sweeps,
            t.elapsed().as_secs_f64()
        );
    }
}
