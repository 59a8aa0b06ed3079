// xorshift64 (Marsaglia 2003: shifts 13, 7, 17), uniform in [0, 1) from the top 53 bits: the
// fixed pseudo-random stream of the benchmark input sets (`friction_set.rs`, `batch_set.rs`;
// `include!`d by them, so also by the firmware and host-tests/wrench.rs). no_std.

/// Uniform draws in [0, 1) from xorshift64 started at `seed` (non-zero).
fn xorshift64(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}
