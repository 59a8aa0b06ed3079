//! The exact linear theory of a patch rolled at an angle to its axes, per call: the creep
//! shape of the aligned ellipse ([`super::skew`]) turned into the real patch's creep matrix.
//!
//! # Formula
//!
//! The aligned-ellipse rule ([`super::aligned_ellipse`]) gives a patch rolled at the angle θ to
//! its major axis the coefficients (C₁₁, C₂₂, C₂₃, C₃₃) of the ellipse aligned with the rolling
//! direction, ratio q = a_r/b_r. The exact theory's matrix K differs from that diagonal by
//! 13–53 % at e² = 0.9 and couples ξ into F_y and M_z ([`super::CreepMatrix`]):
//!
//! K₁₁ = ρ₁₁C₁₁, K₂₂ = ρ₂₂C₂₂, K₃₃ = ρ₃₃C₃₃, K₂₃ = ρ₂₃C₂₃,
//! K₁₂ = K₂₁ = ∓κ₁₂√(C₁₁C₂₂)·|sinθ cosθ|, K₁₃ = −K₃₁ = ∓κ₁₃√(C₁₁C₃₃)·|sinθ cosθ|
//!
//! (upper sign when cos θ·sin θ > 0 in the contact frame, the mirror image otherwise), the six
//! ratios (ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) functions of r = a/b ≥ 1 (the patch's own ratio),
//! t = ½(1 − ln q/ln r) ∈ [0, 1] (0: rolling along the major axis, 1: along the minor one)
//! and ν: the exact reference's table of [`super::CreepMatrix`] (ln r = (i/6)·ln 20, i < 7;
//! t = j/8, j < 9; quadratic in ν). Per contact ν is fixed and the table collapsed to it:
//!
//! - a fixed contact (r fixed, so t and every entry are functions of ln q alone): the six
//!   entries (K₁₁, K₂₂, K₂₃, K₃₃, κ₁₂√(C₁₁C₂₂), κ₁₃√(C₁₁C₃₃)) of [`super::CreepMatrix::new`]
//!   (the aligned coefficients times the table's cubic Hermite in t and ln r) on 17 nodes in
//!   ln q (t = j/16), values and slopes, cubic Hermite per call (`SkewPath`: the per-step
//!   wrench's); or
//!   one row of the ratios alone, 17 t-nodes (t = j/16) at its r, linear in t per call,
//!   [`SkewRow`];
//! - a varying contact: the 7 × 9 nodes, [`SkewGrid`], linear in t and in ln r per call
//!   (clamped to r ≤ 20: the table's end).
//!
//! Exact on the axes (ρ = 1, κ·sinθcosθ = 0) and for a circle.
//!
//! # Domain and error
//!
//! Any r ≥ 1 (ln r ≤ 0: the circle's, no skew), any q (t clamped to [0, 1]). Against the
//! exact reference's 40 held-out matrices (`tools/data/rolling_linear_check.csv`, entries as in
//! [`super::creep_matrix`]; `host-tests/rolling_linear.rs`): the row as
//! [`super::CreepMatrix::new`] (K₁₁ 0.53 %, K₂₂ 0.67 %, K₂₃ 2.0 %, K₃₃ 4.7 %, K₁₂ 0.31 %, K₁₃
//! 4.3 %); the grid K₁₁ 0.82 %, K₂₂ 0.88 %, K₂₃ 2.5 % (1.8 % at r = 3), K₃₃ 6.9 % (bilinear near the major axis
//! of long patches at ν ≈ ½), K₁₂ 0.46 %, K₁₃ 4.3 %. `SkewPath` is [`super::CreepMatrix::new`]
//! to its Hermite in ln q: a fixed contact's skewed wrench within 3.1e-4 fN / fNc of the one
//! built on [`super::CreepMatrix::new`] per call at a/b ≈ 4, 7.4e-3 at a/b ≈ 40
//! (`host-tests/rolling_wrench.rs`).
//!
//! # Cost
//!
//! Per call: one division, one linear (row) or bilinear (grid) interpolation of six numbers,
//! two square roots; `SkewPath`: one Hermite segment of six numbers (with the coefficients:
//! no [`super::ShapePath`] look-up, no division, no square root). Per contact: 103 numbers
//! (row), 378 (grid), 17 × 12 and 12 (`SkewPath`).

use super::creep_matrix::{
    SKEW_NODES, aligned_f64, skew_column_f64, skew_in_t, skew_node_f64, skew_ratios_f64,
};
use super::skew::{Nodes, kalker_of, shape_of};
use super::{Kalker, RollingShape};
use crate::Real;

/// Nodes in t of the grid (the table's).
const NT: usize = SKEW_NODES.1;
/// Nodes in t of a row: twice as fine as the table's (cubic Hermite of it), so that the
/// per-call linear interpolation follows the table's Hermite.
const NT_ROW: usize = 2 * SKEW_NODES.1 - 1;
/// Nodes in ln r.
const NR: usize = SKEW_NODES.0;
/// ln 20.
const LN20: f64 = 2.995_732_273_553_991;

