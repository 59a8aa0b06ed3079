//! A rolling direction not along an axis of the contact ellipse.
//!
//! # Formula
//!
//! Kalker's coefficients, FASTSIM and the exact reference are for a rolling velocity along a
//! semi-axis. For a patch with semi-axes (a_M, b_m) along the library frame's x (major) and y,
//! and a rolling velocity at the angle θ from x (cos θ, sin θ), the rolling law is evaluated on
//! the ellipse aligned with the rolling direction whose semi-axis along it is the patch's
//! extent in that direction,
//!
//! a_r = a_M b_m / √(b_m² cos²θ + a_M² sin²θ),   b_r = a_M b_m / a_r
//!
//! (the same area and the same c = √(ab)). Exact along either axis (θ = 0: (a_M, b_m);
//! θ = π/2: (b_m, a_M)), continuous in θ, and symmetric under θ → −θ, θ → π − θ. The
//! approximation is the rest of the shape: the aligned ellipse is not the patch. The per-step
//! wrench ([`crate::contact::Rolling`]) takes only the creep shape (Kalker's coefficients, the
//! laws' per-shape data) from it and the full slip from the real patch, so the full-slip
//! limit stays exact in every direction.
//!
//! [`ShapePath`] gives that creep shape per call for an aligned ratio that changes every call.
//!
//! # Domain
//!
//! a_M ≥ b_m > 0 (the library frame's ordering), (cos θ, sin θ) any direction (normalised
//! here; zero → θ = 0). Total: no error, no division by zero for positive semi-axes.
//!
//! # Cost
//!
//! Two square roots and two divisions.

use super::{Kalker, RollingShape};
use crate::Real;

/// The aligned ellipse (a_r along the rolling direction, b_r across) for a patch (a_M along x,
/// b_m along y) and a rolling direction (cx, sx) in the library frame (see the
/// [module docs](self)).
pub fn aligned_ellipse<T: Real>(a_major: T, b_minor: T, cx: T, sx: T) -> (T, T) {
    let n2 = cx * cx + sx * sx;
    let (c2, s2) = if n2 > T::ZERO {
        (cx * cx / n2, sx * sx / n2)
    } else {
        (T::ONE, T::ZERO)
    };
    let ab = a_major * b_minor;
    let ar = ab / (b_minor * b_minor * c2 + a_major * a_major * s2).sqrt();
    (ar, ab / ar)
}

/// Nodes of [`ShapePath`]'s Kalker table.
const PATH_NODES: usize = 33;

/// Where the exact coefficients ([`super::creep_matrix::aligned`]) have a kink in
/// x = ln(a/b): ±ln 20, the ends of the exact table (Kalker's asymptotic growth beyond).
const KINKS: [f64; 2] = [-2.995_732_273_553_991, 2.995_732_273_553_991];

