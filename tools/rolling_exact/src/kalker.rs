//! Kalker's creepage coefficients (Kalker 1990, *Three-dimensional elastic bodies in rolling
//! contact*, Appendix E, Table E3), quoted as cited constants for the checks and for the
//! normalisation of the case set.
//!
//! Source of the numbers: CONTACT (E.A.H. Vollebregt, Apache-2.0, github.com/eve70a/CONTACT),
//! `src/m_hertz.f90`, subroutine `linrol` (data statement `cij`, table E.3), cross-checked
//! against a second public copy of the same table (a `linrol` in another CONTACT source file,
//! which has the known typo C23 = 1.15 for 1.25 at a/b = 0.8, ν = 0.25; the rows used here
//! agree digit for digit). Only ν = 0.25 and a/b ∈ {0.2, 0.5, 1, 2, 5} are quoted.
//! `linrol` holds C11, C22 and C23 only (no C33).

/// (a/b, C11, C22, C23) at ν = 0.25.
pub const TABLE_E3_NU025: [(f64, f64, f64, f64); 5] = [
    (0.2, 3.37, 2.63, 0.603),
    (0.5, 3.62, 3.01, 0.929),
    (1.0, 4.12, 3.67, 1.47),
    (2.0, 5.10, 4.90, 2.62),
    (5.0, 7.78, 8.14, 6.63),
];

/// Table row for `aob` (exact match), at ν = 0.25.
pub fn coefficients(aob: f64) -> Option<(f64, f64, f64)> {
    TABLE_E3_NU025
        .iter()
        .find(|r| (r.0 - aob).abs() < 1e-12)
        .map(|r| (r.1, r.2, r.3))
}
