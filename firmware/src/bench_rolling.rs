//! Stage `rolling`: the rolling laws' dimensional call `RollingContact::wrench::<L>` (creepages
//! → F_x, F_y, M_z on body B), contact built once (a/b = 1.5, ν = 0.28, G = 80 GPa).
//!
//! Inputs: 64 states along creep curves, a = 6 mm, b = 4 mm, N = 80 kN, f = 0.3, V = 30 m/s;
//! the creepage magnitude log-uniform from 1e-3 of saturation to 30× past it (ξ_sat ≈ 3fN/(Gc²C₁₁)
//! ≈ 2.5e-3), the direction of (ξ, η, cφ) on a fixed spiral over the sphere (pure and combined
//! creepage and spin); methods `table` (the default), `blend`, `fastsim-16` (16 × 16 grid),
//! `fastsim` (32 × 32), `full-slip`.
//!
//! Methods `wrench-*`: the per-step wrench of a rolling contact (`contact::Rolling`, law
//! `table`, Hertz + undamped, P = 25, Q = 100 1/m, E* = 115 GPa, h = 2 µm, f = 0.3): the same
//! 64 creep-curve states in the rolling frame at V = 30 m/s, the rolling velocity along the
//! major axis (`wrench-axis`: creep shape cached), at 30° from it (`wrench-skewed`: the
//! aligned ellipse's creep shape built per call), and a `VaryingContact` at the same
//! curvatures (`wrench-varying`: shape table + creep shape per call).

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, Rolling, VaryingContact, Wrench as ContactWrench};
use contensou::friction::rolling::{
    Blend, Elasticity, Table, Fastsim, FastsimGrid, FullSlip, Patch, RollingContact, RollingLaw,
    RollingSlip, RollingVelocity, Wrench,
};
use contensou::friction::{Best, Friction, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;

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

type Fixed<T> = Rolling<T, Contact<T, Hertz<T>, Undamped, Best>, Table>;
type Varying<T> = Rolling<T, VaryingContact<T, Undamped, Best>, Table>;
type Step<T> = (T, Slip<T>, RollingVelocity<T>);

#[inline(never)]
fn fixed<T: Real>(i: (&Fixed<T>, Step<T>)) -> ContactWrench<T, ()> {
    i.0.wrench(i.1.0, T::ZERO, i.1.1, i.1.2)
}

#[inline(never)]
fn varying<T: Real>(i: (&Varying<T>, &Curvatures<T>, Step<T>)) -> ContactWrench<T, ()> {
    i.0.wrench(i.1, i.2.0, T::ZERO, i.2.1, i.2.2)
}

/// The 64 creep states in the rolling frame at V = 30 m/s along (cos θ, sin θ), turned into
/// the contact frame.
fn steps<T: Real>(c: f64, theta: f64) -> [Step<T>; N] {
    let (ct, st) = (libm::cos(theta), libm::sin(theta));
    core::array::from_fn(|i| {
        let mag = 2.5e-3 * libm::pow(10.0, -3.0 + 4.5 * (i as f64 + 0.5) / N as f64);
        let z = 1.0 - 2.0 * (i as f64 + 0.5) / N as f64;
        let rr = libm::sqrt(1.0 - z * z);
        let th = 2.399_963_229_728_653 * i as f64;
        let (xi, eta, cphi) = (rr * libm::cos(th), rr * libm::sin(th), z);
        let (vx, vy) = (30.0 * mag * xi, 30.0 * mag * eta);
        let slip = Slip::new(
            T::from_f64(ct * vx - st * vy),
            T::from_f64(st * vx + ct * vy),
            T::from_f64(30.0 * mag * cphi / c),
        )
        .expect("finite slip");
        let v = RollingVelocity::new(T::from_f64(30.0 * ct), T::from_f64(30.0 * st))
            .expect("finite velocity");
        (T::from_f64(2e-6), slip, v)
    })
}

fn wrenches<T: Real>(r: &Runner) {
    let x = T::from_f64;
    let curv = Curvatures::new(x(25.0), x(100.0)).expect("valid curvatures");
    let estar = Modulus::new(x(1.15e11)).expect("valid modulus");
    let friction = Friction::<T, Best>::with_law(x(0.3), T::ZERO).expect("valid friction");
    let el = Elasticity::new(x(8e10), x(0.28)).expect("valid elasticity");
    let contact = Contact::hertz::<Newton>(&curv, estar, Undamped, friction).expect("valid");
    let rolling: Fixed<T> = Rolling::new(contact, el).expect("valid rolling contact");
    let moving: Varying<T> =
        Rolling::new(VaryingContact::new(estar, Undamped, friction), el).expect("valid");
    let p = rolling.wrench(x(2e-6), T::ZERO, Slip::default(), RollingVelocity::ZERO).patch;
    let c = libm::sqrt(p.a.to_f64() * p.b.to_f64());
    let axis = steps::<T>(c, 0.0).map(|s| (&rolling, s));
    r.bench("rolling", "wrench-axis", T::NAME, &axis, fixed::<T>);
    let skewed = steps::<T>(c, core::f64::consts::FRAC_PI_6).map(|s| (&rolling, s));
    r.bench("rolling", "wrench-skewed", T::NAME, &skewed, fixed::<T>);
    let vary = steps::<T>(c, 0.0).map(|s| (&moving, &curv, s));
    r.bench("rolling", "wrench-varying", T::NAME, &vary, varying::<T>);
}

pub fn run(r: &Runner) {
    precision::<f32>(r, true);
    precision::<f64>(r, false);
    wrenches::<f32>(r);
}
