//! Kalker's linear-theory creepage coefficients C₁₁, C₂₂, C₂₃ (and C₃₃) of the Hertz ellipse
//! over the semi-axis ratio a/b (a along the rolling direction) and Poisson's ratio ν.
//!
//! # Formula
//!
//! Linear theory (vanishing creepage; forces on body B, frame of [`super`]):
//! F_x = −G c² C₁₁ ξ, F_y = −G c² C₂₂ η − G c³ C₂₃ φ, M_z = G c³ C₂₃ η − G c⁴ C₃₃ φ, c = √(ab).
//!
//! - **Table**: Kalker 1990, *Three-dimensional elastic bodies in rolling contact*, Appendix E,
//!   Table E3 — C₁₁, C₂₂, C₂₃ at g = min(a/b, b/a) ∈ {0.1, 0.2, …, 1} on both sides of the
//!   circle and ν ∈ {0, 0.25, 0.5}, three significant digits, as quoted in CONTACT's
//!   `src/m_hertz.f90` (`linrol`, Apache-2.0, E.A.H. Vollebregt). Cross-checked against the
//!   second copy in CONTACT's `src/usetab_table.f90`: the two agree except at a/b = 0.8,
//!   ν = 0.25, C₂₃, where `usetab_table.f90` has 1.15 — a typo (the neighbours are 1.14 at
//!   a/b = 0.7 and 1.36 at 0.9; C₂₃ rises smoothly); this module uses 1.25 (`m_hertz.f90`).
//! - **Between the nodes in g**: cubic Hermite interpolation with finite-difference
//!   (Catmull–Rom) slopes, one-sided at the ends of each side (C¹ inside each side; a/b = 1
//!   joins the two sides with a kink), of C for a < b and of C·g^p for a > b (p = 1 for
//!   C₁₁, C₂₂ ∝ 1/g, p = 3/2 for C₂₃ ∝ g^{-3/2}: the asymptotic growth removed).
//! - **In ν**: 1/C quadratic through the three columns (Kalker's and CONTACT's choice: 1/C
//!   is much closer to linear in ν than C).
//! - **Outside the table** (g < 0.1): the asymptotic forms of `linrol` (Kalker 1990, App. E),
//!   with α = ln(16/g²):
//!   a < b (g = a/b → 0): C₁₁ = π²/(4(1−ν)), C₂₂ = π²/4,
//!   C₂₃ = π√g/(3(1−ν))·[1 + ν(ln(16/g) − 5)];
//!   a > b (g = b/a → 0): C₁₁ = 2π/((α−2ν)g)·[1 + (3 − ln 4)/(α − 2ν)],
//!   C₂₂ = 2π/g·[1 + (1−ν)(3 − ln 4)/((1−ν)α + 2ν)]/((1−ν)α + 2ν),
//!   C₂₃ = 2π/(3g^{3/2}((1−ν)α − 2 + 4ν)).
//!   The asymptote and the table differ at g = 0.1 by up to 2 % (CONTACT switches there with a
//!   jump); here the asymptote is multiplied by 1 + (r − 1)·g/0.1, r = table/asymptote at 0.1:
//!   continuous at g = 0.1 and exact as g → 0.
//! - **C₃₃** is not in CONTACT's copies of Table E3 and no second public copy was found. It is
//!   taken from the exact steady-rolling reference instead (`tools/data/rolling_ref.csv`,
//!   family `linear`: Kalker's exact theory in full adhesion, grid-extrapolated, written by
//!   `tools/rolling_exact`; own error estimate ≤ 0.4 %) at a/b ∈ {0.2, 0.5, 1, 2, 5} and
//!   ν ∈ {0, 0.25, 0.5}: quartic in ln(a/b) through the five rows (of ln C₃₃), 1/C quadratic
//!   in ν. Outside [0.2, 5]: the simplified theory's C₃₃ = (32/(15π))·C₂₃·(b/a)^{3/2} (FASTSIM's
//!   L₃, which gives M_z = −(8/15)a²b³φ/L₃) times its ratio to the exact value at the nearer end
//!   row (continuous; the ratio is 0.72–2.4 at a/b = 5 and 0.93–0.95 at 0.2, so this
//!   extrapolation is rough). The simplified value alone is 5–60 % off inside the range.
//!   The reference's force coefficients agree with Table E3 within 0.4 %, so both come from
//!   one consistent theory.
//!
//! # Domain
//!
//! a/b ∈ [0.01, 100], ν ∈ [0, 0.5] (validated by [`super::RollingContact::new`] and
//! [`super::Elasticity::new`]).
//!
//! # Error
//!
//! At the table's nodes: the table to rounding (asserted in `host-tests/rolling.rs`, ν at the
//! columns). Between nodes in g, measured on the table itself by
//! `python3 tools/kalker_interp_check.py`: the scheme built on every other row (spacing 0.2)
//! predicts the omitted rows within 1.9 % (a < b, C₂₃ at a/b = 0.2, ν = 0) and 1.3 % (a > b,
//! C₂₂ at b/a = 0.2) — CONTACT's linear interpolation: 2.6 % and 46 % (C₂₃ ∝ g^{-3/2}) — so
//! on the full table (an O(h³) scheme at half the spacing) ≈ 0.24 % and 0.16 %, below the
//! table's three digits except near g = 0.1–0.2. In ν: the 1/C quadratic is exact at the three
//! columns; between them it is Kalker's own recommended form (no finer table to measure it
//! against).
//!
//! # Cost
//!
//! Per contact (built once by [`super::RollingContact::new`]): three cubics, three quadratics
//! in ν and a few divisions; a `ln` and a `sqrt` outside the table (g < 0.1).

