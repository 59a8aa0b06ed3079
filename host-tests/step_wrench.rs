//! The step-aware wrench (src/step/): typed errors for Δt and W, W from rigid bodies against
//! its closed form, the Δt → 0 limit (the plain wrench), closed-form backward-Euler steps of a
//! block on a plane (normal, full slip, sticking), sticking below δ at any Δt, slip reversal,
//! two contacts with an active set, and passivity / limit-set checks on random states (the
//! 1e5-state run is `#[ignore]`d: `cargo test --release --test step_wrench -- --include-ignored`).
//!
//! The contacts are linearised by central differences of the wrench itself
//! ([`contensou::step::Numeric`]): an independent reference for the derivatives.

#![allow(clippy::needless_range_loop)] // small dense matrices by index

use contensou::Error;
use contensou::contact::Contact;
use contensou::frame::{Frame, MajorAxis};
use contensou::friction::{Best, Coulomb, Friction, FrictionLaw, Slip};
use contensou::geometry::Curvatures;
use contensou::jacobian::{Linearize, State};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::step::{
    Body, ContactPoint, Free, InverseMass, Numeric, TimeStep, step_wrench, step_wrenches,
};

/// A steel ball (R = 10 mm, m = 32.67 g) on a steel plane, f = 0.1.
const R: f64 = 10e-3;
const M: f64 = 32.67e-3;
const ESTAR: f64 = 1.15e11;
const F: f64 = 0.1;
const G: f64 = 9.81;

fn contact<L: FrictionLaw>(delta: f64) -> Contact<f64, Hertz<f64>, Undamped, L> {
    contact_f(F, delta)
}

fn contact_f<L: FrictionLaw>(f: f64, delta: f64) -> Contact<f64, Hertz<f64>, Undamped, L> {
    Contact::circular(
        &Curvatures::sphere_plane(R).unwrap(),
        Modulus::new(ESTAR).unwrap(),
        Undamped,
        Friction::<f64, L>::with_law(f, delta).unwrap(),
    )
    .unwrap()
}

/// The Hertz constant k (N = k·h^{3/2}) of the ball on the plane, by hand: (4/3)E*√R.
fn k_hertz() -> f64 {
    4.0 / 3.0 * ESTAR * R.sqrt()
}

/// The static approach under the ball's weight.
fn h_static() -> f64 {
    (M * G / k_hertz()).powf(2.0 / 3.0)
}

/// A central-difference `Linearize` of a fixed contact, steps scaled to the ball's contact.
fn numeric<L: FrictionLaw>(
    c: Contact<f64, Hertz<f64>, Undamped, L>,
    dv: f64,
) -> Numeric<impl Fn(&State<f64>) -> [f64; 4], f64> {
    Numeric::new(
        move |s: &State<f64>| {
            let w = c.wrench(s.h, s.hdot, s.slip);
            [w.n, w.fx, w.fy, w.tz]
        },
        [1e-4 * h_static(), 1e-6, dv, dv, dv / 1e-4],
    )
}

/// W of the ball on the plane by hand: diag(1/m, 1/m + R²/I, 1/m + R²/I, 1/I), I = (2/5)mR².
fn w_ball() -> [[f64; 4]; 4] {
    let i = 0.4 * M * R * R;
    let t = 1.0 / M + R * R / i;
    [
        [1.0 / M, 0.0, 0.0, 0.0],
        [0.0, t, 0.0, 0.0],
        [0.0, 0.0, t, 0.0],
        [0.0, 0.0, 0.0, 1.0 / i],
    ]
}

fn state(h: f64, hdot: f64, vx: f64, vy: f64, om: f64) -> State<f64> {
    State {
        h,
        hdot,
        slip: Slip::new(vx, vy, om).unwrap(),
        ..State::default()
    }
}

/// u_free of a state under gravity over Δt: v_n decreases by gΔt (the ball falls).
fn under_gravity(dt: f64, s: &State<f64>) -> Free<f64> {
    let u = [-s.hdot - G * dt, s.slip.vx(), s.slip.vy(), s.slip.omega()];
    Free::predicted(TimeStep::new(dt).unwrap(), s, u).unwrap()
}

