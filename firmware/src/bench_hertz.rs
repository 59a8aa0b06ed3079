//! Stage `hertz`: the normal contact per step, per method × precision.
//!
//! - `per_step`: `Hertz::patch(h)` with the geometry precomputed (a, b, N, p0 from h: one
//!   square root and four multiplies).
//! - `table_each_step`: the eccentricity from g every step — `Table::shape` (c, m₁, K, E, B, D)
//!   then `Hertz::from_shape(&curvatures, …).patch(h)` (a, b, N, p0); includes g = P/Q.
//! - `fitted_each_step`: the eccentricity-free fitted law from g every step, then `patch(h)`.
//! - `volumetric`: the eccentricity-free volumetric law from the curvatures every step, then
//!   `patch(h)`.
//! - `shape_<method>`: the shape alone from g (construction-time methods: newton, linear,
//!   hamrock-dowson; table for comparison).
//!
//! Inputs (the same 16 for every method and precision): g = 10^(−k/4), k = 0..15
//! (1 … 1.8e-4), P = 3 m⁻¹, Q = P/g, E* = 1.14e11 Pa, h = (1 + k)·1e-6 m.

use crate::harness::Runner;
use contensou::Real;
use contensou::geometry::Curvatures;
use contensou::normal::{
    Fitted, Hertz, HertzMicromath, Modulus, NormalLaw, Patch, Volumetric,
};
use contensou::shape::{
    Eccentricity, HamrockDowson, HamrockDowsonMicromath, Linear, Newton, Ratio, Shape, Table,
};

const N: usize = 16;

/// (curvatures, E*, h) for input k.
fn case<T: Real>(k: usize) -> (Curvatures<T>, Modulus<T>, T) {
    let g = libm::pow(10.0, -(k as f64) / 4.0);
    (
        Curvatures::new(T::from_f64(3.0), T::from_f64(3.0 / g)).expect("valid curvatures"),
        Modulus::new(T::from_f64(1.142857e11)).expect("positive modulus"),
        T::from_f64((1 + k) as f64 * 1e-6),
    )
}

#[inline(never)]
fn per_step<T: Real>(x: (Hertz<T>, T)) -> Patch<T> {
    x.0.patch(x.1)
}

#[inline(never)]
fn per_step_micromath<T: Real>(x: (HertzMicromath<T>, T)) -> Patch<T> {
    x.0.patch(x.1)
}

#[inline(never)]
fn table_each_step<T: Real>(x: (Curvatures<T>, Modulus<T>, T)) -> Patch<T> {
    let (curv, estar, h) = x;
    let shape = Table::shape(Ratio::clamped(curv.ratio()));
    Hertz::from_shape(&curv, &shape, estar).patch(h)
}

#[inline(never)]
fn fitted_each_step<T: Real>(x: (Curvatures<T>, Modulus<T>, T)) -> Patch<T> {
    let (curv, estar, h) = x;
    Fitted::clamped(&curv, estar).patch(h)
}

#[inline(never)]
fn volumetric_each_step<T: Real>(x: (Curvatures<T>, Modulus<T>, T)) -> Patch<T> {
    let (curv, estar, h) = x;
    Volumetric::new(&curv, estar).patch(h)
}

#[inline(never)]
fn shape<M: Eccentricity, T: Real>(g: Ratio<T>) -> Shape<T> {
    M::shape(g)
}

fn precision<T: Real>(r: &Runner) {
    let cases: [(Curvatures<T>, Modulus<T>, T); N] = core::array::from_fn(case::<T>);
    let laws: [(Hertz<T>, T); N] = core::array::from_fn(|k| {
        let (curv, estar, h) = cases[k];
        (Hertz::new::<Newton>(&curv, estar).expect("g in the domain"), h)
    });
    let gs: [Ratio<T>; N] =
        core::array::from_fn(|k| Ratio::of(&cases[k].0).expect("g in the domain"));
    r.bench("hertz", "per_step", T::NAME, &laws, per_step::<T>);
    r.bench("hertz", "table_each_step", T::NAME, &cases, table_each_step::<T>);
    r.bench("hertz", "fitted_each_step", T::NAME, &cases, fitted_each_step::<T>);
    r.bench("hertz", "volumetric", T::NAME, &cases, volumetric_each_step::<T>);
    r.bench("hertz", "shape_table", T::NAME, &gs, shape::<Table, T>);
    r.bench("hertz", "shape_linear", T::NAME, &gs, shape::<Linear, T>);
    r.bench("hertz", "shape_hamrock-dowson", T::NAME, &gs, shape::<HamrockDowson, T>);
    r.bench("hertz", "shape_newton", T::NAME, &gs, shape::<Newton, T>);
}

/// The micromath twins (f32 only: their f64 is libm).
fn micromath(r: &Runner) {
    let cases: [(Curvatures<f32>, Modulus<f32>, f32); N] = core::array::from_fn(case::<f32>);
    let laws: [(HertzMicromath<f32>, f32); N] = core::array::from_fn(|k| {
        let (curv, estar, h) = cases[k];
        let law = Hertz::new::<Newton>(&curv, estar).expect("g in the domain");
        (HertzMicromath::from(law), h)
    });
    let gs: [Ratio<f32>; N] =
        core::array::from_fn(|k| Ratio::of(&cases[k].0).expect("g in the domain"));
    r.bench("hertz", "per_step-micromath", "f32", &laws, per_step_micromath::<f32>);
    let name = "shape_hamrock-dowson-micromath";
    r.bench("hertz", name, "f32", &gs, shape::<HamrockDowsonMicromath, f32>);
}

pub fn run(r: &Runner) {
    precision::<f32>(r);
    precision::<f64>(r);
    micromath(r);
}
