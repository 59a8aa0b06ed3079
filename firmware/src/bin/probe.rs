//! Flash size probe: links exactly one benchmark key's code into an otherwise empty firmware.
//!
//! The key `stage,method,precision` (as in `bench-results/qemu.csv`) is chosen at build time:
//! `CONTENSOU_PROBE=wrench,fixed,f32 cargo build --release --bin probe`; unset = `baseline`
//! (nothing but the runtime). Only that key's branch survives (a `const` condition), so
//! `.text + .rodata` of this binary minus the baseline's is what the key adds to a firmware:
//! the call and everything it reaches (library code, soft-float and libm routines, tables).
//! An unknown key fails to compile. `tools/flash-bench.sh` builds one probe per key.
//!
//! Inputs go through `black_box`, built by the cheapest constructor of their type (e.g.
//! `Constants::circle()`, `Parameter::new`, `Hertz::circular`): the figure is the call's code,
//! not an input generator's. Where the benchmarked call takes a per-contact form that only a
//! constructor can make, the constructor is included (rows with `BestContact`: `best`,
//! `best-e2-0.99`, `best-dimensional`, `fixed-best` include `BestContact::new`). Scene rows
//! (`scene,<configuration>`) are whole configurations: `Select::build` from validated
//! curvatures plus one `wrench` step. Nothing panics on the probed paths (invalid input
//! halts), so no panic machinery is linked. Not meant to be run.
#![no_std]
#![no_main]

use core::hint::black_box as bb;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::elliptic::{
    Agm, Integrals, Method, Parameter, Table as EllTable, Theta, ThetaMicromath,
};
use contensou::friction::*;
use contensou::geometry::{Curvatures, Principal};
use contensou::jacobian::{Linearize, State};
use contensou::math::{Backend, Micromath};
use contensou::normal::{Fitted, Hertz, HertzMicromath, Modulus, NormalLaw, Undamped, Volumetric};
use contensou::scenes::integrate::{rk4, rk4_step};
use contensou::scenes::rattleback::Rattleback;
use contensou::scenes::tippe_top::{Params, TippeTop};
use contensou::select::*;
use contensou::shape::{
    Eccentricity, HamrockDowson, HamrockDowsonMicromath, Linear, Newton, Ratio, Table,
};
use contensou::step::{Free, InverseMass, TimeStep, step_wrenches};
use cortex_m_rt::entry;
use panic_semihosting as _;

/// The key this probe was built for.
const KEY: &str = match option_env!("CONTENSOU_PROBE") {
    Some(k) => k,
    None => "baseline",
};

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Halts on an invalid probe input (never taken; keeps panics out of the binary).
fn ok<T, E>(r: Result<T, E>) -> T {
    match r {
        Ok(v) => v,
        Err(_) => halt(),
    }
}

fn halt() -> ! {
    loop {
        cortex_m::asm::wfi();
    }
}

fn t<T: Real>(x: f32) -> T {
    bb(T::from_f64(f64::from(x)))
}

fn param<T: Real>() -> Parameter<T> {
    ok(Parameter::new(t(0.5)))
}

fn circle<T: Real>() -> Constants<T> {
    bb(Constants::circle())
}

fn state<T: Real>() -> SlipState<T> {
    ok(SlipState::new(t(0.3), t(0.2), t(1.0), T::ZERO))
}

fn slip<T: Real>() -> Slip<T> {
    ok(Slip::new(t(1e-3), t(2e-3), t(100.0)))
}

fn estar<T: Real>() -> Modulus<T> {
    ok(Modulus::new(t(1.142857e11)))
}

fn curvatures<T: Real>() -> Curvatures<T> {
    ok(Curvatures::new(t(3.0), t(30.0)))
}

fn friction<T: Real, L: FrictionLaw>() -> Friction<T, L> {
    ok(Friction::with_law(t(0.1), t(0.0)))
}

fn hertz<T: Real>() -> Hertz<T> {
    bb(Hertz::circular(t(3.0), estar()))
}

fn best<T: Real>() -> BestContact<T> {
    BestContact::new(&circle())
}

