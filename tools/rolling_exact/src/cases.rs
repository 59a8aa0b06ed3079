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
    /// fN/(Gc²).
    pub nl: f64,
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
        nl: NL,
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

/// CONTACT's published cases (quoted in tests/contact.rs), ν = 0.28, as the families
/// `contact_example` (examples/fastsim.inp case 1: a/b = 2, FN/(G c²)·f = 0.3/32, η = −6.25e-4,
/// φ = 6.25e-4 /mm with c = √32 mm) and `contact_testbank` (a sample of the 3,220-case table,
/// src/test_table.f90: (a/b, spin, angle°, magnitude) with ρ, c as printed in
/// testbank/test_table_mx11.ref_fx).
pub fn contact() -> Vec<Case> {
    let mut v = Vec::new();
    let c = 32f64.sqrt();
    v.push(Case {
        family: "contact_example",
        aob: 2.0,
        nu: 0.28,
        nl: 0.3 / 32.0,
        xi: 0.0,
        eta: -0.000625,
        phi_c: 0.000625 * c,
        coulomb: true,
    });
    let f = 0.3;
    for (aob, spin, angle, mag) in TESTBANK {
        let (rho, cp): (f64, f64) = match aob {
            0.2 | 5.0 => (1772.0, 8.944),
            0.5 | 2.0 => (2075.0, 8.485),
            _ => (2700.0, 9.000),
        };
        let ang = f64::to_radians(angle);
        v.push(Case {
            family: "contact_testbank",
            aob,
            nu: 0.28,
            nl: f / (cp * cp),
            xi: mag * f * ang.cos() * cp / rho,
            eta: mag * f * ang.sin() * cp / rho,
            phi_c: f * spin * cp / rho,
            coulomb: true,
        });
    }
    v
}

/// (a/b, spin, angle°, magnitude) of the testbank sample (tests/contact.rs has the results).
pub const TESTBANK: [(f64, f64, f64, f64); 11] = [
    (1.0, 0.0, 0.0, 0.5),
    (1.0, 0.0, 0.0, 1.1),
    (1.0, 0.0, 0.0, 3.0),
    (1.0, 1.0, 90.0, 0.5),
    (1.0, 0.5, 30.0, 1.4),
    (0.2, 2.0, 0.0, 0.0),
    (0.2, 1.0, 60.0, 0.9),
    (5.0, 0.5, -60.0, 1.4),
    (5.0, 2.0, 90.0, 0.3),
    (0.5, 0.5, -30.0, 2.0),
    (2.0, 1.0, -90.0, 0.7),
];

/// splitmix64 → uniform [0, 1) (the random case sets' generator; deterministic from the seed).
pub fn uniform(state: &mut u64) -> f64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 11) as f64 / (1u64 << 53) as f64
}
