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

/// Segments of a [`Nodes`] path: the range cut at the kinks inside it (at most two).
const SEGMENTS: usize = 3;
/// Stored nodes of a path of `n` nodes: a node where two segments meet is stored once per
/// segment (its one-sided tangents differ).
pub(crate) const fn slots(n: usize) -> usize {
    n + SEGMENTS - 1
}
/// [`ShapePath`]'s stored nodes (33 nodes).
const SHAPE_SLOTS: usize = slots(33);

/// Where the exact coefficients ([`super::creep_matrix::aligned`]) have a kink in
/// x = ln(a/b): ±ln 20, the ends of the exact table (Kalker's asymptotic growth beyond).
const KINKS: [f64; 2] = [-2.995_732_273_553_991, 2.995_732_273_553_991];

/// `N` smooth functions of x = ln(a/b) over a range [lo, hi], per call by cubic Hermite on
/// their values and slopes at the nodes, `S` stored (one per node, a node where two segments
/// meet twice: [`slots`]; built once, `f64`): the ends and the kinks given inside the range
/// ([`ShapePath`]: ±ln 20, the ends of the exact table) are nodes, uniform between them (a
/// segment). The
/// slopes by a central difference of step 10⁻³ of the node spacing, one-sided of second order
/// at a segment's ends. Per call the segment by two comparisons, the interval by its uniform
/// spacing, then one Hermite segment per function: no `exp`, no division. Exact at the nodes,
/// continuous, C¹ inside a segment. The path of [`ShapePath`] (Kalker's coefficients) and of a
/// fixed contact's skewed creep matrix ([`super::skew_linear::SkewPath`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Nodes<T, const N: usize, const S: usize> {
    /// the range [lo, hi] in x
    lo: T,
    hi: T,
    /// where the segments after the first start (hi for a segment not used)
    cut: [T; SEGMENTS - 1],
    /// per segment: its first node in x, 1/(node spacing)
    start: [T; SEGMENTS],
    inv_h: [T; SEGMENTS],
    /// per segment: its first slot, its number of intervals (≥ 1; 1 for a segment not used)
    first: [u8; SEGMENTS],
    intervals: [u8; SEGMENTS],
    /// the functions at the nodes, by slot
    y: [[T; N]; S],
    /// their Hermite tangents at the nodes, by slot: dy/dx times the segment's node spacing
    m: [[T; N]; S],
}

impl<T: Copy, const N: usize, const S: usize> Nodes<T, N, S> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> Nodes<U, N, S> {
        Nodes {
            lo: f(self.lo),
            hi: f(self.hi),
            cut: self.cut.map(f),
            start: self.start.map(f),
            inv_h: self.inv_h.map(f),
            first: self.first,
            intervals: self.intervals,
            y: self.y.map(|v| v.map(f)),
            m: self.m.map(|v| v.map(f)),
        }
    }
}

/// The range [lo, hi] of a path: within [ln 0.01, ln 100], hi > lo.
fn range(lo: f64, hi: f64) -> (f64, f64) {
    let ln100 = libm::log(100.0);
    let lo = super::within(lo, -ln100, ln100);
    (lo, super::within(hi, -ln100, ln100).max(lo + 1e-9))
}

/// w₀a + w₁b + w₂c, entry by entry.
fn combine<const N: usize>(w: [f64; 3], a: [f64; N], b: [f64; N], c: [f64; N]) -> [f64; N] {
    let [w0, w1, w2] = w;
    let mut out = a;
    for (o, (b, c)) in out.iter_mut().zip(b.iter().zip(c.iter())) {
        *o = w0 * *o + w1 * b + w2 * c;
    }
    out
}

