//! Benchmark firmware for `contensou` (rig B): counts executed instructions per call on a
//! Cortex-M4F (`thumbv7em-none-eabihf`) under QEMU `netduinoplus2` with `-icount shift=0`.
//!
//! Prints `BENCH <stage> <method> <precision> insns=<N>` per benchmark over semihosting and
//! exits with code 0. Run it with `tools/qemu-bench.sh` (see README.md in this directory).
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use panic_semihosting as _;

mod counter;
mod harness;

/// One stage per line: module `src/<name>.rs` with `pub fn run(r: &harness::Runner)`.
macro_rules! stages {
    ($($stage:ident,)*) => {
        $(mod $stage;)*
        fn run_all(r: &harness::Runner) {
            $($stage::run(r);)*
        }
    };
}

stages! {
    bench_core,
    bench_elliptic,
    bench_hertz,
    bench_friction,
    bench_wrench,
    bench_frame,
    bench_scene,
    bench_rolling,
    bench_jacobian,
    bench_step,
}

#[entry]
fn main() -> ! {
    let runner = harness::Runner::new();
    run_all(&runner);
    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
