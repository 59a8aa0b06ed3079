//! (a) Linear limit against Kalker's Table E3 (Kalker 1990, Appendix E), ≤ 2 % after grid
//! extrapolation, a/b ∈ {0.2, 0.5, 1, 2, 5} at ν = 0.25 and also at ν = 0 and 0.5; and the
//! reciprocity C23(η → Mz) = C23(φ → Fy) of the exact theory (≤ 0.5 %).
//!
//! Table values: rolling_exact::kalker (CONTACT's `linrol`, src/m_hertz.f90, cross-checked).
//! Fast tests: finest grid ≈ 256 elements (CI); `--ignored`: ≈ 1024 (the generator's grids).

use rolling_exact::kalker::{NU, Row, TABLE_E3};
use rolling_exact::reference::{Patch, finest_k};

/// (C11, C22, C23 from Mz(η), C23 from Fy(φ), C33) extrapolated, and the largest error estimate.
fn coefficients(aob: f64, nu: f64, target: usize) -> ([f64; 5], f64) {
    let p = Patch::new(aob, nu, 1.0, finest_k(aob, target));
    let x = p.solve(1.0, 0.0, 0.0, false);
    let e = p.solve(0.0, 1.0, 0.0, false);
    let f = p.solve(0.0, 0.0, 1.0, false);
    let c = [
        -x.totals.fx,
        -e.totals.fy,
        e.totals.mz,
        -f.totals.fy,
        -f.totals.mz,
    ];
    let err = [x.err_f, e.err_f, e.err_m, f.err_f, f.err_m]
        .into_iter()
        .fold(0.0, f64::max);
    (c, err)
}

fn check_table(target: usize, bound: f64) {
    let mut worst = 0.0f64;
    for &Row { aob, c11, c22, c23 } in &TABLE_E3 {
        for (col, &nu) in NU.iter().enumerate() {
            let (c, err) = coefficients(aob, nu, target);
            let want = [c11[col], c22[col], c23[col], c23[col]];
            let rel: Vec<f64> = (0..4).map(|i| c[i] / want[i] - 1.0).collect();
            println!(
                "a/b {aob} nu {nu}: C11 {:.4} ({}) C22 {:.4} ({}) C23 {:.4}/{:.4} ({}) C33 {:.4}; rel {:+.4} {:+.4} {:+.4} {:+.4}; err est {err:.1e}",
                c[0],
                want[0],
                c[1],
                want[1],
                c[2],
                c[3],
                want[2],
                c[4],
                rel[0],
                rel[1],
                rel[2],
                rel[3]
            );
            for r in &rel {
                worst = worst.max(r.abs());
                assert!(
                    r.abs() <= bound,
                    "a/b {aob} nu {nu}: {rel:?} beyond {bound}"
                );
            }
            // reciprocity of the exact theory: the two C23 agree
            assert!(
                (c[2] / c[3] - 1.0).abs() <= 0.005,
                "C23 reciprocity at a/b {aob} nu {nu}: {} vs {}",
                c[2],
                c[3]
            );
        }
    }
    println!("worst relative deviation from Table E3: {worst:.4}");
}

/// Finest grids of about 256 elements (CI).
#[test]
fn table_e3_small_grids() {
    check_table(256, 0.02);
}

/// The generator's grids (about 1,024–1,280 elements on the finest).
#[test]
#[ignore = "generator grids, ~2 min in release"]
fn table_e3_generator_grids() {
    check_table(1024, 0.01);
}