/// The probed bodies, one per precision-generic row.
fn elliptic<T: Real, M: Method>() {
    bb(M::integrals(param::<T>()));
}
fn per_step<T: Real>() {
    bb(hertz::<T>().patch(t(1e-6)));
}
fn table_each_step<T: Real>() {
    let c = curvatures::<T>();
    bb(Hertz::from_shape(&c, &Table::shape(Ratio::clamped(c.ratio())), estar()).patch(t(1e-6)));
}
fn fitted_each_step<T: Real>() {
    bb(Fitted::clamped(&curvatures::<T>(), estar()).patch(t(1e-6)));
}
fn volumetric_each_step<T: Real>() {
    bb(Volumetric::new(&curvatures::<T>(), estar()).patch(t(1e-6)));
}
fn shape<T: Real, M: Eccentricity>() {
    bb(M::shape(ok(Ratio::<T>::new(t(0.1)))));
}
fn core<T: Real, L: FrictionLaw>() {
    bb(L::traction(&circle::<T>(), &state()));
}
fn dimensional<T: Real, L: FrictionLaw>() {
    bb(friction::<T, L>().tangential(&circle(), t(50e-6), t(2.0), slip()));
}
fn from_integrals<T: Real>() {
    let i = Integrals {
        k: t(1.8),
        e: t(1.3),
        b: t(0.8),
        d: t(1.0),
    };
    bb(Constants::from_integrals(param::<T>(), &bb(i)));
}
fn best_core<T: Real>() {
    bb(best::<T>().traction(&state()));
}
fn best_new<T: Real>() {
    bb(BestContact::<T>::new(&circle()));
}
fn best_dimensional<T: Real>() {
    bb(friction::<T, Best>().tangential_prepared(&best(), t(50e-6), t(2.0), slip()));
}
fn fixed<T: Real, L: FrictionLaw>() {
    let c = bb(Contact::from_parts(
        hertz::<T>(),
        Undamped,
        friction::<T, L>(),
        circle(),
    ));
    bb(c.wrench(t(1e-6), T::ZERO, slip()));
}
/// The step-aware wrench (stage `step`): K contacts sharing bodies (`fixed-best`: K = 1,
/// `two-contacts-best`: K = 2), W validated by `InverseMass::new`, the free motion coasting.
fn step_aware<const K: usize>() {
    let c = bb(Contact::from_parts(
        hertz::<f32>(),
        Undamped,
        friction::<f32, Best>(),
        circle(),
    ));
    let dt = ok(TimeStep::new(t::<f32>(1e-3)));
    let mut blocks = [[[[0.0_f32; 4]; 4]; K]; K];
    for (i, row) in blocks.iter_mut().enumerate() {
        for (a, line) in row[i].iter_mut().enumerate() {
            line[a] = t(100.0);
        }
    }
    let w = ok(InverseMass::<f32, K>::new(bb(blocks)));
    let s = State {
        h: t(1e-6),
        hdot: 0.0,
        slip: slip(),
        rolling: rolling::RollingVelocity::ZERO,
    };
    let free = Free::coasting(dt, &s);
    let contacts: [&dyn Linearize<f32>; K] = [&c; K];
    bb(step_wrenches(contacts, dt, &w, &[s; K], &[free; K]));
}
fn varying<T: Real, L: FrictionLaw>() {
    let c = bb(VaryingContact::new(
        estar::<T>(),
        Undamped,
        friction::<T, L>(),
    ));
    bb(c.wrench(&curvatures(), t(1e-6), T::ZERO, slip()));
}
/// The per-step geometry (two bodies' curvatures, the angle as cos/sin) and the varying
/// wrench with `Best`, all `f32`: tools/flash-bench.sh fails if this links `f64` soft float.
fn varying_from_bodies() {
    let c = bb(VaryingContact::new(
        estar::<f32>(),
        Undamped,
        friction::<f32, Best>(),
    ));
    let (a, b) = bb((
        Principal {
            k1: t(38.2),
            k2: t(-151.5),
        },
        Principal {
            k1: t(157.5),
            k2: t(125.0),
        },
    ));
    if let Ok(curv) = Curvatures::from_bodies_cos_sin(a, b, bb(t(0.8)), bb(t(0.6))) {
        bb(c.wrench(&curv, t(1e-6), 0.0, slip()));
    }
}

