//! (a) Linear limit against Kalker's Table E3 (Kalker 1990, Appendix E), ≤ 2 % after grid
//! extrapolation, a/b ∈ {0.2, 0.5, 1, 2, 5}, ν = 0.25; plus ν = 0 and 0.5 at a/b = 1 and the
//! reciprocity C23(η → Mz) = C23(φ → Fy) of the exact theory.
//!
//! Table values: rolling_exact::kalker (CONTACT's `linrol`, src/m_hertz.f90, cross-checked).
//! Fast tests: finest grid ≈ 256 elements (CI); `--ignored`: ≈ 1024 (the generator's grids).

use rolling_exact::kalker::TABLE_E3_NU025;
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
    for &(aob, c11, c22, c23) in &TABLE_E3_NU025 {
        let (c, err) = coefficients(aob, 0.25, target);
        let rel = [
            c[0] / c11 - 1.0,
            c[1] / c22 - 1.0,
            c[2] / c23 - 1.0,
            c[3] / c23 - 1.0,
        ];
        println!(
            "a/b {aob}: C11 {:.4} ({c11}) C22 {:.4} ({c22}) C23 {:.4}/{:.4} ({c23}) C33 {:.4}; rel {:+.4} {:+.4} {:+.4} {:+.4}; err est {err:.1e}",
            c[0], c[1], c[2], c[3], c[4], rel[0], rel[1], rel[2], rel[3]
        );
        for r in rel {
            worst = worst.max(r.abs());
            assert!(r.abs() <= bound, "a/b {aob}: {rel:?} beyond {bound}");
        }
        // reciprocity of the exact theory: the two C23 agree
        assert!(
            (c[2] / c[3] - 1.0).abs() <= 0.005,
            "C23 reciprocity at a/b {aob}: {} vs {}",
            c[2],
            c[3]
        );
    }
    println!("worst relative deviation from Table E3: {worst:.4}");
}

#[test]
fn table_e3_small_grids() {
    check_table(256, 0.02);
}

#[test]
#[ignore = "generator grids (≈1024 elements), ~1 min in release"]
fn table_e3_generator_grids() {
    check_table(1024, 0.01);
}

/// ν = 0 and 0.5 at a/b = 1: Table E3's last row of the a ≤ b half (CONTACT `linrol` data:
/// C11 = 3.40, 4.12, 5.20; C22 = 3.40, 3.67, 3.98; C23 = 1.33, 1.47, 1.63 for ν = 0, 0.25, 0.5).
#[test]
fn table_e3_poisson_ratio_circle() {
    for (nu, c11, c22, c23) in [(0.0, 3.40, 3.40, 1.33), (0.5, 5.20, 3.98, 1.63)] {
        let (c, _) = coefficients(1.0, nu, 256);
        println!(
            "nu {nu}: C11 {:.4} C22 {:.4} C23 {:.4}/{:.4} C33 {:.4}",
            c[0], c[1], c[2], c[3], c[4]
        );
        for (got, want) in [(c[0], c11), (c[1], c22), (c[2], c23), (c[3], c23)] {
            assert!((got / want - 1.0).abs() <= 0.02, "nu {nu}: {got} vs {want}");
        }
    }
}
