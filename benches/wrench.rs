//! criterion: the full per-step wrench (Hertz + no damping + `simplified` or `best` friction), geometry
//! fixed (`Contact`) and with the eccentricity by table each step (`VaryingContact`), f32 and
//! f64, on the friction stage's mixed input set (the same one as the QEMU stage `wrench`).
use std::hint::black_box;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::{Best, Friction, FrictionLaw, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;
use criterion::Criterion;

include!("friction_set.rs");
include!("group.rs");
include!("wrench_set.rs");

fn wrench<T: Real, L: FrictionLaw>(c: &mut Criterion) {
    let (curv, contact, varying, h, slips) = wrench_scene::<T, L>();
    let name = |form: &str| format!("wrench/{form}/{}/{}", L::NAME, T::NAME);
    bench_cycling!(c, &name("fixed"), SET, |i| contact.wrench(
        black_box(h),
        T::ZERO,
        black_box(slips[i])
    ));
    bench_cycling!(c, &name("table_each_step"), SET, |i| varying.wrench(
        black_box(&curv),
        black_box(h),
        T::ZERO,
        black_box(slips[i])
    ));
}

fn benches(c: &mut Criterion) {
    each!(wrench(c), [f32, f64], [Simplified, Best]);
}

bench_main!(benches, warm_up_ms: 300, measure_ms: 1000, samples: 30);