fn rattleback_step() {
    let celt: Rattleback<f32, Best> = ok(Rattleback::new(
        &contensou::scenes::rattleback::Params::kane_levinson(),
        friction(),
    ));
    let y = celt.initial_state(t(0.0087), t(-2.0));
    bb(rk4_step(&celt, 0.0, &y, t(1e-4)));
}
fn tippe_top(steps: usize) {
    let top: TippeTop<f32, Simplified> = ok(TippeTop::new(&Params::paper(), friction()));
    let y = top.initial_state(t(0.1), t(180.0));
    if steps == 1 {
        bb(rk4_step(&top, 0.0, &y, t(1e-5)));
    } else {
        bb(rk4(&top, 0.0, y, t(1e-5), steps, |_, _, _| {}));
    }
}
/// As [`scene`] for `Scene<Elliptic, Varying, _, _, T>` resolving to law `L` (used where the
/// declaration resolves to a micromath twin here: this firmware enables the feature).
fn scene_varying<T: Real, L: FrictionLaw>() {
    let curv = curvatures::<T>();
    bb(curv);
    let c = VaryingContact::new(estar(), Undamped, friction::<T, L>());
    bb(c.step(&curv, t(1e-6), T::ZERO, slip()));
}
fn scene<S: Select>() {
    let curv = if S::GEOMETRY == "sphere-plane" {
        ok(Curvatures::new(t(78.7), t(78.7)))
    } else {
        curvatures()
    };
    let c = ok(S::build(
        &S::geometry(&bb(curv)),
        estar(),
        Undamped,
        friction(),
    ));
    bb(c.step(&curv, t(1e-6), S::Real::ZERO, slip()));
}

/// `contensou::frame` per step (stage `frame`): the frame from normal, tangent and major axis
/// (cos, sin), then the slip and ḣ from world velocities, or the world load of a wrench.
fn frame_slip<T: Real>() {
    use contensou::frame::{ContactFrame, Frame, MajorAxis};
    let frame = Frame::new(
        bb([t::<T>(0.0), t(0.0), t(1.0)]),
        bb([t(1.0), t(0.0), t(0.0)]),
        MajorAxis::from_cos_sin(bb(t(0.8)), bb(t(0.6))),
    );
    let (v, w) = bb((
        [t::<T>(0.01), t(0.02), t(-0.001)],
        [t::<T>(0.0), t(1.0), t(30.0)],
    ));
    let _ = bb((frame.slip(v, w), frame.approach_rate(v)));
}

fn frame_load<T: Real>() {
    use contensou::frame::{ContactFrame, Frame, MajorAxis};
    let frame = Frame::new(
        bb([t::<T>(0.0), t(0.0), t(1.0)]),
        bb([t(1.0), t(0.0), t(0.0)]),
        MajorAxis::from_cos_sin(bb(t(0.8)), bb(t(0.6))),
    );
    let c = ok(Contact::circular(
        &ok(Curvatures::sphere_plane(t::<T>(0.01))),
        estar::<T>(),
        Undamped,
        friction::<T, Best>(),
    ));
    let w = c.wrench(bb(t(1e-6)), t(0.0), slip());
    bb(frame.on_b(&w, bb([t(0.0), t(0.0), t(-0.01)])));
}

/// The `best` wrench through `contensou::dynamic` (rows `wrench,dyn-*-best`): the contract's
/// construction and one step.
fn dynamic_best(form: contensou::dynamic::Form) {
    use contensou::dynamic::{DynContact, Law, Spec, Step};
    let spec = bb(Spec {
        p: t::<f32>(38.0),
        q: t(1500.0),
        estar: t(1.1e11),
        cd: t(0.0),
        f: t(0.07),
        delta: t(0.0),
    });
    if let Ok(c) = DynContact::new(&spec, Law::Best, form) {
        let _ = bb(c.wrench(&bb(Step {
            h: t(5e-6),
            hdot: t(0.0),
            vx: t(0.02),
            vy: t(0.0),
            omega: t(100.0),
        })));
    }
}