/// The creep shape ([`RollingShape`]) of any aligned ratio a/b in a range [e^{lo}, e^{hi}], per
/// call in the working precision, for a contact whose aligned ratio changes every call (a
/// skewed rolling velocity: the range between the two axes' ratios; a varying contact: the
/// laws' domain).
///
/// # Formula
///
/// - The coefficients: ln C of the exact theory's ([`super::creep_matrix::aligned`]) at 33
///   nodes in x = ln(a/b) ∈ [lo, hi] (built once, `f64`): the ends and the kinks inside
///   (±ln 20, the ends of the exact table) are nodes, uniform between them; per call cubic
///   Hermite in x with finite-difference slopes, one-sided at the ends and the kinks, then
///   `exp`. Exact at the nodes (the ends: the two axes of a fixed contact), continuous. (A
///   skewed patch's own matrix: [`super::skew_linear`], applied by the per-step wrench.)
/// - `blend`'s (σ, γ): linear in x between the fitted shapes, as [`super::Blend::shape`].
/// - `table`'s residual tables: [`super::table::Tables::at_ln`] (linear in x between the
///   fitted shapes, as [`super::table::Tables::new`]).
///
/// # Domain and error
///
/// lo < hi in [ln 0.01, ln 100] (clamped; a/b outside the range is clamped to it).
/// Measured (`host-tests/rolling_wrench.rs`): over [0.01, 100] the coefficients within
/// 3.1e-3 relative of [`super::creep_matrix::aligned`] inside [0.1, 10], 4.4e-3 beyond; a fixed
/// contact's skewed rolling wrench: `host-tests/rolling_wrench.rs` and
/// [`crate::contact::Rolling`]'s docs (the skew ratios dominate the difference to the `f64`
/// build).
///
/// # Cost
///
/// Per call one `ln`, a 6-step bisection, one Hermite segment and one `exp` per coefficient
/// (and one for the shape's √(a/b)); `table`'s curves are built with no grid
/// ([`super::table::Tables::at_ln_once`]: the look-ups compute the grids they read, at most
/// four per call, with an `exp` only in a tail). M4F f32 (`bench-results/qemu.csv`): the
/// per-step wrench with a skewed V 2,282 instructions against 1,098 along an axis (the skew
/// ratios included). Per contact 33 × 5 numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapePath<T> {
    /// the nodes x = ln(a/b), increasing
    x: [T; PATH_NODES],
    /// ln of Kalker's coefficients at the nodes
    kalker: [Kalker<T>; PATH_NODES],
    /// bit j: node j is a kink (slopes one-sided); kinks are interior nodes (j ≤ 31). A `u32`,
    /// not a `u64`: an 8-byte-aligned `DynContact<f32>` made the firmware's `dyn-fixed-best`
    /// stage fault under QEMU (not root-caused; see the branch's report).
    kinks: u32,
}

impl<T: Copy> ShapePath<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> ShapePath<U> {
        ShapePath {
            x: self.x.map(f),
            kalker: self.kalker.map(|k| k.map(f)),
            kinks: self.kinks,
        }
    }
}

impl<T: Real> ShapePath<T> {
    /// For aligned ratios in [e^{lo}, e^{hi}] and ν ∈ [0, 0.5] (an [`super::Elasticity`]'s).
    pub fn new(lo: T, hi: T, nu: T) -> Self {
        let ln100 = libm::log(100.0);
        let lo = super::within(lo.to_f64(), -ln100, ln100);
        let hi = super::within(hi.to_f64(), -ln100, ln100).max(lo + 1e-9);
        // breakpoints: the ends and the kinks strictly inside
        let mut br = [0.0f64; 7];
        let mut n = 0;
        for b in core::iter::once(lo)
            .chain(
                KINKS
                    .iter()
                    .copied()
                    .filter(|k| *k > lo + 1e-9 && *k < hi - 1e-9),
            )
            .chain(core::iter::once(hi))
        {
            if let Some(slot) = br.get_mut(n) {
                *slot = b;
                n += 1;
            }
        }
        // PATH_NODES − 1 intervals shared among the n − 1 segments by length, ≥ 1 each
        let total = hi - lo;
        let mut xs = [0.0f64; PATH_NODES];
        let mut at = 0usize;
        let mut left = PATH_NODES - 1;
        let mut kinks = 0u32;
        for s in 0..n.saturating_sub(1) {
            let (a, b) = (
                br.get(s).copied().unwrap_or(lo),
                br.get(s + 1).copied().unwrap_or(hi),
            );
            let rest = n - 2 - s; // segments after this one
            let k = if rest == 0 {
                left
            } else {
                let share = ((b - a) / total * (PATH_NODES - 1) as f64) as usize;
                share.max(1).min(left.saturating_sub(rest).max(1))
            };
            for j in 0..k {
                if let Some(x) = xs.get_mut(at + j) {
                    *x = a + (b - a) * j as f64 / k as f64;
                }
            }
            at += k;
            left -= k;
            if rest > 0 {
                kinks |= 1u32.checked_shl(at as u32).unwrap_or(0); // the next segment starts at a kink
            }
        }
        if let Some(x) = xs.get_mut(PATH_NODES - 1) {
            *x = hi;
        }
        // ln C: Kalker's coefficients are near power laws of a/b (C₁₁, C₂₂ ∝ a/b, C₂₃ ∝
        // (a/b)^{3/2} for long patches), nearly linear in ln(a/b) in the logarithm
        let kalker = xs.map(|x| {
            let [c11, c22, c23, c33] = super::creep_matrix::aligned_f64(libm::exp(x), nu.to_f64());
            let ln = |c: f64| T::from_f64(libm::log(c));
            Kalker {
                c11: ln(c11),
                c22: ln(c22),
                c23: ln(c23),
                c33: ln(c33),
            }
        });
        Self {
            x: xs.map(T::from_f64),
            kalker,
            kinks,
        }
    }

