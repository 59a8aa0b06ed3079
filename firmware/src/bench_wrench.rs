//! Stage `wrench`: the full per-step call (h, ḣ, v_P, ω) → (N, F_x, F_y, T_z), Hertz + no
//! damping + the `simplified` friction law.
//!
//! - `fixed`: `Contact::wrench`, geometry precomputed (the 209 bearing's inner-race contact,
//!   e² = 0.989, solved once by Newton).
//! - `table_each_step`: `VaryingContact::wrench`, the eccentricity and every shape constant from
//!   `shape::Table` each step (includes g = P/Q, Hertz constants and friction constants).
//!
//! Inputs: the friction stage's mixed set (64 states, u log-uniform in [0.01, 100], ψ uniform),
//! h = 5 µm (a ≈ 1.1 mm), ω = 100 rad/s, v = u·a·ω, ḣ = 0.

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::friction::{Friction, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;

include!("../../benches/friction_set.rs");

const N: usize = SET;
type Branch = <Simplified as contensou::friction::FrictionLaw>::Branch;

type FixedInput<'a, T> = (&'a Contact<T, Hertz<T>, Undamped, Simplified>, T, Slip<T>);

#[inline(never)]
fn fixed<T: Real>(x: FixedInput<'_, T>) -> Wrench<T, Branch> {
    x.0.wrench(x.1, T::ZERO, x.2)
}

type VaryingInput<'a, T> = (&'a VaryingContact<T, Undamped, Simplified>, &'a Curvatures<T>, T, Slip<T>);

#[inline(never)]
fn table_each_step<T: Real>(x: VaryingInput<'_, T>) -> Wrench<T, Branch> {
    x.0.wrench(x.1, x.2, T::ZERO, x.3)
}

fn precision<T: Real>(r: &Runner) {
    let curv = Curvatures::<T>::ball_race(
        T::from_f64(12.7e-3),
        T::from_f64(6.6e-3),
        T::from_f64(65e-3),
        T::ZERO,
        Race::Inner,
    )
    .expect("valid bearing geometry");
    let estar = Modulus::new(T::from_f64(1.142857e11)).expect("positive modulus");
    let friction = Friction::<T, Simplified>::new(T::from_f64(0.07), T::ZERO).expect("valid f");
    let contact =
        Contact::hertz::<Newton>(&curv, estar, Undamped, friction).expect("g in the domain");
    let varying = VaryingContact::new(estar, Undamped, friction);
    let h = T::from_f64(5e-6);
    let a = contact.wrench(h, T::ZERO, Slip::default()).patch.a.to_f64();
    let pairs = mixed_set();
    let slips: [Slip<T>; N] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let v = u * a * 100.0;
        Slip::new(
            T::from_f64(v * libm::cos(psi)),
            T::from_f64(v * libm::sin(psi)),
            T::from_f64(100.0),
        )
        .expect("finite slip")
    });
    let fixed_inputs: [FixedInput<'_, T>; N] = core::array::from_fn(|i| (&contact, h, slips[i]));
    r.bench("wrench", "fixed", T::NAME, &fixed_inputs, fixed::<T>);
    let varying_inputs: [VaryingInput<'_, T>; N] = core::array::from_fn(|i| (&varying, &curv, h, slips[i]));
    r.bench("wrench", "table_each_step", T::NAME, &varying_inputs, table_each_step::<T>);
}

pub fn run(r: &Runner) {
    precision::<f32>(r);
    precision::<f64>(r);
}
