//! Measuring one benchmark: per-call executed instructions, averaged over a fixed input set.

use crate::counter;
use core::hint::black_box;
use cortex_m_semihosting::hprintln;

/// Measures regions and prints `BENCH <stage> <method> <precision> insns=<N>` lines.
pub struct Runner {
    /// Instructions of an empty measured region (two counter reads), subtracted from every
    /// measurement.
    overhead: u32,
}

/// Per-input instructions of `f(x)`, overhead subtracted: (total, min, max).
///
/// `f` reaches the call site through `black_box`, so the compiler sees an indirect call to an
/// unknown function: it can neither drop the call, nor inline it, nor move it across the
/// (volatile) counter reads. Each input also goes through `black_box` (before the first read),
/// so nothing is constant-folded.
#[inline(never)]
fn measure<I: Copy, O>(f: fn(I) -> O, inputs: &[I], overhead: u32) -> (u64, u32, u32) {
    let f = black_box(f);
    let (mut total, mut min, mut max) = (0u64, u32::MAX, 0u32);
    for &x in inputs {
        let x = black_box(x);
        let t0 = counter::now();
        let y = f(x);
        let t1 = counter::now();
        black_box(y);
        let n = t1.wrapping_sub(t0).saturating_sub(overhead);
        total += u64::from(n);
        min = min.min(n);
        max = max.max(n);
    }
    (total, min, max)
}

/// An empty region: the two counter reads and nothing between them.
#[inline(never)]
fn empty_region() -> u32 {
    let t0 = counter::now();
    let t1 = counter::now();
    t1.wrapping_sub(t0)
}

impl Runner {
    /// Starts the counter and measures the empty-region overhead (the smallest of 8 samples;
    /// under `-icount` they are all equal).
    pub fn new() -> Self {
        counter::init();
        let overhead = (0..8).map(|_| empty_region()).min().unwrap_or(0);
        hprintln!("OVERHEAD insns={}", overhead);
        Runner { overhead }
    }

    /// Measures `f` once per input and prints the per-call average, rounded to the nearest
    /// instruction, with the empty-region overhead subtracted. The count includes the call of
    /// `f` (`blx`, return) and loading its argument: the `core call` row measures that floor.
    /// Make `f` an `#[inline(never)]` function. A `DETAIL` line gives min/max over the inputs.
    pub fn bench<I: Copy, O>(
        &self,
        stage: &str,
        method: &str,
        precision: &str,
        inputs: &[I],
        f: fn(I) -> O,
    ) {
        let (total, min, max) = measure(f, inputs, self.overhead);
        let count = inputs.len().max(1) as u64;
        let avg = (total + count / 2) / count;
        hprintln!("BENCH {} {} {} insns={}", stage, method, precision, avg);
        hprintln!(
            "DETAIL {} {} {} inputs={} min={} max={} total={}",
            stage,
            method,
            precision,
            inputs.len(),
            min,
            max,
            total
        );
    }

    /// The most expensive input of `inputs` for `f` (per-call instructions, overhead
    /// subtracted) and its count: one step of an input search (call it per chunk of candidates,
    /// keep the largest, then [`Runner::bench`] it alone to print its row).
    #[allow(dead_code)] // the main firmware only (the `scenes` binary shares this file)
    pub fn costliest<I: Copy, O>(&self, inputs: &[I], f: fn(I) -> O) -> Option<(I, u32)> {
        let mut worst: Option<(I, u32)> = None;
        for &x in inputs {
            let (_, _, n) = measure(f, &[x], self.overhead);
            if worst.is_none_or(|(_, w)| n > w) {
                worst = Some((x, n));
            }
        }
        worst
    }
}