/// One rolling wrench by the law `L` (stage `rolling`): the contact built and called.
fn rolling<T: Real, L: contensou::friction::rolling::RollingLaw>() {
    use contensou::friction::rolling::{Elasticity, Patch, RollingContact, RollingSlip};
    let el = ok(Elasticity::<T>::new(t(8e10), t(0.28)));
    let c = ok(RollingContact::new(t(1.5), el));
    let p = ok(Patch::new(t(6e-3), t(4e-3), t(8e4), t(0.3)));
    let s = ok(RollingSlip::from_creepages(
        t(1e-3),
        t(2e-4),
        t(0.5),
        t(30.0),
    ));
    bb(c.wrench::<L>(&p, &s));
}

/// `probes! { "stage,method,precision" => body; … }`: every key, and the body run for `KEY`.
macro_rules! probes {
    ($($key:literal => $body:expr;)*) => {
        /// Every key this probe knows (`tools/flash-bench.sh` reads them from this file).
        const KEYS: &[&str] = &["baseline", $($key),*];

        const _: () = {
            let mut i = 0;
            let mut known = false;
            while i < KEYS.len() {
                known |= same(KEYS[i], KEY);
                i += 1;
            }
            assert!(known, "CONTENSOU_PROBE names no key of firmware/src/bin/probe.rs");
        };

        fn probe() {
            $(if const { same(KEY, $key) } { $body; })*
        }
    };
}

