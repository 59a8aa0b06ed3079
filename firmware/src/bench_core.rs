//! Stage `core`: the float core's building blocks.
//!
//! - `call`: an `#[inline(never)]` identity function — the harness floor (call, return,
//!   argument and result moves) that every row includes.
//! - `vsqrt`: `Real::sqrt` for `f32`, the crate's hardware-sqrt shim (`vsqrt.f32`).
//! - `libm`: `libm::sqrtf`, the software square root the shim replaces.
//! - `ln-libm`, `exp-libm`: `Real::ln`, `Real::exp` for `f32` (libm's `logf`, `expf`).
//! - `sqrt-micromath`, `ln-micromath`, `exp-micromath`: the same through
//!   `contensou::math::Micromath` (feature `micromath`).
//! - `ln-raw-micromath`: micromath's own `ln` (the backend keeps its argument ≥ 1).
//!
//! Inputs: the 32 values x_i = (1 + 0.093 i)·2^(i−16), i = 0..31 (1.5e-5 … 1.7e4); for `exp`
//! their logarithms (−11.1 … 9.7).

use crate::harness::Runner;
use contensou::Real;
use contensou::math::{Backend, Micromath};

fn inputs() -> [f32; 32] {
    let mut scale = 1.0 / 65536.0f32;
    core::array::from_fn(|i| {
        let x = (1.0 + 0.093 * i as f32) * scale;
        scale *= 2.0;
        x
    })
}

/// The measured functions, `f32 → f32`, each `#[inline(never)]`: `name(x) = body`.
macro_rules! measured {
    ($($name:ident($x:ident) = $body:expr;)*) => {$(
        #[inline(never)]
        fn $name($x: f32) -> f32 {
            $body
        }
    )*};
}

measured! {
    call(x) = x;
    sqrt_vsqrt(x) = Real::sqrt(x);
    sqrt_libm(x) = libm::sqrtf(x);
    ln_libm(x) = Real::ln(x);
    exp_libm(x) = Real::exp(x);
    sqrt_micromath(x) = Micromath::sqrt(x);
    ln_micromath(x) = Micromath::ln(x);
    ln_raw_micromath(x) = micromath::F32(x).ln().0;
    exp_micromath(x) = Micromath::exp(x);
}

pub fn run(r: &Runner) {
    let xs = inputs();
    r.bench("core", "call", "f32", &xs, call);
    r.bench("core", "vsqrt", "f32", &xs, sqrt_vsqrt);
    r.bench("core", "libm", "f32", &xs, sqrt_libm);
    let logs = xs.map(libm::logf);
    r.bench("core", "ln-libm", "f32", &xs, ln_libm);
    r.bench("core", "exp-libm", "f32", &logs, exp_libm);
    r.bench("core", "sqrt-micromath", "f32", &xs, sqrt_micromath);
    r.bench("core", "ln-micromath", "f32", &xs, ln_micromath);
    r.bench("core", "exp-micromath", "f32", &logs, exp_micromath);
    r.bench("core", "ln-raw-micromath", "f32", &xs, ln_raw_micromath);
}