    /// The creep shape for the aligned ratio a/b (see the type docs). Total.
    pub fn shape(&self, a_over_b: T) -> RollingShape<T> {
        let x = if a_over_b > T::ZERO {
            a_over_b.ln()
        } else {
            T::from_f64(f64::NEG_INFINITY)
        };
        self.shape_at_ln(x)
    }

    /// [`ShapePath::shape`] for x = ln(a/b) (clamped to the path's range; NaN: its low end).
    /// Total.
    pub fn shape_at_ln(&self, x: T) -> RollingShape<T> {
        let last = PATH_NODES - 1;
        let node = |j: usize| self.x.get(j).copied().unwrap_or(T::ZERO);
        let (lo, hi) = (node(0), node(last));
        let x = if x >= lo { x.min(hi) } else { lo };
        // bisection: node(i) ≤ x ≤ node(i + 1), 6 steps (2⁶ > 32 intervals)
        let (mut i, mut j) = (0usize, last);
        for _ in 0..6 {
            let m = (i + j) / 2;
            if j - i > 1 {
                if x < node(m) {
                    j = m;
                } else {
                    i = m;
                }
            }
        }
        let i = i.min(last - 1);
        let d = node(i + 1) - node(i);
        let f = if d > T::ZERO {
            ((x - node(i)) / d).max(T::ZERO).min(T::ONE)
        } else {
            T::ZERO
        };
        let k = |j: usize| self.kalker.get(j).copied().unwrap_or(self.kalker[0]);
        let kink = |j: usize| self.kinks.checked_shr(j as u32).unwrap_or(0) & 1 == 1;
        // slopes dy/dx at the interval's ends, one-sided at the ends and the kinks
        let slope = |j: usize, from_right: bool, c: fn(&Kalker<T>) -> T| {
            let y = |n: usize| c(&k(n));
            let dx = |a: usize, b: usize| {
                let d = node(b) - node(a);
                if d > T::ZERO { d } else { T::ONE }
            };
            if j == 0 || (kink(j) && from_right) {
                (y(j + 1) - y(j)) / dx(j, j + 1)
            } else if j == last || kink(j) {
                (y(j) - y(j - 1)) / dx(j - 1, j)
            } else {
                (y(j + 1) - y(j - 1)) / dx(j - 1, j + 1)
            }
        };
        let hermite = |c: fn(&Kalker<T>) -> T| {
            let (y0, y1) = (c(&k(i)), c(&k(i + 1)));
            let (m0, m1) = (slope(i, true, c) * d, slope(i + 1, false, c) * d);
            let f2 = f * f;
            let f3 = f2 * f;
            let h00 = T::TWO * f3 - T::from_f64(3.0) * f2 + T::ONE;
            let h10 = f3 - T::TWO * f2 + f;
            let h01 = T::from_f64(3.0) * f2 - T::TWO * f3;
            let h11 = f3 - f2;
            h00 * y0 + h10 * m0 + h01 * y1 + h11 * m1
        };
        let kalker = Kalker {
            c11: hermite(|k| k.c11).exp(),
            c22: hermite(|k| k.c22).exp(),
            c23: hermite(|k| k.c23).exp(),
            c33: hermite(|k| k.c33).exp(),
        };
        RollingShape {
            rho: (T::HALF * x).exp(),
            kalker,
            blend: super::fitted::blend_at_ln(x),
            table: super::residual::Tables::at_ln_once(x),
            coupling: (T::ZERO, T::ZERO),
        }
    }
}
