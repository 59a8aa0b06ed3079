//! Kalker's linear theory over the whole domain from the exact theory: the coefficients C₁₁,
//! C₂₂, C₂₃, C₃₃ of a patch rolling along an axis for a/b from 1/20 to 20, and the full 3 × 3
//! creep matrix of a patch rolling at any angle to its axes.
//!
//! # Formula
//!
//! Linear theory in the rolling frame (x along the rolling velocity; forces on body B, frame
//! and signs of [`super`]): (F_x, F_y, M_z/c)/(Gc²) = −K·(ξ, η, cφ), c = √(ab). Along an axis
//! K = [[C₁₁, 0, 0], [0, C₂₂, C₂₃], [0, −C₂₃, C₃₃]] ([`Kalker`]); rolled at an angle to the
//! patch's axes every entry is coupled, with K₂₁ = K₁₂, K₃₁ = −K₁₃, K₃₂ = −K₂₃ (reciprocity of
//! the exact theory, measured to ≤ 0.05 % by the reference) — so six numbers.
//!
//! - **Along an axis** ([`aligned`]): ln C at 17 values of a/b = 20^(i/8 − 1) (log-uniform over
//!   [1/20, 20]) and ν = 0, ¼, ½ from the exact steady-rolling reference in full adhesion
//!   (`tools/rolling_exact`, example `linear_table`, grid-extrapolated:
//!   `tools/data/rolling_linear_aligned.csv`); cubic Hermite in ln(a/b) with finite-difference
//!   slopes, `exp`, then 1/C quadratic in ν for C₁₁, C₂₂, C₂₃ (Kalker's form, as
//!   [`Kalker::new`]) and C₃₃ itself quadratic in ν (at a/b = 20 it falls from 0.79 to 0.16
//!   over ν ∈ [0, ½] nearly linearly; 1/C₃₃ is far from quadratic there). Outside
//!   [1/20, 20]: the end value times [`Kalker::new`]'s ratio between a/b and the end
//!   (continuous; Kalker's asymptotes carry the growth; the ratio is computed from its
//!   asymptotic forms and first row directly, so the table's interpolation is not linked).
//! - **At an angle** ([`CreepMatrix::new`]): the patch a ≥ b (library frame, x the major axis)
//!   rolled along (cos α, sin α). With r = a/b and the aligned ellipse's ratio
//!   q = a_r/b_r = 1/(cos²α/r + r sin²α) ([`super::aligned_ellipse`]), t = ½(1 − ln q/ln r) ∈ [0, 1]
//!   (0: along the major axis, 1: along the minor one). The entries divided by the aligned
//!   coefficients at q, ρ₁₁ = K₁₁/C₁₁, ρ₂₂ = K₂₂/C₂₂, ρ₃₃ = K₃₃/C₃₃, ρ₂₃ = K₂₃/C₂₃,
//!   κ₁₂ = K₁₂/(√(C₁₁C₂₂) sinθ cosθ), κ₁₃ = K₁₃/(√(C₁₁C₃₃) sinθ cosθ) (θ the angle between
//!   the rolling direction and the major axis, reduced to [0°, 90°]; the couplings vanish like
//!   sin 2θ at the axes) are tabulated from the reference
//!   (`tools/data/rolling_linear_skewed.csv`) at ln r = (i/6)·ln 20, i = 0 … 6, t = j/8, j = 0 … 8,
//!   ν = 0, ¼, ½ (exactly 1 and 0 on the axes and for the circle); cubic Hermite in t, then in
//!   ln r, quadratic in ν. The mirror image (cos α·sin α > 0) flips the signs of K₁₂, K₁₃.
//!   So the matrix is exact (to the table) along both axes and the aligned-ellipse rule of
//!   [`super::skew`] is what the ρ's correct: it has ρ = 1, κ = 0.
//!
//! Tables: `tools/fit_rolling_linear.py --write` (nothing fitted: the reference's values at the
//! nodes); `--check` in CI.
//!
//! # Domain
//!
//! a/b ∈ [0.01, 100] (clamped to it), a ≥ b > 0 for [`CreepMatrix::new`] (otherwise the
//! circle's), ν ∈ [0, 0.5] (clamped), any direction (zero → along x). Measured over
//! a/b ∈ [1/20, 20]; beyond, along an axis Kalker's asymptotic growth, at an angle the table's
//! r = 20 (not measured). Total: finite for finite input, no panic path.
//!
//! # Error
//!
//! Against the exact reference's held-out matrices (`tools/data/rolling_linear_check.csv`: 12
//! aligned patches, a/b log-uniform over [1/20, 20], and 28 patches rolled at random angles, r
//! log-uniform over [1, 20], ν uniform over [0, ½]; none a node of the tables; asserted in
//! `host-tests/rolling_linear.rs`; coupling errors relative to √(K_ii K_jj)):
//!
//! | entries | r = max(a/b, b/a) ≤ 6.5 (23 patches) | r > 6.5 (17 patches) |
//! |---|---|---|
//! | C₁₁ / K₁₁, C₂₂ / K₂₂ | 0.36 %, 0.43 % | 0.56 %, 0.68 % |
//! | C₂₃ / K₂₃ | 0.51 % | 2.1 % (a/b = 10.3 at 65°, ν = 0.49) |
//! | C₃₃ / K₃₃ | 3.3 % (aligned a/b = 2.97), skewed 1.6 % | 4.7 % (aligned a/b = 7.4) |
//! | K₁₂, K₁₃ | 0.30 %, 0.75 % | 0.31 %, 4.3 % (a/b = 10.3 at 65°, ν = 0.49) |
//!
//! The reference's own extrapolation estimate for C₃₃ is ≈ 1 % at a/b ≈ 3 and 1–7 % beyond
//! a/b = 7 (C₃₃ is a small difference there, ≈ 0.5 against C₂₃²/C₂₂ ≈ 50), so the C₃₃ figures
//! beyond a/b ≈ 2.5 are as much the reference's as the tables'. Along the narrow side (a/b from
//! 1/20 to 1) every coefficient is within 0.3 % (C₃₃ 0.3 %). Compared with Table E3's
//! interpolation ([`Kalker::new`], ν = 0.3): C₃₃ 17.73 / 8.89 / 6.39 / 0.421 here at
//! a/b = 0.05 / 0.1 / 0.14 / 20 against 24.08 / 10.29 / 6.82 / 0.348 there; C₁₁, C₂₂, C₂₃
//! within 1.5 %.
//!
//! # Cost
//!
//! Per contact, in `f64`: [`aligned`] 12 Hermite segments, 12 `exp`; [`CreepMatrix::new`] that
//! plus 6 × 7 × 3 Hermite segments, one `ln`, two `sqrt`. Not for the hot path: the per-step
//! wrench reads the same table through [`super::skew_linear`] (linear, per contact collapsed
//! in ν).

