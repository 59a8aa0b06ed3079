//! Link-time no-panic proof for `contensou` on `thumbv7em-none-eabihf` (issue 8).
//!
//! `main` calls every public constructor and evaluation entry point, in `f32` and `f64`, and
//! every function the C API exports (`capi.rs`, crate `contensou-capi`), on
//! inputs the optimiser cannot see (`black_box`), and black-boxes every output. The panic
//! handler calls `contensou_panic_path_survived`, a function that is declared but never
//! defined: if any panic path survives optimisation (opt-level 3, fat LTO, one codegen unit,
//! `panic = "abort"`), the handler is referenced and **linking fails** with an undefined
//! symbol. A successful link is the proof. Run by `tools/no-panic.sh`, which on failure rebuilds
//! with `--features locate` and names the probes that still reach the panic machinery.
//!
//! Each entry point is called from its own `#[inline(never)]` probe (`probe_*`), so a surviving
//! panic call site is attributed to the entry point that reaches it.
#![no_std]
#![no_main]

use core::hint::black_box;

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::elliptic::{self, Agm, Method, Parameter, Theta, ThetaMicromath};
use contensou::friction::{
    self, Best, BestMicromath, BestSeries, Constants, Coulomb, CoulombMicromath, Ellipsoid,
    EllipsoidMicromath, Exact, Explicit, Friction, FrictionLaw, Pade, Simplified,
    SimplifiedMicromath, Slip, SlipState,
};
use contensou::geometry::{Curvatures, Principal, Race};
use contensou::normal::{
    CompressionDamping, Damping, Fitted, Hertz, HertzMicromath, HuntCrossley, Material, Modulus,
    NormalLaw, Undamped, Volumetric,
};
use contensou::select::Precision;
use contensou::shape::{
    self, Eccentricity, HamrockDowson, HamrockDowsonMicromath, Linear, Newton, Ratio,
};
use cortex_m_rt::entry;

mod capi;

#[cfg(not(feature = "locate"))]
unsafe extern "Rust" {
    /// Never defined anywhere: referencing it makes the link fail.
    fn contensou_panic_path_survived() -> !;
}

#[cfg(not(feature = "locate"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    // SAFETY: never executed in a linked image — the symbol does not exist, so an image that
    // still references this handler does not link.
    unsafe { contensou_panic_path_survived() }
}

/// `--features locate`: a real handler, so the image links and the call sites can be found.
#[cfg(feature = "locate")]
#[panic_handler]
#[inline(never)]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    loop {
        core::hint::spin_loop();
    }
}

/// An input the optimiser knows nothing about.
#[inline(always)]
fn x<T: Real>(v: f64) -> T {
    black_box(T::from_f64(v))
}

/// One probe per entry point: `#[inline(never)]` keeps its name in the image; every argument
/// is re-black-boxed inside so that no constant reaches the library through LTO.
macro_rules! probes {
    ($( fn $name:ident<$T:ident>($($arg:ident),*) $body:block )*) => {
        $(
            #[inline(never)]
            #[allow(clippy::too_many_arguments)]
            fn $name<$T: Precision>($($arg: $T),*) {
                $(let $arg = black_box($arg);)*
                let _ = black_box($body);
            }
        )*
        fn run_all<R: Precision>() {
            // Every argument is a black-boxed value: the probes must hold for any.
            $( $name::<R>($(probes!(@arg $arg)),*); )*
        }
    };
    (@arg $arg:ident) => { x(0.5) };
}

