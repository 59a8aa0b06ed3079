//! criterion: the batch path (`wrench_many`, src/batch/) against the scalar loop over the same
//! rows (`wrench` per row, the seven outputs stored), every law × form × precision, in the
//! same run: group `batch/<law>/<form>/<precision>`, functions `scalar` and `batch`, 4,096
//! rows per iteration (throughput in elements). Forms: `fixed` (`Contact`), `varying`
//! (`VaryingContact`, curvatures per row), `varying_at` (`VaryingContact::wrench_many_at`, one
//! pair for every row: the path of `DynContact`, the C API and Python). The contract's contact (Hunt–Crossley
//! c_d = 0.5 s/m, f = 0.3, δ = 1e-4 m/s), P = 40, Q = 60 1/m (varying: Q per row in 60…120),
//! rows in contact with mixed slips (inside and outside `best`'s ellipse, spin and no spin).
//! `tools/batch-bench.sh` turns the estimates into bench-results/batch.csv and batch.md.
use std::hint::black_box;

use contensou::Real;
use contensou::batch::{self, BatchLaw, BatchReal, CurvatureColumns, Steps, Wrenches};
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::friction::{Best, Coulomb, Ellipsoid, Friction, Pade, Simplified, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, HuntCrossley, Modulus};
use contensou::shape::Newton;
use criterion::{Criterion, Throughput};

const ROWS: usize = 4096;

include!("batch_set.rs");

fn law<T: Real + BatchReal, L: BatchLaw>(c: &mut Criterion) {
    let [p, q, h, hdot, vx, vy, omega] = columns::<T>(ROWS);
    let estar = Modulus::new(T::from_f64(1.15e11)).unwrap();
    let damping = HuntCrossley::new(T::from_f64(0.5)).unwrap();
    let friction = Friction::<T, L>::with_law(T::from_f64(0.3), T::from_f64(1e-4)).unwrap();
    let fixed: Contact<T, Hertz<T>, _, L> = Contact::hertz::<Newton>(
        &Curvatures::ordered(T::from_f64(40.0), T::from_f64(60.0)).unwrap(),
        estar,
        damping,
        friction,
    )
    .unwrap();
    let varying = VaryingContact::new(estar, damping, friction);
    let mut out: [Vec<T>; 7] = core::array::from_fn(|_| vec![T::ZERO; ROWS]);
    let steps = Steps {
        h: &h,
        hdot: &hdot,
        vx: &vx,
        vy: &vy,
        omega: &omega,
    };
    let curvatures = CurvatureColumns { p: &p, q: &q };

    scalar_and_batch::<T, L>(
        c,
        "fixed",
        &mut out,
        |i| {
            let slip = Slip::new(vx[i], vy[i], omega[i]).unwrap();
            row(fixed.wrench(h[i], hdot[i], slip))
        },
        |w| fixed.wrench_many(black_box(&steps), w).unwrap(),
    );
    scalar_and_batch::<T, L>(
        c,
        "varying",
        &mut out,
        |i| {
            let curv = Curvatures::ordered(p[i], q[i]).unwrap();
            let slip = Slip::new(vx[i], vy[i], omega[i]).unwrap();
            row(varying.wrench(&curv, h[i], hdot[i], slip))
        },
        |w| {
            varying
                .wrench_many(black_box(&curvatures), black_box(&steps), w)
                .unwrap()
        },
    );
    // The varying form at one pair of curvatures for every row (`wrench_many_at`: the shape
    // solved once; the path of DynContact, the C API and Python).
    let at = Curvatures::ordered(T::from_f64(40.0), T::from_f64(60.0)).unwrap();
    scalar_and_batch::<T, L>(
        c,
        "varying_at",
        &mut out,
        |i| {
            let slip = Slip::new(vx[i], vy[i], omega[i]).unwrap();
            row(varying.wrench(black_box(&at), h[i], hdot[i], slip))
        },
        |w| {
            varying
                .wrench_many_at(black_box(&at), black_box(&steps), w)
                .unwrap()
        },
    );
}

/// The seven outputs of a wrench, in the batch's column order.
fn row<T: Copy, B>(w: Wrench<T, B>) -> [T; 7] {
    [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
}

/// Group `batch/<law>/<form>/<precision>`: `scalar` stores `wrench(i)`'s seven outputs for
/// every row into `out`, `batch` fills `out` by `many`.
fn scalar_and_batch<T: Real, L: BatchLaw>(
    c: &mut Criterion,
    form: &str,
    out: &mut [Vec<T>; 7],
    mut wrench: impl FnMut(usize) -> [T; 7],
    mut many: impl FnMut(&mut Wrenches<'_, T>),
) {
    let mut g = c.benchmark_group(format!("batch/{}/{form}/{}", L::NAME, T::NAME));
    g.throughput(Throughput::Elements(ROWS as u64));
    g.bench_function("scalar", |b| {
        b.iter(|| {
            for i in 0..ROWS {
                for (c, v) in out.iter_mut().zip(wrench(i)) {
                    c[i] = v;
                }
            }
            black_box(&mut *out);
        })
    });
    g.bench_function("batch", |b| {
        b.iter(|| {
            let [n, fx, fy, tz, a, b_, e2] = &mut *out;
            let mut w = Wrenches {
                n,
                fx,
                fy,
                tz,
                a,
                b: b_,
                e2,
            };
            many(&mut w);
            black_box(&mut *out);
        })
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    eprintln!("batch level: {}", batch::level().name());
    macro_rules! all {
        ($($l:ty),*) => {$(
            law::<f32, $l>(c);
            law::<f64, $l>(c);
        )*};
    }
    all!(Best, Simplified, Pade, Ellipsoid, Coulomb);
}

include!("group.rs");
bench_main!(benches, warm_up_ms: 200, measure_ms: 700, samples: 15);
