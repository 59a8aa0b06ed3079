//! The per-step wrench (Hertz patch + friction law) against independent references: the
//! mpmath Hertz rows (tools/data/hertz_ref.csv) and the circle's closed forms (model.md §1, §3).
#![allow(clippy::excessive_precision)]

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::friction::{Best, Exact, Friction, FrictionLaw, Simplified, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{CompressionDamping, Hertz, Modulus, Undamped};
use contensou::shape::Newton;
use std::f64::consts::PI;

#[macro_use]
#[path = "common/each.rs"]
mod each;

fn rel(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

/// mpmath rows of one case: (E*, h, E(m), a, N).
fn reference(case: &str) -> Vec<(f64, f64, f64, f64, f64)> {
    include_str!("../tools/data/hertz_ref.csv")
        .lines()
        .filter(|l| l.starts_with(&format!("{case},")))
        .map(|l| {
            let f: Vec<f64> = l.split(',').skip(1).map(|x| x.parse().unwrap()).collect();
            // P,Q,Estar,h,c,m1,K,E,B,D,a,b,N,p0
            (f[2], f[3], f[7], f[10], f[12])
        })
        .collect()
}

/// Pure spin through the whole chain: N and a from Hertz, T_z = −f·N·a·(3/8)E(m) (exact for
/// every friction law that is exact at v = 0, as `Simplified` is).
fn bearing_pure_spin<T: Real>(race: Race, case: &str, tol: f64, varying: bool) {
    let f = 0.07;
    let curv = Curvatures::<T>::ball_race(
        T::from_f64(12.7e-3),
        T::from_f64(6.6e-3),
        T::from_f64(65e-3),
        T::ZERO,
        race,
    )
    .unwrap();
    let friction = Friction::<T, Simplified>::with_law(T::from_f64(f), T::ZERO).unwrap();
    let rows = reference(case);
    assert!(!rows.is_empty());
    for (estar, h, e, a, n) in rows {
        let modulus = Modulus::new(T::from_f64(estar)).unwrap();
        let slip = Slip::new(T::ZERO, T::ZERO, T::from_f64(300.0)).unwrap();
        let (h, hdot) = (T::from_f64(h), T::ZERO);
        let w = if varying {
            VaryingContact::new(modulus, Undamped, friction).wrench(&curv, h, hdot, slip)
        } else {
            Contact::hertz::<Newton>(&curv, modulus, Undamped, friction)
                .unwrap()
                .wrench(h, hdot, slip)
        };
        let want_tz = -f * n * a * 0.375 * e;
        for (what, got, want) in [("N", w.n, n), ("a", w.patch.a, a), ("Tz", w.tz, want_tz)] {
            let err = rel(got.to_f64(), want);
            assert!(
                err <= tol,
                "{case} {} varying={varying} {what}: rel err {err:e}",
                T::NAME
            );
        }
        assert_eq!((w.fx, w.fy), (T::ZERO, T::ZERO));
    }
}

#[test]
fn bearing_209_pure_spin_fixed_and_varying_geometry() {
    for (race, case) in [
        (Race::Inner, "bearing209_inner"),
        (Race::Outer, "bearing209_outer"),
    ] {
        bearing_pure_spin::<f64>(race, case, 1e-12, false);
        bearing_pure_spin::<f64>(race, case, 1e-10, true);
        bearing_pure_spin::<f32>(race, case, 2e-5, false);
        bearing_pure_spin::<f32>(race, case, 2e-5, true);
    }
}

/// The default law (`Best`, per-contact tables) against the same closed forms, within its
/// stated error (5.5e-5 fN, 4.5e-6 fNa), and its per-call form in `VaryingContact`.
#[test]
fn sphere_plane_default_law_within_its_stated_error() {
    let (r, estar, f, h, omega) = (0.01, 2e11, 0.3, 1e-6, 40.0);
    let curv = Curvatures::sphere_plane(r).unwrap();
    let modulus = Modulus::new(estar).unwrap();
    let friction = Friction::<f64>::new(f, 0.0).unwrap();
    let contact = Contact::hertz::<Newton>(&curv, modulus, Undamped, friction).unwrap();
    let varying = VaryingContact::new(modulus, Undamped, friction);
    let n = 4.0 / 3.0 * estar * r.sqrt() * h * h.sqrt();
    let a = (r * h).sqrt();
    for &u in &[0.0, 0.3, 0.8, 1.0] {
        let v = u * a * omega;
        let slip = Slip::new(v * 0.6, v * 0.8, omega).unwrap();
        let force = f * n * 3.0 * PI / 8.0 * u * (1.0 - u * u / 4.0);
        let torque = -f * n * a * 3.0 * PI / 16.0 * (1.0 - u * u + 3.0 * u.powi(4) / 8.0);
        for w in [
            contact.wrench(h, 0.0, slip),
            varying.wrench(&curv, h, 0.0, slip),
        ] {
            assert!((w.fx.hypot(w.fy) - force).abs() <= 5.5e-5 * f * n, "u={u}");
            assert!((w.tz - torque).abs() <= 4.5e-6 * f * n * a, "u={u}");
        }
    }
}

/// Sphere on plane with the exact law: N = (4/3)E*√R h^{3/2}, a = √(Rh) and, for u = v/(aω) ≤ 1,
/// |F| = fN(3π/8)u(1 − u²/4), T_z = −fNa(3π/16)(1 − u² + 3u⁴/8) (closed forms, model.md §3).
#[test]
fn sphere_plane_exact_law_matches_closed_forms() {
    let (r, estar, f, h, omega) = (0.01, 2e11, 0.3, 1e-6, 40.0);
    let contact = Contact::hertz::<Newton>(
        &Curvatures::sphere_plane(r).unwrap(),
        Modulus::new(estar).unwrap(),
        Undamped,
        Friction::<f64, Exact>::with_law(f, 0.0).unwrap(),
    )
    .unwrap();
    let n = 4.0 / 3.0 * estar * r.sqrt() * h * h.sqrt();
    let a = (r * h).sqrt();
    for &u in &[0.0, 0.1, 0.5, 0.9, 1.0] {
        for &psi in &[0.0, 0.7, 2.0, -1.2] {
            let v = u * a * omega;
            let slip = Slip::new(v * f64::cos(psi), v * f64::sin(psi), omega).unwrap();
            let w = contact.wrench(h, 0.0, slip);
            let force = f * n * 3.0 * PI / 8.0 * u * (1.0 - u * u / 4.0);
            let torque = -f * n * a * 3.0 * PI / 16.0 * (1.0 - u * u + 3.0 * u.powi(4) / 8.0);
            assert!(rel(w.n, n) < 1e-14 && rel(w.patch.a, a) < 1e-14);
            assert!(
                (w.fx.hypot(w.fy) - force).abs() <= 1e-9 * f * n,
                "u={u} psi={psi}"
            );
            assert!((w.tz - torque).abs() <= 1e-9 * f * n * a, "u={u} psi={psi}");
            // The force opposes the slip of the centre.
            assert!(w.fx * slip.vx() + w.fy * slip.vy() <= 0.0);
        }
    }
}

/// No contact, no wrench; a damped rebound (N clamped to 0) carries no friction either.
#[test]
fn contact_loss_and_rebound_give_zero_wrench() {
    let friction = Friction::<f64, Simplified>::with_law(0.3, 0.0).unwrap();
    let curv = Curvatures::sphere_plane(0.015).unwrap();
    let modulus = Modulus::new(5e9).unwrap();
    let slip = Slip::new(0.2, -0.1, 30.0).unwrap();
    let damped = Contact::hertz::<Newton>(
        &curv,
        modulus,
        CompressionDamping::new(1e9).unwrap(),
        friction,
    )
    .unwrap();
    for h in [0.0, -1e-6, -0.0] {
        let w = damped.wrench(h, -1.0, slip);
        assert_eq!((w.n, w.fx, w.fy, w.tz), (0.0, 0.0, 0.0, 0.0));
    }
    // Compression-only damping d·h·ḣ: during compression it adds to the elastic force.
    let w = damped.wrench(1e-7, 1.0, slip);
    let undamped = Contact::hertz::<Newton>(&curv, modulus, Undamped, friction).unwrap();
    assert!(w.n > undamped.wrench(1e-7, 1.0, slip).n);
}

/// Passivity and finiteness of the full wrench over a seeded random sweep of states, both
/// precisions, fixed and varying geometry: F·v_P + T_z·ω ≤ 0.
fn passive_sweep<T: Real, L: FrictionLaw>() {
    let mut next = xorshift64(0x9e37_79b9_7f4a_7c15);
    let friction = Friction::<T, L>::with_law(T::from_f64(0.25), T::from_f64(1e-4)).unwrap();
    let modulus = Modulus::new(T::from_f64(1e11)).unwrap();
    let varying = VaryingContact::new(modulus, Undamped, friction);
    for _ in 0..20_000 {
        let p = 10f64.powf(4.0 * next());
        let q = p * 10f64.powf(3.5 * next());
        let curv = Curvatures::new(T::from_f64(p), T::from_f64(q)).unwrap();
        let h = T::from_f64(10f64.powf(-9.0 + 4.0 * next()));
        let signs = [next(), next(), next()].map(|s| if s < 0.5 { -1.0 } else { 1.0 });
        let vx = signs[0] * 10f64.powf(-6.0 + 6.0 * next());
        let vy = signs[1] * 10f64.powf(-6.0 + 6.0 * next());
        let omega = signs[2] * 10f64.powf(-3.0 + 6.0 * next());
        let slip = Slip::new(T::from_f64(vx), T::from_f64(vy), T::from_f64(omega)).unwrap();
        let fixed = Contact::hertz::<Newton>(&curv, modulus, Undamped, friction).unwrap();
        for w in [
            fixed.wrench(h, T::ZERO, slip),
            varying.wrench(&curv, h, T::ZERO, slip),
        ] {
            let all = [w.n, w.fx, w.fy, w.tz];
            assert!(all.iter().all(|x| x.is_finite()), "{all:?}");
            let power = w.fx.to_f64() * vx + w.fy.to_f64() * vy + w.tz.to_f64() * omega;
            assert!(
                power <= 0.0,
                "power {power:e} > 0 at p={p} q={q} v=({vx},{vy}) w={omega}"
            );
            assert!(w.fx.hypot(w.fy) <= T::from_f64(0.25) * w.n * T::from_f64(1.0 + 1e-6));
        }
    }
}

#[test]
fn full_wrench_is_passive_and_finite() {
    each!(passive_sweep, [f64, f32], [Simplified, Best]);
}

include!("../benches/friction_set.rs");
include!("../benches/wrench_set.rs");

/// `Contact::wrench` skips the friction wrapper's clamps of a and N for a `NON_NEGATIVE`
/// normal law, and the patch's damping for `Undamped` (`Damping::ELASTIC`): the step must
/// equal, bit for bit, the public clamped call on the same patch, over contact loss, tiny and
/// huge approaches and every slip kind, for both law forms and both dampings.
fn unclamped_step_is_the_clamped_call<T: Real, L: FrictionLaw>() {
    use contensou::normal::NormalLaw;
    // The wrench benchmarks' scene (209 bearing, inner race), here with δ > 0.
    let (curv, ..) = wrench_scene::<T, L>();
    let estar = Modulus::new(T::from_f64(1.142857e11)).unwrap();
    let friction = Friction::<T, L>::with_law(T::from_f64(0.07), T::from_f64(1e-4)).unwrap();
    let plain = Contact::hertz::<Newton>(&curv, estar, Undamped, friction).unwrap();
    let damper = CompressionDamping::new(T::from_f64(0.5)).unwrap();
    let damped = Contact::hertz::<Newton>(&curv, estar, damper, friction).unwrap();
    let hertz = Hertz::new::<Newton>(&curv, estar).unwrap();
    let hs = [-1e-6, 0.0, 1e-40, 1e-30, 1e-12, 5e-6, 1e-3, 1e10];
    let vs = [0.0, 1e-40, -3e-5, 1e-4, 0.02, -7.0, 1e30];
    let ws = [0.0, -1e-20, 3.0, 100.0, -1e25];
    for &h in &hs {
        for &hdot in &[0.0, -2.0, 1e3] {
            for &vx in &vs {
                for &vy in &vs {
                    for &w in &ws {
                        let (h, hdot) = (T::from_f64(h), T::from_f64(hdot));
                        let slip =
                            Slip::new(T::from_f64(vx), T::from_f64(vy), T::from_f64(w)).unwrap();
                        let got = plain.wrench(h, hdot, slip);
                        assert_eq!(got.patch, hertz.patch(h), "Undamped patch at h = {h:?}");
                        for (c, got) in [
                            (plain.prepared(), got),
                            (damped.prepared(), damped.wrench(h, hdot, slip)),
                        ] {
                            let p = got.patch;
                            let want = friction.tangential_prepared(c, p.a, p.n, slip);
                            let same =
                                |x: T, y: T| x == y || (x.to_f64().is_nan() && y.to_f64().is_nan());
                            assert!(
                                same(got.fx, want.fx)
                                    && same(got.fy, want.fy)
                                    && same(got.tz, want.tz),
                                "{} h = {h:?} ḣ = {hdot:?} slip = {slip:?}: {got:?} vs {want:?}",
                                L::NAME
                            );
                            assert_eq!(got.branch, want.branch);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn unclamped_step_equals_the_clamped_call() {
    each!(
        unclamped_step_is_the_clamped_call,
        [f32, f64],
        [Simplified, Best]
    );
}
