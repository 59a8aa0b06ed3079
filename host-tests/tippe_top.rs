//! The tippe top scene (feature `scenes`): energy is non-increasing, the top inverts with the
//! simplified Contensou law and not with a steep Coulomb law, Jellett's quantity is kept by
//! Coulomb friction on the big sphere, and the f32 RK4 step stays finite.

use contensou::friction::{Constants, Coulomb, Friction, FrictionLaw, Simplified};
use contensou::scenes::integrate::{dopri45, rk4};
use contensou::scenes::tippe_top::{Events, Params, Probe, TippeTop};

#[path = "common/paper_top.rs"]
mod paper_top;
use paper_top::{paper_top, tolerance};

/// Adaptive run of the paper's top to `t_end`: the probes after every accepted step.
fn run<L: FrictionLaw>(delta: f64, t_end: f64) -> Vec<(f64, Probe<f64>)> {
    run_events::<L>(delta, t_end).0
}

/// [`run`] and the events located between its accepted steps.
fn run_events<L: FrictionLaw>(delta: f64, t_end: f64) -> (Vec<(f64, Probe<f64>)>, Events<f64>) {
    let (top, y0) = paper_top::<f64, L>(delta);
    let tol = tolerance(1e-6);
    let mut out = vec![(0.0, top.probe(&y0))];
    let mut events = Events::new(&top, 0.0, &y0);
    let (t, _, s) = dopri45(&top, 0.0, y0, t_end, 1e-6, 1e-3, &tol, 1_000_000, |t, y| {
        events.update(&top, t, y);
        out.push((t, top.probe(y)))
    });
    assert!(s.finished && t == t_end);
    (out, events)
}

fn theta_star() -> f64 {
    (-10.0f64 / 13.0).acos()
}

// The simplified law's events with f64 RK4 at h = 10 µs, located between steps
// (`cargo run --release --features scenes --example tippe_top`; docs/guide/src/tippe-top.md).
/// θ = π/2 (s).
const T_HALF: f64 = 1.148067;
/// θ = θ* (s).
const T_INVERSION: f64 = 1.847504;
/// The small sphere touches down (s).
const T_TOUCH: f64 = 1.847495;

#[test]
fn simplified_inverts_and_energy_does_not_grow() {
    let (rows, events) = run_events::<Simplified>(1e-4, 2.5);
    // Located between the adaptive steps (up to 1 ms long) as between RK4's 10 µs steps
    // (example: θ = π/2 at T_HALF, θ* at T_INVERSION, touch-down at T_TOUCH).
    for (what, got, rk4) in [
        ("θ = π/2", events.half(), T_HALF),
        ("θ = θ*", events.inversion(), T_INVERSION),
        ("touch-down", events.touch_down(), T_TOUCH),
    ] {
        println!("{what}: Dormand–Prince {got:?}, RK4 10 µs {rk4}");
        assert!(
            got.is_some_and(|t| (t - rk4).abs() < 2e-4),
            "{what}: {got:?} vs RK4 {rk4}"
        );
    }
    let e0 = rows[0].1.energy;
    // Non-increasing up to integration error: never above any earlier value by > 1e-6·E₀.
    let mut min_so_far = e0;
    for (t, p) in &rows {
        assert!(
            p.energy <= min_so_far + 1e-6 * e0,
            "t = {t}: {} > {min_so_far}",
            p.energy
        );
        min_so_far = min_so_far.min(p.energy);
    }
    let inversion = rows
        .iter()
        .find(|(_, p)| p.theta >= theta_star())
        .map(|r| r.0);
    assert!(inversion.is_some_and(|t| t < 2.5), "{inversion:?}");
    let last = rows.last().unwrap().1;
    // On the head: the big sphere off the floor, the spin reversed relative to e₃.
    assert!(last.theta > theta_star() && last.n_big == 0.0 && last.n_small > 0.0);
    assert!(last.spin < 0.0);
    // The drilling torque changes Jellett's quantity.
    assert!((last.jellett - rows[0].1.jellett).abs() > 0.05 * rows[0].1.jellett.abs());
}