use super::Kalker;
use super::creep_matrix_data::{ALIGNED, SKEWED};
use super::kalker::in_nu;
use crate::Real;

/// ln 20.
const LN20: f64 = 2.995_732_273_553_991;

/// Cubic Hermite through `y(i)`, i < n, at x0 + i·h (see [`super::hermite`]), x clamped to
/// the nodes' range.
fn hermite(n: usize, y: impl Fn(usize) -> f64, x0: f64, h: f64, x: f64) -> f64 {
    super::hermite(n, y, (x - x0) / h)
}

/// Quadratic in ν through ν = 0, ¼, ½.
fn quad_nu(c: [f64; 3], nu: f64) -> f64 {
    (nu - 0.25) * (nu - 0.5) * 8.0 * c[0] - (nu - 0.5) * nu * 16.0 * c[1]
        + nu * (nu - 0.25) * 8.0 * c[2]
}

/// (C₁₁, C₂₂, C₂₃, C₃₃) from the table at a/b ∈ [1/20, 20] (clamped).
fn tabulated(a_over_b: f64, nu: f64) -> [f64; 4] {
    let x = libm::log(a_over_b);
    let n = ALIGNED.len();
    [0, 1, 2, 3].map(|c| {
        let col = |j: usize| {
            let y = |i: usize| {
                ALIGNED
                    .get(i)
                    .and_then(|r| r.get(c))
                    .and_then(|r| r.get(j))
                    .copied()
                    .unwrap_or(0.0)
            };
            libm::exp(hermite(n, y, -LN20, LN20 / 8.0, x))
        };
        if c < 3 {
            in_nu([col(0), col(1), col(2)], nu)
        } else {
            quad_nu([col(0), col(1), col(2)], nu)
        }
    })
}

