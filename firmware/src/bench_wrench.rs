//! Stage `wrench`: the full per-step call (h, ḣ, v_P, ω) → (N, F_x, F_y, T_z), Hertz + no
//! damping + the `simplified` friction law.
//!
//! - `fixed`: `Contact::wrench`, geometry precomputed (the 209 bearing's inner-race contact,
//!   e² = 0.989, solved once by Newton).
//! - `table_each_step`: `VaryingContact::wrench`, the eccentricity and every shape constant from
//!   `shape::Table` each step (includes g = P/Q, Hertz constants and friction constants).
//! - `fixed-best`, `table_each_step-best`: the same with the default law `Best` (per-contact
//!   tables for `fixed`; the per-step flash-table form for `table_each_step`).
//! - `table_each_step-best-worst` (f32): the costliest input of `VaryingContact::wrench` with
//!   `Best` found by a search — every combination of 20 curvature ratios P/Q log-spaced in
//!   [1e-4, 1] (e² from 0 to 0.99998, beyond the table too), 12 slip directions ψ (axes and
//!   irregular angles) and 24 u = v/(aω) (log-spaced in [1e-3, 1e3], points ±1 % around the
//!   ellipse boundary, pure translation, pure spin), each measured alone; the row is that
//!   input's count.
//! - `table_each_step-best-from-bodies` (f32): the per-step geometry too —
//!   `Curvatures::from_bodies_cos_sin` (two bodies' principal curvatures, the relative angle as
//!   cos/sin: no trigonometry, no `f64`) then `VaryingContact::wrench` with `Best`; the mixed
//!   set's slips, the relative angle stepping by 0.1 rad per input.
//!
//! - `dyn-fixed-best`, `dyn-varying-best` (f32): the `best` work through `contensou::dynamic`
//!   (`DynContact::wrench`: the run-time law/form contract that `contact_eval wrench`, the C API
//!   and the Python package share — Hunt–Crossley with c_d = 0, the step's finiteness checks,
//!   the law and form dispatch). The Rust rows for the same work as the C image's
//!   `c-fixed-best` / `c-varying-best` (`capi/examples/firmware/bench.c`).
//!
//! Inputs: the friction stage's mixed set (64 states, u log-uniform in [0.01, 100], ψ uniform),
//! h = 5 µm (a ≈ 1.1 mm), ω = 100 rad/s, v = u·a·ω, ḣ = 0.

use crate::harness::Runner;
use contensou::Real;
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::dynamic::{DynContact, Form, Invalid, Law, Output, Spec, Step};
use contensou::friction::{Best, Friction, FrictionLaw, Simplified, Slip, best};
use contensou::geometry::{Curvatures, Principal, Race};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;

include!("../../benches/friction_set.rs");
include!("../../benches/wrench_set.rs");

const N: usize = SET;
type FixedInput<'a, T, L> = (&'a Contact<T, Hertz<T>, Undamped, L>, T, Slip<T>);

#[inline(never)]
fn fixed<T: Real, L: FrictionLaw>(x: FixedInput<'_, T, L>) -> Wrench<T, L::Branch> {
    x.0.wrench(x.1, T::ZERO, x.2)
}

type VaryingInput<'a, T, L> = (&'a VaryingContact<T, Undamped, L>, &'a Curvatures<T>, T, Slip<T>);

#[inline(never)]
fn table_each_step<T: Real, L: FrictionLaw>(x: VaryingInput<'_, T, L>) -> Wrench<T, L::Branch> {
    x.0.wrench(x.1, x.2, T::ZERO, x.3)
}

fn law<T: Real, L: FrictionLaw>(r: &Runner, suffix: &str) {
    let (curv, contact, varying, h, slips) = wrench_scene::<T, L>();
    let mut name = bench_name("fixed", suffix);
    let fixed_inputs: [FixedInput<'_, T, L>; N] = core::array::from_fn(|i| (&contact, h, slips[i]));
    r.bench("wrench", name.as_str(), T::NAME, &fixed_inputs, fixed::<T, L>);
    name = bench_name("table_each_step", suffix);
    let varying_inputs: [VaryingInput<'_, T, L>; N] =
        core::array::from_fn(|i| (&varying, &curv, h, slips[i]));
    r.bench("wrench", name.as_str(), T::NAME, &varying_inputs, table_each_step::<T, L>);
}

/// `base` + `suffix` in a fixed-capacity string (no allocation on the MCU). The names are
/// this file's literals; one that did not fit would be a wrong qemu.csv key, so it stops the rig.
fn bench_name(base: &str, suffix: &str) -> heapless::String<32> {
    let mut name = heapless::String::new();
    name.push_str(base)
        .and_then(|()| name.push_str(suffix))
        .expect("bench name fits 32 bytes");
    name
}

type BodiesInput<'a> = (
    &'a VaryingContact<f32, Undamped, Best>,
    Principal<f32>,
    Principal<f32>,
    (f32, f32),
    f32,
    Slip<f32>,
);

#[inline(never)]
fn from_bodies_each_step(x: BodiesInput<'_>) -> Option<Wrench<f32, best::Branch>> {
    let c = Curvatures::from_bodies_cos_sin(x.1, x.2, x.3.0, x.3.1).ok()?;
    Some(x.0.wrench(&c, x.4, 0.0, x.5))
}

/// `table_each_step-best-from-bodies`: an inner race (rolling radius 26.15 mm, groove 7.5 mm)
/// under a toroidal body (radii 6.35 mm and 6 mm) turned by 0.1 rad per input (e² ≈ 0.93).
fn best_from_bodies(r: &Runner) {
    let (curv, _, varying, h, slips) = wrench_scene::<f32, Best>();
    let _ = curv;
    let race = Principal { k1: 1.0 / 26.15e-3, k2: -1.0 / 7.5e-3 };
    let body = Principal { k1: 1.0 / 6.35e-3, k2: 1.0 / 6e-3 };
    let inputs: [BodiesInput<'_>; N] = core::array::from_fn(|i| {
        let w = 0.1 * i as f32;
        (&varying, race, body, (libm::cosf(w), libm::sinf(w)), h, slips[i])
    });
    r.bench("wrench", "table_each_step-best-from-bodies", "f32", &inputs, from_bodies_each_step);
}

