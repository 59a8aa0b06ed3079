//! K, E, B, D from precomputed piecewise polynomials (generated, `static` in flash/rodata).
//!
//! # Formula
//!
//! The table holds B(m) and D(m) as functions of m₁ = 1 − m; then
//! K = B + D and E = B + m₁·D — sums of positive terms, so no cancellation anywhere, and all four
//! come from two polynomial evaluations.
//!
//! The m₁ axis (0, 1] is cut into binary octaves [2ᵉ, 2ᵉ⁺¹) and each octave into 2^s equal
//! sub-intervals. The interval index is the float's bit pattern shifted right (exponent and the
//! s leading mantissa bits); the remaining mantissa bits, read as a fraction, are the local
//! variable u ∈ [0, 2⁻ˢ). One cubic (`f32`) or degree-7 (`f64`) polynomial in u per quantity
//! and interval, coefficients by Chebyshev interpolation (mpmath) in
//! `tools/gen_elliptic_table.py` → `table_data.rs`.
//!
//! The logarithmic singularity of K and D as m → 1 (K ≈ ½ ln(16/m₁)) needs no split: on an
//! interval of relative width ≤ 2⁻ˢ, ln m₁ is as smooth as any analytic function, and octaves
//! get denser towards m₁ = 0 automatically. No `ln`, `exp` or division is executed.
//!
//! | precision | m₁ range | octaves × sub-intervals | degree | size |
//! |---|---|---|---|---|
//! | `f32` | [2⁻²⁴, 1] | 24 × 16 + 1 | 3 | 12,320 bytes |
//! | `f64` | [2⁻⁴⁰, 1] | 40 × 4 + 1 | 7 | 20,608 bytes |
//!
//! Only the table of the precision a program uses is linked.

use super::table_data as data;
use super::{Integrals, Method, Parameter};
use crate::Real;

/// Precomputed piecewise polynomials of B and D in m₁, indexed by the float's bits.
///
/// Domain: every valid [`Parameter`]. Built from m ≤ ½ by [`Parameter::new`], m₁ = 1 − m is
/// rounded, which is harmless (K, E are smooth there); near m = 1 build with
/// [`Parameter::from_complement`]. m = 0 (m₁ = 1) gives B = D = π/4 rounded.
///
/// Size: 12,320 bytes (`f32`, 385 intervals × 8 coefficients) or 20,608 bytes (`f64`,
/// 161 × 16). Fit error of the rounded coefficients ([`Table::F32_FIT_ERROR`],
/// [`Table::F64_FIT_ERROR`]): 5.7e-8 and 1.2e-11. Measured max relative error of K, E, B, D
/// against mpmath, evaluated in the working precision (1,408 reference points, `f32` 318; a dense
/// scan of 3,000 `f32` points agrees): `f64` 1.2e-11 (stated bound, asserted by the tests:
/// [`Table::F64_MAX_REL_ERROR`] = 5e-11), `f32` 1.2e-7.
///
/// Cost: one shift/mask index computation, two Horner polynomials, two adds and a multiply;
/// no `ln`, no division, no branch on m. For `f32` on `thumbv7em-none-eabihf` the K+E code is
/// 38 instructions straight-line including call overhead (read from the disassembly); executed:
/// 45 per call in `f32` (K, E, B, D; includes the QEMU rig's 8-instruction call floor), 2,279 in
/// `f64` (soft float), from bench-results/qemu.csv. Host time and ratio to `ellip` in the [module table](super).
#[derive(Clone, Copy, Debug, Default)]
pub struct Table;

impl Table {
    /// Bytes of the `f32` table.
    pub const F32_BYTES: usize = data::F32_BYTES;
    /// Bytes of the `f64` table.
    pub const F64_BYTES: usize = data::F64_BYTES;
    /// Max relative error of the rounded `f32` coefficients in exact arithmetic (generator's
    /// measurement, 40 points per interval).
    pub const F32_FIT_ERROR: f64 = data::F32_FIT_ERROR;
    /// Same for `f64`.
    pub const F64_FIT_ERROR: f64 = data::F64_FIT_ERROR;
    /// The stated `f64` accuracy bound (max relative error of K, E, B, D), asserted by the tests.
    pub const F64_MAX_REL_ERROR: f64 = 5e-11;
}

/// `(B, D)` at m₁ ∈ [2⁻²⁴, 1] in `f32`.
#[inline(always)]
fn lookup_f32(m1: f32) -> (f32, f32) {
    const SHIFT: u32 = data::F32_MANT - data::F32_LOG2_SUB;
    const BASE: u32 = data::F32_BASE_EXP << data::F32_LOG2_SUB;
    const LAST: usize = data::F32.len() - 1;
    let bits = m1.to_bits();
    let index = ((bits >> SHIFT).wrapping_sub(BASE) as usize).min(LAST);
    let u = f32::from_bits((bits & ((1 << SHIFT) - 1)) | 1.0f32.to_bits()) - 1.0;
    // The cubics are written out: the type checks the generated rows (2 × (degree + 1)) and
    // the assertion their degree.
    const _: () = assert!(data::F32_DEG == 3);
    let c: &[f32; 2 * (data::F32_DEG + 1)] = &data::F32[index];
    let b = c[0] + u * (c[1] + u * (c[2] + u * c[3]));
    let d = c[4] + u * (c[5] + u * (c[6] + u * c[7]));
    (b, d)
}

/// `(B, D)` at m₁ ∈ [2⁻⁴⁰, 1] in `f64`.
#[inline(always)]
fn lookup_f64(m1: f64) -> (f64, f64) {
    const SHIFT: u32 = data::F64_MANT - data::F64_LOG2_SUB;
    const BASE: u64 = (data::F64_BASE_EXP as u64) << data::F64_LOG2_SUB;
    const LAST: usize = data::F64.len() - 1;
    let bits = m1.to_bits();
    let index = ((bits >> SHIFT).wrapping_sub(BASE) as usize).min(LAST);
    let u = f64::from_bits((bits & ((1 << SHIFT) - 1)) | 1.0f64.to_bits()) - 1.0;
    let c = &data::F64[index];
    let horner = |k: &[f64]| k.iter().rev().fold(0.0, |acc, &x| acc * u + x);
    let (cb, cd) = c.split_at(data::F64_DEG + 1);
    (horner(cb), horner(cd))
}

impl Method for Table {
    const NAME: &'static str = "table";

    #[inline]
    fn integrals<T: Real>(p: Parameter<T>) -> Integrals<T> {
        let m1 = p.m1();
        // Compile-time dispatch: the conversions fold to nothing for the matching type.
        let (b, d) = if T::MANTISSA_DIGITS > 24 {
            let (b, d) = lookup_f64(m1.to_f64());
            (T::from_f64(b), T::from_f64(d))
        } else {
            let (b, d) = lookup_f32(m1.to_f64() as f32);
            (T::from_f64(b as f64), T::from_f64(d as f64))
        };
        Integrals {
            k: b + d,
            e: b + m1 * d,
            b,
            d,
        }
    }
}