#[test]
fn bad_step_and_bad_w_are_typed_errors() {
    assert_eq!(TimeStep::new(0.0), Err(Error::StepNotPositive));
    assert_eq!(TimeStep::new(-1e-3), Err(Error::StepNotPositive));
    assert_eq!(TimeStep::new(f64::NAN), Err(Error::NonFinite("dt")));
    assert_eq!(TimeStep::new(f32::INFINITY), Err(Error::NonFinite("dt")));
    assert!(TimeStep::new(1e-3).is_ok());

    let mut w = w_ball();
    assert!(InverseMass::single(w).is_ok());
    w[1][2] = 1e-3 * w[1][1];
    assert_eq!(InverseMass::single(w), Err(Error::InverseMassNotSymmetric));
    w[2][1] = w[1][2]; // symmetric now, and PSD (small off-diagonal)
    assert!(InverseMass::single(w).is_ok());
    w[1][2] = 1.5 * w[1][1];
    w[2][1] = w[1][2]; // |W_xy| > √(W_xx·W_yy): indefinite
    assert_eq!(
        InverseMass::single(w),
        Err(Error::InverseMassNotPositiveSemidefinite)
    );
    let mut w = w_ball();
    w[0][0] = -1.0;
    assert_eq!(
        InverseMass::single(w),
        Err(Error::InverseMassNotPositiveSemidefinite)
    );
    let mut w = w_ball();
    w[3][3] = f64::NAN;
    assert_eq!(InverseMass::single(w), Err(Error::NonFinite("W")));
    // A rank-one W (one direction only) is positive semidefinite.
    let v = [1.0, 2.0, -0.5, 3.0];
    let mut r1 = [[0.0; 4]; 4];
    for a in 0..4 {
        for b in 0..4 {
            r1[a][b] = v[a] * v[b];
        }
    }
    assert!(InverseMass::single(r1).is_ok());
    // Zero rows (a fixed direction) are fine; a zero diagonal with a non-zero row is not.
    let mut z = [[0.0; 4]; 4];
    z[1][1] = 1.0;
    assert!(InverseMass::single(z).is_ok());
    z[0][1] = 1e-20;
    z[1][0] = 1e-20;
    // symmetric, but W_01² > W_00·W_11 = 0 (what an underflowed L·Lᵀ diagonal gives)
    assert_eq!(
        InverseMass::single(z),
        Err(Error::InverseMassNotPositiveSemidefinite)
    );
    z[1][0] = 0.0; // asymmetric: no tolerance scales at a zero diagonal entry
    assert_eq!(InverseMass::single(z), Err(Error::InverseMassNotSymmetric));
    // W = L·Lᵀ built in f32 from factors 1e-30 and 1: W_00 = 1e-60 underflows to 0, W_01 =
    // 1e-30 does not — refused as not positive semidefinite (as rounded, it is not), by
    // `from_upper` too (never as not symmetric: symmetric by construction)
    let l = [1e-30f32, 1.0];
    let u = [
        l[0] * l[0],
        l[0] * l[1],
        0.0,
        0.0,
        l[1] * l[1],
        0.0,
        0.0,
        1.0,
        0.0,
        1.0,
    ];
    assert_eq!(u[0], 0.0);
    assert_eq!(
        InverseMass::from_upper(u),
        Err(Error::InverseMassNotPositiveSemidefinite)
    );
    // Within the symmetry tolerance (64 ε·√(W_aa W_bb)): accepted and symmetrised.
    let mut w = w_ball();
    w[1][0] = 1e-15 * w[1][1];
    let ok = InverseMass::single(w).unwrap();
    assert_eq!(ok.get(0, 1), ok.get(1, 0));
    // Bodies.
    assert_eq!(
        Body::new(
            0.0,
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            [0.0; 3]
        ),
        Err(Error::MassNotPositive)
    );
    assert_eq!(
        Body::new(
            1.0,
            [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]],
            [0.0; 3]
        ),
        Err(Error::InertiaNotPositiveDefinite)
    );
    assert_eq!(
        Body::new(
            1.0,
            [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            [0.0; 3]
        ),
        Err(Error::InertiaNotPositiveDefinite)
    );
    assert_eq!(
        Body::new(
            f64::NAN,
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            [0.0; 3]
        ),
        Err(Error::NonFinite("mass"))
    );
    assert_eq!(
        Free::new([0.0, f64::INFINITY, 0.0, 0.0], 0.0),
        Err(Error::NonFinite("u_free"))
    );
}

fn frame_z() -> Frame<f64> {
    Frame::new(
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
        MajorAxis::from_cos_sin(1.0, 0.0),
    )
}

