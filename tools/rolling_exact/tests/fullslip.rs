//! (b) Full slip against the library's exact Contensou–Erismann integrals
//! (`contensou::friction::exact::traction`, 5e-15 vs its own reference), ≤ 1e-3 fN (force) and
//! ≤ 1e-3 fNc (moment).
//!
//! At normalised creepage q = 1e4 the elastic correction is O(1/q) = 1e-4; what remains is the
//! quadrature of f·p·ŵ over the elements, extrapolated over three grids.
//! The library's frame has x along the MAJOR axis: for a < b it is this crate's frame turned
//! by +90° (x' = y, y' = −x), and its torque is normalised by fN·(major semi-axis).

use contensou::elliptic::Parameter;
use contensou::friction::exact::traction;
use rolling_exact::cases::Q_FULL;
use rolling_exact::kalker::{Row, TABLE_E3};
use rolling_exact::reference::{Patch, finest_k};

/// Library full-slip totals in this crate's frame: (F/fN, Mz/(fNc)), c = √(ab) = 1.
fn library(aob: f64, xi: f64, eta: f64, phi_c: f64) -> (f64, f64, f64) {
    let (a, b) = (aob.sqrt(), 1.0 / aob.sqrt());
    if a >= b {
        let p = Parameter::from_complement((b / a).powi(2)).unwrap();
        let t = traction(p, xi, eta, a * phi_c);
        (t.fx, t.fy, t.tz * a)
    } else {
        let p = Parameter::from_complement((a / b).powi(2)).unwrap();
        // slip in the turned frame: (w'x, w'y) = (wy, −wx)
        let t = traction(p, eta, -xi, b * phi_c);
        (-t.fy, t.fx, t.tz * b)
    }
}

fn check(target: usize, bound: f64) {
    let mut worst = (0.0f64, 0.0f64);
    let mut failures = Vec::new();
    for &Row { aob, c11, c22, c23 } in &TABLE_E3 {
        let (c11, c22, c23) = (c11[1], c22[1], c23[1]);
        let nl = 0.01;
        let p = Patch::new(aob, 0.25, nl, finest_k(aob, target));
        let s = 3.0 * nl * Q_FULL;
        for (xi, eta, phi_c) in [
            (s / c11, 0.0, 0.0),
            (0.0, s / c22, 0.0),
            (0.0, 0.0, s / c23),
            (0.0, 0.5 * s / c22, -0.5 * s / c23),
            (0.6 * s / c11, -0.3 * s / c22, 0.4 * s / c23),
            (0.0, 0.1 * s / c22, s / c23),
        ] {
            let got = p.solve(xi, eta, phi_c, true);
            let (fx, fy, mz) = library(aob, xi, eta, phi_c);
            let df = (got.totals.fx - fx).abs().max((got.totals.fy - fy).abs());
            let dm = (got.totals.mz - mz).abs();
            println!(
                "a/b {aob} ({xi:.3e},{eta:.3e},{phi_c:.3e}): solver ({:+.5},{:+.5},{:+.5}) exact ({fx:+.5},{fy:+.5},{mz:+.5}) dF {df:.1e} dM {dm:.1e} (est {:.1e}, {:.1e})",
                got.totals.fx, got.totals.fy, got.totals.mz, got.err_f, got.err_m
            );
            worst = (worst.0.max(df), worst.1.max(dm));
            if df > bound || dm > bound {
                failures.push(format!(
                    "a/b {aob} ({xi:e},{eta:e},{phi_c:e}): dF {df:e}, dM {dm:e}"
                ));
            }
        }
    }
    println!("worst: dF {:.2e} fN, dMz {:.2e} fNc", worst.0, worst.1);
    assert!(failures.is_empty(), "beyond {bound:e}: {failures:#?}");
}

/// On the generator's grids (≈1024 elements on the finest): the building of the influence
/// coefficients dominates (full slip converges in ~5 sweeps), a few seconds in release.
#[test]
fn exact_integrals_generator_grids() {
    check(1024, 1e-3);
}
