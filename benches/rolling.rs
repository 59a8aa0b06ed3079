//! criterion: the rolling laws' dimensional call `RollingContact::wrench` per law × precision
//! on the 64 creep-curve states of the QEMU stage `rolling` (firmware/src/bench_rolling.rs:
//! a = 6 mm, b = 4 mm, N = 80 kN, f = 0.3, G = 80 GPa, ν = 0.28, V = 30 m/s, creepage
//! magnitudes from 1e-3 of saturation to 30× past it, directions of (ξ, η, cφ) on a spiral),
//! `full-slip` (`best` alone) as the peer of the same run; and the per-step rolling wrench
//! (`contact::Rolling`, `table`, the firmware stage's `wrench-axis`, `wrench-skewed`,
//! `wrench-varying` inputs: P = 25, Q = 100 1/m, h = 2 µm, the same creep states at V = 30 m/s
//! along x, at 30°, and a varying contact):
//!
//! ```text
//! cargo bench --bench rolling
//! ```
use std::hint::black_box;
use std::time::Duration;

use contensou::Real;
use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
};
use criterion::Criterion;

/// Creep state `i` of 64: (magnitude, r, z, θ) — magnitudes log-spaced from 1e-3 of
/// saturation to 30× past it, the direction (r cos θ, r sin θ, z) on a golden-angle spiral.
fn creep(i: usize) -> (f64, f64, f64, f64) {
    let mag = 2.5e-3 * 10f64.powf(-3.0 + 4.5 * (i as f64 + 0.5) / 64.0);
    let z = 1.0 - 2.0 * (i as f64 + 0.5) / 64.0;
    (
        mag,
        (1.0 - z * z).sqrt(),
        z,
        2.399_963_229_728_653 * i as f64,
    )
}

fn states<T: Real>() -> Vec<RollingSlip<T>> {
    let c = (6e-3f64 * 4e-3).sqrt();
    (0..64)
        .map(|i| {
            let (mag, r, z, th) = creep(i);
            RollingSlip::from_creepages(
                T::from_f64(mag * r * th.cos()),
                T::from_f64(mag * r * th.sin()),
                T::from_f64(mag * z / c),
                T::from_f64(30.0),
            )
            .unwrap()
        })
        .collect()
}

fn bench<T: Real, L: RollingLaw>(cr: &mut Criterion, name: &str) {
    let el = Elasticity::new(T::from_f64(8e10), T::from_f64(0.28)).unwrap();
    let contact = RollingContact::new(T::from_f64(1.5), el).unwrap();
    let x = T::from_f64;
    let patch = Patch::new(x(6e-3), x(4e-3), x(8e4), x(0.3)).unwrap();
    let set = states::<T>();
    cr.bench_function(&format!("rolling/{name}-{}", T::NAME), |b| {
        b.iter(|| {
            let mut acc = T::ZERO;
            for s in &set {
                let w = contact.wrench::<L>(black_box(&patch), black_box(s));
                acc += w.fx + w.fy + w.mz;
            }
            acc
        })
    });
}

fn wrench_bench<T: Real>(cr: &mut Criterion) {
    use contensou::contact::{Contact, Rolling, VaryingContact};
    use contensou::friction::rolling::RollingVelocity;
    use contensou::friction::{Best, Friction, Slip};
    use contensou::geometry::Curvatures;
    use contensou::normal::{Modulus, Undamped};
    use contensou::shape::Newton;
    let x = T::from_f64;
    let curv = Curvatures::new(x(25.0), x(100.0)).unwrap();
    let estar = Modulus::new(x(1.15e11)).unwrap();
    let fr = Friction::<T, Best>::with_law(x(0.3), T::ZERO).unwrap();
    let el = Elasticity::new(x(8e10), x(0.28)).unwrap();
    let fixed = Rolling::<T, _, Table>::new(
        Contact::hertz::<Newton>(&curv, estar, Undamped, fr).unwrap(),
        el,
    )
    .unwrap();
    let varying =
        Rolling::<T, _, Table>::new(VaryingContact::new(estar, Undamped, fr), el).unwrap();
    let p = fixed
        .wrench(x(2e-6), T::ZERO, Slip::default(), RollingVelocity::ZERO)
        .patch;
    let c = (p.a * p.b).sqrt().to_f64();
    let steps = |theta: f64| -> Vec<(Slip<T>, RollingVelocity<T>)> {
        let (ct, st) = (theta.cos(), theta.sin());
        (0..64)
            .map(|i| {
                let (mag, r, z, th) = creep(i);
                let (vx, vy) = (30.0 * mag * r * th.cos(), 30.0 * mag * r * th.sin());
                (
                    Slip::new(
                        x(ct * vx - st * vy),
                        x(st * vx + ct * vy),
                        x(30.0 * mag * z / c),
                    )
                    .unwrap(),
                    RollingVelocity::new(x(30.0 * ct), x(30.0 * st)).unwrap(),
                )
            })
            .collect()
    };
    for (name, theta) in [("axis", 0.0), ("skewed", std::f64::consts::FRAC_PI_6)] {
        let set = steps(theta);
        cr.bench_function(&format!("rolling/wrench-{name}-{}", T::NAME), |b| {
            b.iter(|| {
                let mut acc = T::ZERO;
                for (s, v) in &set {
                    let w = fixed.wrench(black_box(x(2e-6)), T::ZERO, *s, *v);
                    acc += w.fx + w.fy + w.tz;
                }
                acc
            })
        });
    }
    let set = steps(0.0);
    cr.bench_function(&format!("rolling/wrench-varying-{}", T::NAME), |b| {
        b.iter(|| {
            let mut acc = T::ZERO;
            for (s, v) in &set {
                let w = varying.wrench(black_box(&curv), x(2e-6), T::ZERO, *s, *v);
                acc += w.fx + w.fy + w.tz;
            }
            acc
        })
    });
}

fn main() {
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20)
        .configure_from_args();
    bench::<f32, Table>(&mut c, "table");
    bench::<f64, Table>(&mut c, "table");
    bench::<f32, Blend>(&mut c, "blend");
    bench::<f64, Blend>(&mut c, "blend");
    bench::<f32, FullSlip>(&mut c, "full-slip");
    bench::<f64, FullSlip>(&mut c, "full-slip");
    bench::<f32, FastsimGrid<16, 16>>(&mut c, "fastsim-16");
    bench::<f64, FastsimGrid<16, 16>>(&mut c, "fastsim-16");
    bench::<f32, Fastsim>(&mut c, "fastsim");
    bench::<f64, Fastsim>(&mut c, "fastsim");
    wrench_bench::<f32>(&mut c);
    wrench_bench::<f64>(&mut c);
    c.final_summary();
}
