//! criterion: Hertz normal contact per step (geometry precomputed), per step with the
//! eccentricity from g every step (table; fitted law), and construction (Newton, linear,
//! Hamrock–Dowson) — f32 and f64. Short runs; figures go to bench-results/hertz.md via
//! `cargo run --release --example hertz_report`. With `--features micromath` also
//! `hertz/per_step_micromath_f32` and `hertz/shape_hamrock-dowson_micromath_f32`.
use std::hint::black_box;

use contensou::Real;
use contensou::geometry::Curvatures;
use contensou::normal::{Fitted, Hertz, Modulus, NormalLaw, Volumetric};
use contensou::shape::{Eccentricity, HamrockDowson, Linear, Newton, Ratio, Table};
use criterion::Criterion;

include!("group.rs");

/// The 209 bearing's inner-race contact (P, Q in 1/m), steel E*, a few approaches.
fn inputs<T: Real>() -> (T, T, Modulus<T>, [T; 4]) {
    (
        T::from_f64(2.982581722739203),
        T::from_f64(97.86061637132834),
        Modulus::new(T::from_f64(1.1428571e11)).unwrap(),
        [1e-6, 3e-6, 7e-6, 2e-5].map(T::from_f64),
    )
}

/// `law.patch(h)` over the four approaches, as benchmark `id`.
fn patch<T: Real, L: NormalLaw<T>>(c: &mut Criterion, id: &str, law: L, hs: [T; 4]) {
    let mut i = 0;
    c.bench_function(id, |b| {
        b.iter(|| {
            i = (i + 1) & 3;
            black_box(law.patch(black_box(hs[i])))
        })
    });
}

fn per_step<T: Real>(c: &mut Criterion) {
    let (p, q, estar, hs) = inputs::<T>();
    let curv = Curvatures::new(p, q).unwrap();
    let law = Hertz::new::<Newton>(&curv, estar).unwrap();
    patch(c, &format!("hertz/per_step/{}", T::NAME), law, hs);
    let mut i = 0;
    let curvs = [0.0305, 0.045, 0.2, 0.7].map(|g| Curvatures::new(p, p / T::from_f64(g)).unwrap());
    c.bench_function(&format!("hertz/table_each_step/{}", T::NAME), |b| {
        b.iter(|| {
            i = (i + 1) & 3;
            let curv = black_box(curvs[i]);
            let shape = Table::shape(Ratio::clamped(curv.ratio()));
            black_box(Hertz::from_shape(&curv, &shape, estar).patch(black_box(hs[i])))
        })
    });
    c.bench_function(&format!("hertz/fitted_each_step/{}", T::NAME), |b| {
        b.iter(|| {
            i = (i + 1) & 3;
            let law = Fitted::clamped(&black_box(curvs[i]), estar);
            black_box(law.patch(black_box(hs[i])))
        })
    });
    c.bench_function(&format!("hertz/volumetric/{}", T::NAME), |b| {
        b.iter(|| {
            i = (i + 1) & 3;
            let law = Volumetric::new(&black_box(curvs[i]), estar);
            black_box(law.patch(black_box(hs[i])))
        })
    });
}

fn construct<T: Real, M: Eccentricity>(c: &mut Criterion) {
    construct_as::<T, M>(c, &format!("hertz/shape_{}/{}", M::NAME, T::NAME));
}

fn construct_as<T: Real, M: Eccentricity>(c: &mut Criterion, id: &str) {
    let gs = [0.0305, 0.045, 0.2, 0.7].map(|g| Ratio::new(T::from_f64(g)).unwrap());
    let mut i = 0;
    c.bench_function(id, |b| {
        b.iter(|| {
            i = (i + 1) & 3;
            black_box(M::shape(black_box(gs[i])))
        })
    });
}

fn benches(c: &mut Criterion) {
    per_step::<f32>(c);
    per_step::<f64>(c);
    each!(
        construct(c),
        [f32, f64],
        [Newton, Table, Linear, HamrockDowson]
    );
    #[cfg(feature = "micromath")]
    {
        use contensou::normal::HertzMicromath;
        let (p, q, estar, hs) = inputs::<f32>();
        let law = Hertz::new::<Newton>(&Curvatures::new(p, q).unwrap(), estar).unwrap();
        patch(
            c,
            "hertz/per_step_micromath_f32",
            HertzMicromath::from(law),
            hs,
        );
        let id = "hertz/shape_hamrock-dowson_micromath_f32";
        construct_as::<f32, contensou::shape::HamrockDowsonMicromath>(c, id);
    }
}

bench_main!(benches, warm_up_ms: 300, measure_ms: 1000, samples: 20);