probes! {
    "core,call,f32" => bb(t::<f32>(1.0));
    "rolling,table,f32" => rolling::<f32, contensou::friction::rolling::Table>();
    "rolling,table,f64" => rolling::<f64, contensou::friction::rolling::Table>();
    "rolling,blend,f32" => rolling::<f32, contensou::friction::rolling::Blend>();
    "rolling,blend,f64" => rolling::<f64, contensou::friction::rolling::Blend>();
    "rolling,full-slip,f32" => rolling::<f32, contensou::friction::rolling::FullSlip>();
    "rolling,full-slip,f64" => rolling::<f64, contensou::friction::rolling::FullSlip>();
    "rolling,fastsim-16,f32" => rolling::<f32, contensou::friction::rolling::FastsimGrid<16, 16>>();
    "rolling,fastsim,f32" => rolling::<f32, contensou::friction::rolling::Fastsim>();
    "wrench,dyn-fixed-best,f32" => dynamic_best(contensou::dynamic::Form::Fixed);
    "wrench,dyn-varying-best,f32" => dynamic_best(contensou::dynamic::Form::Varying);
    "frame,slip,f32" => frame_slip::<f32>();
    "frame,slip,f64" => frame_slip::<f64>();
    "frame,load,f32" => frame_load::<f32>();
    "frame,load,f64" => frame_load::<f64>();
    "core,vsqrt,f32" => bb(t::<f32>(2.0).sqrt());
    "core,libm,f32" => bb(libm::sqrtf(t(2.0)));
    "elliptic,agm,f32" => elliptic::<f32, Agm>();
    "elliptic,agm,f64" => elliptic::<f64, Agm>();
    "elliptic,theta,f32" => elliptic::<f32, Theta>();
    "elliptic,theta,f64" => elliptic::<f64, Theta>();
    "elliptic,table,f32" => elliptic::<f32, EllTable>();
    "elliptic,table,f64" => elliptic::<f64, EllTable>();
    "hertz,per_step,f32" => per_step::<f32>();
    "hertz,per_step,f64" => per_step::<f64>();
    "hertz,table_each_step,f32" => table_each_step::<f32>();
    "hertz,table_each_step,f64" => table_each_step::<f64>();
    "hertz,fitted_each_step,f32" => fitted_each_step::<f32>();
    "hertz,fitted_each_step,f64" => fitted_each_step::<f64>();
    "hertz,volumetric,f32" => volumetric_each_step::<f32>();
    "hertz,volumetric,f64" => volumetric_each_step::<f64>();
    "hertz,shape_table,f32" => shape::<f32, Table>();
    "hertz,shape_table,f64" => shape::<f64, Table>();
    "hertz,shape_linear,f32" => shape::<f32, Linear>();
    "hertz,shape_linear,f64" => shape::<f64, Linear>();
    "hertz,shape_hamrock-dowson,f32" => shape::<f32, HamrockDowson>();
    "hertz,shape_hamrock-dowson,f64" => shape::<f64, HamrockDowson>();
    "hertz,shape_newton,f32" => shape::<f32, Newton>();
    "hertz,shape_newton,f64" => shape::<f64, Newton>();
    "friction,simplified,f32" => core::<f32, Simplified>();
    "friction,simplified,f64" => core::<f64, Simplified>();
    "friction,pade,f32" => core::<f32, Pade>();
    "friction,pade,f64" => core::<f64, Pade>();
    "friction,ellipsoid,f32" => core::<f32, Ellipsoid>();
    "friction,ellipsoid,f64" => core::<f64, Ellipsoid>();
    "friction,coulomb,f32" => core::<f32, Coulomb>();
    "friction,coulomb,f64" => core::<f64, Coulomb>();
    "friction,exact,f32" => core::<f32, Exact>();
    "friction,exact,f64" => core::<f64, Exact>();
    "friction,simplified-dimensional,f32" => dimensional::<f32, Simplified>();
    "friction,simplified-dimensional,f64" => dimensional::<f64, Simplified>();
    "friction,constants-from-integrals,f32" => from_integrals::<f32>();
    "friction,constants-from-integrals,f64" => from_integrals::<f64>();
    "friction,best,f32" => best_core::<f32>();
    "friction,best,f64" => best_core::<f64>();
    "friction,best-e2-0.99,f32" => best_core::<f32>();
    "friction,best-e2-0.99,f64" => best_core::<f64>();
    "friction,best-varying,f32" => core::<f32, Best>();
    "friction,best-varying,f64" => core::<f64, Best>();
    "friction,best-contact-new,f32" => best_new::<f32>();
    "friction,best-contact-new,f64" => best_new::<f64>();
    "friction,best-dimensional,f32" => best_dimensional::<f32>();
    "friction,best-dimensional,f64" => best_dimensional::<f64>();
    "wrench,fixed,f32" => fixed::<f32, Simplified>();
    "wrench,fixed,f64" => fixed::<f64, Simplified>();
    "wrench,table_each_step,f32" => varying::<f32, Simplified>();
    "wrench,table_each_step,f64" => varying::<f64, Simplified>();
    "step,fixed-best,f32" => step_aware::<1>();
    "step,two-contacts-best,f32" => step_aware::<2>();
    "wrench,fixed-best,f32" => fixed::<f32, Best>();
    "wrench,fixed-best,f64" => fixed::<f64, Best>();
    "wrench,table_each_step-best,f32" => varying::<f32, Best>();
    "wrench,table_each_step-best,f64" => varying::<f64, Best>();
    "wrench,table_each_step-best-worst,f32" => varying::<f32, Best>();
    "wrench,table_each_step-best-from-bodies,f32" => varying_from_bodies();
    "scene,tippe_top_step,f32" => tippe_top(1);
    "scene,tippe_top_step_two_contacts,f32" => tippe_top(1);
    "scene,tippe_top_10ms,f32" => tippe_top(1_000);
    "scene,rattleback_step,f32" => rattleback_step();
    "scene,tippe_top_8s,f32" => tippe_top(85_107);
    "scene,sphere-plane-spin-coarse,f32" => scene::<Scene<Circular, Fixed, Spin, Coarse, f32>>();
    "scene,sphere-plane-spin-coarse,f64" => scene::<Scene<Circular, Fixed, Spin, Coarse, f64>>();
    "scene,sphere-plane-spin-exact,f32" => scene::<Scene<Circular, Fixed, Spin, ExactGrade, f32>>();
    "scene,sphere-plane-spin-exact,f64" => scene::<Scene<Circular, Fixed, Spin, ExactGrade, f64>>();
    "scene,sphere-plane-nospin,f32" => scene::<Scene<Circular, Fixed, NoSpin, ExactGrade, f32>>();
    "scene,sphere-plane-nospin,f64" => scene::<Scene<Circular, Fixed, NoSpin, ExactGrade, f64>>();
    "scene,ball-race-spin-coarse,f32" => scene::<Scene<Elliptic, Fixed, Spin, Coarse, f32>>();
    "scene,ball-race-spin-coarse,f64" => scene::<Scene<Elliptic, Fixed, Spin, Coarse, f64>>();
    "scene,ball-race-spin-exact,f32" => scene::<Scene<Elliptic, Fixed, Spin, ExactGrade, f32>>();
    "scene,ball-race-spin-exact,f64" => scene::<Scene<Elliptic, Fixed, Spin, ExactGrade, f64>>();
    "scene,ball-race-nospin,f32" => scene::<Scene<Elliptic, Fixed, NoSpin, ExactGrade, f32>>();
    "scene,ball-race-nospin,f64" => scene::<Scene<Elliptic, Fixed, NoSpin, ExactGrade, f64>>();
    "scene,varying-spin-coarse,f32" => scene::<Scene<Elliptic, Varying, Spin, Coarse, f32>>();
    "scene,varying-spin-coarse,f64" => scene::<Scene<Elliptic, Varying, Spin, Coarse, f64>>();
    // Without the feature `micromath` the declaration resolves to this (with it, to the
    // `-micromath` row below).
    "scene,varying-spin-exact,f32" => scene_varying::<f32, Best>();
    "scene,varying-spin-exact,f64" => scene::<Scene<Elliptic, Varying, Spin, ExactGrade, f64>>();
    "scene,varying-nospin,f32" => scene::<Scene<Elliptic, Varying, NoSpin, ExactGrade, f32>>();
    "scene,varying-nospin,f64" => scene::<Scene<Elliptic, Varying, NoSpin, ExactGrade, f64>>();
    // The micromath backend (feature `micromath`, f32 only) and libm's ln, exp.
    "core,ln-libm,f32" => bb(Real::ln(t::<f32>(2.0)));
    "core,exp-libm,f32" => bb(Real::exp(t::<f32>(2.0)));
    "core,sqrt-micromath,f32" => bb(Micromath::sqrt(t::<f32>(2.0)));
    "core,ln-micromath,f32" => bb(Micromath::ln(t::<f32>(2.0)));
    "core,exp-micromath,f32" => bb(Micromath::exp(t::<f32>(2.0)));
    "core,ln-raw-micromath,f32" => bb(micromath::F32(t(2.0)).ln().0);
    "elliptic,theta-micromath,f32" => elliptic::<f32, ThetaMicromath>();
    "hertz,per_step-micromath,f32" => bb(HertzMicromath::from(hertz::<f32>()).patch(t(1e-6)));
    "hertz,shape_hamrock-dowson-micromath,f32" => shape::<f32, HamrockDowsonMicromath>();
    "friction,simplified-micromath,f32" => core::<f32, SimplifiedMicromath>();
    "friction,ellipsoid-micromath,f32" => core::<f32, EllipsoidMicromath>();
    "friction,coulomb-micromath,f32" => core::<f32, CoulombMicromath>();
    "friction,best-micromath,f32" => core::<f32, BestMicromath>();
    "scene,sphere-plane-spin-rough-micromath,f32" => scene::<Scene<Circular, Fixed, Spin, Rough, f32>>();
    "scene,sphere-plane-nospin-rough-micromath,f32" => scene::<Scene<Circular, Fixed, NoSpin, Rough, f32>>();
    "scene,ball-race-spin-rough-micromath,f32" => scene::<Scene<Elliptic, Fixed, Spin, Rough, f32>>();
    "scene,ball-race-nospin-rough-micromath,f32" => scene::<Scene<Elliptic, Fixed, NoSpin, Rough, f32>>();
    "scene,varying-spin-exact-micromath,f32" => scene::<Scene<Elliptic, Varying, Spin, ExactGrade, f32>>();
}

#[entry]
fn main() -> ! {
    probe();
    halt()
}
