//! Where the C API's extra instructions go (issue 15 item 4): the `wrench` stage's `best` work
//! (`src/bench_wrench.rs`, the 209 bearing's inner race, 64 mixed slips) measured step by
//! step from the generic Rust call to the C call:
//!
//! - `generic-undamped`: `Contact<Hertz, Undamped, Best>::wrench` (= row `wrench,fixed-best`);
//! - `generic-hc0`: the same contact with `HuntCrossley` c_d = 0, the damping the contract uses;
//! - `dynamic`: `contensou::dynamic::DynContact::wrench` (`Step` → `Result<Output, Invalid>`:
//!   finiteness checks, `Slip::new`, the law and form dispatch);
//!
//! each `fixed` and `varying` (`VaryingContact`, shape by table each step). The C call on top
//! (`contensou_contact_wrench_f32`: pointer, alignment and initialisation checks, status and
//! the out-struct) is measured by the C image (`capi/examples/firmware/bench.c`). Prints
//! `BENCH wrench-dispatch <method> f32 insns=N` and the input set's fingerprint (`INPUTS`,
//! which `bench.c` checks); run by hand (see
//! `bench-results/c-firmware.md`), not part of `qemu.csv`.
#![no_std]
#![no_main]

#[path = "../counter.rs"]
mod counter;
#[path = "../harness.rs"]
mod harness;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::dynamic::{DynContact, Form, Invalid, Law, Output, Spec, Step};
use contensou::friction::{Best, Friction, FrictionLaw, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Hertz, HuntCrossley, Modulus, Undamped};
use contensou::shape::Newton;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use harness::Runner;
use panic_semihosting as _;

include!("../../../benches/friction_set.rs");
include!("../../../benches/wrench_set.rs");

type Undamp<'a> = (&'a Contact<f32, Hertz<f32>, Undamped, Best>, f32, Slip<f32>);
type Hc<'a> = (
    &'a Contact<f32, Hertz<f32>, HuntCrossley<f32>, Best>,
    f32,
    Slip<f32>,
);
type VUndamp<'a> = (
    &'a VaryingContact<f32, Undamped, Best>,
    &'a Curvatures<f32>,
    f32,
    Slip<f32>,
);
type VHc<'a> = (
    &'a VaryingContact<f32, HuntCrossley<f32>, Best>,
    &'a Curvatures<f32>,
    f32,
    Slip<f32>,
);
type Dyn<'a> = (&'a DynContact<f32>, Step<f32>);

#[inline(never)]
fn generic_undamped(x: Undamp<'_>) -> Wrench<f32, <Best as FrictionLaw>::Branch> {
    x.0.wrench(x.1, 0.0, x.2)
}

#[inline(never)]
fn generic_hc0(x: Hc<'_>) -> Wrench<f32, <Best as FrictionLaw>::Branch> {
    x.0.wrench(x.1, 0.0, x.2)
}

#[inline(never)]
fn varying_undamped(x: VUndamp<'_>) -> Wrench<f32, <Best as FrictionLaw>::Branch> {
    x.0.wrench(x.1, x.2, 0.0, x.3)
}

#[inline(never)]
fn varying_hc0(x: VHc<'_>) -> Wrench<f32, <Best as FrictionLaw>::Branch> {
    x.0.wrench(x.1, x.2, 0.0, x.3)
}

#[inline(never)]
fn dynamic(x: Dyn<'_>) -> Result<Output<f32>, Invalid> {
    x.0.wrench(&x.1)
}

#[entry]
fn main() -> ! {
    let r = Runner::new();
    let (curv, contact, varying, h, slips) = wrench_scene::<f32, Best>();
    let estar = Modulus::new(1.142857e11_f64 as f32).expect("positive");
    let friction = Friction::<f32, Best>::with_law(0.07_f64 as f32, 0.0).expect("valid f");
    let hc = HuntCrossley::new(0.0).expect("c_d = 0");
    let contact_hc = Contact::hertz::<Newton>(&curv, estar, hc, friction).expect("domain");
    let varying_hc = VaryingContact::new(estar, hc, friction);
    let spec = Spec {
        p: curv.p(),
        q: curv.q(),
        estar: estar.get(),
        cd: 0.0,
        f: 0.07_f64 as f32,
        delta: 0.0,
    };
    let fixed_dyn = DynContact::new(&spec, Law::Best, Form::Fixed).expect("valid");
    let varying_dyn = DynContact::new(&spec, Law::Best, Form::Varying).expect("valid");
    let step = |s: &Slip<f32>| Step {
        h,
        hdot: 0.0,
        vx: s.vx(),
        vy: s.vy(),
        omega: s.omega(),
    };

    // The input set's fingerprint, which the C image (bench.c) requires of its own set.
    let mut hash = 0xcbf2_9ce4_8422_2325_u64;
    for s in &slips {
        for byte in [s.vx(), s.vy()]
            .iter()
            .flat_map(|v| v.to_bits().to_le_bytes())
        {
            hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
    }
    hprintln!("INPUTS wrench rust f32 slips=64 fnv1a64={:016x}", hash);
    // One row of stage `wrench-dispatch` in f32.
    macro_rules! dispatch {
        ($name:literal, $inputs:expr, $f:ident) => {
            r.bench("wrench-dispatch", $name, "f32", &$inputs, $f)
        };
    }
    let a: [Undamp<'_>; SET] = core::array::from_fn(|i| (&contact, h, slips[i]));
    dispatch!("fixed-generic-undamped", a, generic_undamped);
    let b: [Hc<'_>; SET] = core::array::from_fn(|i| (&contact_hc, h, slips[i]));
    dispatch!("fixed-generic-hc0", b, generic_hc0);
    let c: [Dyn<'_>; SET] = core::array::from_fn(|i| (&fixed_dyn, step(&slips[i])));
    dispatch!("fixed-dynamic", c, dynamic);
    let d: [VUndamp<'_>; SET] = core::array::from_fn(|i| (&varying, &curv, h, slips[i]));
    dispatch!("varying-generic-undamped", d, varying_undamped);
    let e: [VHc<'_>; SET] = core::array::from_fn(|i| (&varying_hc, &curv, h, slips[i]));
    dispatch!("varying-generic-hc0", e, varying_hc0);
    let f: [Dyn<'_>; SET] = core::array::from_fn(|i| (&varying_dyn, step(&slips[i])));
    dispatch!("varying-dynamic", f, dynamic);
    debug::exit(debug::EXIT_SUCCESS);
    #[allow(clippy::empty_loop)]
    loop {}
}
