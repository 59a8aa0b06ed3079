//! The shapes the data-fitted rolling laws were fitted at and what is interpolated between
//! them: `blend`'s constants (σ, γ), fitted at a/b = 0.2, 0.5, 1, 2, 5 (`Blend`), and the
//! shapes of `table`'s residual tables, those five and the ends of the domain, 1/20 and 20
//! (the weight of two neighbouring shapes, for `super::residual`; `blend`'s constants are its
//! end values beyond [0.2, 5] there, as [`blend_at`]). Below the laws and the contact: data
//! only.

use crate::Real;

/// The shapes of `blend`'s fit (a/b).
const SHAPES: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 5.0];

/// `blend`'s σ at the fitted shapes (`Blend::SIGMA`).
pub(super) const SIGMA: [f64; 5] = [6.965, 4.392, 3.517, 2.626, 2.18];
/// `blend`'s γ at the fitted shapes (`Blend::GAMMA`).
pub(super) const GAMMA: [f64; 5] = [98.74, 0.3724, 0.0001841, 5.05e-5, 0.1578];

/// The number of shapes of `table`'s residual tables (a/b = 1/20, 0.2, 0.5, 1, 2, 5, 20).
pub(crate) const NODES: usize = 7;

/// A table over `blend`'s fitted shapes at `table`'s shapes: its end values at 1/20 and 20
/// (so that linear interpolation between the nodes gives [`blend_at`]'s values, bit for bit:
/// between equal values a + u·(a − a) = a).
const fn padded(v: [f64; 5]) -> [f64; NODES] {
    [v[0], v[0], v[1], v[2], v[3], v[4], v[4]]
}

/// A table over `table`'s shapes rounded to `f32` at compile time: with its `f64` original,
/// read through [`Real::of_precision`] ([`at`]), an `f32` look-up at a run-time index needs no
/// per-call `f64` → `f32` conversion (a library call on the Cortex-M4F) and reads the same
/// values as `T::from_f64`, bit for bit.
const fn single(v: [f64; NODES]) -> [[f32; NODES]; 1] {
    let mut out = [0.0f32; NODES];
    let mut k = 0;
    while k < NODES {
        out[k] = v[k] as f32;
        k += 1;
    }
    [out]
}

/// Entry `k` of a table over `table`'s shapes in the working precision (`single`: its
/// [`single`] copy).
#[inline(always)]
fn at<T: Real>(single: &[[f32; NODES]; 1], double: &[f64; NODES], k: usize) -> T {
    let [v] = T::of_precision(single, core::array::from_ref(double));
    T::from_base(v.get(k).copied().unwrap_or(<T::Base as Real>::ZERO))
}

const SIGMA_NODES: [f64; NODES] = padded(SIGMA);
const GAMMA_NODES: [f64; NODES] = padded(GAMMA);
const SIGMA_F32: [[f32; NODES]; 1] = single(SIGMA_NODES);
const GAMMA_F32: [[f32; NODES]; 1] = single(GAMMA_NODES);

/// `blend`'s (σ, γ) for a/b: piecewise linear in ln(a/b) between the fitted shapes, the end
/// values outside [0.2, 5] (built once per contact, f64): `Blend::shape`.
pub(super) fn blend_at<T: Real>(a_over_b: T) -> (T, T) {
    let x = libm::log(super::within(a_over_b.to_f64(), 0.2, 5.0));
    let mut i = 0;
    while i < 3 && x > libm::log(SHAPES.get(i + 1).copied().unwrap_or(5.0)) {
        i += 1;
    }
    // `get`: no bounds-check panic path (i ≤ 3 by the loop)
    let at = |v: &[f64; 5], k: usize| v.get(k).copied().unwrap_or(1.0);
    let (x0, x1) = (libm::log(at(&SHAPES, i)), libm::log(at(&SHAPES, i + 1)));
    let u = super::within((x - x0) / (x1 - x0), 0.0, 1.0);
    let lerp = |v: [f64; 5]| T::from_f64(at(&v, i) + u * (at(&v, i + 1) - at(&v, i)));
    (lerp(SIGMA), lerp(GAMMA))
}

/// ln of `table`'s shapes (a/b = 1/20, 0.2, 0.5, 1, 2, 5, 20).
const LN_NODES: [f64; NODES] = [
    -2.995_732_273_553_991,
    -1.609_437_912_434_100_3,
    -core::f64::consts::LN_2,
    0.0,
    core::f64::consts::LN_2,
    1.609_437_912_434_100_3,
    2.995_732_273_553_991,
];
const LN_NODES_F32: [[f32; NODES]; 1] = single(LN_NODES);