use crate::Real;

/// The table's rows: g = 0.1 … 1.0; per row C₁₁(ν = 0, 0.25, 0.5), C₂₂(…), C₂₃(…).
/// Side a < b (g = a/b).
#[allow(clippy::approx_constant)] // 3.14 is C₂₂, not π
const NARROW: [[f64; 9]; 10] = [
    [2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731],
    [2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809],
    [2.68, 3.44, 4.80, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889],
    [2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.720, 0.823, 0.977],
    [2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07],
    [2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.930, 1.03, 1.18],
    [3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29],
    [3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40],
    [3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51],
    [3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63],
];

/// Side a > b (g = b/a), rows g = 0.1 … 1.0 as [`NARROW`].
const LONG: [[f64; 9]; 10] = [
    [10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0],
    [6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89],
    [5.57, 6.34, 7.34, 5.57, 6.40, 7.51, 3.79, 4.32, 5.01],
    [4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.70],
    [4.37, 5.10, 6.11, 4.37, 4.90, 5.56, 2.35, 2.62, 2.96],
    [4.06, 4.78, 5.80, 4.06, 4.50, 5.04, 2.01, 2.23, 2.50],
    [3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18],
    [3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94],
    [3.51, 4.22, 5.30, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77],
    [3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63],
];

/// C₃₃ of the exact steady-rolling reference (the `linear` family of
/// `tools/data/rolling_ref.csv`: full adhesion, Richardson-extrapolated over three grids, own
/// error estimate ≤ 0.4 %): rows a/b = 0.2, 0.5, 1, 2, 5, columns ν = 0, 0.25, 0.5.
const C33_EXACT: [[f64; 3]; 5] = [
    [3.4707, 4.2943, 5.6935],
    [1.7461, 1.9375, 2.2275],
    [1.2068, 1.1838, 1.1580],
    [0.9595, 0.8193, 0.6491],
    [0.8329, 0.6044, 0.3428],
];

/// ln(a/b) of the rows of [`C33_EXACT`].
const C33_NODES: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 5.0];

/// The simplified theory's C₃₃ = (32/(15π))·C₂₃·(b/a)^{3/2} (FASTSIM's flexibility L₃).
fn c33_simplified(r: f64, c23: f64) -> f64 {
    32.0 / (15.0 * core::f64::consts::PI) * c23 / (r * libm::sqrt(r))
}

/// C₃₃ for a/b = r, ν: in [0.2, 5] the quartic in ln(a/b) through the five rows of
/// [`C33_EXACT`] of ln C₃₃ per column, then 1/C quadratic in ν; outside, the simplified
/// theory's value times its ratio to the exact one at the nearer end row (continuous).
fn c33(r: f64, nu: f64) -> f64 {
    let x = libm::log(super::within(r, 0.2, 5.0));
    // the nodes' logarithms once (the same values as evaluated in the loop: bit for bit)
    let ln_nodes = C33_NODES.map(libm::log);
    let col = |j: usize| {
        let mut sum = 0.0;
        for (i, row) in C33_EXACT.iter().enumerate() {
            let mut l = 1.0;
            let xi = ln_nodes.get(i).copied().unwrap_or(0.0);
            for (k, xk) in ln_nodes.iter().enumerate() {
                if k != i {
                    l *= (x - xk) / (xi - xk);
                }
            }
            sum += l * libm::log(row.get(j).copied().unwrap_or(1.0));
        }
        libm::exp(sum)
    };
    let inside = in_nu([col(0), col(1), col(2)], nu);
    if (0.2..=5.0).contains(&r) {
        return inside;
    }
    let end = super::within(r, 0.2, 5.0);
    let ratio = inside / c33_simplified(end, coefficients_f64(end, nu)[2]);
    ratio * c33_simplified(r, coefficients_f64(r, nu)[2])
}