/// A generic friction-law probe set, instantiated per law below.
macro_rules! law_probes {
    ($($law:ident: $tangential:ident, $core:ident, $wrench:ident, $varying:ident;)*) => {
        probes! {
            $(
            fn $tangential<T>(f, delta, m, a, n, vx, vy, om) {
                let (Ok(fr), Ok(p), Ok(s)) =
                    (Friction::<T, $law>::with_law(f, delta), Parameter::new(m), Slip::new(vx, vy, om))
                else { return };
                fr.tangential(&Constants::from_parameter(p), a, n, s)
            }
            fn $core<T>(m1, vx, vy, aw, delta) {
                let (Ok(p), Ok(s)) = (Parameter::from_complement(m1), SlipState::new(vx, vy, aw, delta))
                else { return };
                <$law as FrictionLaw>::traction(&Constants::from_parameter(p), &s)
            }
            fn $wrench<T>(p, q, e, f, delta, h, hdot, vx, vy, om, cd) {
                let (Ok(c), Ok(e), Ok(fr), Ok(s), Ok(hc)) = (
                    Curvatures::new(p, q),
                    Modulus::new(e),
                    Friction::<T, $law>::with_law(f, delta),
                    Slip::new(vx, vy, om),
                    HuntCrossley::new(cd),
                ) else { return };
                let Ok(contact) = Contact::hertz::<Newton>(&c, e, hc, fr) else { return };
                black_box(contact.wrench(h, hdot, s))
            }
            fn $varying<T>(p, q, e, f, delta, h, hdot, vx, vy, om, d) {
                let (Ok(c), Ok(e), Ok(fr), Ok(s), Ok(cdamp)) = (
                    Curvatures::new(p, q),
                    Modulus::new(e),
                    Friction::<T, $law>::with_law(f, delta),
                    Slip::new(vx, vy, om),
                    CompressionDamping::new(d),
                ) else { return };
                VaryingContact::new(e, cdamp, fr).wrench(&c, h, hdot, s)
            }
            )*
        }
    };
}

law_probes! {
    Simplified: probe_tangential_simplified, probe_core_simplified, probe_contact_wrench_simplified, probe_varying_wrench_simplified;
    Pade: probe_tangential_pade, probe_core_pade, probe_contact_wrench_pade, probe_varying_wrench_pade;
    Ellipsoid: probe_tangential_ellipsoid, probe_core_ellipsoid, probe_contact_wrench_ellipsoid, probe_varying_wrench_ellipsoid;
    Coulomb: probe_tangential_coulomb, probe_core_coulomb, probe_contact_wrench_coulomb, probe_varying_wrench_coulomb;
    Exact: probe_tangential_exact, probe_core_exact, probe_contact_wrench_exact, probe_varying_wrench_exact;
    Best: probe_tangential_best, probe_core_best, probe_contact_wrench_best, probe_varying_wrench_best;
    BestSeries: probe_tangential_best_series, probe_core_best_series, probe_contact_wrench_best_series, probe_varying_wrench_best_series;
}

/// The rest of the API, one probe per entry point.
mod api {
    use super::*;
    use contensou::friction::rolling::{
        Blend, CreepMatrix, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear as KalkerLinear,
        Patch, RollingContact, RollingLaw, RollingSlip, Table, Wrench, creep_matrix,
    };

    /// A contact for the step-aware wrench's probe: its wrench, and a Jacobian whose entries
    /// are black-boxed inputs (the step must hold for any finite Jacobian).
    struct StepContact<T: Real> {
        contact: Contact<T, Hertz<T>, Undamped, Coulomb>,
        d: [T; 5],
    }

    impl<T: Real> contensou::jacobian::Linearize<T> for StepContact<T> {
        fn wrench4(&self, s: &contensou::jacobian::State<T>) -> [T; 4] {
            let w = self.contact.wrench(s.h, s.hdot, s.slip);
            [w.n, w.fx, w.fy, w.tz]
        }
        fn linearize(&self, s: &contensou::jacobian::State<T>) -> contensou::jacobian::Jacobian<T> {
            contensou::jacobian::Jacobian {
                value: self.wrench4(s),
                d: black_box([self.d; 4]),
            }
        }
    }

