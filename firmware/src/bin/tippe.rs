//! Benchmark firmware, row `scene tippe_top_8s f32`: the paper's tippe top for 8 s of simulated
//! time on the MCU (fourth binary of rig B, run by `tools/qemu-bench.sh`; a binary of its own
//! so the main firmware's code and counts stay as they are).
//!
//! `f32`, simplified Contensou friction (f = 0.3, δ = 1e-4 m/s), fixed-step RK4 at
//! [`H`] = 94 µs (85,107 steps, 8.000 s): the largest step whose small-sphere touch-down stays within 5 ms of the
//! `f64`, 10 µs run and that `Friction::stable_step` allows (host search:
//! `cargo run --release --features scenes --example tippe_top_step`). Start θ₀ = 0.1 rad,
//! ω₃ = 180 rad/s. The measured region is the whole run, one call: the RK4 steps plus a
//! touch-down test per step ([`TippeTop::penetrations`], 8 multiply-adds). Prints the
//! touch-down step and the final state's bits (`STATE`) after measuring.
//!
//! `tools/qemu-bench.sh` runs it plainly (twice) and traced once (cycles); the 8 s are
//! ≈ 2e8 executed instructions.
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use contensou::friction::{Friction, Simplified};
use contensou::scenes::integrate::rk4_step;
use contensou::scenes::tippe_top::{N, Params, State, TippeTop};
use core::sync::atomic::{AtomicU32, AtomicUsize, Ordering::Relaxed};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprint, hprintln};
use harness::Runner;
use panic_semihosting as _;

type Top = TippeTop<f32, Simplified>;
/// The fixed step (s).
const H: f32 = 94e-6;
/// 8 s of simulated time (⌈8 s / H⌉ steps).
const STEPS: usize = 85_107;

/// The first step after which the small sphere touches the floor (0: never), and the final
/// state's bits, stored by the measured run for printing afterwards.
static TOUCH: AtomicUsize = AtomicUsize::new(0);
static FINAL: [AtomicU32; N] = [const { AtomicU32::new(0) }; N];

/// 8 s from `x`; the result goes to [`TOUCH`] and [`FINAL`].
#[inline(never)]
fn tippe_top_8s(x: (&Top, State<f32>)) {
    let (top, mut y) = x;
    let mut touch = 0;
    for i in 0..STEPS {
        y = rk4_step(top, H * i as f32, &y, H);
        if touch == 0 && top.penetrations(&y)[1] > 0.0 {
            touch = i + 1;
        }
    }
    TOUCH.store(touch, Relaxed);
    for (f, v) in FINAL.iter().zip(y) {
        f.store(v.to_bits(), Relaxed);
    }
}

#[entry]
fn main() -> ! {
    let r = Runner::new();
    let top = Top::new(
        &Params::paper(),
        Friction::with_law(0.3, 1e-4).expect("valid f and δ"),
    )
    .expect("the paper's parameters are valid");
    let y0 = top.initial_state(0.1, 180.0);
    r.bench("scene", "tippe_top_8s", "f32", &[(&top, y0)], tippe_top_8s);
    let touch = TOUCH.load(Relaxed);
    hprintln!("TOUCHDOWN step={} t={}", touch, touch as f32 * H);
    hprint!("STATE");
    for v in &FINAL {
        hprint!(" {:08x}", v.load(Relaxed));
    }
    hprintln!();
    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
