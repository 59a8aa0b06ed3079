//! Benchmark firmware, stage `scene` (second binary of rig B, run after the main one by
//! `tools/qemu-bench.sh`): one row per `contensou::select` configuration (method = its key,
//! e.g. `sphere-plane-spin-coarse`, in f32 and f64). A binary of its own, so that the main
//! firmware's code — and so its counts — stay exactly as they were.
//!
//! Each row is one per-step call `wrench(h, 0, slip)` of the contact type the declaration
//! resolves to, over the `wrench` stage's 64 mixed slips (v = u·a·ω, ω = 100 rad/s; ω = 0 and
//! the same speeds for `nospin`), ḣ = 0, f = 0.1, E* = 1.142857e11 Pa: sphere on plane = a
//! 6.35 mm ball, h = 1 µm; ball–race = the 209 bearing's inner race (e² = 0.989), h = 5 µm;
//! varying = curvatures P = 3 m⁻¹, Q = P/g with g cycling over 16 values in [0.0275, 1]
//! (e² ≤ 0.99), h = 5 µm.
//!
//! This firmware enables contensou's `micromath` feature, so an `f32` declaration whose budget
//! admits a micromath twin resolves to it: those rows get keys ending in `-micromath`
//! (`*-rough-micromath`, `varying-spin-exact-micromath`). The libm row of a declaration that
//! resolves to a twin here (`varying-spin-exact`, `f32`) is built from the types it resolves to
//! without the feature.
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use contensou::Real;
use contensou::contact::{VaryingContact, Wrench};
use contensou::friction::{Best, Friction, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Modulus, Undamped};
use contensou::select::*;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use harness::Runner;
use panic_semihosting as _;

include!("../../../benches/friction_set.rs");

/// Every scene configuration: `$m!(method key, patch, geometry, motion, budget)`.
macro_rules! scene_configs {
    ($m:ident) => {
        $m!("sphere-plane-spin-coarse", Circular, Fixed, Spin, Coarse);
        $m!("sphere-plane-spin-exact", Circular, Fixed, Spin, ExactGrade);
        $m!("sphere-plane-nospin", Circular, Fixed, NoSpin, ExactGrade);
        $m!("ball-race-spin-coarse", Elliptic, Fixed, Spin, Coarse);
        $m!("ball-race-spin-exact", Elliptic, Fixed, Spin, ExactGrade);
        $m!("ball-race-nospin", Elliptic, Fixed, NoSpin, ExactGrade);
        $m!("varying-spin-coarse", Elliptic, Varying, Spin, Coarse);
        $m!("varying-spin-exact", Elliptic, Varying, Spin, ExactGrade);
        $m!("varying-nospin", Elliptic, Varying, NoSpin, ExactGrade);
    };
}

/// The `f32` configurations that resolve to a micromath twin (feature `micromath`).
macro_rules! micromath_configs {
    ($m:ident) => {
        $m!(
            "sphere-plane-spin-rough-micromath",
            Circular,
            Fixed,
            Spin,
            Rough
        );
        $m!(
            "sphere-plane-nospin-rough-micromath",
            Circular,
            Fixed,
            NoSpin,
            Rough
        );
        $m!(
            "ball-race-spin-rough-micromath",
            Elliptic,
            Fixed,
            Spin,
            Rough
        );
        $m!(
            "ball-race-nospin-rough-micromath",
            Elliptic,
            Fixed,
            NoSpin,
            Rough
        );
        $m!(
            "varying-spin-exact-micromath",
            Elliptic,
            Varying,
            Spin,
            ExactGrade
        );
    };
}

/// The ratios g = P/Q the varying scene cycles through.
const VARYING_G: [f64; 16] = [
    1.0, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.25, 0.2, 0.15, 0.1, 0.07, 0.04, 0.0275,
];

type SceneInput<'a, C, T> = (&'a C, &'a Curvatures<T>, T, Slip<T>);