/// Kalker's linear-theory coefficients of one patch shape and ν (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kalker<T> {
    /// C₁₁ (longitudinal creepage ξ → F_x)
    pub c11: T,
    /// C₂₂ (lateral creepage η → F_y)
    pub c22: T,
    /// C₂₃ (spin → F_y, and η → M_z)
    pub c23: T,
    /// C₃₃ (spin → M_z; from the exact reference, see the module docs)
    pub c33: T,
}

/// The table's C₁₁, C₂₂, C₂₃ of Table E3 at one of its nodes: `narrow` (a ≤ b) or not,
/// row `i` (g = 0.1·(i+1), i < 10), ν column `j` (ν = 0.25·j, j < 3); `None` outside. For tests.
pub fn table_node(narrow: bool, i: usize, j: usize) -> Option<[f64; 3]> {
    let row = if narrow { NARROW.get(i)? } else { LONG.get(i)? };
    Some([*row.get(j)?, *row.get(3 + j)?, *row.get(6 + j)?])
}

/// Cubic Hermite interpolation of a column over g ∈ [0.1, 1] on 10 uniform nodes
/// ([`super::hermite`]).
fn hermite(rows: &[[f64; 9]; 10], col: usize, g: f64) -> f64 {
    // `get`: no bounds-check panic path (k ≤ 9 and col ≤ 8 by construction)
    let y = |k: usize| rows.get(k).and_then(|r| r.get(col)).copied().unwrap_or(0.0);
    super::hermite(10, y, (g - 0.1) * 10.0)
}

/// 1/C quadratic in ν through the columns ν = 0, 0.25, 0.5.
pub(crate) fn in_nu(c: [f64; 3], nu: f64) -> f64 {
    let inv = (nu - 0.25) * (nu - 0.5) * 8.0 / c[0] - (nu - 0.5) * nu * 16.0 / c[1]
        + nu * (nu - 0.25) * 8.0 / c[2];
    1.0 / inv
}

/// C₁₁, C₂₂, C₂₃ from the table (g ∈ [0.1, 1]).
///
/// For a > b the interpolated quantity is C·g^p with the asymptotic growth removed
/// (C₁₁, C₂₂ ∝ 1/g: p = 1; C₂₃ ∝ g^{-3/2}: p = 3/2), for a < b C itself.
fn tabulated(narrow: bool, g: f64, nu: f64) -> [f64; 3] {
    let rows = if narrow { &NARROW } else { &LONG };
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let gp = |g: f64| match (narrow, k) {
            (true, _) => 1.0,
            (false, 2) => g * libm::sqrt(g),
            (false, _) => g,
        };
        let mut scaled = *rows;
        for (i, row) in scaled.iter_mut().enumerate() {
            for c in row.iter_mut().skip(3 * k).take(3) {
                *c *= gp(0.1 * (i + 1) as f64);
            }
        }
        let c = [0, 1, 2].map(|j| hermite(&scaled, 3 * k + j, g) / gp(g));
        *o = in_nu(c, nu);
    }
    out
}

/// The asymptotic forms for g → 0 (module docs).
fn asymptote(narrow: bool, g: f64, nu: f64) -> [f64; 3] {
    use core::f64::consts::PI;
    if narrow {
        [
            PI * PI / 4.0 / (1.0 - nu),
            PI * PI / 4.0,
            PI * libm::sqrt(g) / 3.0 / (1.0 - nu) * (1.0 + nu * (libm::log(16.0 / g) - 5.0)),
        ]
    } else {
        let al = libm::log(16.0 / (g * g));
        let k = 3.0 - libm::log(4.0);
        let d = (1.0 - nu) * al + 2.0 * nu;
        [
            2.0 * PI / (al - 2.0 * nu) / g * (1.0 + k / (al - 2.0 * nu)),
            2.0 * PI / g * (1.0 + (1.0 - nu) * k / d) / d,
            2.0 * PI / 3.0 / (g * libm::sqrt(g)) / ((1.0 - nu) * al - 2.0 + 4.0 * nu),
        ]
    }
}