    /// One rolling wrench by law `L` from raw inputs (every constructor on the way).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn rolling<T: Real, L: RollingLaw>(
        r: T,
        g: T,
        nu: T,
        a: T,
        b: T,
        n: T,
        f: T,
        vx: T,
        vy: T,
        om: T,
        v: T,
    ) -> Result<Wrench<T>, contensou::Error> {
        let c = RollingContact::new(r, Elasticity::new(g, nu)?)?;
        let p = Patch::new(a, b, n, f)?;
        let s = RollingSlip::new(vx, vy, om, v)?;
        Ok(c.wrench::<L>(&p, &s))
    }

    probes! {
        // rolling contact (friction::rolling, issue 20)
        fn probe_rolling_elasticity<T>(g, nu) { Elasticity::new(g, nu) }
        fn probe_rolling_dissimilar<T>(g, nu, h, mu) { Elasticity::dissimilar(g, nu, h, mu) }
        fn probe_rolling_contact<T>(r, g, nu) {
            Elasticity::new(g, nu).and_then(|e| RollingContact::new(r, e)).map(|c| *c.kalker())
        }
        fn probe_rolling_slip<T>(vx, vy, om, v) {
            RollingSlip::new(vx, vy, om, v).map(|s| (s.creepages(), s.scaled(vx)))
        }
        fn probe_rolling_blend<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, Blend>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_table<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, Table>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_fastsim<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, Fastsim>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_fastsim_sixteen<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, FastsimGrid<16, 16>>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_full_slip<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, FullSlip>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_linear<T>(r, g, nu, a, b, n, f, vx, vy, om, v) {
            rolling::<T, KalkerLinear>(r, g, nu, a, b, n, f, vx, vy, om, v)
        }
        fn probe_rolling_creep_matrix<T>(a, b, cx, sx, nu) {
            (CreepMatrix::new(a, b, cx, sx, nu), creep_matrix::aligned(a, nu))
        }
        // elliptic
        fn probe_parameter_new<T>(m) { (Parameter::new(m), Parameter::<T>::min_complement()) }
        fn probe_parameter_from_complement<T>(m1) { Parameter::from_complement(m1).map(|p| (p.m(), p.m1())) }
        fn probe_integrals_agm<T>(m) { Parameter::new(m).map(Agm::integrals) }
        fn probe_integrals_theta<T>(m) { Parameter::new(m).map(Theta::integrals) }
        fn probe_integrals_table<T>(m) { Parameter::new(m).map(elliptic::Table::integrals) }
        fn probe_integrals_agm_c<T>(m1) { Parameter::from_complement(m1).map(Agm::integrals) }
        fn probe_integrals_theta_c<T>(m1) { Parameter::from_complement(m1).map(Theta::integrals) }
        fn probe_integrals_table_c<T>(m1) { Parameter::from_complement(m1).map(elliptic::Table::integrals) }
        fn probe_paper_k_e<T>(m1) { Parameter::from_complement(m1).map(elliptic::paper_k_e) }
        // geometry
        fn probe_principal_sphere<T>(r) { (Principal::sphere(r), Principal::<T>::plane()) }
        fn probe_curvatures_new<T>(p, q) {
            Curvatures::new(p, q).map(|c| (c.ratio(), c.major_angle(), c.gaussian_radius()))
        }
        fn probe_curvatures_from_bodies<T>(a1, a2, b1, b2, om) {
            Curvatures::from_bodies(Principal { k1: a1, k2: a2 }, Principal { k1: b1, k2: b2 }, om)
        }
        fn probe_curvatures_from_bodies_cos_sin<T>(a1, a2, b1, b2, c, sn) {
            Curvatures::from_bodies_cos_sin(Principal { k1: a1, k2: a2 }, Principal { k1: b1, k2: b2 }, c, sn)
                .map(|c| (c.major_axis(), c.major_angle()))
        }
        fn probe_curvatures_from_quadratic<T>(mxx, myy, mxy) { Curvatures::from_quadratic(mxx, myy, mxy) }
        fn probe_curvatures_sphere_plane<T>(r) { Curvatures::sphere_plane(r) }
        fn probe_curvatures_sphere_sphere<T>(ra, rb) { Curvatures::sphere_sphere(ra, rb) }
        fn probe_curvatures_ball_race<T>(d, rg, dm, alpha) {
            (
                Curvatures::ball_race(d, rg, dm, alpha, Race::Inner),
                Curvatures::ball_race(d, rg, dm, alpha, Race::Outer),
            )
        }
        // shape
        fn probe_ratio<T>(g, p, q) {
            (Ratio::new(g), Ratio::clamped(g), Curvatures::new(p, q).and_then(|c| Ratio::of(&c)))
        }
        fn probe_shape_newton<T>(g) { Ratio::new(g).map(|g| (Newton::shape(g), Newton::solve(g))) }
        fn probe_shape_linear<T>(g) { Ratio::new(g).map(|g| (Linear::shape(g), Linear::solve(g))) }
        fn probe_shape_hamrock_dowson<T>(g) {
            Ratio::new(g).map(|g| (HamrockDowson::shape(g), HamrockDowson::solve(g)))
        }
        fn probe_shape_table<T>(g) { shape::Table::shape(Ratio::clamped(g)) }
        // the wrench's Jacobian (contensou::jacobian): the contract (every law and form, the
        // rolling columns) and the generic contacts' Linearize
        fn probe_jacobian_dynamic<T>(p, q, e, cd, f, delta, h, hdot, vx, vy, om, vrx, vry) {
            use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
            let spec = Spec { p, q, estar: e, cd, f, delta };
            let step = Step { h, hdot, vx, vy, omega: om };
            for law in Law::ALL {
                for form in Form::ALL {
                    let Ok(c) = DynContact::new_rolling(&spec, &RollingSpec::default(), black_box(law), black_box(form))
                    else { continue };
                    black_box(c.jacobian_rolling(&step, &RollingStep { vrx, vry })).ok();
                }
            }
        }
        fn probe_jacobian_contact<T>(p, q, e, f, delta, h, hdot, vx, vy, om, d) {
            use contensou::friction::rolling::RollingVelocity;
            use contensou::jacobian::{Linearize, State};
            let (Ok(c), Ok(e), Ok(fr), Ok(s), Ok(cdamp)) = (
                Curvatures::new(p, q),
                Modulus::new(e),
                Friction::<T, Best>::with_law(f, delta),
                Slip::new(vx, vy, om),
                CompressionDamping::new(d),
            ) else { return };
            let state = State { h, hdot, slip: s, rolling: RollingVelocity::ZERO };
            let Ok(contact) = Contact::hertz::<Newton>(&c, e, cdamp, fr) else { return };
            let varying = VaryingContact::new(e, cdamp, fr);
            (contact.linearize(&state), varying.at(&c).linearize(&state))
        }
        // normal
        fn probe_material_modulus<T>(e1, n1, e2, n2, es) {
            let m = (Material::new(e1, n1), Material::new(e2, n2));
            let of = match m { (Ok(a), Ok(b)) => Some(Modulus::of(a, b)), _ => None };
            (m, of, Modulus::new(es))
        }
        fn probe_damping<T>(cd, d, el, h, hdot) {
            (
                Undamped.force(el, h, hdot),
                HuntCrossley::new(cd).map(|c| c.force(el, h, hdot)),
                CompressionDamping::new(d).map(|c| c.force(el, h, hdot)),
            )
        }
        fn probe_hertz<T>(p, q, e, h, hdot, cd, n) {
            let (Ok(c), Ok(e), Ok(hc)) = (Curvatures::new(p, q), Modulus::new(e), HuntCrossley::new(cd))
            else { return };
            black_box(Hertz::circular(c.p(), e).patch(h));
            let Ok(law) = Hertz::new::<Newton>(&c, e) else { return };
            (law.patch(h), law.damped_patch(h, hdot, &hc), law.approach(n), law.energy(h), law.stiffness())
        }
        fn probe_hertz_from_shape<T>(p, q, e, h, hdot, d) {
            let (Ok(c), Ok(e), Ok(cdamp)) = (Curvatures::new(p, q), Modulus::new(e), CompressionDamping::new(d))
            else { return };
            let law = Hertz::from_shape(&c, &shape::Table::shape(Ratio::clamped(c.ratio())), e);
            (law.patch(h), law.damped_patch(h, hdot, &cdamp))
        }
        fn probe_volumetric<T>(p, q, e, h, hdot, n) {
            let (Ok(c), Ok(e)) = (Curvatures::new(p, q), Modulus::new(e)) else { return };
            let law = Volumetric::new(&c, e);
            (law.patch(h), law.damped_patch(h, hdot, &Undamped), law.approach(n), law.energy(h))
        }
        fn probe_fitted<T>(p, q, e, h, hdot, cd) {
            let (Ok(c), Ok(e), Ok(hc)) = (Curvatures::new(p, q), Modulus::new(e), HuntCrossley::new(cd))
            else { return };
            let law = Fitted::clamped(&c, e);
            (Fitted::new(&c, e), law.patch(h), law.damped_patch(h, hdot, &hc))
        }
        // friction
        fn probe_slip_state<T>(vx, vy, om, a, delta, psi, u) {
            let s = Slip::new(vx, vy, om);
            let from = s.map(|s| SlipState::from_slip(s, a, delta));
            (s, from, SlipState::new(vx, vy, a, delta), SlipState::from_polar(psi, u))
        }
        fn probe_constants<T>(m, m1, g) {
            let (Ok(p), Ok(pc)) = (Parameter::new(m), Parameter::from_complement(m1)) else { return };
            (
                Constants::new::<Agm>(p),
                Constants::new::<Theta>(pc),
                Constants::new::<elliptic::Table>(p),
                Constants::from_parameter(pc),
                Constants::from_integrals(p, &Agm::integrals(p)),
                Constants::from_shape(&shape::Table::shape(Ratio::clamped(g))),
                Constants::<T>::circle(),
            )
        }
        fn probe_exact_traction<T>(m1, vx, vy, aw) {
            Parameter::from_complement(m1).map(|p| friction::exact::traction(p, vx, vy, aw))
        }
        // stability guards
        fn probe_newton_unchecked<T>(g) { Newton::solve_unchecked(g, black_box(6)) }
        fn probe_volumetric_checked<T>(p, q, e, h) {
            let (Ok(c), Ok(e)) = (Curvatures::new(p, q), Modulus::new(e)) else { return };
            Volumetric::checked(&c, e).map(|law| law.patch(h))
        }
        fn probe_stable_step<T>(f, delta, mass, n) {
            let (Ok(co), Ok(si)) =
                (Friction::<T, Coulomb>::with_law(f, delta), Friction::<T, Simplified>::with_law(f, delta))
            else { return };
            let k = Constants::circle();
            (co.stable_step(&k, mass, n, Explicit::Euler), si.stable_step(&k, mass, n, Explicit::Rk4))
        }
        fn probe_best_stable_step<T>(m1, f, delta, mass, n) {
            let (Ok(p), Ok(be)) = (Parameter::from_complement(m1), Friction::<T, Best>::with_law(f, delta))
            else { return };
            be.stable_step(&Constants::from_parameter(p), mass, n, Explicit::Rk4)
        }
        // the step-aware wrench (contensou::step)
        fn probe_step_time_step<T>(dt) { contensou::step::TimeStep::new(dt) }
        fn probe_step_inverse_mass<T>(a, b, c, d, e, f, g, h, i, j) {
            contensou::step::InverseMass::from_upper([a, b, c, d, e, f, g, h, i, j])
        }
        fn probe_step_bodies<T>(m, i, cx, cz, px, py, nx, nz) {
            use contensou::frame::{Frame, MajorAxis};
            use contensou::step::{Body, ContactPoint, InverseMass};
            let Ok(body) = Body::new(m, [[i, cx, px], [cx, i, py], [px, py, i]], [cx, px, cz]) else { return };
            let frame = Frame::new([nx, py, nz], [nz, px, nx], MajorAxis::from_cos_sin(cx, cz));
            let cp = ContactPoint { a: None, b: Some(0), point: [px, py, px], frame };
            InverseMass::<T, 1>::from_bodies(&[body], &[cp])
        }
        fn probe_step_wrench<T>(p, e, f, delta, h, hdot, vx, vy, om, dt, wn, wt, ww, un) {
            use contensou::jacobian::State;
            use contensou::step::{step_wrench, Free, InverseMass, TimeStep};
            let (Ok(c), Ok(e), Ok(fr), Ok(s), Ok(dt)) = (
                Curvatures::new(p, p),
                Modulus::new(e),
                Friction::<T, Coulomb>::with_law(f, delta),
                Slip::new(vx, vy, om),
                TimeStep::new(dt),
            ) else { return };
            let Ok(contact) = Contact::circular(&c, e, Undamped, fr) else { return };
            // any Jacobian: the derivatives are black-boxed inputs
            let lin = StepContact { contact, d: [h, hdot, vx, vy, om] };
            let z = T::ZERO;
            let st = State { h, hdot, slip: s, ..State::default() };
            let (Ok(w1), Ok(free)) = (
                InverseMass::single([[wn, z, z, z], [z, wt, z, z], [z, z, wt, z], [z, z, z, ww]]),
                Free::predicted(dt, &st, [un, vx, vy, om]),
            ) else { return };
            (step_wrench(&lin, dt, &w1, &st, &free), Free::coasting(dt, &st))
        }
        fn probe_step_stable<T>(p, e, mass, n) {
            let (Ok(c), Ok(e), Ok(fr)) = (Curvatures::new(p, p), Modulus::new(e), Friction::<T, Coulomb>::with_law(n, mass))
            else { return };
            let Ok(contact) = Contact::circular(&c, e, Undamped, fr) else { return };
            (contact.stable_normal_step(mass, n, Explicit::Rk4), contensou::step::stable::normal_period(contact.normal(), mass, n))
        }
        fn probe_stable_spin_step<T>(m1, f, delta, a, inertia, n) {
            let (Ok(p), Ok(be), Ok(si), Ok(co)) = (
                Parameter::from_complement(m1),
                Friction::<T, Best>::with_law(f, delta),
                Friction::<T, Simplified>::with_law(f, delta),
                Friction::<T, Coulomb>::with_law(f, delta),
            ) else { return };
            let k = Constants::from_parameter(p);
            (
                be.stable_spin_step(&k, a, inertia, n, Explicit::Rk4),
                si.stable_spin_step(&k, a, inertia, n, Explicit::Euler),
                co.stable_spin_step(&k, a, inertia, n, Explicit::Euler),
            )
        }
        // the frame helper, and the stable steps from a built contact
        fn probe_frame<T>(nx, ny, nz, rx, ry, rz, c, s, v, e, h) {
            use contensou::frame::{ContactFrame, Frame, MajorAxis, WorldAxes, point_velocity};
            let (Ok(curv), Ok(e), Ok(fr)) = (Curvatures::new(nx, ny), Modulus::new(e), Friction::<T, Best>::with_law(c, s))
            else { return };
            let Ok(contact) = Contact::hertz::<Newton>(&curv, e, Undamped, fr) else { return };
            let frame = Frame::from_reference([nx, ny, nz], [rx, ry, rz], MajorAxis::of(&curv));
            let other = Frame::new([nx, ny, nz], [rx, ry, rz], MajorAxis::from_cos_sin(c, s));
            let vel = point_velocity([v, rx, ry], [rz, c, s], [nx, ny, nz]);
            let Ok(slip) = frame.slip(vel, [s, c, v]) else { return };
            let w = contact.wrench(h, frame.approach_rate(vel), slip);
            (
                frame.on_b(&w, vel),
                other.on_a(&w, vel),
                WorldAxes.on_b(&w, vel),
                WorldAxes.slip(vel, vel),
                other.to_contact(vel),
                contact.stable_step(v, h, Explicit::Euler),
                contact.stable_spin_step(c, s, h, Explicit::Rk4),
            )
        }
        fn probe_spin_stiffness<T>(m1) {
            Parameter::from_complement(m1).map(|p| friction::best::spin_stiffness(&Constants::from_parameter(p)))
        }
        // contact (other normal laws through from_parts)
        fn probe_contact_from_parts<T>(p, q, e, f, h, hdot, vx, vy, om) {
            let (Ok(c), Ok(e), Ok(fr), Ok(s)) =
                (Curvatures::new(p, q), Modulus::new(e), Friction::<T, Simplified>::with_law(f, f), Slip::new(vx, vy, om))
            else { return };
            let v = Contact::from_parts(Volumetric::new(&c, e), Undamped, fr, Constants::circle());
            let k = Constants::from_shape(&shape::Table::shape(Ratio::clamped(c.ratio())));
            let ft = Contact::from_parts(Fitted::clamped(&c, e), Undamped, fr, k);
            let hd = Contact::hertz::<HamrockDowson>(&c, e, Undamped, fr);
            let li = Contact::hertz::<Linear>(&c, e, Undamped, fr);
            let tb = Contact::hertz::<shape::Table>(&c, e, Undamped, fr);
            (
                v.wrench(h, hdot, s),
                ft.wrench(h, hdot, s),
                hd.map(|w| w.wrench(h, hdot, s)),
                li.map(|w| w.wrench(h, hdot, s)),
                tb.map(|w| w.wrench(h, hdot, s)),
            )
        }
        // Contact::circular and contensou::select: each geometry kind, each law it resolves to
        fn probe_select<T>(p, q, e, f, h, hdot, vx, vy, om) {
            use contensou::select::*;
            let (Ok(c), Ok(e), Ok(s)) = (Curvatures::new(p, q), Modulus::new(e), Slip::new(vx, vy, om))
            else { return };
            let (Ok(f1), Ok(f2), Ok(f3)) = (Friction::with_law(f, f), Friction::with_law(f, f), Friction::with_law(f, f))
            else { return };
            type Ball<T> = Scene<Circular, Fixed, Spin, Coarse, T>;
            type Race<T> = Scene<Elliptic, Fixed, Spin, ExactGrade, T>;
            type Wander<T> = Scene<Elliptic, Varying, NoSpin, Coarse, T>;
            // Micromath's √h (f32) and Best's per-call twin (f32) where the feature resolves to them.
            type Rolling<T> = Scene<Circular, Fixed, Spin, Rough, T>;
            type Track<T> = Scene<Elliptic, Fixed, NoSpin, Rough, T>;
            type Drift<T> = Scene<Elliptic, Varying, Spin, ExactGrade, T>;
            let (Ok(f4), Ok(f5), Ok(f6)) = (Friction::with_law(f, f), Friction::with_law(f, f), Friction::with_law(f, f))
            else { return };
            (
                Ball::<T>::build(&Ball::<T>::geometry(&c), e, Undamped, f1).map(|k| k.step(&c, h, hdot, s)),
                Race::<T>::build(&Race::<T>::geometry(&c), e, Undamped, f2).map(|k| k.step(&c, h, hdot, s)),
                Wander::<T>::build(&Wander::<T>::geometry(&c), e, Undamped, f3).map(|k| k.step(&c, h, hdot, s)),
                Rolling::<T>::build(&Rolling::<T>::geometry(&c), e, Undamped, f4).map(|k| k.step(&c, h, hdot, s)),
                Track::<T>::build(&Track::<T>::geometry(&c), e, Undamped, f5).map(|k| k.step(&c, h, hdot, s)),
                Drift::<T>::build(&Drift::<T>::geometry(&c), e, Undamped, f6).map(|k| k.step(&c, h, hdot, s)),
            )
        }
    }

    pub(crate) fn run<T: Precision>() {
        run_all::<T>();
    }
}