impl<T: Real, const N: usize, const S: usize> Nodes<T, N, S> {
    /// The functions `f` over [lo, hi] (clamped to [ln 0.01, ln 100]; hi > lo).
    pub(crate) fn new(lo: f64, hi: f64, kinks: &[f64], f: impl Fn(f64) -> [f64; N]) -> Self {
        let (lo, hi) = range(lo, hi);
        // breakpoints: the ends and the kinks strictly inside
        let mut br = [hi; SEGMENTS + 1];
        let mut n = 0;
        for b in core::iter::once(lo)
            .chain(
                kinks
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
        let segments = n.saturating_sub(1);
        // the nodes' intervals (one slot per node, a node where two segments meet twice)
        // shared among the segments by length, ≥ 1 each
        let total = hi - lo;
        let intervals = S.saturating_sub(segments).max(segments);
        let mut left = intervals;
        let mut path = Self {
            lo: T::from_f64(lo),
            hi: T::from_f64(hi),
            cut: [T::from_f64(hi); SEGMENTS - 1],
            start: [T::from_f64(hi); SEGMENTS],
            inv_h: [T::ONE; SEGMENTS],
            first: [0; SEGMENTS],
            intervals: [1; SEGMENTS],
            y: [[T::ZERO; N]; S],
            m: [[T::ZERO; N]; S],
        };
        let mut slot = 0usize;
        for s in 0..segments.min(SEGMENTS) {
            let (a, b) = (
                br.get(s).copied().unwrap_or(lo),
                br.get(s + 1).copied().unwrap_or(hi),
            );
            let rest = segments - 1 - s; // segments after this one
            let k = if rest == 0 {
                left
            } else {
                let share = ((b - a) / total * intervals as f64) as usize;
                share.max(1).min(left.saturating_sub(rest).max(1))
            };
            left -= k;
            let h = (b - a) / k as f64;
            if let Some(c) = s.checked_sub(1).and_then(|i| path.cut.get_mut(i)) {
                *c = T::from_f64(a);
            }
            if let (Some(x0), Some(ih), Some(f), Some(n)) = (
                path.start.get_mut(s),
                path.inv_h.get_mut(s),
                path.first.get_mut(s),
                path.intervals.get_mut(s),
            ) {
                (*x0, *ih, *f, *n) = (T::from_f64(a), T::from_f64(1.0 / h), slot as u8, k as u8);
            }
            // the nodes a + jh, j = 0 … k: y and h·dy/dx (one-sided at the segment's ends)
            let e = 1e-3 * h;
            for j in 0..=k {
                let x = if j == k {
                    b
                } else {
                    a + (b - a) * j as f64 / k as f64
                };
                let y = f(x);
                let (w, p, q) = if j == 0 {
                    ([-3.0, 4.0, -1.0], f(x + e), f(x + 2.0 * e))
                } else if j == k {
                    ([3.0, -4.0, 1.0], f(x - e), f(x - 2.0 * e))
                } else {
                    ([0.0, 1.0, -1.0], f(x + e), f(x - e))
                };
                let d = combine(w.map(|w| w * h / (2.0 * e)), y, p, q);
                if let (Some(yy), Some(m)) = (path.y.get_mut(slot), path.m.get_mut(slot)) {
                    *yy = y.map(T::from_f64);
                    *m = d.map(T::from_f64);
                }
                slot += 1;
            }
        }
        path
    }

    /// x clamped to the range (NaN: its low end).
    #[inline(always)]
    pub(crate) fn clamp(&self, x: T) -> T {
        if x >= self.lo {
            x.min(self.hi)
        } else {
            self.lo
        }
    }

    /// x and a companion value clamped together: (x, `inside`) within [lo, hi], else the
    /// nearer end and its value (`ends`; NaN: the low end's). One pair of comparisons where
    /// [`Self::clamp`] and a separate clamp of the companion take two.
    #[inline(always)]
    pub(crate) fn clamp_with(&self, x: T, inside: impl FnOnce() -> T, ends: (T, T)) -> (T, T) {
        if x >= self.lo && x <= self.hi {
            (x, inside())
        } else if x > self.hi {
            (self.hi, ends.1)
        } else {
            (self.lo, ends.0)
        }
    }

    /// The functions at x, already clamped ([`Self::clamp`], [`Self::clamp_with`]). Total.
    #[inline(always)]
    pub(crate) fn at(&self, x: T) -> [T; N] {
        // the segment: past the cuts (a cut not used is hi, never passed)
        let s = usize::from(x > self.cut[0]) + usize::from(x > self.cut[1]);
        let (x0, inv_h, first, n) = (
            self.start.get(s).copied().unwrap_or(self.lo),
            self.inv_h.get(s).copied().unwrap_or(T::ONE),
            self.first.get(s).copied().unwrap_or(0),
            self.intervals.get(s).copied().unwrap_or(1),
        );
        // x ≥ x₀: x is clamped to [lo, hi] (not NaN) and past the cut that starts its segment
        let u = (x - x0) * inv_h;
        let j = u.trunc_usize().min(usize::from(n).max(1) - 1);
        // f ∈ [0, 1): j = ⌊u⌋ but on the last interval, where u ≤ n but for rounding at hi
        // (f = 1 + O(ε) there: the cubic a rounding beyond its end)
        let f = u - T::from_usize(j);
        // the interval's two slots, within the stored ones by `min` (no zero fallback to
        // materialise, which costs more than the look-up; S ≥ 2 for every path)
        let i = (usize::from(first) + j).min(S.saturating_sub(2));
        let (y0, y1, m0, m1) = (&self.y[i], &self.y[i + 1], &self.m[i], &self.m[i + 1]);
        // cubic Hermite in f ∈ [0, 1]
        let f2 = f * f;
        let f3 = f2 * f;
        let h01 = T::from_f64(3.0) * f2 - T::TWO * f3;
        let h00 = T::ONE - h01;
        let h10 = f3 - T::TWO * f2 + f;
        let h11 = f3 - f2;
        let mut out = [T::ZERO; N];
        for (o, (((y0, y1), m0), m1)) in out
            .iter_mut()
            .zip(y0.iter().zip(y1.iter()).zip(m0.iter()).zip(m1.iter()))
        {
            *o = h00 * *y0 + h10 * *m0 + h01 * *y1 + h11 * *m1;
        }
        out
    }
}

/// The creep shape ([`RollingShape`]) of any aligned ratio a/b in a range [e^{lo}, e^{hi}], per
/// call in the working precision, for a contact whose aligned ratio changes every call (a
/// varying contact: the laws' domain; a fixed contact's skewed rolling velocity uses
/// [`super::skew_linear`]'s path of the patch's own creep matrix instead).
///
/// # Formula
///
/// - The coefficients: C of the exact theory ([`super::creep_matrix::aligned`]) and its slope
///   dC/dx at 33 nodes in x = ln(a/b) ∈ [lo, hi] (built once, `f64`; the slope by a central
///   difference of step 10⁻³ of the node spacing, one-sided of second order at the ends and
///   the kinks): the ends and the kinks inside (±ln 20, the ends of the exact table) are
///   nodes, uniform between them (a segment); per call the segment by two comparisons, the
///   interval by its uniform spacing, cubic Hermite in x of C itself (no `exp`). Exact at the
///   nodes, continuous (C¹ inside a segment). (A skewed patch's own matrix:
///   [`super::skew_linear`], applied by the per-step wrench.)
/// - √(a/b) (FASTSIM's): from a/b itself where the caller has it, else e^{x/2}.
/// - `blend`'s (σ, γ): linear in x between the fitted shapes, as [`super::Blend::shape`].
/// - `table`'s residual tables: [`super::table::Tables::at_ln`] (linear in x between the
///   fitted shapes, as [`super::table::Tables::new`]).
///
/// # Domain and error
///
/// lo < hi in [ln 0.01, ln 100] (clamped; a/b outside the range is clamped to it).
/// Measured (`host-tests/rolling_wrench.rs`): over [0.01, 100] the coefficients within
/// 7.7e-4 relative of [`super::creep_matrix::aligned`] inside [0.1, 10], 8.8e-4 beyond (3.1e-3
/// and 4.4e-3 with ln C interpolated on finite-difference slopes, then `exp`); a varying
/// contact's rolling wrench: [`crate::contact::Rolling`]'s docs.
///
/// # Cost
///
/// Per call two comparisons and one truncation for the interval, one Hermite segment per
/// coefficient (no `exp`, no division: ≈ 100 M4F instructions), `blend`'s constants, and
/// `table`'s tables with no grid ([`super::table::Tables::at_ln_once`]: the pair of fitted
/// shapes and the weight, found once for both; the look-ups compute the grids they read, at
/// most four per call, with an `exp` only in a tail; ≈ 330 while the tables were twelve
/// curve views built per call); [`ShapePath::shape_at_ln`] alone 963 → 590 M4F f32
/// instructions against the path of ln C (6-step bisection, an `exp` per coefficient and for
/// √(a/b)), before the tables held only the pair. Per contact 35 × 8
/// numbers and 12 (a node where two segments meet is stored twice).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapePath<T> {
    /// (C₁₁, C₂₂, C₂₃, C₃₃) along x
    nodes: Nodes<T, 4, SHAPE_SLOTS>,
    /// √(a/b) at the ends: e^{lo/2}, e^{hi/2}
    rho: (T, T),
}

