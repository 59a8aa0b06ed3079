//! Stage `scene`: the paper's tippe top in `f32` with the fixed-step RK4 integrator
//! (`contensou::scenes`, feature `scenes`), simplified Contensou friction, h = 10 µs (≈1/68 of
//! the 1.5 kHz contact period).
//!
//! - `tippe_top_step`: one RK4 step (4 right-hand sides, each with both sphere–floor contacts)
//!   over 16 states of the first 10 ms of the paper's start (only the big sphere touches).
//! - `tippe_top_step_two_contacts`: one RK4 step at θ* = arccos(−10/13), both spheres pressed
//!   in by 0.17 µm (both contacts active: the worst case), 16 spins.
//! - `tippe_top_10ms`: the whole 10 ms from the paper's start, 1,000 steps in one call; ×100
//!   gives instructions per simulated second.
//! - `rattleback_step`: one RK4 step of the rattleback (`scenes::rattleback`, Kane–Levinson
//!   body, default law `Best`, f = 0.3, δ = 1 mm/s, h = 0.1 ms): 4 right-hand sides, each the
//!   closed-form ellipsoid geometry + `VaryingContact` (shape table per call) + frame mapping;
//!   16 states along the first 0.16 s of the unstable start (ω₀ = −2 rad/s, 0.5° rock).
//! - `rattleback_rolling_step`: the same with the default rolling law (`Creeping<Table>`:
//!   `contact::Rolling` over the `VaryingContact<Best>`, the contact's rolling velocity, the
//!   polymer-on-glass `Params::elasticity`), over the same law's 16 states.

use crate::harness::Runner;
use contensou::friction::{Best, Friction, Simplified};
use contensou::scenes::integrate::{rk4, rk4_step};
use contensou::friction::rolling::Table;
use contensou::scenes::rattleback::{self, Creeping, FloorLaw, Rattleback};
use contensou::scenes::tippe_top::{Params, State, TippeTop};

type Top = TippeTop<f32, Simplified>;
const H: f32 = 1e-5;
const STEPS_10MS: usize = 1_000;

#[inline(never)]
fn tippe_top_step(x: (&Top, State<f32>)) -> State<f32> {
    rk4_step(x.0, 0.0, &x.1, H)
}

#[inline(never)]
fn tippe_top_10ms(x: (&Top, State<f32>)) -> State<f32> {
    rk4(x.0, 0.0, x.1, H, STEPS_10MS, |_, _, _| {})
}

type Celt = Rattleback<f32, Best>;
const H_CELT: f32 = 1e-4;

type CeltRolling = Rattleback<f32, Creeping<Table>>;

#[inline(never)]
fn rattleback_step(x: (&Celt, rattleback::State<f32>)) -> rattleback::State<f32> {
    rk4_step(x.0, 0.0, &x.1, H_CELT)
}

#[inline(never)]
fn rattleback_rolling_step(
    x: (&CeltRolling, rattleback::State<f32>),
) -> rattleback::State<f32> {
    rk4_step(x.0, 0.0, &x.1, H_CELT)
}

/// 16 states along the first 0.16 s of the unstable start.
fn celt_states<L: FloorLaw<f32>>(
    celt: &Rattleback<f32, L>,
) -> [(&Rattleback<f32, L>, rattleback::State<f32>); 16] {
    let y0 = celt.initial_state(0.5 * core::f32::consts::PI / 180.0, -2.0);
    let mut along = [(celt, y0); 16];
    let mut k = 1;
    rk4(celt, 0.0, y0, H_CELT, 1_600, |i, _, y| {
        if i % 100 == 0 && k < 16 {
            along[k] = (celt, *y);
            k += 1;
        }
    });
    along
}

pub fn run(r: &Runner) {
    let top = Top::new(
        &Params::paper(),
        Friction::with_law(0.3, 1e-4).expect("valid f and δ"),
    )
    .expect("the paper's parameters are valid");
    let y0 = top.initial_state(0.1, 180.0);

    // 16 states along the first 10 ms.
    let mut along = [(&top, y0); 16];
    let mut k = 1;
    rk4(&top, 0.0, y0, H, STEPS_10MS, |i, _, y| {
        if i % (STEPS_10MS / 16) == 0 && k < 16 {
            along[k] = (&top, *y);
            k += 1;
        }
    });
    r.bench("scene", "tippe_top_step", "f32", &along, tippe_top_step);

    // Both spheres touching: θ = θ*, G lowered by the static approach 0.17 µm.
    let theta_star = libm::acosf(-10.0 / 13.0);
    let both: [(&Top, State<f32>); 16] = core::array::from_fn(|i| {
        let mut y = top.initial_state(theta_star, 20.0 + 10.0 * i as f32);
        y[2] -= 1.7e-7;
        (&top, y)
    });
    r.bench(
        "scene",
        "tippe_top_step_two_contacts",
        "f32",
        &both,
        tippe_top_step,
    );

    r.bench(
        "scene",
        "tippe_top_10ms",
        "f32",
        &[(&top, y0)],
        tippe_top_10ms,
    );

    let celt = Celt::new(
        &rattleback::Params::kane_levinson(),
        Friction::new(0.3, 1e-3).expect("valid f and δ"),
    )
    .expect("Kane–Levinson's parameters are valid");
    r.bench("scene", "rattleback_step", "f32", &celt_states(&celt), rattleback_step);

    let p = rattleback::Params::kane_levinson();
    let rolling = CeltRolling::rolling(
        &p,
        Friction::new(0.3, 1e-3).expect("valid f and δ"),
        p.elasticity().expect("valid E*"),
    )
    .expect("Kane–Levinson's parameters are valid");
    r.bench(
        "scene",
        "rattleback_rolling_step",
        "f32",
        &celt_states(&rolling),
        rattleback_rolling_step,
    );
}