#[test]
fn steep_coulomb_does_not_invert_and_keeps_jellett() {
    let rows = run::<Coulomb>(1e-4, 1.0);
    let j0 = rows[0].1.jellett;
    for (t, p) in &rows {
        assert!(p.theta < 0.5, "t = {t}: θ = {}", p.theta);
        assert!(
            (p.jellett - j0).abs() < 1e-3 * j0.abs(),
            "t = {t}: J = {} vs {j0}",
            p.jellett
        );
    }
}

#[test]
fn f32_rk4_with_a_40us_step_inverts_like_f64() {
    let (top, y0) = paper_top::<f32, Simplified>(1e-4);
    let mut events = Events::new(&top, 0.0, &y0);
    rk4(&top, 0.0, y0, 4e-5, 50_000, |_, t, y| {
        events.update(&top, t, y)
    });
    // f64 RK4 at h = 10 µs: T_INVERSION (located; the adaptive integrator agrees, above).
    let inversion = events.inversion().map(f64::from);
    assert!(
        inversion.is_some_and(|t| (t - T_INVERSION).abs() < 0.02),
        "{inversion:?}"
    );
}

#[test]
fn f32_rk4_resolves_the_contact_and_stays_finite() {
    let (top, y0) = paper_top::<f32, Simplified>(1e-4);
    let e0 = top.probe(&y0).energy;
    let mut n_max = 0.0f32;
    let y = rk4(&top, 0.0, y0, 1e-5, 2_000, |_, _, y| {
        n_max = n_max.max(top.probe(y).n_big);
    });
    let p = top.probe(&y);
    assert!(y.iter().all(|v| v.is_finite()));
    assert!(
        p.energy <= e0 * (1.0 + 1e-4) && p.energy > 0.99 * e0,
        "{} vs {e0}",
        p.energy
    );
    // Dropped from zero penetration, the undamped Hertz spring overshoots to h = 2.5^{2/3}·h_static,
    // N = 2.5·mg = 0.147 N (energy balance mg·h = (2/5)k h^{5/2}); damping takes a little off.
    let mg = 6e-3 * 9.81;
    assert!(n_max > 2.3 * mg && n_max < 2.5 * mg * 1.005, "{n_max}");
}

/// The MCU configuration (firmware/src/bin/tippe.rs): f32 RK4 at 94 µs, just under the
/// stable-step bound, touches the small sphere down within 5 ms of the f64 10 µs run (both
/// located between steps: 1.847327 s against 1.847495 s,
/// `cargo run --release --features scenes --example tippe_top_step`); `penetrations` agrees
/// with the contact evaluation.
#[test]
fn f32_rk4_at_94us_touches_down_within_5ms_of_f64() {
    use contensou::friction::Explicit;
    let p = Params::<f32>::paper();
    let friction = Friction::<f32, Simplified>::with_law(0.3, 1e-4).unwrap();
    let h = 94e-6f32;
    assert!(
        h <= friction.stable_step(
            &Constants::circle(),
            p.mass,
            p.mass * p.gravity,
            Explicit::Rk4
        )
    );
    let top = TippeTop::new(&p, friction).unwrap();
    let mut y = top.initial_state(0.1, 180.0);
    let mut events = Events::new(&top, 0.0, &y);
    let mut touch = None;
    for i in 0..30_000 {
        let t = i as f32 * h;
        y = contensou::scenes::integrate::rk4_step(&top, t, &y, h);
        events.update(&top, t + h, &y);
        let [hb, hs] = top.penetrations(&y);
        let [big, small] = top.contacts(&y);
        assert!(
            (hs - small.h).abs() <= 1e-8 && (hb - big.h).abs() <= 1e-8,
            "{hb} {} {hs} {}",
            big.h,
            small.h
        );
        if let Some(t) = events.touch_down() {
            assert!(hs >= 0.0 && t <= (i + 1) as f32 * h);
            touch = Some(f64::from(t));
            break;
        }
    }
    assert!(
        touch.is_some_and(|t| (t - T_TOUCH).abs() <= 5e-3),
        "{touch:?}"
    );
}