#[test]
fn w_of_a_ball_on_a_plane_is_its_closed_form() {
    let i = 0.4 * M * R * R;
    let ball = Body::new(
        M,
        [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        [0.3, -0.2, R],
    )
    .unwrap();
    let cp = ContactPoint {
        a: None,
        b: Some(0),
        point: [0.3, -0.2, 0.0],
        frame: frame_z(),
    };
    let w = InverseMass::<f64, 1>::from_bodies(&[ball], &[cp]).unwrap();
    let want = w_ball();
    for a in 0..4 {
        for b in 0..4 {
            let scale = (want[a][a] * want[b][b]).sqrt();
            assert!(
                (w.get(a, b) - want[a][b]).abs() <= 1e-14 * scale,
                "W[{a}][{b}] = {} want {}",
                w.get(a, b),
                want[a][b]
            );
        }
    }
    // The same ball as body A (below a fixed world body B): the same W.
    let cp_a = ContactPoint {
        a: Some(0),
        b: None,
        ..cp
    };
    let wa = InverseMass::<f64, 1>::from_bodies(&[ball], &[cp_a]).unwrap();
    assert_eq!(wa, w);
    assert_eq!(
        InverseMass::<f64, 1>::from_bodies(&[ball], &[ContactPoint { b: Some(1), ..cp }]),
        Err(Error::BodyIndexInvalid)
    );
}

/// Δt → 0: the step-aware wrench tends to the plain wrench at the start state (first order:
/// the error halves with Δt).
#[test]
fn tends_to_the_plain_wrench_as_dt_shrinks() {
    let c = contact::<Best>(1e-4);
    let lin = numeric(c, 1e-7);
    let w = InverseMass::single(w_ball()).unwrap();
    let hs = h_static();
    let cases = [
        state(hs, 0.0, 0.05, 0.0, 0.0),
        state(2.0 * hs, 1e-3, 0.02, -0.01, 30.0),
        state(0.5 * hs, -2e-3, 0.0, 0.0, 100.0),
        state(hs, 0.0, 3e-5, 2e-5, 0.1),
    ];
    for s in cases {
        let plain = lin.wrench4(&s);
        let scale = plain[0];
        let mut last = f64::INFINITY;
        for dt in [1e-6, 1e-7, 1e-8, 1e-9] {
            let tstep = TimeStep::new(dt).unwrap();
            let o = step_wrench(&lin, tstep, &w, &s, &Free::coasting(tstep, &s));
            let err = (0..4)
                .map(|k| (o.wrench[k] - plain[k]).abs())
                .fold(0.0, f64::max)
                / scale;
            assert!(err < last.max(1e-12), "dt {dt}: err {err} after {last}");
            last = err;
        }
        eprintln!("dt → 0: {last:.2e} at 1 ns");
        assert!(last < 1e-4, "{s:?}: {last}");
    }
}

/// The backward-Euler normal force of a Hertz contact by bisection (by hand, independent of the
/// library): N̄ = k·(h_free − Δt²·W_nn·N̄)^{3/2}.
fn be_normal(k: f64, h_free: f64, c: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, k * h_free.powf(1.5));
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let h = h_free - c * mid;
        let n = if h > 0.0 { k * h.powf(1.5) } else { 0.0 };
        if n > mid { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

/// A block on a plane, Coulomb friction, W = diag(1/m, 1/m + R²/I, …), under gravity: the
/// backward-Euler step in closed form, by hand from N = k h^{3/2} (k analytic) and
/// F = −fN·v/max(|v|, δ): N̄ = k·(h_free − Δt²W_nn N̄)^{3/2} (bisection); full slip
/// F̄ = −f·N̄; sticking F̄ = −(fN̄/δ)·v_f/(1 + Δt·W_xx·fN̄/δ). The step's normal predictor and
/// two linearisations reach them within the asserted bounds (measured: N 1.8e-9, sticking F
/// 9.6e-6 relative at 5 ms, 1e-4 to 2 ms better).
#[test]
fn block_on_a_plane_matches_the_closed_form_backward_euler_step() {
    let delta = 1e-4;
    let c = contact::<Coulomb>(delta);
    let lin = numeric(c, 1e-7);
    let w = w_ball();
    let wm = InverseMass::single(w).unwrap();
    let k = k_hertz();
    let hs = h_static();
    let (mut worst, mut worst_f) = (0.0_f64, 0.0_f64);
    for dt in [1e-4, 1e-3, 2e-3, 5e-3] {
        let tstep = TimeStep::new(dt).unwrap();
        // Full slip along x (a fast slide that the step cannot stop).
        let s = state(hs, 0.0, 0.5, 0.0, 0.0);
        let free = under_gravity(dt, &s);
        let o = step_wrench(&lin, tstep, &wm, &s, &free);
        let n_bar = be_normal(k, free.h(), dt * dt * w[0][0]);
        let err = (o.wrench[0] - n_bar).abs() / n_bar;
        worst = worst.max(err);
        assert!(err < 1e-7, "{dt}: N {} vs {n_bar}", o.wrench[0]);
        let n = o.wrench[0];
        assert!(
            (o.wrench[1] + F * n).abs() < 1e-6 * n,
            "{dt}: F {} vs {}",
            o.wrench[1],
            -F * n
        );
        assert_eq!((o.wrench[2], o.wrench[3]), (0.0, 0.0));
        let v_end = 0.5 + dt * w[1][1] * o.wrench[1];
        assert!((o.u_end[1] - v_end).abs() < 1e-12);
        assert!(!o.flags.reversed_slip && !o.flags.limited && !o.flags.force_scaled);

        // Sticking: v_free inside the ramp (|v| < δ).
        let v_f = 0.3 * delta;
        let s = state(hs, 0.0, v_f, 0.0, 0.0);
        let free = under_gravity(dt, &s);
        let o = step_wrench(&lin, tstep, &wm, &s, &free);
        let n = o.wrench[0];
        let f_bar = -(F * v_f * n / delta) / (1.0 + dt * w[1][1] * F * n / delta);
        let err_f = (o.wrench[1] - f_bar).abs() / f_bar.abs();
        worst_f = worst_f.max(err_f);
        assert!(err_f < 1e-4, "{dt}: F {} vs {f_bar}", o.wrench[1]);
        assert!(o.u_end[1].abs() < v_f && o.u_end[1] >= 0.0);
    }
    eprintln!(
        "worst relative error against backward Euler: N {worst:.2e}, sticking F {worst_f:.2e}"
    );
}

/// Two contacts on one body (two feet at x = ±L of a compact body, I = 4mL² so that a push at
/// one foot lifts the other): foot 1 lands fast, foot 2 rests. The joint solve finds N₂ ≤ 0,
/// drops foot 2 and solves again: foot 1's wrench is then the single-contact step with W₁₁,
/// foot 2's is zero (not clamped after a joint solve).
#[test]
fn two_contacts_sharing_a_body_use_an_active_set() {
    let l = 5e-3;
    let i = 4.0 * M * l * l;
    let ident = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let body = Body::principal(M, [i, i, i], ident, [0.0, 0.0, R]).unwrap();
    let feet = [-l, l].map(|x| ContactPoint {
        a: None,
        b: Some(0),
        point: [x, 0.0, 0.0],
        frame: frame_z(),
    });
    let w = InverseMass::<f64, 2>::from_bodies(&[body], &feet).unwrap();
    // 1/m − L²/I > 0 (a push up at one foot moves the other up) minus the tilt's lever: check
    // the sign the scenario relies on.
    assert!(w.block(1, 0)[0][0] > 0.0);
    let c = contact::<Coulomb>(1e-4);
    let lin = numeric(c, 1e-7);
    let hs = h_static();
    let dt = TimeStep::new(1e-3).unwrap();
    let states = [
        state(hs, 0.05, 0.0, 0.0, 0.0),
        state(hs, 0.0, 0.0, 0.0, 0.0),
    ];
    let free = states.map(|s| Free::coasting(dt, &s));
    let both = step_wrenches([&lin as &dyn Linearize<f64>, &lin], dt, &w, &states, &free);
    assert!(both[0].flags.active && both[0].wrench[0] > 0.0);
    assert!(!both[1].flags.active);
    assert_eq!(both[1].wrench, [0.0; 4]);
    let w11 = InverseMass::single(w.block(0, 0)).unwrap();
    let one = step_wrench(&lin, dt, &w11, &states[0], &free[0]);
    for k in 0..4 {
        assert!(
            (one.wrench[k] - both[0].wrench[k]).abs() <= 1e-12 * one.wrench[0],
            "{k}: {:?} vs {:?}",
            one.wrench,
            both[0].wrench
        );
    }
    // Foot 2 lifts: its end velocity is positive (separating).
    assert!(both[1].u_end[0] > 0.0);
    // Both feet resting: both active and each carries about half the weight after settling
    // (steady state of the semi-implicit step under gravity).
    let mut st = [state(hs, 0.0, 0.0, 0.0, 0.0); 2];
    let mut vz = 0.0;
    let mut h = hs;
    for _ in 0..2000 {
        let s = state(h, -vz, 0.0, 0.0, 0.0);
        st = [s, s];
        let u = [vz - G * dt.get(), 0.0, 0.0, 0.0];
        let fr = st.map(|s| Free::predicted(dt, &s, u).unwrap());
        let o = step_wrenches([&lin as &dyn Linearize<f64>, &lin], dt, &w, &st, &fr);
        vz = o[0].u_end[0];
        h = o[0].h_end;
        assert!(o[0].flags.active && o[1].flags.active);
        assert!(
            (o[0].wrench[0] - o[1].wrench[0]).abs() <= 1e-9 * o[0].wrench[0],
            "{o:?}"
        );
    }
    let o = step_wrenches(
        [&lin as &dyn Linearize<f64>, &lin],
        dt,
        &w,
        &st,
        &st.map(|s| Free::predicted(dt, &s, [vz - G * dt.get(), 0.0, 0.0, 0.0]).unwrap()),
    );
    let total = o[0].wrench[0] + o[1].wrench[0];
    assert!((total - M * G).abs() < 1e-6 * M * G, "{total} vs {}", M * G);
}

/// A ball resting under gravity (semi-implicit steps at 1–5 ms, far above the normal mode's
/// explicit limit ≈ 0.14 ms): it settles to N = mg, no bounce, energy never rising.
#[test]
fn a_resting_ball_settles_at_large_steps() {
    let c = contact::<Best>(1e-4);
    let lin = numeric(c, 1e-7);
    let w = InverseMass::single(w_ball()).unwrap();
    for dt in [1e-3, 2e-3, 5e-3] {
        let mut s = state(h_static(), 0.0, 0.0, 0.0, 0.0);
        let tstep = TimeStep::new(dt).unwrap();
        let mut n = 0.0;
        for _ in 0..500 {
            let free = under_gravity(dt, &s);
            let o = step_wrench(&lin, tstep, &w, &s, &free);
            assert!(o.flags.active, "{dt}: lost contact");
            n = o.wrench[0];
            s = state(o.h_end, -o.u_end[0], o.u_end[1], o.u_end[2], o.u_end[3]);
        }
        assert!((n - M * G).abs() < 1e-6 * M * G, "{dt}: N {n} vs {}", M * G);
        assert!(s.hdot.abs() < 1e-9);
    }
}

/// Sticking: a ball on a plane pushed along x by a tangential acceleration of half what
/// friction can hold (u_free,x = v + a_t·Δt), at steps from 0.1 ms to 20 ms (the friction
/// ramp's explicit limit is ≈ 20 µs here): the end slip stays below δ at every step, never
/// changes sign, and the friction force holds the push on average.
#[test]
fn sticking_keeps_the_end_slip_below_delta_at_any_step() {
    let delta = 1e-4;
    for law in 0..2 {
        let lin_best = numeric(contact::<Best>(delta), 1e-7);
        let lin_coul = numeric(contact::<Coulomb>(delta), 1e-7);
        let lin: &dyn Linearize<f64> = if law == 0 { &lin_best } else { &lin_coul };
        let w = w_ball();
        let wm = InverseMass::single(w).unwrap();
        // the push, as a slip acceleration: half of f·N·W_xx at N = mg
        let a_t = 0.5 * F * M * G * w[1][1];
        for dt in [1e-4, 1e-3, 5e-3, 2e-2] {
            let tstep = TimeStep::new(dt).unwrap();
            let mut s = state(h_static(), 0.0, 0.0, 0.0, 0.0);
            let mut worst = 0.0_f64;
            let mut impulse = 0.0;
            let steps = (0.2 / dt) as usize;
            for _ in 0..steps {
                let u = [
                    -s.hdot - G * dt,
                    s.slip.vx() + a_t * dt,
                    s.slip.vy(),
                    s.slip.omega(),
                ];
                let free = Free::predicted(tstep, &s, u).unwrap();
                let o = step_wrenches([lin], tstep, &wm, &[s], &[free])[0];
                assert!(o.u_end[1] >= 0.0, "law {law} dt {dt}: slip flipped: {o:?}");
                worst = worst.max(o.u_end[1]);
                impulse += o.wrench[1] * dt;
                s = state(o.h_end, -o.u_end[0], o.u_end[1], o.u_end[2], o.u_end[3]);
            }
            assert!(worst < delta, "law {law} dt {dt}: end slip {worst} ≥ δ");
            // friction's mean force balances the push (within the slip's own growth)
            let mean = -impulse / (steps as f64 * dt) * w[1][1];
            assert!(
                (mean - a_t).abs() < 0.02 * a_t,
                "law {law} dt {dt}: {mean} vs {a_t}"
            );
        }
    }
}

/// Slip reversal: a ball sliding at 1 cm/s (100 δ) that friction stops within one 5 ms step
/// (f·g·W_xx·m·Δt ≈ 1.7 cm/s): the step detects the reversal, the end slip is below δ and keeps
/// its sign; the force is the one that stops the slip, −v/(Δt·W_xx), not the full fN
/// (which would drive the slip to −0.7 cm/s and back every step). The same for the spin
/// (δ = 1e-9 so that the spin is in full slip: aω ≫ δ).
#[test]
fn a_slip_that_would_reverse_within_the_step_is_stopped() {
    let dt = 5e-3;
    let tstep = TimeStep::new(dt).unwrap();
    let w = w_ball();
    let wm = InverseMass::single(w).unwrap();
    let delta = 1e-4;
    let lin = numeric(contact::<Best>(delta), 1e-7);
    let mut s = state(h_static(), 0.0, 0.01, 0.0, 0.0);
    for k in 0..50 {
        let free = under_gravity(dt, &s);
        let o = step_wrench(&lin, tstep, &wm, &s, &free);
        if k == 0 {
            assert!(o.flags.reversed_slip || o.flags.force_scaled, "{o:?}");
            let stop = -0.01 / (dt * w[1][1]);
            assert!(
                (o.wrench[1] - stop).abs() < 0.01 * stop.abs(),
                "{o:?} vs {stop}"
            );
        }
        assert!(o.u_end[1] >= 0.0 && o.u_end[1] < delta, "step {k}: {o:?}");
        s = state(o.h_end, -o.u_end[0], o.u_end[1], o.u_end[2], o.u_end[3]);
    }
    // Spin: full slip down to 1e-9 m/s.
    let lin = numeric(contact::<Best>(1e-9), 1e-10);
    let hs = h_static();
    let a = (R * hs).sqrt();
    let om = 1e-3; // a·ω ≈ 2.8e-8 m/s ≫ δ; the torque (≈ 2e-3 rad/s per step) stops it
    let mut s = state(hs, 0.0, 0.0, 0.0, om);
    for k in 0..20 {
        let free = under_gravity(dt, &s);
        let o = step_wrench(&lin, tstep, &wm, &s, &free);
        if k == 0 {
            assert!(o.flags.reversed_spin || o.flags.torque_scaled, "{o:?}");
        }
        assert!(
            o.u_end[3] >= 0.0 && a * o.u_end[3] < 1e-9,
            "step {k}: {o:?}"
        );
        s = state(o.h_end, -o.u_end[0], o.u_end[1], o.u_end[2], o.u_end[3]);
    }
}

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;
#[path = "common/on_plane.rs"]
mod on_plane;
use on_plane::on_plane;

impl Rng {
    /// 10^x, x uniform in [lo, hi).
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.range(lo, hi))
    }
}