impl<T: Copy> ShapePath<T> {
    /// Every `T` field through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U + Copy) -> ShapePath<U> {
        ShapePath {
            nodes: self.nodes.map(f),
            rho: (f(self.rho.0), f(self.rho.1)),
        }
    }
}

/// Kalker's coefficients from (C₁₁, C₂₂, C₂₃, C₃₃).
#[inline(always)]
pub(crate) fn kalker_of<T>([c11, c22, c23, c33]: [T; 4]) -> Kalker<T> {
    Kalker { c11, c22, c23, c33 }
}

/// The aligned ellipse's ratio q = a_r/b_r = a_M b_m/(b_m² cos²θ + a_M² sin²θ) for a rolling
/// direction (cx, sx) of unit length ([`aligned_ellipse`] without its normalisation and square
/// root). Total for positive semi-axes (1 otherwise).
#[inline(always)]
pub(crate) fn aligned_ratio<T: Real>(a_major: T, b_minor: T, cx: T, sx: T) -> T {
    let d = b_minor * b_minor * cx * cx + a_major * a_major * sx * sx;
    if d > T::ZERO {
        a_major * b_minor / d
    } else {
        T::ONE
    }
}

impl<T: Real> ShapePath<T> {
    /// For aligned ratios in [e^{lo}, e^{hi}] and ν ∈ [0, 0.5] (an [`super::Elasticity`]'s).
    pub fn new(lo: T, hi: T, nu: T) -> Self {
        let nu = nu.to_f64();
        let (lo, hi) = range(lo.to_f64(), hi.to_f64());
        Self {
            nodes: Nodes::new(lo, hi, &KINKS, |x| {
                super::creep_matrix::aligned_f64(libm::exp(x), nu)
            }),
            rho: (
                T::from_f64(libm::exp(0.5 * lo)),
                T::from_f64(libm::exp(0.5 * hi)),
            ),
        }
    }