/// The micromath twins (feature `micromath`): `f32` only. Their `f64` is libm, the same code as
/// their libm twins' (the linker folds such probes into one symbol), already probed above.
/// tools/no-panic.sh counts the probes named `*_mm` once.
mod mm_laws {
    use super::*;

    law_probes! {
    SimplifiedMicromath: probe_tangential_simplified_mm, probe_core_simplified_mm, probe_contact_wrench_simplified_mm, probe_varying_wrench_simplified_mm;
    EllipsoidMicromath: probe_tangential_ellipsoid_mm, probe_core_ellipsoid_mm, probe_contact_wrench_ellipsoid_mm, probe_varying_wrench_ellipsoid_mm;
    CoulombMicromath: probe_tangential_coulomb_mm, probe_core_coulomb_mm, probe_contact_wrench_coulomb_mm, probe_varying_wrench_coulomb_mm;
    BestMicromath: probe_tangential_best_mm, probe_core_best_mm, probe_contact_wrench_best_mm, probe_varying_wrench_best_mm;
    }

    pub(crate) fn run() {
        run_all::<f32>();
    }
}

mod mm_api {
    use super::*;

    probes! {
        fn probe_integrals_theta_mm<T>(m1) { Parameter::from_complement(m1).map(ThetaMicromath::integrals) }
        fn probe_shape_hamrock_dowson_mm<T>(g) { Ratio::new(g).map(HamrockDowsonMicromath::shape) }
        fn probe_hertz_mm<T>(p, q, e, h, hdot, cd) {
            let (Ok(c), Ok(e), Ok(hc)) = (Curvatures::new(p, q), Modulus::new(e), HuntCrossley::new(cd))
            else { return };
            let Ok(law) = HertzMicromath::new::<Newton>(&c, e) else { return };
            (law.patch(h), law.damped_patch(h, hdot, &hc), HertzMicromath::from(Hertz::circular(c.p(), e)).patch(h))
        }
    }