/// (C₁₁, C₂₂, C₂₃, C₃₃) in `f64` for a/b > 0, ν ∈ [0, 0.5] (see the module docs).
pub(crate) fn aligned_f64(a_over_b: f64, nu: f64) -> [f64; 4] {
    // the library's domain (as validated by `RollingContact::new`, `Elasticity::new`)
    let (a_over_b, nu) = (
        super::within(a_over_b, 0.01, 100.0),
        super::within(nu, 0.0, 0.5),
    );
    let end = super::within(a_over_b, 1.0 / 20.0, 20.0);
    let inside = tabulated(end, nu);
    if end == a_over_b {
        return inside;
    }
    // beyond the table: Kalker's asymptotic growth from the end value
    let [g11, g22, g23, g33] = super::kalker::growth(a_over_b, end, nu);
    // destructured, not indexed: no bounds check survives at opt-level "z" (tools/no-panic.sh)
    let [c11, c22, c23, c33] = inside;
    [c11 * g11, c22 * g22, c23 * g23, c33 * g33]
}

/// Kalker's coefficients of a patch rolling along an axis (a/b with a along the rolling
/// direction), from the exact theory over a/b ∈ [1/20, 20] (see the [module docs](self)).
/// Computed in `f64`. The rolling laws' coefficients ([`super::RollingShape::new`],
/// [`super::ShapePath`]); not [`Kalker::new`] (Table E3's interpolation).
pub fn aligned<T: Real>(a_over_b: T, nu: T) -> Kalker<T> {
    let [c11, c22, c23, c33] = aligned_f64(a_over_b.to_f64(), nu.to_f64());
    Kalker {
        c11: T::from_f64(c11),
        c22: T::from_f64(c22),
        c23: T::from_f64(c23),
        c33: T::from_f64(c33),
    }
}

/// Nodes of the skewed table in x = ln r ((i/6)·ln 20, i < 7) and in t (j/8, j < 9).
pub(crate) const SKEW_NODES: (usize, usize) = (7, 9);

/// Entry `e` of the skewed table's six ratios (ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) at node (i, j),
/// quadratic in ν ∈ [0, ½] (see the [module docs](self)); zero outside the table.
fn skew_entry_f64(i: usize, j: usize, e: usize, nu: f64) -> f64 {
    let col = |col: usize| {
        SKEWED
            .get(i)
            .and_then(|s| s.get(j))
            .and_then(|s| s.get(e))
            .and_then(|s| s.get(col))
            .copied()
            .unwrap_or(0.0)
    };
    quad_nu([col(0), col(1), col(2)], super::within(nu, 0.0, 0.5))
}

/// The skewed table's six ratios at node (i, j) ([`skew_entry_f64`] of each entry).
pub(crate) fn skew_node_f64(i: usize, j: usize, nu: f64) -> [f64; 6] {
    [0, 1, 2, 3, 4, 5].map(|e| skew_entry_f64(i, j, e, nu))
}

/// The six ratios at x = ln r ∈ [0, ln 20], t ∈ [0, 1] (clamped): cubic Hermite in t, then in
/// x, of [`skew_node_f64`] (what [`CreepMatrix::new`] multiplies the aligned coefficients by).
pub(crate) fn skew_ratios_f64(x: f64, t: f64, nu: f64) -> [f64; 6] {
    let (nx, nt) = SKEW_NODES;
    [0, 1, 2, 3, 4, 5].map(|e| {
        let at_x = |i: usize| {
            let node = |j: usize| skew_entry_f64(i, j, e, nu);
            hermite(nt, node, 0.0, 1.0 / 8.0, t)
        };
        hermite(nx, at_x, 0.0, LN20 / 6.0, x)
    })
}