/// Worst figures of a random run: friction power over its rounding scale (force, torque), the
/// largest excess over the limit set's supporting planes, the smallest N.
#[derive(Debug, Default)]
struct Worst {
    force_power: f64,
    torque_power: f64,
    limit: f64,
    reversals: usize,
    limited: usize,
    scaled: usize,
}

/// Random states, steps and bodies for friction law `L` (module docs of src/step/): every
/// result finite, N ≥ 0, F·v⁺ ≤ 0 and T_z·ω⁺ ≤ 0 (up to rounding: 1e-12 of |F|·(|v_free| +
/// |Δv|)) with u⁺ = u_free + Δt·W·w̄ computed here, and the friction pair inside the law's
/// full-slip limit set at N̄: −p·s ≤ (1 + tol)·D(s) over 26 support directions s, D(s) the
/// law's full-slip dissipation at the patch of N̄.
fn random_run<L: FrictionLaw>(n: usize, seed: u64) -> Worst {
    let mut rng = Rng(seed);
    let k = k_hertz();
    let hs = h_static();
    let mut worst = Worst::default();
    for case in 0..n {
        let f = rng.range(0.05, 0.8);
        let delta = rng.log(-6.0, -2.0);
        let c = contact_f::<L>(f, delta);
        let lin = numeric(c, 1e-3 * delta);
        // A random body: mass, an inertia of the ball's order with random axes, the centre
        // above the contact point with a random offset.
        let m = rng.log(-3.0, 0.0);
        let mut a = [[0.0; 3]; 3];
        for r in a.iter_mut() {
            for e in r.iter_mut() {
                *e = rng.range(-1.0, 1.0);
            }
        }
        let mut inertia = [[0.0; 3]; 3];
        for r in 0..3 {
            for cc in 0..3 {
                let mut s = if r == cc { 0.2 } else { 0.0 };
                for q in 0..3 {
                    s += 0.3 * a[r][q] * a[cc][q];
                }
                inertia[r][cc] = m * R * R * s;
            }
        }
        let centre = [
            rng.range(-1.0, 1.0) * R,
            rng.range(-1.0, 1.0) * R,
            rng.range(0.5, 1.5) * R,
        ];
        let body = Body::new(m, inertia, centre).unwrap();
        let phi = rng.range(0.0, 6.3);
        let wm = on_plane(body, [phi.cos(), phi.sin(), 0.0]);
        let dt = rng.log(-5.0, -2.0);
        let tstep = TimeStep::new(dt).unwrap();
        let h = if rng.next() < 0.1 {
            -hs * rng.next()
        } else {
            hs * rng.log(-1.0, 1.0)
        };
        let speed = rng.log(-7.0, 0.0);
        let dir = rng.range(0.0, 6.3);
        let om = rng.sign() * rng.log(-3.0, 3.0);
        let s = state(
            h,
            rng.range(-1e-2, 1e-2),
            speed * dir.cos(),
            speed * dir.sin(),
            om,
        );
        let u = [
            -s.hdot - G * dt * rng.range(0.0, 2.0),
            s.slip.vx() + rng.range(-1.0, 1.0) * speed,
            s.slip.vy() + rng.range(-1.0, 1.0) * speed,
            s.slip.omega() * rng.range(0.0, 2.0),
        ];
        let free = Free::predicted(tstep, &s, u).unwrap();
        let o = step_wrench(&lin, tstep, &wm, &s, &free);
        let w = o.wrench;
        assert!(w.iter().all(|x| x.is_finite()), "case {case}: {o:?}");
        assert!(w[0] >= 0.0, "case {case}: {o:?}");
        // u⁺ here, from W and the wrench.
        let mut up = u;
        for r in 0..4 {
            for cc in 0..4 {
                up[r] += dt * wm.get(r, cc) * w[cc];
            }
        }
        let fmag = w[1].hypot(w[2]);
        let fp = w[1] * up[1] + w[2] * up[2];
        let fscale = fmag * (u[1].hypot(u[2]) + (up[1] - u[1]).hypot(up[2] - u[2]));
        if fp > 0.0 {
            worst.force_power = worst.force_power.max(fp / fscale);
            assert!(fp <= 1e-12 * fscale, "case {case}: F·v⁺ = {fp:e}: {o:?}");
        }
        let tp = w[3] * up[3];
        let tscale = w[3].abs() * (u[3].abs() + (up[3] - u[3]).abs());
        if tp > 0.0 {
            worst.torque_power = worst.torque_power.max(tp / tscale);
            assert!(tp <= 1e-12 * tscale, "case {case}: T·ω⁺ = {tp:e}: {o:?}");
        }
        worst.reversals += (o.flags.reversed_slip || o.flags.reversed_spin) as usize;
        worst.limited += o.flags.limited as usize;
        worst.scaled += (o.flags.force_scaled || o.flags.torque_scaled) as usize;
        if w[0] > 0.0 && (fmag > 0.0 || w[3] != 0.0) {
            // The limit set at N̄: the patch of h = (N̄/k)^{2/3}, full slip at 1e4 m/s.
            let hn = (w[0] / k).powf(2.0 / 3.0);
            let a_n = (R * hn).sqrt();
            if !L::MAXIMALLY_DISSIPATIVE {
                // The cylinder |F| ≤ F_max (pure translation along −F), |T_z| ≤ T_max (pure
                // spin), at N̄ (src/step/project.rs).
                let (ex, ey) = if fmag > 0.0 {
                    (w[1] / fmag, w[2] / fmag)
                } else {
                    (1.0, 0.0)
                };
                let tr = c.wrench(hn, 0.0, Slip::new(-1e4 * ex, -1e4 * ey, 0.0).unwrap());
                let sp = c.wrench(
                    hn,
                    0.0,
                    Slip::new(0.0, 0.0, -1e4 * w[3].signum() / a_n).unwrap(),
                );
                let f_max = tr.fx.hypot(tr.fy) * w[0] / tr.n;
                let t_max = sp.tz.abs() * w[0] / sp.n;
                let excess = (fmag / f_max - 1.0).max(if t_max > 0.0 {
                    w[3].abs() / t_max - 1.0
                } else {
                    0.0
                });
                worst.limit = worst.limit.max(excess);
                continue;
            }
            let mut dirs: Vec<[f64; 3]> = vec![
                [1.0, 0.0, 0.0],
                [-1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, -1.0, 0.0],
                [0.0, 0.0, 1.0],
                [0.0, 0.0, -1.0],
                // the pair's own ellipsoidal dual direction
                [-w[1], -w[2], -w[3] / (0.589 * a_n)],
            ];
            for _ in 0..19 {
                dirs.push([
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                    rng.range(-1.0, 1.0),
                ]);
            }
            for d in dirs {
                let m_ = d[0].abs().max(d[1].abs()).max(d[2].abs());
                if m_ == 0.0 {
                    continue;
                }
                // s = (v_x, v_y, a·ω) direction → slip (v_x, v_y, ω)
                let sc = 1e4 / m_;
                let sl = Slip::new(d[0] * sc, d[1] * sc, d[2] * sc / a_n).unwrap();
                let pf = c.wrench(hn, 0.0, sl);
                let scale = w[0] / pf.n;
                let s3 = [d[0], d[1], d[2] / a_n];
                let dsup = -(pf.fx * s3[0] + pf.fy * s3[1] + pf.tz * s3[2]) * scale;
                let dp = -(w[1] * s3[0] + w[2] * s3[1] + w[3] * s3[2]);
                let excess = (dp - dsup) / dsup.abs().max(1e-300);
                if std::env::var("STEP_DEBUG")
                    .ok()
                    .and_then(|v| v.parse::<f64>().ok())
                    .is_some_and(|t| excess > t)
                {
                    eprintln!(
                        "{} excess {excess:.3e} d {d:?} hn {hn:e} o {o:?} dt {dt:e} delta {delta:e} s {s:?} u {u:?} f {f} case {case} W {:?}",
                        std::any::type_name::<L>(),
                        (0..4)
                            .map(|r| (0..4).map(|q| wm.get(r, q)).collect::<Vec<_>>())
                            .collect::<Vec<_>>()
                    );
                }
                worst.limit = worst.limit.max(excess);
            }
        }
    }
    worst
}