    pub(crate) fn run() {
        run_all::<f32>();
    }
}

/// The batch path (`contensou::batch`): both forms of every law and `DynContact::wrench_many`,
/// on black-boxed columns of a black-boxed length (one lane on this target).
mod batch_api {
    use super::*;
    use contensou::batch::{BatchLaw, BatchReal, CurvatureColumns, Steps, Wrenches};
    use contensou::dynamic::{DynContact, Form, Law, Spec};

    /// Nine black-boxed rows of each column, cut to a black-boxed length.
    fn run_columns<T: Precision + BatchReal>(
        f: impl FnOnce(&[T], &Steps<'_, T>, &mut Wrenches<'_, T>),
    ) {
        let vals = [x::<T>(0.5); 9];
        let len = black_box(9usize).min(9);
        let c = vals.get(..len).unwrap_or(&[]);
        let mut o = [[x::<T>(0.0); 9]; 7];
        let [n, fx, fy, tz, a, b, e2] = o.each_mut().map(|c| &mut c[..]);
        let steps = Steps {
            h: c,
            hdot: c,
            vx: c,
            vy: c,
            omega: c,
        };
        f(
            c,
            &steps,
            &mut Wrenches {
                n,
                fx,
                fy,
                tz,
                a,
                b,
                e2,
            },
        );
        black_box(o);
    }

