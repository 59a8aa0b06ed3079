//! criterion: the full per-step wrench (Hertz + no damping + `simplified` or `best` friction), geometry
//! fixed (`Contact`) and with the eccentricity by table each step (`VaryingContact`), f32 and
//! f64, on the friction stage's mixed input set (the same one as the QEMU stage `wrench`).
use std::hint::black_box;
use std::time::Duration;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::{Best, Friction, FrictionLaw, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Modulus, Undamped};
use contensou::shape::Newton;
use criterion::{Criterion, criterion_group, criterion_main};

include!("friction_set.rs");

fn wrench<T: Real, L: FrictionLaw>(c: &mut Criterion) {
    let curv = Curvatures::<T>::ball_race(
        T::from_f64(12.7e-3),
        T::from_f64(6.6e-3),
        T::from_f64(65e-3),
        T::ZERO,
        Race::Inner,
    )
    .unwrap();
    let estar = Modulus::new(T::from_f64(1.142857e11)).unwrap();
    let friction = Friction::<T, L>::new(T::from_f64(0.07), T::ZERO).unwrap();
    let contact = Contact::hertz::<Newton>(&curv, estar, Undamped, friction).unwrap();
    let varying = VaryingContact::new(estar, Undamped, friction);
    let h = T::from_f64(5e-6);
    let a = contact.wrench(h, T::ZERO, Slip::default()).patch.a.to_f64();
    let slips: Vec<Slip<T>> = mixed_set()
        .iter()
        .map(|&(u, psi)| {
            let v = u * a * 100.0;
            Slip::new(
                T::from_f64(v * psi.cos()),
                T::from_f64(v * psi.sin()),
                T::from_f64(100.0),
            )
            .unwrap()
        })
        .collect();
    let mut i = 0;
    c.bench_function(&format!("wrench/fixed/{}/{}", L::NAME, T::NAME), |b| {
        b.iter(|| {
            i = (i + 1) % SET;
            black_box(contact.wrench(black_box(h), T::ZERO, black_box(slips[i])))
        })
    });
    c.bench_function(
        &format!("wrench/table_each_step/{}/{}", L::NAME, T::NAME),
        |b| {
            b.iter(|| {
                i = (i + 1) % SET;
                black_box(varying.wrench(
                    black_box(&curv),
                    black_box(h),
                    T::ZERO,
                    black_box(slips[i]),
                ))
            })
        },
    );
}

fn benches(c: &mut Criterion) {
    wrench::<f32, Simplified>(c);
    wrench::<f64, Simplified>(c);
    wrench::<f32, Best>(c);
    wrench::<f64, Best>(c);
}

criterion_group! {
    name = group;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .sample_size(30);
    targets = benches
}
criterion_main!(group);
