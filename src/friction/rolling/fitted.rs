//! The shapes the data-fitted rolling laws were fitted at (a/b = 0.2, 0.5, 1, 2, 5) and
//! what is interpolated between them: `blend`'s constants (σ, γ) (`Blend`) and the
//! weight of two neighbouring shapes (for `table`'s residual tables, `super::residual`).
//! Below the laws and the contact: data only.

use crate::Real;

/// The shapes of the fit (a/b).
const SHAPES: [f64; 5] = [0.2, 0.5, 1.0, 2.0, 5.0];

/// `blend`'s σ at the fitted shapes (`Blend::SIGMA`).
pub(super) const SIGMA: [f64; 5] = [6.965, 4.392, 3.517, 2.626, 2.18];
/// `blend`'s γ at the fitted shapes (`Blend::GAMMA`).
pub(super) const GAMMA: [f64; 5] = [98.74, 0.3724, 0.0001841, 5.05e-5, 0.1578];

/// A table over the fitted shapes rounded to `f32` at compile time: with its `f64` original,
/// read through [`Real::of_precision`] ([`at`]), an `f32` look-up at a run-time index needs no
/// per-call `f64` → `f32` conversion (a library call on the Cortex-M4F) and reads the same
/// values as `T::from_f64`, bit for bit.
const fn single(v: [f64; 5]) -> [[f32; 5]; 1] {
    [[
        v[0] as f32,
        v[1] as f32,
        v[2] as f32,
        v[3] as f32,
        v[4] as f32,
    ]]
}

/// Entry `k` of a table over the fitted shapes in the working precision (`single`: its
/// [`single`] copy).
#[inline(always)]
fn at<T: Real>(single: &[[f32; 5]; 1], double: &[f64; 5], k: usize) -> T {
    let [v] = T::of_precision(single, core::array::from_ref(double));
    T::from_base(v.get(k).copied().unwrap_or(<T::Base as Real>::ZERO))
}

const SIGMA_F32: [[f32; 5]; 1] = single(SIGMA);
const GAMMA_F32: [[f32; 5]; 1] = single(GAMMA);

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

/// ln of the fitted shapes of `blend` and `table` (a/b = 0.2, 0.5, 1, 2, 5).
const LN_FITTED: [f64; 5] = [
    -1.609_437_912_434_100_3,
    -core::f64::consts::LN_2,
    0.0,
    core::f64::consts::LN_2,
    1.609_437_912_434_100_3,
];
const LN_FITTED_F32: [[f32; 5]; 1] = single(LN_FITTED);

/// Where x = ln(a/b) falls among the fitted shapes: the interval i (0 … 3) and the fraction
/// u ∈ [0, 1] (the end shapes outside), in the working precision.
pub(crate) fn between<T: Real>(x: T) -> (usize, T) {
    let node = |k: usize| at::<T>(&LN_FITTED_F32, &LN_FITTED, k);
    let x = x.max(node(0)).min(node(4));
    let mut i = 0;
    while i < 3 && x > node(i + 1) {
        i += 1;
    }
    (
        i,
        ((x - node(i)) / (node(i + 1) - node(i)))
            .max(T::ZERO)
            .min(T::ONE),
    )
}

/// [`blend_at`] between the fitted shapes `i`, `i + 1` at the weight `u` ([`between`]).
#[inline(always)]
pub(super) fn blend_between<T: Real>((i, u): (usize, T)) -> (T, T) {
    let lerp = |s: &[[f32; 5]; 1], d: &[f64; 5]| {
        at::<T>(s, d, i) + u * (at::<T>(s, d, i + 1) - at::<T>(s, d, i))
    };
    (lerp(&SIGMA_F32, &SIGMA), lerp(&GAMMA_F32, &GAMMA))
}
