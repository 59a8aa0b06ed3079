//! Stage `core`: the float core's building blocks.
//!
//! - `call`: an `#[inline(never)]` identity function — the harness floor (call, return,
//!   argument and result moves) that every row includes.
//! - `vsqrt`: `Real::sqrt` for `f32`, the crate's hardware-sqrt shim (`vsqrt.f32`).
//! - `libm`: `libm::sqrtf`, the software square root the shim replaces.
//!
//! Inputs: the 32 values x_i = (1 + 0.093 i)·2^(i−16), i = 0..31 (1.5e-5 … 1.7e4).

use crate::harness::Runner;
use contensou::Real;

fn inputs() -> [f32; 32] {
    let mut scale = 1.0 / 65536.0f32;
    core::array::from_fn(|i| {
        let x = (1.0 + 0.093 * i as f32) * scale;
        scale *= 2.0;
        x
    })
}

#[inline(never)]
fn call(x: f32) -> f32 {
    x
}

#[inline(never)]
fn sqrt_vsqrt(x: f32) -> f32 {
    Real::sqrt(x)
}

#[inline(never)]
fn sqrt_libm(x: f32) -> f32 {
    libm::sqrtf(x)
}

pub fn run(r: &Runner) {
    let xs = inputs();
    r.bench("core", "call", "f32", &xs, call);
    r.bench("core", "vsqrt", "f32", &xs, sqrt_vsqrt);
    r.bench("core", "libm", "f32", &xs, sqrt_libm);
}