    fn fixed<T: Precision + BatchReal, L: BatchLaw>() {
        let (Ok(c), Ok(e), Ok(fr), Ok(hc)) = (
            Curvatures::new(x::<T>(0.5), x(0.5)),
            Modulus::new(x::<T>(0.5)),
            Friction::<T, L>::with_law(x(0.5), x(0.5)),
            HuntCrossley::new(x::<T>(0.5)),
        ) else {
            return;
        };
        let Ok(contact) = Contact::hertz::<Newton>(&c, e, hc, fr) else {
            return;
        };
        run_columns::<T>(|_, s, o| {
            black_box(contact.wrench_many(s, o)).ok();
        });
    }

    fn varying<T: Precision + BatchReal, L: BatchLaw>() {
        let (Ok(c), Ok(e), Ok(fr), Ok(d)) = (
            Curvatures::new(x::<T>(0.5), x(0.5)),
            Modulus::new(x::<T>(0.5)),
            Friction::<T, L>::with_law(x(0.5), x(0.5)),
            CompressionDamping::new(x::<T>(0.5)),
        ) else {
            return;
        };
        let contact = VaryingContact::new(e, d, fr);
        run_columns::<T>(|col, s, o| {
            black_box(contact.wrench_many(&CurvatureColumns { p: col, q: col }, s, o)).ok();
            black_box(contact.wrench_many_at(&c, s, o)).ok();
        });
    }

