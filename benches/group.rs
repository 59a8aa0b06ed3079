// Included by the criterion benches (`include!("group.rs")`): their group and `main`, with
// the warm-up and measurement times (ms) and the sample size each bench chooses (short runs:
// tools/host-ns.sh re-measures every bench).

/// `bench_cycling!(c, name, N, |i| body)`: benchmark `name`, each iteration `body` (black-boxed)
/// at the next index `i` of a set of `N` entries, cycling through the set.
#[allow(unused_macros)] // not every bench cycles through a set
macro_rules! bench_cycling {
    ($c:expr, $name:expr, $n:expr, |$i:ident| $body:expr) => {{
        let mut $i = 0;
        $c.bench_function($name, |b| {
            b.iter(|| {
                $i = ($i + 1) % $n;
                std::hint::black_box($body)
            })
        });
    }};
}

/// `each!(f(args…), [T…], [L…])`: `f::<T, L>(args…)` for each precision `T` and, within it,
/// each law or method `L`.
#[allow(unused_macros)] // not every bench runs a grid of precisions × laws
macro_rules! each {
    ($f:ident $args:tt, [$($t:ty),*], $ls:tt) => {
        $(each!(@laws $f $args, $t, $ls);)*
    };
    (@laws $f:ident $args:tt, $t:ty, [$($l:ty),*]) => {
        $($f::<$t, $l> $args;)*
    };
}

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