/// The six ratios at the t-nodes for one patch ratio r, linear in t per call (see the
/// [module docs](self); the per-step wrench of a fixed contact reads its creep matrix from
/// one path in ln q instead, cubic Hermite of the same table).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkewRow<T> {
    /// (ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) at t = j/16
    node: [[T; 6]; NT_ROW],
    /// 1/ln r (0 for a circle)
    inv_ln_r: T,
}

/// The six ratios at the 7 × 9 (ln r, t) nodes: a varying contact (see the
/// [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkewGrid<T> {
    /// (ρ₁₁, ρ₂₂, ρ₃₃, ρ₂₃, κ₁₂, κ₁₃) at ln r = (i/6)·ln 20, t = j/8
    node: [[[T; 6]; NT]; NR],
}

/// No skew: ρ = 1, κ = 0.
const ONE: [f64; 6] = [1.0, 1.0, 1.0, 1.0, 0.0, 0.0];

impl<T: Copy> SkewGrid<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> SkewGrid<U> {
        SkewGrid {
            node: self.node.map(|r| r.map(|n| n.map(f))),
        }
    }
}

impl<T: Real> SkewRow<T> {
    /// For a patch ratio r = a/b ≥ 1 (< 1 or NaN: the circle's) and ν ∈ [0, 0.5] (clamped).
    /// Built in `f64`.
    pub fn new(r: T, nu: T) -> Self {
        let r = r.to_f64();
        let x = if r > 1.0 { libm::log(r) } else { 0.0 };
        let nu = nu.to_f64();
        let node = core::array::from_fn(|j| {
            let v = if x > 0.0 {
                skew_ratios_f64(x, j as f64 / (NT_ROW - 1) as f64, nu)
            } else {
                ONE
            };
            v.map(T::from_f64)
        });
        Self {
            node,
            inv_ln_r: T::from_f64(if x > 0.0 { 1.0 / x } else { 0.0 }),
        }
    }

    /// The six ratios for the aligned ratio q (as ln q; q between 1/r and r): linear in t
    /// between the nodes.
    #[inline]
    pub fn at(&self, ln_q: T) -> [T; 6] {
        let t = T::HALF * (T::ONE - ln_q * self.inv_ln_r);
        let (j, f) = cell(t, NT_ROW);
        let at = |j: usize| self.node.get(j).copied().unwrap_or([T::ZERO; 6]);
        lerp(at(j), at(j + 1), f)
    }
}

impl<T: Real> SkewGrid<T> {
    /// For ν ∈ [0, 0.5] (clamped). Built in `f64`.
    pub fn new(nu: T) -> Self {
        let nu = nu.to_f64();
        Self {
            node: core::array::from_fn(|i| {
                core::array::from_fn(|j| skew_node_f64(i, j, nu).map(T::from_f64))
            }),
        }
    }

    /// The six ratios for a patch ratio r (as ln r ≥ 0; clamped to [0, ln 20]) and the aligned
    /// ratio q (as ln q): bilinear in (ln r, t) between the nodes.
    #[inline]
    pub fn at(&self, ln_r: T, ln_q: T) -> [T; 6] {
        if ln_r <= T::ZERO {
            return ONE.map(T::from_f64);
        }
        let t = T::HALF * (T::ONE - ln_q / ln_r);
        let (j, ft) = cell(t, NT);
        let (i, fr) = cell(ln_r * T::from_f64(1.0 / LN20), NR);
        let at = |i: usize, j: usize| {
            self.node
                .get(i)
                .and_then(|r| r.get(j))
                .copied()
                .unwrap_or([T::ZERO; 6])
        };
        lerp(
            lerp(at(i, j), at(i, j + 1), ft),
            lerp(at(i + 1, j), at(i + 1, j + 1), ft),
            fr,
        )
    }
}

/// The cell (j, f) of u ∈ [0, 1] (clamped; NaN: 0) on n uniform nodes: u·(n − 1) = j + f,
/// j ≤ n − 2, f ∈ [0, 1].
#[inline(always)]
fn cell<T: Real>(u: T, n: usize) -> (usize, T) {
    let last = T::from_usize(n - 1);
    let s = if u > T::ZERO {
        (u * last).min(last)
    } else {
        T::ZERO
    };
    let j = s.trunc_usize().min(n - 2);
    (j, s - T::from_usize(j))
}

#[inline(always)]
fn lerp<T: Real>(a: [T; 6], b: [T; 6], f: T) -> [T; 6] {
    let [a0, a1, a2, a3, a4, a5] = a;
    let [b0, b1, b2, b3, b4, b5] = b;
    [
        a0 + f * (b0 - a0),
        a1 + f * (b1 - a1),
        a2 + f * (b2 - a2),
        a3 + f * (b3 - a3),
        a4 + f * (b4 - a4),
        a5 + f * (b5 - a5),
    ]
}

