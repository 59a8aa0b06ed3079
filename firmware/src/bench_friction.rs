//! Stage `friction`: the dimensionless friction core per law × precision, patch constants given
//! (`FrictionLaw::traction(&Constants, &SlipState)`), plus the full dimensional call
//! (`Friction::tangential`: normalisation + core + scaling by fN, fNa) for `simplified`, and
//! `Constants::from_integrals` (method `constants-from-integrals`).
//!
//! Inputs (the same mixed set as the host bench `benches/friction.rs`): 64 states with u
//! log-uniform in [0.01, 100], ψ uniform in [0, 2π), ω > 0, δ = 0, e² = 0.5.

use crate::harness::Runner;
use contensou::Real;
use contensou::elliptic::{Agm, Integrals, Method, Parameter};
use contensou::friction::*;

include!("../../benches/friction_set.rs");

const N: usize = SET;

#[inline(never)]
fn core<T: Real, L: FrictionLaw>(input: (&Constants<T>, SlipState<T>)) -> Traction<T> {
    L::traction(input.0, &input.1).0
}

/// One per-step call's inputs: the law with f and δ, the patch constants, a, N, the slip.
type StepInput<'a, T, L> = (&'a Friction<T, L>, &'a Constants<T>, T, T, Slip<T>);

#[inline(never)]
fn dimensional<T: Real, L: FrictionLaw>(input: StepInput<'_, T, L>) -> Tangential<T, L::Branch> {
    input.0.tangential(input.1, input.2, input.3, input.4)
}

fn law<T: Real, L: FrictionLaw>(r: &Runner) {
    let k = Constants::<T>::from_parameter(
        Parameter::new(T::from_f64(0.5)).expect("e² = 0.5 is inside the domain"),
    );
    let pairs = mixed_set();
    let states: [(&Constants<T>, SlipState<T>); N] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).expect("finite input");
        (&k, s)
    });
    r.bench("friction", L::NAME, T::NAME, &states, core::<T, L>);
}

fn full<T: Real, L: FrictionLaw>(r: &Runner) {
    let k = Constants::<T>::from_parameter(
        Parameter::new(T::from_f64(0.5)).expect("e² = 0.5 is inside the domain"),
    );
    let f = Friction::<T, L>::with_law(T::from_f64(0.3), T::ZERO).expect("valid friction");
    let pairs = mixed_set();
    // ω = 100 rad/s, a = 50 µm: v = u·aω.
    let slips: [StepInput<'_, T, L>; N] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let v = u * 50e-6 * 100.0;
        let slip = Slip::new(
            T::from_f64(v * libm::cos(psi)),
            T::from_f64(v * libm::sin(psi)),
            T::from_f64(100.0),
        )
        .expect("finite input");
        // a = 50 µm, N = 2 N: a typical small Hertz patch.
        (&f, &k, T::from_f64(50e-6), T::from_f64(2.0), slip)
    });
    let name = if L::NAME == "simplified" { "simplified-dimensional" } else { L::NAME };
    r.bench("friction", name, T::NAME, &slips, dimensional::<T, L>);
}

#[inline(never)]
fn constants<T: Real>(input: (Parameter<T>, Integrals<T>)) -> Constants<T> {
    Constants::from_integrals(input.0, &input.1)
}

/// Building the patch constants from given integrals (the per-step cost when the eccentricity
/// changes every step), over 16 parameters m = i/16.
fn from_integrals<T: Real>(r: &Runner) {
    let inputs: [(Parameter<T>, Integrals<T>); 16] = core::array::from_fn(|i| {
        let p = Parameter::new(T::from_f64(i as f64 / 16.0)).expect("m inside the domain");
        (p, Agm::integrals(p))
    });
    r.bench("friction", "constants-from-integrals", T::NAME, &inputs, constants::<T>);
}

#[inline(never)]
fn best_core<T: Real>(input: (&BestContact<T>, SlipState<T>)) -> Traction<T> {
    input.0.traction(&input.1).0
}