/// Where x = ln(a/b) falls among `table`'s shapes: the interval i (0 … 5) and the fraction
/// u ∈ [0, 1] (the end shapes outside [1/20, 20]; NaN: the first), in the working precision.
///
/// The shapes are symmetric in x (a/b and b/a), so the search runs on |x| over the half
/// nodes 0, ln 2, ln 5, ln 20 (two comparisons) and mirrors: the same (i, u), bit for bit,
/// as a search over all seven (x = 0 and x = −ln 2, −ln 5 end the interval below them, u = 1).
pub(crate) fn between<T: Real>(x: T) -> (usize, T) {
    let node = |k: usize| at::<T>(&LN_NODES_F32, &LN_NODES, k);
    // |x| within [0, ln 20] (NaN: ln 20, then the mirrored side: i = 0, u = 0)
    let ax = x.abs().min(node(NODES - 1));
    let (n1, n2) = (node(HALF + 1), node(HALF + 2));
    // x > 0: intervals above 0 include their upper node; x ≤ 0 (mirrored) their lower one
    let k = if x > T::ZERO {
        usize::from(ax > n1) + usize::from(ax > n2)
    } else {
        usize::from(ax >= n1) + usize::from(ax >= n2)
    };
    let (lo, hi) = (node(HALF + k), node(HALF + k + 1));
    // lo ≤ |x| ≤ hi and rounding is monotone: both fractions lie in [0, 1] without a clamp
    if x > T::ZERO {
        (HALF + k, (ax - lo) / (hi - lo))
    } else {
        // x − node(i) = hi − |x| for i = HALF − 1 − k (the nodes are exact negatives)
        (HALF - 1 - k, (hi - ax) / (hi - lo))
    }
}

/// The index of the shape a/b = 1 (x = 0) among `table`'s seven.
const HALF: usize = NODES / 2;

/// [`blend_at`] between `table`'s shapes `i`, `i + 1` at the weight `u` ([`between`]).
#[inline(always)]
pub(super) fn blend_between<T: Real>((i, u): (usize, T)) -> (T, T) {
    let lerp = |s: &[[f32; NODES]; 1], d: &[f64; NODES]| {
        at::<T>(s, d, i) + u * (at::<T>(s, d, i + 1) - at::<T>(s, d, i))
    };
    (
        lerp(&SIGMA_F32, &SIGMA_NODES),
        lerp(&GAMMA_F32, &GAMMA_NODES),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_nodes_are_the_logs_of_the_shapes() {
        let shapes = [0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 20.0];
        for (ln, aob) in LN_NODES.iter().zip(shapes) {
            assert!((ln - libm::log(aob)).abs() < 1e-15, "{ln} {aob}");
        }
    }

    /// The search over all seven nodes that `between`'s mirrored search replaced.
    fn between_by_search<T: Real>(x: T) -> (usize, T) {
        let node = |k: usize| at::<T>(&LN_NODES_F32, &LN_NODES, k);
        let x = x.max(node(0)).min(node(NODES - 1));
        let mut i = 0;
        while i < NODES - 2 && x > node(i + 1) {
            i += 1;
        }
        (i, (x - node(i)) / (node(i + 1) - node(i)))
    }

    #[test]
    fn between_is_the_full_search_bit_for_bit() {
        let check = |x: f64| {
            let (i, u) = between(x);
            let (j, v) = between_by_search(x);
            assert!(
                i == j && u.to_bits() == v.to_bits(),
                "f64 {x}: ({i}, {u}) against ({j}, {v})"
            );
            assert!((0.0..=1.0).contains(&u) && i <= NODES - 2, "{x}");
            let xf = x as f32;
            let (i, u) = between(xf);
            let (j, v) = between_by_search(xf);
            assert!(
                i == j && u.to_bits() == v.to_bits(),
                "f32 {xf}: ({i}, {u}) against ({j}, {v})"
            );
        };
        // every node and its neighbours one ulp away (in both precisions), beyond the ends,
        // NaN, ±0, and a fine sweep
        for &n in &LN_NODES {
            for x in [n, n.next_up(), n.next_down()] {
                check(x);
            }
            let nf = n as f32;
            for x in [nf, nf.next_up(), nf.next_down()] {
                check(f64::from(x));
            }
        }
        for x in [
            -0.0,
            0.0,
            -10.0,
            10.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            check(x);
        }
        for k in 0..=20_000 {
            check(-3.5 + 7.0 * f64::from(k) / 20_000.0);
        }
    }

    #[test]
    fn blend_between_is_blend_at_on_both_sides_of_the_fitted_range() {
        for aob in [
            0.03, 0.05, 0.07, 0.12, 0.2, 0.3, 1.0, 3.0, 5.0, 8.0, 15.0, 20.0, 40.0,
        ] {
            let (s, g) = blend_at::<f64>(aob);
            let (sb, gb) = blend_between(between(libm::log(aob)));
            assert!(
                (s - sb).abs() <= 1e-12 * s && (g - gb).abs() <= 1e-12 * g,
                "{aob}"
            );
        }
    }
}
