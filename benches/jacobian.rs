//! criterion: the wrench's Jacobian ([`Linearize::linearize`]) against the plain wrench on the
//! wrench benches' scene and mixed slip set (benches/wrench_set.rs), fixed and varying
//! geometry, `best` and `simplified`, f32 and f64: the cost ratio of the dual-number form.
use std::hint::black_box;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::rolling::RollingVelocity;
use contensou::friction::{Best, Friction, FrictionLaw, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::jacobian::{LinearLaw, Linearize, State};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;
use criterion::Criterion;

include!("friction_set.rs");
include!("group.rs");
include!("wrench_set.rs");

fn jacobian<T: Real, L: LinearLaw>(c: &mut Criterion) {
    let (curv, contact, varying, h, slips) = wrench_scene::<T, L>();
    let states = slips.map(|slip| State {
        h,
        hdot: T::ZERO,
        slip,
        rolling: RollingVelocity::ZERO,
    });
    let at = varying.at(&curv);
    let name = |what: &str, form: &str| format!("jacobian/{what}/{form}/{}/{}", L::NAME, T::NAME);
    bench_cycling!(c, &name("wrench", "fixed"), SET, |i| contact
        .wrench4(black_box(&states[i])));
    bench_cycling!(c, &name("linearize", "fixed"), SET, |i| contact
        .linearize(black_box(&states[i])));
    bench_cycling!(c, &name("wrench", "table_each_step"), SET, |i| at
        .wrench4(black_box(&states[i])));
    bench_cycling!(c, &name("linearize", "table_each_step"), SET, |i| at
        .linearize(black_box(&states[i])));
}

fn benches(c: &mut Criterion) {
    each!(jacobian(c), [f32, f64], [Best, Simplified]);
}

bench_main!(benches, warm_up_ms: 300, measure_ms: 1000, samples: 30);
