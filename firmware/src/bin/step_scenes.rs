//! Benchmark firmware, rows `scene-step,<scene>,f32`: one step-aware step of each scene
//! (`contensou::scenes`, the `step_aware` integrators) in `f32`, at the scene's largest
//! holding step (the guide's "Scenes at large steps" table): the instructions of one step,
//! to turn into a real-time factor on a 168 MHz Cortex-M4F (instructions per simulated second
//! = insns / Δt). A binary of its own (fifth of rig B, run by `tools/qemu-bench.sh`) so the
//! main firmware's code and counts stay as they are.
//!
//! - `tippe-top`: the paper's top (`best`, f = 0.3, δ = 1e-4 m/s), Δt = 1 ms, 16 states along
//!   the first 16 ms (one contact) and 16 with both spheres pressed in (two contacts).
//! - `ball`: the guide's steel ball (`best`, f = 0.1), Δt = 2 ms, 16 states along 32 ms.
//! - `rattleback`: Kane–Levinson (`best`, f = 0.3, δ = 1 mm/s), Δt = 1 ms, 16 states along the
//!   first 0.16 s of the unstable start; `rattleback-table`: the same with the rolling law
//!   `table` (`Creeping<Table>`).
//!
//! Each input carries the previous step's [`Warm`] (the first iterate), as in a run.
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use contensou::friction::rolling::Table;
use contensou::friction::{Best, Friction};
use contensou::scenes::ball::{self, Ball};
use contensou::scenes::rattleback::{self, Creeping, FloorLaw, Rattleback};
use contensou::scenes::step_aware::Warm;
use contensou::scenes::tippe_top::{self, TippeTop};
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use harness::Runner;
use panic_semihosting as _;

type Top = TippeTop<f32, Best>;
const H_TOP: f32 = 1e-3;
type BallB = Ball<f32, Best>;
const H_BALL: f32 = 2e-3;
const H_CELT: f32 = 1e-3;

#[inline(never)]
fn top_step(x: (&Top, tippe_top::State<f32>, Warm<f32>)) -> tippe_top::State<f32> {
    let mut w = x.2;
    x.0.step_aware(&x.1, H_TOP, &mut w)
}

#[inline(never)]
fn ball_step(x: (&BallB, ball::State<f32>, Warm<f32>)) -> ball::State<f32> {
    let mut w = x.2;
    x.0.step_aware(&x.1, H_BALL, &mut w)
}

#[inline(never)]
fn celt_step(x: CeltInput<'_, Best>) -> rattleback::State<f32> {
    let mut w = x.2;
    x.0.step_aware(&x.1, H_CELT, &mut w)
}

#[inline(never)]
fn celt_table_step(x: CeltInput<'_, Creeping<Table>>) -> rattleback::State<f32> {
    let mut w = x.2;
    x.0.step_aware(&x.1, H_CELT, &mut w)
}

/// 16 consecutive (state, warm) pairs of `step` from `y0`.
fn along<S: Copy, const N: usize>(
    y0: [f32; N],
    mut step: impl FnMut(&[f32; N], &mut Warm<f32>) -> [f32; N],
    scene: S,
    w0: Warm<f32>,
) -> [(S, [f32; N], Warm<f32>); 16] {
    let mut out = [(scene, y0, w0); 16];
    let (mut y, mut w) = (y0, w0);
    for o in out.iter_mut() {
        *o = (scene, y, w);
        y = step(&y, &mut w);
    }
    out
}

/// One rattleback step's input: the scene, the state, the previous step's warm start.
type CeltInput<'a, L> = (&'a Rattleback<f32, L>, rattleback::State<f32>, Warm<f32>);

fn celt_along<L: FloorLaw<f32>>(rb: &Rattleback<f32, L>) -> [CeltInput<'_, L>; 16] {
    let y0 = rb.initial_state(0.5 * core::f32::consts::PI / 180.0, -2.0);
    // Every 10th step of the first 0.16 s.
    let mut out = [(rb, y0, Warm::default()); 16];
    let (mut y, mut w) = (y0, Warm::default());
    for o in out.iter_mut() {
        *o = (rb, y, w);
        for _ in 0..10 {
            y = rb.step_aware(&y, H_CELT, &mut w);
        }
    }
    out
}

#[entry]
fn main() -> ! {
    let r = Runner::new();

    let top = Top::new(
        &tippe_top::Params::paper(),
        Friction::with_law(0.3, 1e-4).expect("valid f and δ"),
    )
    .expect("the paper's parameters are valid");
    let y0 = top.initial_state(0.1, 180.0);
    let one = along(
        y0,
        |y, w| top.step_aware(y, H_TOP, w),
        &top,
        Warm::default(),
    );
    r.bench("scene-step", "tippe-top", "f32", &one, top_step);
    // Both spheres touching: θ = θ*, G lowered by the static approach 0.17 µm.
    let theta_star = libm::acosf(-10.0 / 13.0);
    let both: [(&Top, tippe_top::State<f32>, Warm<f32>); 16] = core::array::from_fn(|i| {
        let mut y = top.initial_state(theta_star, 20.0 + 10.0 * i as f32);
        y[2] -= 1.7e-7;
        (&top, y, Warm::default())
    });
    r.bench(
        "scene-step",
        "tippe-top-two-contacts",
        "f32",
        &both,
        top_step,
    );

    let b = BallB::new(0.1, 1e-4).expect("valid f and δ");
    let balls = along(
        b.initial_state(),
        |y, w| b.step_aware(y, H_BALL, w),
        &b,
        b.initial_warm(),
    );
    r.bench("scene-step", "ball", "f32", &balls, ball_step);

    let celt = Rattleback::<f32, Best>::new(
        &rattleback::Params::kane_levinson(),
        Friction::with_law(0.3, 1e-3).expect("valid f and δ"),
    )
    .expect("Kane–Levinson's parameters are valid");
    r.bench(
        "scene-step",
        "rattleback",
        "f32",
        &celt_along(&celt),
        celt_step,
    );

    let p = rattleback::Params::kane_levinson();
    let rolling = Rattleback::<f32, Creeping<Table>>::rolling(
        &p,
        Friction::with_law(0.3, 1e-3).expect("valid f and δ"),
        p.elasticity().expect("valid E*"),
    )
    .expect("Kane–Levinson's parameters are valid");
    r.bench(
        "scene-step",
        "rattleback-table",
        "f32",
        &celt_along(&rolling),
        celt_table_step,
    );

    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
