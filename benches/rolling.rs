//! criterion: the rolling laws' dimensional call `RollingContact::wrench` per law × precision
//! on the 64 creep-curve states of the QEMU stage `rolling` (firmware/src/bench_rolling.rs:
//! a = 6 mm, b = 4 mm, N = 80 kN, f = 0.3, G = 80 GPa, ν = 0.28, V = 30 m/s, creepage
//! magnitudes from 1e-3 of saturation to 30× past it, directions of (ξ, η, cφ) on a spiral),
//! `full-slip` (`best` alone) as the peer of the same run:
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

fn states<T: Real>() -> Vec<RollingSlip<T>> {
    let c = (6e-3f64 * 4e-3).sqrt();
    (0..64)
        .map(|i| {
            let mag = 2.5e-3 * 10f64.powf(-3.0 + 4.5 * (i as f64 + 0.5) / 64.0);
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / 64.0;
            let r = (1.0 - z * z).sqrt();
            let th = 2.399_963_229_728_653 * i as f64;
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
    c.final_summary();
}
