//! Stage `jacobian`: the wrench and its Jacobian with respect to (h, ḣ, v_x, v_y, ω) by
//! forward-mode dual numbers (`contensou::jacobian::Linearize::linearize`), on the `wrench`
//! stage's scene and inputs (the 209 bearing's inner-race contact, h = 5 µm, the mixed set of
//! 64 slips, ω = 100 rad/s), Hertz + no damping + the default law `Best`, f32.
//!
//! - `fixed-best`: `Contact::linearize` (per-contact tables; compare `wrench,fixed-best`).
//! - `table_each_step-best`: `VaryingContact::at(&curvatures).linearize` (the shape by table
//!   each step; compare `wrench,table_each_step-best`).

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::rolling::RollingVelocity;
use contensou::friction::{Best, Friction, FrictionLaw, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::jacobian::{At, Jacobian, Linearize, State};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;

include!("../../benches/friction_set.rs");
include!("../../benches/wrench_set.rs");

const N: usize = SET;

/// A fixed contact and the state it is linearised at.
type FixedInput<'a> = (&'a Contact<f32, Hertz<f32>, Undamped, Best>, State<f32>);

#[inline(never)]
fn fixed(x: FixedInput<'_>) -> Jacobian<f32> {
    x.0.linearize(&x.1)
}

/// A varying contact at its curvatures and the state it is linearised at.
type VaryingInput<'a, 'c> = (&'a At<'c, VaryingContact<f32, Undamped, Best>, f32>, State<f32>);

#[inline(never)]
fn varying(x: VaryingInput<'_, '_>) -> Jacobian<f32> {
    x.0.linearize(&x.1)
}

pub fn run(r: &Runner) {
    let (curv, contact, varying_contact, h, slips) = wrench_scene::<f32, Best>();
    let states: [State<f32>; N] = core::array::from_fn(|i| State {
        h,
        hdot: 0.0,
        slip: slips[i],
        rolling: RollingVelocity::ZERO,
    });
    let fixed_inputs: [_; N] = core::array::from_fn(|i| (&contact, states[i]));
    r.bench("jacobian", "fixed-best", f32::NAME, &fixed_inputs, fixed);
    let at = varying_contact.at(&curv);
    let varying_inputs: [_; N] = core::array::from_fn(|i| (&at, states[i]));
    r.bench("jacobian", "table_each_step-best", f32::NAME, &varying_inputs, varying);
}
