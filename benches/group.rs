// Included by the criterion benches (`include!("group.rs")`): their group and `main`, with
// the warm-up and measurement times (ms) and the sample size each bench chooses (short runs:
// tools/host-ns.sh re-measures every bench).

/// `criterion_group!` of `targets` with the given times and sample size, and `criterion_main!`.
macro_rules! bench_main {
    ($targets:path, warm_up_ms: $w:expr, measure_ms: $m:expr, samples: $n:expr) => {
        criterion::criterion_group! {
            name = group;
            config = criterion::Criterion::default()
                .warm_up_time(std::time::Duration::from_millis($w))
                .measurement_time(std::time::Duration::from_millis($m))
                .sample_size($n);
            targets = $targets
        }
        criterion::criterion_main!(group);
    };
}