    macro_rules! batch_probes {
        ($( fn $name:ident<T>() $body:block )*) => {
            $(
                #[inline(never)]
                fn $name<T: Precision + BatchReal>() $body
            )*
            pub(crate) fn run<R: Precision + BatchReal>() {
                $( $name::<R>(); )*
            }
        };
    }

    batch_probes! {
        fn probe_batch_fixed_best<T>() { fixed::<T, Best>() }
        fn probe_batch_fixed_simplified<T>() { fixed::<T, Simplified>() }
        fn probe_batch_fixed_pade<T>() { fixed::<T, Pade>() }
        fn probe_batch_fixed_ellipsoid<T>() { fixed::<T, Ellipsoid>() }
        fn probe_batch_fixed_coulomb<T>() { fixed::<T, Coulomb>() }
        fn probe_batch_varying_best<T>() { varying::<T, Best>() }
        fn probe_batch_varying_simplified<T>() { varying::<T, Simplified>() }
        fn probe_batch_varying_pade<T>() { varying::<T, Pade>() }
        fn probe_batch_varying_ellipsoid<T>() { varying::<T, Ellipsoid>() }
        fn probe_batch_varying_coulomb<T>() { varying::<T, Coulomb>() }
        fn probe_batch_dynamic<T>() {
            let spec = Spec { p: x::<T>(0.5), q: x(0.5), estar: x(0.5), cd: x(0.5), f: x(0.5), delta: x(0.5) };
            for law in Law::ALL {
                for form in Form::ALL {
                    let Ok(c) = DynContact::new(&spec, black_box(law), black_box(form)) else { continue };
                    run_columns::<T>(|_, s, o| {
                        black_box(c.wrench_many(s, o)).ok();
                    });
                }
            }
        }
    }
}

/// `--features canary`: a probe that can panic (an unchecked slice index), to show that the
/// proof detects one (`tools/no-panic.sh` requires this build to fail).
#[cfg(feature = "canary")]
#[inline(never)]
fn probe_canary(i: usize) -> u8 {
    let t = black_box([1u8, 2, 3]);
    t[black_box(i)]
}

#[entry]
fn main() -> ! {
    #[cfg(feature = "canary")]
    black_box(probe_canary(black_box(7)));
    run_all::<f32>();
    run_all::<f64>();
    api::run::<f32>();
    api::run::<f64>();
    mm_laws::run();
    mm_api::run();
    batch_api::run::<f32>();
    batch_api::run::<f64>();
    capi::run();
    loop {
        core::hint::spin_loop();
    }
}