/// The patch's creep shape from the aligned ellipse's coefficients `k` and the six ratios, for
/// the rolling direction (cx, sx) (unit) in the contact frame (x the major axis): the exact
/// diagonal and the couplings (K₁₂, K₁₃) (see the [module docs](self)).
#[inline(always)]
pub(crate) fn skewed<T: Real>(k: &Kalker<T>, ratios: [T; 6], cx: T, sx: T) -> (Kalker<T>, (T, T)) {
    let [r11, r22, r33, r23, q12, q13] = ratios;
    let cs = cx * sx;
    // ∓|sinθ cosθ|: −cs when cs > 0 (the table's sign convention, as CreepMatrix::new)
    let s = -cs;
    (
        Kalker {
            c11: r11 * k.c11,
            c22: r22 * k.c22,
            c23: r23 * k.c23,
            c33: r33 * k.c33,
        },
        (
            s * q12 * (k.c11 * k.c22).sqrt(),
            s * q13 * (k.c11 * k.c33).sqrt(),
        ),
    )
}

/// [`SkewPath`]'s nodes: 17, uniform in ln q over [−ln r, ln r] (no segments), so at
/// t = j/16: the skew table's t-nodes (j/8, where its cubic pieces meet) are nodes.
const SKEW_NODES_T: usize = 17;

/// A fixed contact's creep matrix over its skewed rolling directions, as functions of the
/// aligned ratio alone: the patch ratio r is fixed, so t = ½(1 − ln q/ln r) is a function of
/// x = ln q, and so is every entry (see the [module docs](self)). The six functions
/// (K₁₁, K₂₂, K₂₃, K₃₃, κ₁₂√(C₁₁C₂₂), κ₁₃√(C₁₁C₃₃)) of x ∈ [−ln r, ln r], each the product of
/// the exact coefficients ([`super::creep_matrix::aligned`]) and the skew table's ratios (cubic
/// Hermite in t and ln r, as [`super::CreepMatrix::new`]), on the nodes of a
/// [`super::skew::Nodes`] path (17 nodes uniform in x, one segment: t = j/16, so the skew
/// table's t-nodes j/8, where its cubic pieces meet, are nodes — 33 nodes cut at ±ln 20 as
/// [`super::ShapePath`]'s were 12 times closer to [`super::CreepMatrix::new`] at a/b ≈ 4 but
/// made a fixed contact 0.7 KB larger; values and slopes, built once in `f64`); per call one
/// Hermite segment each, the couplings times ∓|sinθ cosθ|. One look-up for the coefficients
/// and the skew ratios, no square root. Exact at the nodes (the ends: the two axes, ρ = 1,
/// κ·sinθcosθ = 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SkewPath<T> {
    nodes: Nodes<T, 6, SKEW_NODES_T>,
    /// √q at the ends: 1/√r, √r
    rho: (T, T),
}

impl<T: Copy> SkewPath<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> SkewPath<U> {
        SkewPath {
            nodes: self.nodes.map(f),
            rho: (f(self.rho.0), f(self.rho.1)),
        }
    }
}

impl<T: Real> SkewPath<T> {
    /// For a patch ratio r = a/b ≥ 1 (clamped to [1, 100]; < 1 or NaN: the circle's, a path
    /// never read) and ν ∈ [0, 0.5] (clamped). Built in `f64`.
    pub(crate) fn new(r: T, nu: T) -> Self {
        let r = r.to_f64();
        let x_r = if r > 1.0 {
            libm::log(r.min(100.0))
        } else {
            0.0
        };
        let nu = super::within(nu.to_f64(), 0.0, 0.5);
        let column = skew_column_f64(x_r, nu);
        let entries = |x: f64| {
            let [c11, c22, c23, c33] = aligned_f64(libm::exp(x), nu);
            let [r11, r22, r33, r23, q12, q13] = if x_r > 0.0 {
                skew_in_t(&column, super::within(0.5 * (1.0 - x / x_r), 0.0, 1.0))
            } else {
                ONE
            };
            [
                r11 * c11,
                r22 * c22,
                r23 * c23,
                r33 * c33,
                q12 * libm::sqrt(c11 * c22),
                q13 * libm::sqrt(c11 * c33),
            ]
        };
        let rho = libm::exp(0.5 * x_r);
        Self {
            nodes: Nodes::new(-x_r, x_r, &[], entries),
            rho: (T::from_f64(1.0 / rho), T::from_f64(rho)),
        }
    }

    /// The patch's creep shape rolled along (cx, sx) (unit, contact frame), for the aligned
    /// ellipse's ratio q and x = ln q: its creep matrix (diagonal and couplings) from the path,
    /// `blend`'s and `table`'s per-shape data of q (as [`super::ShapePath`]). Total.
    #[inline]
    pub(crate) fn shape_at(&self, q: T, x: T, cx: T, sx: T) -> RollingShape<T> {
        // x = ln q within the path and √q with it (outside: the ends' √q)
        let (x, rho) = self.nodes.clamp_with(x, || q.sqrt(), self.rho);
        let [k11, k22, k23, k33, p12, p13] = self.nodes.at(x);
        // ∓|sinθ cosθ|: −cs when cs > 0 (the table's sign convention, as `skewed`)
        let s = -(cx * sx);
        RollingShape {
            coupling: (s * p12, s * p13),
            ..shape_of(x, rho, kalker_of([k11, k22, k23, k33]))
        }
    }
}