/// The skewed table's six ratios at its t-nodes (t = j/8) for x = ln r ∈ [0, ln 20] (clamped):
/// each node's cubic Hermite in x. [`skew_in_t`] of it equals [`skew_ratios_f64`] (the two
/// Hermites are linear in the nodes: their order does not matter) at one Hermite in t per
/// call (a fixed contact's r).
pub(crate) fn skew_column_f64(x: f64, nu: f64) -> [[f64; 6]; SKEW_NODES.1] {
    let (nx, _) = SKEW_NODES;
    core::array::from_fn(|j| {
        [0, 1, 2, 3, 4, 5].map(|e| hermite(nx, |i| skew_entry_f64(i, j, e, nu), 0.0, LN20 / 6.0, x))
    })
}

/// The six ratios at t ∈ [0, 1] (clamped) from a column of [`skew_column_f64`]: cubic Hermite
/// in t.
pub(crate) fn skew_in_t(column: &[[f64; 6]; SKEW_NODES.1], t: f64) -> [f64; 6] {
    let (_, nt) = SKEW_NODES;
    [0, 1, 2, 3, 4, 5].map(|e| {
        let node = |j: usize| column.get(j).and_then(|c| c.get(e)).copied().unwrap_or(0.0);
        hermite(nt, node, 0.0, 1.0 / 8.0, t)
    })
}

/// Kalker's linear creep matrix of a patch rolled at any angle to its axes (see the
/// [module docs](self)): (F_x, F_y, M_z/c)/(Gc²) = −K·(ξ, η, cφ) in the rolling frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CreepMatrix<T> {
    /// K, rows (F_x, F_y, M_z/c), columns (ξ, η, cφ).
    pub k: [[T; 3]; 3],
}

impl<T: Real> CreepMatrix<T> {
    /// The patch with semi-axes `a_major` ≥ `b_minor` > 0 along the library frame's x and y,
    /// rolled along (cx, sx) in that frame (normalised here; zero: along x), Poisson's ratio ν.
    /// Computed in `f64`.
    pub fn new(a_major: T, b_minor: T, cx: T, sx: T, nu: T) -> Self {
        let (a, b) = (a_major.to_f64(), b_minor.to_f64());
        let r = if b > 0.0 && a >= b { a / b } else { 1.0 };
        let (cx, sx) = (cx.to_f64(), sx.to_f64());
        let n2 = cx * cx + sx * sx;
        let (c2, s2) = if n2 > 0.0 {
            (cx * cx / n2, sx * sx / n2)
        } else {
            (1.0, 0.0)
        };
        let nu = super::within(nu.to_f64(), 0.0, 0.5);
        // the aligned ellipse's ratio along the rolling direction, and t
        let q = 1.0 / (c2 / r + r * s2);
        let [c11, c22, c23, c33] = aligned_f64(q, nu);
        let x = libm::log(r);
        let t = if x > 0.0 {
            super::within(0.5 * (1.0 - libm::log(q) / x), 0.0, 1.0)
        } else {
            0.0
        };
        let [r11, r22, r33, r23, q12, q13] = skew_ratios_f64(x, t, nu);
        // the mirror image (the major axis at −α from the rolling direction, in (90°, 180°))
        // sinθ cosθ ≥ 0 of the reduced angle θ ∈ [0°, 90°] (θ = −α, or 180° + α mirrored)
        let sc = if n2 > 0.0 {
            libm::fabs(cx * sx) / n2
        } else {
            0.0
        };
        let sign = if cx * sx > 0.0 { -sc } else { sc };
        let k11 = r11 * c11;
        let k22 = r22 * c22;
        let k33 = r33 * c33;
        let k23 = r23 * c23;
        let k12 = sign * q12 * libm::sqrt(c11 * c22);
        let k13 = sign * q13 * libm::sqrt(c11 * c33);
        let f = T::from_f64;
        Self {
            k: [
                [f(k11), f(k12), f(k13)],
                [f(k12), f(k22), f(k23)],
                [f(-k13), f(-k23), f(k33)],
            ],
        }
    }
}
