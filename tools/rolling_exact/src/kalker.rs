//! Kalker's creepage coefficients (Kalker 1990, *Three-dimensional elastic bodies in rolling
//! contact*, Appendix E, Table E3), quoted as cited constants for the checks and for the
//! normalisation of the case set.
//!
//! Source of the numbers: CONTACT (E.A.H. Vollebregt, Apache-2.0, github.com/eve70a/CONTACT),
//! `src/m_hertz.f90`, subroutine `linrol` (data statement `cij`, "table E.3"; rows g = a/b for
//! a ≤ b and g = b/a for a > b), cross-checked against a second public copy of the same table
//! (another `linrol`, which has the known typo C23 = 1.15 for 1.25 at a/b = 0.8, ν = 0.25; the
//! rows quoted here agree digit for digit). `linrol` holds C11, C22 and C23 only (no C33).

/// Poisson ratios of the table's columns.
pub const NU: [f64; 3] = [0.0, 0.25, 0.5];

/// One row of Table E3: the coefficients at ν = 0, 0.25, 0.5.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    pub aob: f64,
    pub c11: [f64; 3],
    pub c22: [f64; 3],
    pub c23: [f64; 3],
}

const fn row(aob: f64, c11: [f64; 3], c22: [f64; 3], c23: [f64; 3]) -> Row {
    Row { aob, c11, c22, c23 }
}

/// The rows a/b = 0.2, 0.5, 1, 2, 5.
#[allow(clippy::approx_constant)] // 3.14 is C22(a/b = 0.5, ν = 0.5), not π
#[rustfmt::skip]
pub const TABLE_E3: [Row; 5] = [
    //  a/b  C11 at ν = 0, 0.25, 0.5  C22                  C23
    row(0.2, [2.59, 3.37, 4.81], [2.59, 2.63, 2.66], [0.483, 0.603, 0.809]),
    row(0.5, [2.88, 3.62, 4.83], [2.88, 3.01, 3.14], [0.827, 0.929, 1.07]),
    row(1.0, [3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63]),
    row(2.0, [4.37, 5.10, 6.11], [4.37, 4.90, 5.56], [2.35, 2.62, 2.96]),
    row(5.0, [6.96, 7.78, 8.82], [6.96, 8.14, 9.79], [5.72, 6.63, 7.89]),
];

/// (C11, C22, C23) for `aob` (a row of the table, exact match) and ν = 0, 0.25 or 0.5.
pub fn coefficients_nu(aob: f64, nu: f64) -> Option<(f64, f64, f64)> {
    let col = NU.iter().position(|&n| (n - nu).abs() < 1e-12)?;
    TABLE_E3
        .iter()
        .find(|r| (r.aob - aob).abs() < 1e-12)
        .map(|r| (r.c11[col], r.c22[col], r.c23[col]))
}

/// (C11, C22, C23) for `aob` at ν = 0.25.
pub fn coefficients(aob: f64) -> Option<(f64, f64, f64)> {
    coefficients_nu(aob, 0.25)
}
