// The friction benchmarks' fixed mixed input set, shared verbatim (`include!`) by the host
// bench `benches/friction.rs` and the QEMU stage `firmware/src/bench_friction.rs`.

include!("xorshift.rs");

/// States in the set.
const SET: usize = 64;

/// (u, ψ): u log-uniform in [0.01, 100], ψ uniform in [0, 2π), from a fixed xorshift64 seed.
fn mixed_set() -> [(f64, f64); SET] {
    let mut unit = xorshift64(0x2545_F491_4F6C_DD1D);
    core::array::from_fn(|_| {
        let u = libm::pow(10.0, -2.0 + 4.0 * unit());
        let psi = 2.0 * core::f64::consts::PI * unit();
        (u, psi)
    })
}
