//! Benchmark firmware, stage `model`: micro-benchmarks whose Cortex-M4F cycle counts the ARM
//! technical reference manual states, run to check `tools/cycle_model.py` (third binary of rig
//! B; `tools/qemu-bench.sh` runs it traced and writes `bench-results/cycle-model-check.csv`).
//!
//! Every case is the same `#[inline(never)]` shape — `vmov s0/s1/s2` from the argument, an
//! inline `asm!` block between two `nop`s, `vmov` back — so a case minus `model empty` is the
//! block alone. Each `EXPECT <case> <lo> <mid> <hi>` line states what the manual gives for the
//! block (refill P = 1, 2, 3 for lo, mid, hi); the model must reproduce it exactly:
//!
//! | case | block | TRM cycles |
//! |---|---|---|
//! | `vdiv-chain-16` | 16 dependent `vdiv.f32 s0, s0, s1` | 16 × 14 |
//! | `vsqrt-chain-16` | 16 dependent `vsqrt.f32 s0, s0` | 16 × 14 |
//! | `vmla-chain-16` | 16 dependent `vmla.f32 s0, s1, s2` | 16 × 3 |
//! | `vldr-run-16` | 16 `vldr` from consecutive words | 2 + 15 × 1 (pipelined) |
//! | `ldr-str-8` | `ldr`/`str` alternating, 8 each | 2 + 15 × 1 |
//! | `push-pop-8` | `push {r4-r11}`, `pop {r4-r11}` | 2 × (1 + 8) |
//! | `branch-8` | 8 taken `b` to the next instruction | 8 × (1 + P) |
//!
//! These are not measurements of silicon (QEMU has none to offer): they check that the trace
//! expansion and the classification apply the manual's table as documented.
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use core::arch::asm;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use harness::Runner;
use panic_semihosting as _;

/// 16 words for the load runs.
static WORDS: [u32; 16] = [0; 16];
/// 8 words the store runs write.
static mut SCRATCH: [u32; 8] = [0; 8];

/// A case: the argument into s0, s1, s2, `nop`, the block, `nop`, s0 back.
macro_rules! case {
    ($name:ident $(, $block:literal)*) => {
        #[inline(never)]
        fn $name(x: f32) -> f32 {
            let y: u32;
            // SAFETY: FPU and core register arithmetic on declared clobbers; memory reads are
            // within WORDS (16 aligned words, through `p`), writes within SCRATCH (8 words,
            // through `q`, nothing else references it); push/pop restore sp and r4-r11.
            unsafe {
                asm!(
                    "@ operands {p} {q} {t}",
                    "vmov s0, {x}",
                    "vmov s1, {x}",
                    "vmov s2, {x}",
                    "nop",
                    $($block,)*
                    "nop",
                    "vmov {y}, s0",
                    x = in(reg) x.to_bits(),
                    y = lateout(reg) y,
                    p = in(reg) WORDS.as_ptr(),
                    q = in(reg) (&raw mut SCRATCH).cast::<u32>(),
                    t = out(reg) _,
                    out("s0") _, out("s1") _, out("s2") _, out("s3") _, out("s4") _,
                    out("s5") _, out("s6") _, out("s7") _, out("s8") _, out("s9") _,
                    out("s10") _, out("s11") _, out("s12") _, out("s13") _, out("s14") _,
                    out("s15") _,
                    options(preserves_flags),
                );
            }
            f32::from_bits(y)
        }
    };
}

case!(empty);
case!(vdiv_chain_16, ".rept 16", "vdiv.f32 s0, s0, s1", ".endr");
case!(vsqrt_chain_16, ".rept 16", "vsqrt.f32 s0, s0", ".endr");
case!(vmla_chain_16, ".rept 16", "vmla.f32 s0, s1, s2", ".endr");
case!(
    vldr_run_16,
    "vldr s0, [{p}]",
    "vldr s1, [{p}, #4]",
    "vldr s2, [{p}, #8]",
    "vldr s3, [{p}, #12]",
    "vldr s4, [{p}, #16]",
    "vldr s5, [{p}, #20]",
    "vldr s6, [{p}, #24]",
    "vldr s7, [{p}, #28]",
    "vldr s8, [{p}, #32]",
    "vldr s9, [{p}, #36]",
    "vldr s10, [{p}, #40]",
    "vldr s11, [{p}, #44]",
    "vldr s12, [{p}, #48]",
    "vldr s13, [{p}, #52]",
    "vldr s14, [{p}, #56]",
    "vldr s15, [{p}, #60]"
);
case!(
    ldr_str_8,
    ".irp k, 0, 4, 8, 12, 16, 20, 24, 28",
    "ldr {t}, [{p}, #\\k]",
    "str {t}, [{q}, #\\k]",
    ".endr"
);
case!(push_pop_8, "push {{r4-r11}}", "pop {{r4-r11}}");
case!(
    branch_8, "b 1f", "1:", "b 1f", "1:", "b 1f", "1:", "b 1f", "1:", "b 1f", "1:", "b 1f", "1:",
    "b 1f", "1:", "b 1f", "1:"
);

/// A probe: its name, the block, and the TRM cycles of the block for refill P = 1, 2, 3.
type Case = (&'static str, fn(f32) -> f32, [u32; 3]);

#[entry]
fn main() -> ! {
    let r = Runner::new();
    let xs = [1.5f32, 2.0, 3.0, 0.75];
    let cases: [Case; 8] = [
        ("empty", empty, [0, 0, 0]),
        ("vdiv-chain-16", vdiv_chain_16, [16 * 14; 3]),
        ("vsqrt-chain-16", vsqrt_chain_16, [16 * 14; 3]),
        ("vmla-chain-16", vmla_chain_16, [16 * 3; 3]),
        ("vldr-run-16", vldr_run_16, [2 + 15; 3]),
        ("ldr-str-8", ldr_str_8, [2 + 15; 3]),
        ("push-pop-8", push_pop_8, [2 * (1 + 8); 3]),
        ("branch-8", branch_8, [8 * 2, 8 * 3, 8 * 4]),
    ];
    for (name, f, [lo, mid, hi]) in cases {
        r.bench("model", name, "f32", &xs, f);
        hprintln!("EXPECT model {} f32 {} {} {}", name, lo, mid, hi);
    }
    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