/// One dimensional per-step call of `Friction::<T, Best>::tangential_prepared`.
type BestStep<'a, T> = (&'a BestContact<T>, &'a Friction<T, Best>, T, T, Slip<T>);

#[inline(never)]
fn best_dimensional<T: Real>(input: BestStep<'_, T>) -> Tangential<T, best::Branch> {
    input.1.tangential_prepared(input.0, input.2, input.3, input.4)
}

#[inline(never)]
fn best_new<T: Real>(k: &Constants<T>) -> BestContact<T> {
    BestContact::new(k)
}

/// `best` per contact ([`BestContact`], method `best`), its once-per-contact construction
/// (`best-contact-new`), and the per-call form [`Best`] for e² changing every call
/// (`best-varying`).
fn best<T: Real>(r: &Runner) {
    let k = Constants::<T>::from_parameter(
        Parameter::new(T::from_f64(0.5)).expect("e² = 0.5 is inside the domain"),
    );
    let b = BestContact::new(&k);
    let pairs = mixed_set();
    let states: [(&BestContact<T>, SlipState<T>); N] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).expect("finite input");
        (&b, s)
    });
    r.bench("friction", "best", T::NAME, &states, best_core::<T>);
    // The thinnest fitted patch, e² = 0.99: the outside path with b_c² from the
    // cancellation-free quotient (u < e) is taken there.
    let k99 = Constants::<T>::from_parameter(
        Parameter::new(T::from_f64(0.99)).expect("e² = 0.99 is inside the domain"),
    );
    let b99 = BestContact::new(&k99);
    let thin: [(&BestContact<T>, SlipState<T>); N] = core::array::from_fn(|i| (&b99, states[i].1));
    r.bench("friction", "best-e2-0.99", T::NAME, &thin, best_core::<T>);
    let states: [(&Constants<T>, SlipState<T>); N] = core::array::from_fn(|i| (&k, states[i].1));
    r.bench("friction", "best-varying", T::NAME, &states, core::<T, Best>);
    r.bench("friction", "best-contact-new", T::NAME, &[&k], best_new::<T>);
    let f = Friction::<T, Best>::with_law(T::from_f64(0.3), T::ZERO).expect("valid friction");
    // The same slips as `full`: ω = 100 rad/s, a = 50 µm, N = 2 N, v = u·aω.
    let steps: [BestStep<'_, T>; N] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let (s, c) = (libm::sin(psi), libm::cos(psi));
        let v = T::from_f64(u * 50e-6 * 100.0);
        let slip = Slip::new(v * T::from_f64(c), v * T::from_f64(s), T::from_f64(100.0));
        (&b, &f, T::from_f64(50e-6), T::from_f64(2.0), slip.expect("finite input"))
    });
    r.bench("friction", "best-dimensional", T::NAME, &steps, best_dimensional::<T>);
}

/// `$f::<f32[, $L]>(r)` then `$f::<f64[, $L]>(r)` for each bench function `$f`.
macro_rules! f32_f64 {
    ($r:ident: $($f:ident$(<$L:ty>)?),* $(,)?) => {$(
        $f::<f32 $(, $L)?>($r);
        $f::<f64 $(, $L)?>($r);
    )*};
}

/// One line per law (each measures f32 and f64).
pub fn run(r: &Runner) {
    // `f32` then `f64` of each (the law after the precision); `Exact` is the reference path
    // (adaptive quadrature: data-dependent, not for the hot path)
    f32_f64!(
        r: law<Simplified>,
        law<Pade>,
        law<Ellipsoid>,
        law<Coulomb>,
        law<Exact>,
        full<Simplified>,
        from_integrals,
        best
    );
    // micromath twins: f32 only (their f64 is libm). `best-micromath` is the per-call form,
    // to compare with `best-varying`.
    law::<f32, SimplifiedMicromath>(r);
    law::<f32, EllipsoidMicromath>(r);
    law::<f32, CoulombMicromath>(r);
    law::<f32, BestMicromath>(r);
}