/// Limit-set bound per law: 2e-3 relative for the laws whose full-slip value is the support
/// point of their own limit set (maximal dissipation: `coulomb`, `ellipsoid`; measured on 1e5
/// states: 1.0e-3, 1.0e-3 — the projection's 1e-3 tolerance) and for `best`, whose projection
/// works on its table's full-slip values (measured 1.42e-3: the one supporting plane tested at
/// the pair's dual direction). The normal re-solve (src/step/normal.rs) scales the torque with
/// the patch as well as with N, so that a friction pair on the boundary of the set at the old N
/// stays on it at the new one (scaled with N alone, a torque at a falling N lay outside by
/// (N_old/N)^{1/3}, up to 2.004e-3 by this measure, which the one-plane test let through).
/// `simplified` and `pade` (not maximally dissipative) are checked against their cylinder
/// |F| ≤ F_max, |T_z| ≤ T_max (src/step/project.rs), 2e-3 as well (measured 1.0e-3 and
/// 9.6e-4 on 1e5 states: the projection's tolerance).
const LIMIT_BOUND: [(&str, f64); 5] = [
    ("best", 2e-3),
    ("coulomb", 2e-3),
    ("ellipsoid", 2e-3),
    ("simplified", 2e-3),
    ("pade", 2e-3),
];