/// C₁₁, C₂₂, C₂₃ in `f64` for a/b > 0 and ν ∈ [0, 0.5].
pub(crate) fn coefficients_f64(a_over_b: f64, nu: f64) -> [f64; 3] {
    let narrow = a_over_b <= 1.0;
    let g = if narrow { a_over_b } else { 1.0 / a_over_b };
    if g >= 0.1 {
        return tabulated(narrow, g, nu);
    }
    below_table(narrow, g, nu, tabulated(narrow, 0.1, nu))
}

/// Below the table's first row (g < 0.1): the asymptotic forms corrected towards the table's
/// values `tab` at g = 0.1, the correction fading linearly in g.
fn below_table(narrow: bool, g: f64, nu: f64, tab: [f64; 3]) -> [f64; 3] {
    let (at, here) = (asymptote(narrow, 0.1, nu), asymptote(narrow, g, nu));
    let mut out = [0.0; 3];
    for (o, ((h, t), a)) in out.iter_mut().zip(here.iter().zip(tab).zip(at)) {
        *o = h * (1.0 + (t / a - 1.0) * g / 0.1);
    }
    out
}

/// Table E3's growth from a/b = `end` to a/b = `r` beyond its rows (g = min(r, 1/r) < 0.1 at
/// both, on the same side): [`Kalker::new`]`(r)` over [`Kalker::new`]`(end)` per coefficient
/// (the same formulas: the asymptotic forms corrected towards the table's first row, C₃₃ the
/// simplified theory's, whose ratio to the exact one is the same at both), without the table's
/// interpolation (the row g = 0.1 is a node), so that the rolling laws' coefficients
/// ([`super::creep_matrix::aligned`]) do not link it.
pub(crate) fn growth(r: f64, end: f64, nu: f64) -> [f64; 4] {
    // [`coefficients_f64`] below the table, its row g = 0.1 read as a node
    let c = |r: f64| {
        let narrow = r <= 1.0;
        let g = if narrow { r } else { 1.0 / r };
        let row = if narrow { &NARROW[0] } else { &LONG[0] };
        let col = |k: usize, j: usize| row.get(3 * k + j).copied().unwrap_or(1.0);
        let tab = [0, 1, 2].map(|k| in_nu([col(k, 0), col(k, 1), col(k, 2)], nu));
        below_table(narrow, g, nu, tab)
    };
    let ([h11, h22, h23], [t11, t22, t23]) = (c(r), c(end));
    [
        h11 / t11,
        h22 / t22,
        h23 / t23,
        c33_simplified(r, h23) / c33_simplified(end, t23),
    ]
}

impl<T: Copy> Kalker<T> {
    /// Every coefficient through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Kalker<U> {
        Kalker {
            c11: f(self.c11),
            c22: f(self.c22),
            c23: f(self.c23),
            c33: f(self.c33),
        }
    }
}

impl<T: Real> Kalker<T> {
    /// The coefficients for a/b (a along the rolling direction) and ν, both already
    /// validated (a/b ∈ [0.01, 100], ν ∈ [0, 0.5]); computed in `f64`.
    pub fn new(a_over_b: T, nu: T) -> Self {
        let r = a_over_b.to_f64();
        let [c11, c22, c23] = coefficients_f64(r, nu.to_f64());
        let c33 = c33(r, nu.to_f64());
        Self {
            c11: T::from_f64(c11),
            c22: T::from_f64(c22),
            c23: T::from_f64(c23),
            c33: T::from_f64(c33),
        }
    }
}

#[cfg(test)]
mod growth_tests {
    use super::{Kalker, growth};

    /// `growth` is `Kalker::new`'s ratio between a/b and the end row beyond Table E3 (the
    /// same formulas restated without the table's interpolation).
    #[test]
    fn growth_is_the_ratio_of_kalker_new() {
        for &(r, end) in &[
            (0.01, 0.05),
            (0.02, 0.05),
            (0.049, 0.05),
            (20.5, 20.0),
            (50.0, 20.0),
            (100.0, 20.0),
        ] {
            for &nu in &[0.0, 0.25, 0.3, 0.5] {
                let (h, t) = (Kalker::<f64>::new(r, nu), Kalker::<f64>::new(end, nu));
                let want = [h.c11 / t.c11, h.c22 / t.c22, h.c23 / t.c23, h.c33 / t.c33];
                for (g, w) in growth(r, end, nu).iter().zip(want) {
                    assert!(
                        (g / w - 1.0).abs() < 1e-13,
                        "a/b {r} nu {nu}: {g} against {w}"
                    );
                }
            }
        }
    }
}