#[inline(never)]
fn scene_step<T: Real, C: Step<T>>(x: SceneInput<'_, C, T>) -> Wrench<T, C::Branch> {
    x.0.step(x.1, x.2, T::ZERO, x.3)
}

/// One row: the contact `S` resolves to, over the 64 mixed slips (see the module docs).
fn scene<S: Select>(r: &Runner, method: &str) {
    let t = <S::Real as Real>::from_f64;
    let contact = S::build(
        &S::geometry(&curvatures::<S::Real>(S::GEOMETRY, 0)),
        Modulus::new(t(1.142857e11)).expect("positive modulus"),
        Undamped,
        Friction::with_law(t(0.1), t(0.0)).expect("valid f"),
    )
    .expect("valid scene");
    scene_row(r, method, S::GEOMETRY, S::SPINS, &contact);
}

/// The `i`-th curvatures of geometry kind `kind`.
fn curvatures<T: Real>(kind: &str, i: usize) -> Curvatures<T> {
    let t = T::from_f64;
    match kind {
        "sphere-plane" => Curvatures::sphere_plane(t(6.35e-3)),
        "ball-race" => Curvatures::ball_race(t(12.7e-3), t(6.6e-3), t(65e-3), t(0.0), Race::Inner),
        _ => Curvatures::new(t(3.0), t(3.0 / VARYING_G[i % VARYING_G.len()])),
    }
    .expect("valid curvatures")
}

/// One row for a built contact of geometry kind `kind`.
fn scene_row<T: Real, C: Step<T>>(r: &Runner, method: &str, kind: &str, spins: bool, contact: &C) {
    let t = T::from_f64;
    let curvs: [Curvatures<T>; SET] = core::array::from_fn(|i| curvatures(kind, i));
    let h = t(if kind == "sphere-plane" { 1e-6 } else { 5e-6 });
    let pairs = mixed_set();
    let omega = if spins { 100.0 } else { 0.0 };
    let inputs: [SceneInput<'_, C, T>; SET] = core::array::from_fn(|i| {
        let (u, psi) = pairs[i];
        let a = contact
            .step(&curvs[i], h, T::ZERO, Slip::default())
            .patch
            .a
            .to_f64();
        let v = u * a * 100.0;
        let slip = Slip::new(t(v * libm::cos(psi)), t(v * libm::sin(psi)), t(omega));
        (contact, &curvs[i], h, slip.expect("finite slip"))
    });
    r.bench("scene", method, T::NAME, &inputs, scene_step::<T, C>);
}

fn scenes<T: Precision>(r: &Runner) {
    macro_rules! row {
        ("varying-spin-exact", $p:ident, $g:ident, $s:ident, $b:ident) => {
            // Without the feature `Scene<Elliptic, Varying, Spin, ExactGrade, T>` is this.
            let contact: VaryingContact<T, Undamped, Best> = VaryingContact::new(
                Modulus::new(T::from_f64(1.142857e11)).expect("positive modulus"),
                Undamped,
                Friction::new(T::from_f64(0.1), T::ZERO).expect("valid f"),
            );
            scene_row(r, "varying-spin-exact", "varying", true, &contact);
        };
        ($key:literal, $p:ident, $g:ident, $s:ident, $b:ident) => {
            scene::<Scene<$p, $g, $s, $b, T>>(r, $key);
        };
    }
    scene_configs!(row);
}

fn micromath_scenes(r: &Runner) {
    macro_rules! row {
        ($key:literal, $p:ident, $g:ident, $s:ident, $b:ident) => {
            scene::<Scene<$p, $g, $s, $b, f32>>(r, $key);
        };
    }
    micromath_configs!(row);
}

#[entry]
fn main() -> ! {
    let runner = Runner::new();
    scenes::<f32>(&runner);
    scenes::<f64>(&runner);
    micromath_scenes(&runner);
    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