    /// The creep shape for the aligned ratio a/b (see the type docs). Total.
    pub fn shape(&self, a_over_b: T) -> RollingShape<T> {
        let x = if a_over_b > T::ZERO {
            a_over_b.ln()
        } else {
            T::from_f64(f64::NEG_INFINITY)
        };
        self.shape_at(a_over_b, x)
    }

    /// [`ShapePath::shape`] for x = ln(a/b) (clamped to the path's range; NaN: its low end).
    /// Total.
    pub fn shape_at_ln(&self, x: T) -> RollingShape<T> {
        let x = self.nodes.clamp(x);
        shape_of(x, (T::HALF * x).exp(), kalker_of(self.nodes.at(x)))
    }

    /// [`ShapePath::shape`] for the aligned ratio q = a/b and x = ln q (the caller's: no `exp`
    /// for √q).
    #[inline]
    pub(crate) fn shape_at(&self, q: T, x: T) -> RollingShape<T> {
        // x within the path and √q with it (outside: the ends' √q)
        let (x, rho) = self.nodes.clamp_with(x, || q.sqrt(), self.rho);
        shape_of(x, rho, kalker_of(self.nodes.at(x)))
    }
}

/// The creep shape at x = ln(a/b) (clamped) with √(a/b) and the coefficients given.
#[inline(always)]
pub(crate) fn shape_of<T: Real>(x: T, rho: T, kalker: Kalker<T>) -> RollingShape<T> {
    // the fitted shapes around x and the weight, once for `blend`'s constants and the tables
    let at = super::fitted::between(x);
    RollingShape {
        rho,
        kalker,
        blend: super::fitted::blend_between(at),
        table: super::residual::Tables::between_once(at),
        coupling: (T::ZERO, T::ZERO),
    }
}
