//! Stage `rolling`: the rolling laws' dimensional call `RollingContact::wrench::<L>` (creepages
//! → F_x, F_y, M_z on body B), contact built once (a/b = 1.5, ν = 0.28, G = 80 GPa).
//!
//! Inputs: 64 states along creep curves, a = 6 mm, b = 4 mm, N = 80 kN, f = 0.3, V = 30 m/s;
//! the creepage magnitude log-uniform from 1e-3 of saturation to 30× past it (ξ_sat ≈ 3fN/(Gc²C₁₁)
//! ≈ 2.5e-3), the direction of (ξ, η, cφ) on a fixed spiral over the sphere (pure and combined
//! creepage and spin); methods `table` (the default), `blend`, `fastsim-16` (16 × 16 grid),
//! `fastsim` (32 × 32), `full-slip`.

use crate::harness::Runner;
use contensou::Real;
use contensou::friction::rolling::{
    Blend, Elasticity, Table, Fastsim, FastsimGrid, FullSlip, Patch, RollingContact, RollingLaw,
    RollingSlip, Wrench,
};

const N: usize = 64;

type Input<'a, T> = (&'a RollingContact<T>, Patch<T>, RollingSlip<T>);

#[inline(never)]
fn wrench<T: Real, L: RollingLaw>(i: Input<'_, T>) -> Wrench<T> {
    i.0.wrench::<L>(&i.1, &i.2)
}

fn law<T: Real, L: RollingLaw>(r: &Runner, name: &str, contact: &RollingContact<T>) {
    let patch = Patch::new(
        T::from_f64(6e-3),
        T::from_f64(4e-3),
        T::from_f64(8e4),
        T::from_f64(0.3),
    )
    .expect("valid patch");
    let c = libm::sqrt(6e-3 * 4e-3);
    let inputs: [Input<'_, T>; N] = core::array::from_fn(|i| {
        let mag = 2.5e-3 * libm::pow(10.0, -3.0 + 4.5 * (i as f64 + 0.5) / N as f64);
        // golden-angle spiral over the sphere of directions (ξ, η, cφ)
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / N as f64;
        let rr = libm::sqrt(1.0 - z * z);
        let th = 2.399_963_229_728_653 * i as f64;
        let (xi, eta, cphi) = (rr * libm::cos(th), rr * libm::sin(th), z);
        let slip = RollingSlip::from_creepages(
            T::from_f64(mag * xi),
            T::from_f64(mag * eta),
            T::from_f64(mag * cphi / c),
            T::from_f64(30.0),
        )
        .expect("finite input");
        (contact, patch, slip)
    });
    r.bench("rolling", name, T::NAME, &inputs, wrench::<T, L>);
}

fn precision<T: Real>(r: &Runner, all: bool) {
    let el = Elasticity::new(T::from_f64(8e10), T::from_f64(0.28)).expect("valid elasticity");
    let contact = RollingContact::new(T::from_f64(1.5), el).expect("valid contact");
    law::<T, Table>(r, "table", &contact);
    law::<T, Blend>(r, "blend", &contact);
    law::<T, FullSlip>(r, "full-slip", &contact);
    if all {
        law::<T, FastsimGrid<16, 16>>(r, "fastsim-16", &contact);
        law::<T, Fastsim>(r, "fastsim", &contact);
    }
}

pub fn run(r: &Runner) {
    precision::<f32>(r, true);
    precision::<f64>(r, false);
}
