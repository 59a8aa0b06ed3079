//! Benchmark firmware, row `scene-step,bearing,f32`: one step-aware step of the 209 bearing
//! (`contensou::scenes::bearing`) with the creep law `table` on both races, in `f32`, at
//! Δt = 20 µs (`Bearing::step_aware`, the ring seen at its start: ring torque, spin moments
//! and cage speed within 2 % of RK4 at every step 10–40 µs in the steady state): nine balls,
//! each ball's two race contacts solved together. The instructions of one step, to turn into a
//! real-time factor on a 168 MHz Cortex-M4F (compute per simulated time: cycles / (Δt·168e6);
//! the count hardly depends on Δt). Inputs: 8 consecutive states (with their warm starts) after 3 ms of
//! 50 µs steps with the ring seen where its velocity takes it (`RingCoupling::Predicted`:
//! fewer setup instructions; the load's 5 ms ramp at 60 %). A binary of its own (run
//! by `tools/qemu-bench.sh` after `step_scenes`) so the other rows' code and counts stay as
//! they are (linked into `step_scenes`, it moved their counts by up to 1 %).
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use contensou::friction::Friction;
use contensou::geometry::Race;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::scenes::bearing::{self, BALLS, Bearing, RingCoupling};
use contensou::scenes::step_aware::Warm;
use contensou::select::{Elliptic, ExactGrade, Fixed, Rolls, Scene, Select};
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use harness::Runner;
use panic_semihosting as _;

/// A race of the bearing: exact Hertz, Hunt–Crossley, `best` under the rolling law `table`.
type Race209 = Scene<Elliptic, Fixed, Rolls, ExactGrade, f32>;
type Bearing209 = Bearing<f32, <Race209 as Select>::Contact<HuntCrossley<f32>>>;
const H: f32 = 2e-5;
const H_SETUP: f32 = 5e-5;
/// One step's input: the scene, the time, the state, each ball's warm start.
type Input<'a> = (&'a Bearing209, f32, bearing::State<f32>, [Warm<f32>; BALLS]);

#[inline(never)]
fn bearing_step(x: Input<'_>) -> bearing::State<f32> {
    let mut w = x.3;
    x.0.step_aware(x.1, &x.2, H, &mut w).0
}

#[entry]
fn main() -> ! {
    let r = Runner::new();
    let g = bearing::Geometry::<f32>::bearing_209();
    let race = |r| {
        Race209::build(
            &g.curvatures(r).expect("the 209's curvatures"),
            Modulus::new(1.142857e11).expect("valid E*"),
            HuntCrossley::new(0.3).expect("valid damping"),
            Friction::new(0.07, 0.05).expect("valid f and δ"),
        )
        .expect("valid race contact")
    };
    let b = Bearing209::new(&g, race(Race::Inner), race(Race::Outer)).expect("the 209 is valid");
    let (mut y, mut w, mut t) = (b.initial_state(), [Warm::default(); BALLS], 0.0f32);
    for _ in 0..60 {
        y = b
            .step_aware_with(t, &y, H_SETUP, &mut w, RingCoupling::Predicted)
            .0;
        t += H_SETUP;
    }
    let mut states = [(&b, t, y, w); 8];
    for s in states.iter_mut() {
        *s = (&b, t, y, w);
        y = b.step_aware(t, &y, H, &mut w).0;
        t += H;
    }
    r.bench("scene-step", "bearing", "f32", &states, bearing_step);

    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
