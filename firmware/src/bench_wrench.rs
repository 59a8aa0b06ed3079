//! Stage `wrench`: the full per-step call (h, ḣ, v_P, ω) → (N, F_x, F_y, T_z), Hertz + no
//! damping + the `simplified` friction law.
//!
//! - `fixed`: `Contact::wrench`, geometry precomputed (the 209 bearing's inner-race contact,
//!   e² = 0.989, solved once by Newton).
//! - `table_each_step`: `VaryingContact::wrench`, the eccentricity and every shape constant from
//!   `shape::Table` each step (includes g = P/Q, Hertz constants and friction constants).
//! - `fixed-best`, `table_each_step-best`: the same with the default law `Best` (per-contact
//!   tables for `fixed`; the per-call form for `table_each_step`).
//!
//! Inputs: the friction stage's mixed set (64 states, u log-uniform in [0.01, 100], ψ uniform),
//! h = 5 µm (a ≈ 1.1 mm), ω = 100 rad/s, v = u·a·ω, ḣ = 0.

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::friction::{Best, Friction, FrictionLaw, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;

include!("../../benches/friction_set.rs");
include!("../../benches/wrench_set.rs");

const N: usize = SET;
type FixedInput<'a, T, L> = (&'a Contact<T, Hertz<T>, Undamped, L>, T, Slip<T>);

#[inline(never)]
fn fixed<T: Real, L: FrictionLaw>(x: FixedInput<'_, T, L>) -> Wrench<T, L::Branch> {
    x.0.wrench(x.1, T::ZERO, x.2)
}

type VaryingInput<'a, T, L> = (&'a VaryingContact<T, Undamped, L>, &'a Curvatures<T>, T, Slip<T>);

#[inline(never)]
fn table_each_step<T: Real, L: FrictionLaw>(x: VaryingInput<'_, T, L>) -> Wrench<T, L::Branch> {
    x.0.wrench(x.1, x.2, T::ZERO, x.3)
}

fn law<T: Real, L: FrictionLaw>(r: &Runner, suffix: &str) {
    let (curv, contact, varying, h, slips) = wrench_scene::<T, L>();
    let mut name = bench_name("fixed", suffix);
    let fixed_inputs: [FixedInput<'_, T, L>; N] = core::array::from_fn(|i| (&contact, h, slips[i]));
    r.bench("wrench", name.as_str(), T::NAME, &fixed_inputs, fixed::<T, L>);
    name = bench_name("table_each_step", suffix);
    let varying_inputs: [VaryingInput<'_, T, L>; N] =
        core::array::from_fn(|i| (&varying, &curv, h, slips[i]));
    r.bench("wrench", name.as_str(), T::NAME, &varying_inputs, table_each_step::<T, L>);
}

/// `base` + `suffix` in a fixed-capacity string (no allocation on the MCU). The names are
/// this file's literals; one that did not fit would be a wrong qemu.csv key, so it stops the rig.
fn bench_name(base: &str, suffix: &str) -> heapless::String<32> {
    let mut name = heapless::String::new();
    name.push_str(base)
        .and_then(|()| name.push_str(suffix))
        .expect("bench name fits 32 bytes");
    name
}

pub fn run(r: &Runner) {
    law::<f32, Simplified>(r, "");
    law::<f64, Simplified>(r, "");
    law::<f32, Best>(r, "-best");
    law::<f64, Best>(r, "-best");
}