fn run_all(n: usize, seed: u64) {
    use contensou::friction::{Ellipsoid, Pade, Simplified};
    let runs = [
        random_run::<Best>(n, seed),
        random_run::<Coulomb>(n, seed + 1),
        random_run::<Ellipsoid>(n, seed + 2),
        random_run::<Simplified>(n, seed + 3),
        random_run::<Pade>(n, seed + 4),
    ];
    for ((name, bound), wst) in LIMIT_BOUND.iter().zip(runs) {
        eprintln!("{name}: {wst:?}");
        assert!(wst.limit < *bound, "{name}: {wst:?}");
    }
}

#[test]
fn passive_and_inside_the_limit_set_on_random_states() {
    run_all(300, 1);
}

/// The release run on 1e5 random states per law (`cargo test --release --test step_wrench --
/// --include-ignored`).
#[test]
#[ignore]
fn passive_and_inside_the_limit_set_on_1e5_random_states() {
    run_all(100_000, 11);
}

/// The plain path's limits (src/step/stable.rs), measured by integrating: RK4 on the ball's
/// Hertz normal mode (small oscillation about the static approach) decays at 0.97 of
/// `stable_normal_step` and grows at 1.03; forward Euler on the creep of a rolling contact
/// (`table`, small creepage) decays at 0.9 of `stable_creep_step` and grows at 1.1.
#[test]
fn plain_step_limits_for_the_normal_mode_and_the_creep() {
    use contensou::contact::Rolling;
    use contensou::friction::Explicit;
    use contensou::friction::rolling::{Elasticity, RollingVelocity, Table};
    let c = contact::<Best>(1e-4);
    let n0 = M * G;
    let h_star = c.stable_normal_step(M, n0, Explicit::Rk4);
    assert_eq!(c.stable_normal_step(M, n0, Explicit::Euler), 0.0);
    let hs = h_static();
    // ω by hand: k_n = (3/2)·k·h^{1/2}
    let w = (1.5 * k_hertz() * hs.sqrt() / M).sqrt();
    assert!((h_star * w - 8f64.sqrt()).abs() < 1e-9, "{h_star} {w}");
    let rk4_amplitude = |dt: f64| {
        // x = h − h_s, ẍ = g − N(h)/m
        let acc = |x: f64| G - c.wrench(hs + x, 0.0, Slip::default()).n / M;
        let (mut x, mut v) = (1e-4 * hs, 0.0);
        for _ in 0..4000 {
            let (k1x, k1v) = (v, acc(x));
            let (k2x, k2v) = (v + 0.5 * dt * k1v, acc(x + 0.5 * dt * k1x));
            let (k3x, k3v) = (v + 0.5 * dt * k2v, acc(x + 0.5 * dt * k2x));
            let (k4x, k4v) = (v + dt * k3v, acc(x + dt * k3x));
            x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
        (x * x + (v / w) * (v / w)).sqrt() / (1e-4 * hs)
    };
    assert!(rk4_amplitude(0.97 * h_star) < 1.0);
    assert!(rk4_amplitude(1.03 * h_star) > 2.0);

    let base = contact::<Best>(0.0);
    let rolling = Rolling::<_, _, Table>::new(base, Elasticity::new(8e10, 0.3).unwrap()).unwrap();
    let v = RollingVelocity::new(1.0, 0.0).unwrap();
    let m_t = 2.0 * M / 7.0;
    let h_creep = rolling.stable_creep_step(m_t, n0, v, Explicit::Euler);
    let euler_growth = |dt: f64| {
        let mut x = 1e-7;
        for _ in 0..200 {
            let f = rolling
                .wrench(hs, 0.0, Slip::new(x, 0.0, 0.0).unwrap(), v)
                .fx;
            x += dt * f / m_t;
        }
        x.abs() / 1e-7
    };
    assert!(
        euler_growth(0.9 * h_creep) < 1.0,
        "{}",
        euler_growth(0.9 * h_creep)
    );
    assert!(
        euler_growth(1.1 * h_creep) > 10.0,
        "{}",
        euler_growth(1.1 * h_creep)
    );
}

/// f32: the ball resting under gravity at 1 and 5 ms settles at N = mg, and a push below the
/// friction limit sticks (end slip < δ), with the f32 wrench linearised by f32 central
/// differences (steps 1 % of h, δ/10).
#[test]
fn f32_resting_and_sticking() {
    let c = Contact::<f32, Hertz<f32>, Undamped, Best>::circular(
        &Curvatures::sphere_plane(R as f32).unwrap(),
        Modulus::new(ESTAR as f32).unwrap(),
        Undamped,
        Friction::new(F as f32, 1e-4).unwrap(),
    )
    .unwrap();
    let hs = h_static() as f32;
    let lin = Numeric::new(
        move |s: &State<f32>| {
            let w = c.wrench(s.h, s.hdot, s.slip);
            [w.n, w.fx, w.fy, w.tz]
        },
        [1e-2 * hs, 1e-4, 1e-5, 1e-5, 1e-1],
    );
    let w64 = w_ball();
    let mut w = [[0f32; 4]; 4];
    for a in 0..4 {
        for b in 0..4 {
            w[a][b] = w64[a][b] as f32;
        }
    }
    let wm = InverseMass::single(w).unwrap();
    let (m, g) = (M as f32, G as f32);
    let a_t = 0.5 * F as f32 * m * g * w[1][1];
    for dt in [1e-3f32, 5e-3] {
        let tstep = TimeStep::new(dt).unwrap();
        let mut s = State {
            h: hs,
            ..State::default()
        };
        let mut n = 0.0;
        for _ in 0..400 {
            let u = [-s.hdot - g * dt, s.slip.vx() + a_t * dt, 0.0, 0.0];
            let free = Free::predicted(tstep, &s, u).unwrap();
            let o = step_wrench(&lin, tstep, &wm, &s, &free);
            assert!(
                o.wrench.iter().all(|x| x.is_finite()) && o.flags.active,
                "{o:?}"
            );
            assert!(o.u_end[1] >= 0.0 && o.u_end[1] < 1e-4, "{dt}: {o:?}");
            n = o.wrench[0];
            s = State {
                h: o.h_end,
                hdot: -o.u_end[0],
                slip: Slip::new(o.u_end[1], o.u_end[2], o.u_end[3]).unwrap(),
                ..State::default()
            };
        }
        assert!((n - m * g).abs() < 1e-4 * m * g, "{dt}: {n} vs {}", m * g);
    }
}

/// Two contacts on one random body (random feet, frames, states, steps): every result finite,
/// N ≥ 0, and each contact's friction force and drilling torque inject no power at the joint
/// end velocity u⁺ = u_free + Δt·W·w̄ (cross blocks included), computed here. Returns how
/// often the active set dropped a contact that the free motion had in contact.
fn random_pairs(n: usize, seed: u64) -> usize {
    let mut rng = Rng(seed);
    let hs = h_static();
    let mut dropped = 0;
    for case in 0..n {
        let delta = rng.log(-6.0, -2.0);
        let lin = numeric(contact_f::<Best>(rng.range(0.05, 0.8), delta), 1e-3 * delta);
        let m = rng.log(-3.0, 0.0);
        let i = m * R * R * rng.range(0.1, 4.0);
        let ident = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let body =
            Body::principal(m, [i, i * rng.range(0.5, 2.0), i], ident, [0.0, 0.0, R]).unwrap();
        let feet: [ContactPoint<f64>; 2] = core::array::from_fn(|_| {
            let phi = rng.range(0.0, 6.3);
            ContactPoint {
                a: None,
                b: Some(0),
                point: [rng.range(-1.0, 1.0) * R, rng.range(-1.0, 1.0) * R, 0.0],
                frame: Frame::new(
                    [0.0, 0.0, 1.0],
                    [phi.cos(), phi.sin(), 0.0],
                    MajorAxis::from_cos_sin(1.0, 0.0),
                ),
            }
        });
        let wm = InverseMass::<f64, 2>::from_bodies(&[body], &feet).unwrap();
        let dt = rng.log(-5.0, -2.0);
        let tstep = TimeStep::new(dt).unwrap();
        let states: [State<f64>; 2] = core::array::from_fn(|_| {
            let speed = rng.log(-7.0, 0.0);
            let dir = rng.range(0.0, 6.3);
            state(
                hs * rng.log(-1.0, 1.0),
                rng.range(-1e-2, 1e-2),
                speed * dir.cos(),
                speed * dir.sin(),
                rng.sign() * rng.log(-3.0, 3.0),
            )
        });
        let free = states.map(|s| under_gravity(dt, &s));
        let o = step_wrenches(
            [&lin as &dyn Linearize<f64>, &lin],
            tstep,
            &wm,
            &states,
            &free,
        );
        for k in 0..2 {
            let w = o[k].wrench;
            assert!(
                w.iter().all(|x| x.is_finite()) && w[0] >= 0.0,
                "case {case}: {o:?}"
            );
            dropped += (free[k].h() > 0.0 && !o[k].flags.active) as usize;
            let u = free[k].u();
            let mut up = u;
            for a in 0..4 {
                for j in 0..2 {
                    for b in 0..4 {
                        up[a] += dt * wm.block(k, j)[a][b] * o[j].wrench[b];
                    }
                }
            }
            let fp = w[1] * up[1] + w[2] * up[2];
            let fscale = w[1].hypot(w[2]) * (u[1].hypot(u[2]) + (up[1] - u[1]).hypot(up[2] - u[2]));
            assert!(
                fp <= 1e-12 * fscale,
                "case {case} contact {k}: F·v⁺ = {fp:e}: {o:?}"
            );
            let tp = w[3] * up[3];
            let tscale = w[3].abs() * (u[3].abs() + (up[3] - u[3]).abs());
            assert!(
                tp <= 1e-12 * tscale,
                "case {case} contact {k}: T·ω⁺ = {tp:e}: {o:?}"
            );
        }
    }
    dropped
}

#[test]
fn two_contacts_passive_on_random_states() {
    let dropped = random_pairs(300, 21);
    eprintln!("contacts dropped by the active set: {dropped} of 600");
}

/// 2e4 random pairs in release (with the 1e5 single-contact run).
#[test]
#[ignore]
fn two_contacts_passive_on_2e4_random_states() {
    let dropped = random_pairs(20_000, 22);
    eprintln!("contacts dropped by the active set: {dropped} of 40000");
}

/// A rolling contact (`table`, V = 1 m/s along x) whose spin creep drives a lateral force
/// against a small opposite lateral creep: F_y·v_y > 0 while F·v + T_z·ω < 0 (Kalker's
/// spin–lateral coupling). The power check gates on the sum for a rolling contact, so as
/// Δt → 0 the step-aware wrench still tends to the plain one (no part scaled).
#[test]
fn rolling_spin_coupling_is_not_taken_for_injected_power() {
    use contensou::contact::Rolling;
    use contensou::friction::rolling::{Elasticity, RollingVelocity, Table};
    let rolling =
        Rolling::<_, _, Table>::new(contact::<Best>(0.0), Elasticity::new(8e10, 0.3).unwrap())
            .unwrap();
    let v = RollingVelocity::new(1.0, 0.0).unwrap();
    let lin = Numeric::new(
        move |s: &State<f64>| {
            let w = rolling.wrench(s.h, s.hdot, s.slip, s.rolling);
            [w.n, w.fx, w.fy, w.tz]
        },
        [1e-4 * h_static(), 1e-6, 1e-9, 1e-9, 1e-5],
    );
    let s = State {
        rolling: v,
        ..state(h_static(), 0.0, 0.0, -2e-6, 0.5)
    };
    let plain = lin.wrench4(&s);
    assert!(
        plain[2] * s.slip.vy() > 0.0,
        "the scenario needs F_y·v_y > 0: {plain:?}"
    );
    assert!(plain[2] * s.slip.vy() + plain[3] * s.slip.omega() < 0.0);
    let w = InverseMass::single(w_ball()).unwrap();
    let dt = TimeStep::new(1e-9).unwrap();
    let o = step_wrench(&lin, dt, &w, &s, &Free::coasting(dt, &s));
    assert!(!o.flags.force_scaled && !o.flags.torque_scaled, "{o:?}");
    for k in 1..4 {
        assert!(
            (o.wrench[k] - plain[k]).abs() < 1e-4 * plain[0],
            "{o:?} vs {plain:?}"
        );
    }
}
