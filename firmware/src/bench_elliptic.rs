//! Stage `elliptic`: K, E, B, D per method × precision (`Method::integrals`).
//!
//! Inputs (the same 36 parameters for f32 and f64, all exact in both): m = i/16 for
//! i = 0..15, and m₁ = 1 − m = 2⁻ᵏ for k = 5..24 (built with `Parameter::from_complement`),
//! so the dense-near-1 region where bearings live is represented.

use crate::harness::Runner;
use contensou::Real;
use contensou::elliptic::*; // every method, so adding one below is a single line

const N: usize = 36;

fn inputs<T: Real>() -> [Parameter<T>; N] {
    core::array::from_fn(|i| {
        let p = if i < 16 {
            Parameter::new(T::from_f64(i as f64 / 16.0))
        } else {
            let k = (i - 16 + 5) as i32;
            Parameter::from_complement(T::from_f64(libm::ldexp(1.0, -k)))
        };
        p.expect("benchmark parameter inside the domain")
    })
}

#[inline(never)]
fn integrals<M: Method, T: Real>(p: Parameter<T>) -> Integrals<T> {
    M::integrals(p)
}

fn method<M: Method>(r: &Runner) {
    let f32s = inputs::<f32>();
    r.bench("elliptic", M::NAME, f32::NAME, &f32s, integrals::<M, f32>);
    let f64s = inputs::<f64>();
    r.bench("elliptic", M::NAME, f64::NAME, &f64s, integrals::<M, f64>);
}

/// One line per method (each measures f32 and f64), e.g. `method::<Theta>(r);`.
pub fn run(r: &Runner) {
    method::<Agm>(r);
    method::<Theta>(r);
    method::<Table>(r);
    // micromath twins: f32 only (their f64 is libm, identical to the row above).
    r.bench("elliptic", ThetaMicromath::NAME, f32::NAME, &inputs::<f32>(), integrals::<ThetaMicromath, f32>);
}
