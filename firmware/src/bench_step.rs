//! Stage `step`: the step-aware wrench (`contensou::step::step_wrench`) at a control-rate step
//! Δt = 1 ms, on the `wrench` stage's contact (the 209 bearing's inner-race contact: ball
//! Ø 12.7 mm, Hertz, no damping, the default law `Best`, f = 0.07, δ = 0) and its 64 mixed
//! slips (ω = 100 rad/s), f32. The normal state: the steel ball (8.38 g) resting under its
//! weight (h at the static approach, ḣ = 0); the free end velocity: the start velocity plus
//! gravity over the step. Per call: the normal predictor (6 wrench calls), 2 linearisations
//! (the dual-number Jacobian, `jacobian,fixed-best`), the 4 × 4 solves, the projection.
//!
//! - `fixed-best`: one contact, W of the ball on a fixed plane (`InverseMass::from_bodies`;
//!   compare `wrench,fixed-best`).
//! - `two-contacts-best`: the same ball between two fixed races, contacts below and above it
//!   (W 8 × 8 with the cross blocks through the ball; `step_wrenches`, K = 2).

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::frame::{Frame, MajorAxis};
use contensou::friction::rolling::RollingVelocity;
use contensou::friction::{Best, Friction, FrictionLaw, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::jacobian::{Linearize, State};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;
use contensou::step::{
    Body, ContactPoint, Free, InverseMass, Outcome, TimeStep, step_wrench, step_wrenches,
};

include!("../../benches/friction_set.rs");
include!("../../benches/wrench_set.rs");

const N: usize = SET;

type Fixed = Contact<f32, Hertz<f32>, Undamped, Best>;

/// One contact's step: the contact, W, Δt, the start state and the free motion.
type One<'a> = (&'a Fixed, &'a InverseMass<f32, 1>, TimeStep<f32>, State<f32>, Free<f32>);
/// Two contacts' step.
type Two<'a> = (
    &'a Fixed,
    &'a InverseMass<f32, 2>,
    TimeStep<f32>,
    [State<f32>; 2],
    [Free<f32>; 2],
);

#[inline(never)]
fn one(x: One<'_>) -> Outcome<f32> {
    step_wrench(x.0, x.2, x.1, &x.3, &x.4)
}

#[inline(never)]
fn two(x: Two<'_>) -> [Outcome<f32>; 2] {
    let c = x.0 as &dyn Linearize<f32>;
    step_wrenches([c, c], x.2, x.1, &x.3, &x.4)
}

/// The ball's mass (kg) and radius (m).
const MASS: f64 = 8.38e-3;
const RADIUS: f64 = 6.35e-3;
const G: f64 = 9.81;

/// A contact frame with normal z = `up` (x along world x).
fn frame(up: f32) -> Frame<f32> {
    Frame::new([0.0, 0.0, up], [1.0, 0.0, 0.0], MajorAxis::from_cos_sin(1.0, 0.0))
}

pub fn run(r: &Runner) {
    let (_, contact, _, h5, slips) = wrench_scene::<f32, Best>();
    // The static approach under the ball's weight: N ∝ h^1.5 from N(5 µm).
    let n5 = f64::from(contact.wrench(h5, 0.0, Slip::default()).n);
    let h = (f64::from(h5) * libm::pow(MASS * G / n5, 2.0 / 3.0)) as f32;
    let dt = TimeStep::new(1e-3_f32).expect("positive step");
    let i = (0.4 * MASS * RADIUS * RADIUS) as f32;
    let inertia = [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]];
    let ball = Body::new(MASS as f32, inertia, [0.0, 0.0, RADIUS as f32]).expect("valid ball");
    let below = ContactPoint {
        a: None,
        b: Some(0),
        point: [0.0; 3],
        frame: frame(1.0),
    };
    let w1 = InverseMass::<f32, 1>::from_bodies(&[ball], &[below]).expect("valid W");
    let state = |k: usize| State {
        h,
        hdot: 0.0,
        slip: slips[k],
        rolling: RollingVelocity::ZERO,
    };
    let g_dt = (G * 1e-3) as f32;
    // Gravity pulls B (the ball) down: v_n = −ḣ decreases by g·Δt.
    let free = |s: &State<f32>, dn: f32| {
        let u = [-s.hdot + dn, s.slip.vx(), s.slip.vy(), s.slip.omega()];
        Free::predicted(dt, s, u).expect("finite free motion")
    };
    let ones: [One<'_>; N] = core::array::from_fn(|k| {
        let s = state(k);
        (&contact, &w1, dt, s, free(&s, -g_dt))
    });
    r.bench("step", "fixed-best", f32::NAME, &ones, one);

    // The ball between two fixed races: below (A = world, B = ball) and above (A = ball,
    // B = world; the normal from the ball up into the upper race), both at the static approach.
    let above = ContactPoint {
        a: Some(0),
        b: None,
        point: [0.0, 0.0, (2.0 * RADIUS) as f32],
        frame: frame(1.0),
    };
    let w2 = InverseMass::<f32, 2>::from_bodies(&[ball], &[below, above]).expect("valid W");
    let twos: [Two<'_>; N] = core::array::from_fn(|k| {
        let s = state(k);
        // The upper contact sees the ball's slip reversed (B is the race, A the ball).
        let up = State {
            slip: Slip::new(-s.slip.vx(), -s.slip.vy(), -s.slip.omega()).expect("finite slip"),
            ..s
        };
        (&contact, &w2, dt, [s, up], [free(&s, -g_dt), free(&up, g_dt)])
    });
    r.bench("step", "two-contacts-best", f32::NAME, &twos, two);
}
