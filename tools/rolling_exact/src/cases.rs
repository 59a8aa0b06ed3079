//! The case set of tools/data/rolling_ref.csv (ROLLING.md): families, shapes, magnitudes.
//!
//! Normalised creepage q: the linear theory's force reaches 3fN at q = 1 (Kalker's
//! ξ·Gc²C11/(3fN)). With nl = fN/(Gc²) and c = 1: ξ = 3·nl·q/C11, η = 3·nl·q/C22,
//! φc = 3·nl·q/C23 (C from Table E3 at ν = 0.25, only to place the cases).

use crate::kalker;

/// Load ratio fN/(Gc²) used for every generated case.
pub const NL: f64 = 0.01;

/// The patch shapes of the set.
pub const SHAPES: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 5.0];

/// One row to compute.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    pub family: &'static str,
    pub aob: f64,
    pub nu: f64,
    pub xi: f64,
    pub eta: f64,
    pub phi_c: f64,
    /// false: full adhesion (the linear family).
    pub coulomb: bool,
}

/// `count` values log spaced from `lo` to `hi`.
pub fn logspace(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    (0..count)
        .map(|i| lo * (hi / lo).powf(i as f64 / (count - 1) as f64))
        .collect()
}

/// Creep-curve magnitudes q: 15 from 1e-3 to 20 (30 for spin, which saturates slowly).
pub fn magnitudes(spin: bool) -> Vec<f64> {
    logspace(1e-3, if spin { 30.0 } else { 20.0 }, 15)
}

/// Full-slip magnitude: q = 1e4 (elastic correction O(1/q)).
pub const Q_FULL: f64 = 1e4;

/// All cases for one shape at ν = 0.25 (creep curves, full slip, linear), plus the linear
/// family at ν = 0 and 0.5.
pub fn for_shape(aob: f64) -> Vec<Case> {
    let (c11, c22, c23) = kalker::coefficients(aob).expect("shape in Table E3");
    let s = 3.0 * NL;
    let nu = 0.25;
    let mut v = Vec::new();
    let case = |family, xi, eta, phi_c, coulomb, nu| Case {
        family,
        aob,
        nu,
        xi,
        eta,
        phi_c,
        coulomb,
    };
    for q in magnitudes(false) {
        v.push(case("xi", s * q / c11, 0.0, 0.0, true, nu));
    }
    for q in magnitudes(false) {
        v.push(case("eta", 0.0, s * q / c22, 0.0, true, nu));
    }
    for q in magnitudes(true) {
        v.push(case("phi", 0.0, 0.0, s * q / c23, true, nu));
    }
    // η with φ: equal linear lateral-force shares, same sign
    for q in magnitudes(true) {
        v.push(case(
            "combined",
            0.0,
            0.5 * s * q / c22,
            0.5 * s * q / c23,
            true,
            nu,
        ));
    }
    // ξ with η: equal linear shares, |F_linear| = 3fN·q
    let r = std::f64::consts::FRAC_1_SQRT_2;
    for q in magnitudes(false) {
        v.push(case(
            "combined",
            r * s * q / c11,
            r * s * q / c22,
            0.0,
            true,
            nu,
        ));
    }
    // full slip: five directions
    let q = Q_FULL * s;
    for (xi, eta, phi) in [
        (1.0 / c11, 0.0, 0.0),
        (0.0, 1.0 / c22, 0.0),
        (0.0, 0.0, 1.0 / c23),
        (0.0, 0.5 / c22, -0.5 / c23),
        (0.6 / c11, -0.3 / c22, 0.4 / c23),
    ] {
        v.push(case("fullslip", q * xi, q * eta, q * phi, true, nu));
    }
    // linear limit: normalised creepage 1e-3, full adhesion (exactly linear)
    for nu in [0.0, 0.25, 0.5] {
        let q = 1e-3 * s;
        v.push(case("linear", q, 0.0, 0.0, false, nu));
        v.push(case("linear", 0.0, q, 0.0, false, nu));
        v.push(case("linear", 0.0, 0.0, q, false, nu));
    }
    v
}