/// The input search of `table_each_step-best-worst` (see the module docs).
fn best_worst(r: &Runner) {
    type T = f32;
    let estar = Modulus::new(1.142857e11_f32).expect("positive modulus");
    let friction = Friction::<T, Best>::new(0.07, 0.0).expect("valid f");
    let varying = VaryingContact::new(estar, Undamped, friction);
    let h = 5e-6_f32;
    let q = 100.0_f32;
    use core::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    let psis = [0.0, 0.0131, 0.41, FRAC_PI_4, 1.2, FRAC_PI_2, 1.9, 2.6, PI, 3.9, 1.5 * PI, 5.5];
    let mut worst: Option<(VaryingInput<'_, T, Best>, u32)> = None;
    let curvs: [Curvatures<T>; 20] = core::array::from_fn(|i| {
        let g = libm::powf(10.0, -4.0 * i as f32 / 19.0);
        Curvatures::new(g * q, q).expect("positive curvatures")
    });
    for curv in &curvs {
        let patch = varying.wrench(curv, h, 0.0, Slip::default()).patch;
        let (a, m1) = (patch.a, patch.m1);
        let mut inputs: [VaryingInput<'_, T, Best>; 12 * 24] =
            [(&varying, curv, h, Slip::default()); 12 * 24];
        for (k, x) in inputs.iter_mut().enumerate() {
            let psi: f32 = psis[k / 24];
            let j = k % 24;
            let ub = 1.0 / libm::sqrtf(libm::sinf(psi) * libm::sinf(psi) + libm::cosf(psi) * libm::cosf(psi) / m1);
            let (u, omega) = match j {
                0..=15 => (libm::powf(10.0, -3.0 + 6.0 * j as f32 / 15.0), 100.0),
                16 => (ub * 0.99, 100.0),
                17 => (ub * 0.999, 100.0),
                18 => (ub * 1.001, 100.0),
                19 => (ub * 1.01, 100.0),
                20 => (ub * 1.1, 100.0),
                21 => (1.0, 100.0),
                22 => (1.0, 0.0),
                _ => (0.0, 100.0),
            };
            let v = if omega == 0.0 { 0.01 } else { u * a * omega };
            let slip = Slip::new(v * libm::cosf(psi), v * libm::sinf(psi), omega)
                .expect("finite slip");
            x.3 = slip;
        }
        if let Some((x, n)) = r.costliest(&inputs, table_each_step::<T, Best>)
            && worst.is_none_or(|(_, w)| n > w)
        {
            worst = Some((x, n));
        }
    }
    if let Some((x, _)) = worst {
        r.bench("wrench", "table_each_step-best-worst", T::NAME, &[x], table_each_step::<T, Best>);
    }
}

type DynInput<'a> = (&'a DynContact<f32>, Step<f32>);

#[inline(never)]
fn dynamic(x: DynInput<'_>) -> Result<Output<f32>, Invalid> {
    x.0.wrench(&x.1)
}

/// The inputs of `dyn-*`: the contact and each slip at the approach `h`. Out of line: inlined
/// into `run_all`, rustc 1.95.0 (the pinned rig) built this array wrongly for a 3,256-byte
/// `DynContact<f32>` — after an `adds r1, #88` folded into a `stmia` the later stores of the
/// 8-element unrolled loop kept the old base, so element 5's reference was never written
/// (a garbage pointer, an UNALIGNED usage fault under QEMU; `bench-results/qemu-run.txt`
/// stopped after `table_each_step-best-from-bodies`).
#[inline(never)]
fn dyn_inputs<'a>(contact: &'a DynContact<f32>, h: f32, slips: &[Slip<f32>; N]) -> [DynInput<'a>; N] {
    core::array::from_fn(|i| {
        let s = slips[i];
        (contact, Step { h, hdot: 0.0, vx: s.vx(), vy: s.vy(), omega: s.omega() })
    })
}

/// `dyn-fixed-best`, `dyn-varying-best`: the `best` rows' work through `contensou::dynamic`.
fn dynamic_best(r: &Runner) {
    let (curv, _, _, h, slips) = wrench_scene::<f32, Best>();
    let spec = Spec {
        p: curv.p(),
        q: curv.q(),
        estar: 1.142857e11_f64 as f32,
        cd: 0.0,
        f: 0.07_f64 as f32,
        delta: 0.0,
    };
    for (form, name) in [(Form::Fixed, "dyn-fixed-best"), (Form::Varying, "dyn-varying-best")] {
        let contact = DynContact::new(&spec, Law::Best, form).expect("valid contract");
        let inputs = dyn_inputs(&contact, h, &slips);
        r.bench("wrench", name, "f32", &inputs, dynamic);
    }
}

pub fn run(r: &Runner) {
    law::<f32, Simplified>(r, "");
    law::<f64, Simplified>(r, "");
    law::<f32, Best>(r, "-best");
    law::<f64, Best>(r, "-best");
    best_worst(r);
    best_from_bodies(r);
    dynamic_best(r);
}
