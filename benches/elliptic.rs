//! criterion: complete elliptic integrals per method × precision, beside the `ellip` crate, in
//! the same run.
//!
//! Each benchmark evaluates 64 fixed parameters (48 uniform in [0, 0.98], 16 with m₁ log-spaced
//! from 1e-2 down to 1e-9 (f32: not below its domain edge 2⁻²⁴), built with `Parameter::from_complement`); criterion's time per
//! iteration divided by 64 is the time per call. Groups: `ke` (K and E used) and `kebd` (all
//! four; `ellip` has no B, so it computes K, E, D and B = K − D).
//!
//! With `--features micromath` also `ke/theta_micromath_f32` and `kebd/theta_micromath_f32`.
//!
//! `tools/host-bench.sh` runs this and turns criterion's estimates into
//! bench-results/host-elliptic.md with the ratio ours/ellip. Whole run: well under 2 minutes.
use std::hint::black_box;

use contensou::Real;
use contensou::elliptic::{Agm, Method, Parameter, Table, Theta};
use criterion::Criterion;

/// The 64 benchmark parameters as (m, m₁) pairs in f64.
fn points() -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = (0..48)
        .map(|i| {
            let m = 0.98 * i as f64 / 47.0;
            (m, 1.0 - m)
        })
        .collect();
    for i in 0..16 {
        let m1 = 10f64.powf(-2.0 - 7.0 * i as f64 / 15.0);
        v.push((1.0 - m1, m1));
    }
    v
}

fn params<T: Real>() -> Vec<Parameter<T>> {
    points()
        .into_iter()
        .map(|(m, m1)| {
            if m <= 0.5 {
                Parameter::new(T::from_f64(m)).unwrap()
            } else {
                // f32: m₁ below 2⁻²⁴ is outside its domain; use the edge instead
                let m1 = T::from_f64(m1).max(Parameter::<T>::min_complement());
                Parameter::from_complement(m1).unwrap()
            }
        })
        .collect()
}

fn ours<T: Real, M: Method>(c: &mut Criterion) {
    ours_as::<T, M>(c, &format!("{}/{}", M::NAME, T::NAME));
}

/// Benchmarks `ke/<id>` and `kebd/<id>`.
fn ours_as<T: Real, M: Method>(c: &mut Criterion, id: &str) {
    let ps = params::<T>();
    c.bench_function(&format!("ke/{id}"), |b| {
        b.iter(|| {
            let mut acc = T::ZERO;
            for &p in black_box(&ps) {
                let i = M::integrals(black_box(p));
                acc += i.k + i.e;
            }
            acc
        })
    });
    c.bench_function(&format!("kebd/{id}"), |b| {
        b.iter(|| {
            let mut acc = T::ZERO;
            for &p in black_box(&ps) {
                let i = M::integrals(black_box(p));
                acc += i.k + i.e + i.b + i.d;
            }
            acc
        })
    });
}

macro_rules! ellip_bench {
    ($name:ident, $t:ty) => {
        fn $name(c: &mut Criterion) {
            let ms: Vec<$t> = params::<$t>().iter().map(|p| p.m()).collect();
            c.bench_function(concat!("ke/ellip/", stringify!($t)), |b| {
                b.iter(|| {
                    let mut acc: $t = 0.0;
                    for &m in black_box(&ms) {
                        let m = black_box(m);
                        acc += ellip::ellipk(m).unwrap_or(0.0) + ellip::ellipe(m).unwrap_or(0.0);
                    }
                    acc
                })
            });
            c.bench_function(concat!("kebd/ellip/", stringify!($t)), |b| {
                b.iter(|| {
                    let mut acc: $t = 0.0;
                    for &m in black_box(&ms) {
                        let m = black_box(m);
                        let k = ellip::ellipk(m).unwrap_or(0.0);
                        let e = ellip::ellipe(m).unwrap_or(0.0);
                        let d = ellip::ellipd(m).unwrap_or(0.0);
                        acc += k + e + (k - d) + d;
                    }
                    acc
                })
            });
        }
    };
}
ellip_bench!(ellip_f64, f64);
ellip_bench!(ellip_f32, f32);

fn all(c: &mut Criterion) {
    ours::<f64, Agm>(c);
    ours::<f64, Theta>(c);
    ours::<f64, Table>(c);
    ellip_f64(c);
    ours::<f32, Agm>(c);
    ours::<f32, Theta>(c);
    ours::<f32, Table>(c);
    ellip_f32(c);
    #[cfg(feature = "micromath")]
    ours_as::<f32, contensou::elliptic::ThetaMicromath>(c, "theta_micromath_f32");
}

include!("group.rs");
bench_main!(all, warm_up_ms: 300, measure_ms: 1500, samples: 60);
