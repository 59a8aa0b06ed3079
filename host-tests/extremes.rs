//! Valid extremes (issue 8): e² up to 0.99998 (P/Q down to 1e-4, and m₁ = 1e-4 through
//! `Parameter::from_complement`), u = v/(aω) from 1e-12 to 1e12, h from 1e-15 m (and subnormal
//! h), v and ω both tiny at once, subnormal v and ω — for every friction law, through
//! `Contact::wrench` and `VaryingContact::wrench`, in `f32` and `f64`. The wrench must be
//!
//! - **finite**, with N ≥ 0, |F| ≤ fN (1 + 1e-5) and |T_z| ≤ fNa;
//! - **passive**: F·v_P + T_z·ω ≤ 1e-5·(|F·v_P| + |T_z·ω|) (rounding only);
//! - **continuous**: a relative perturbation ε of any one input (h, v_Px, v_Py, ω) changes
//!   N by ≤ 1.5ε(1 + ε) relative (N ∝ h^{3/2}), and F/(fN), T_z/(fNa) by ≤ `SLOPE`·ε plus
//!   rounding (`SLOPE` = 4; measured worst 2.57, every law, both forms, f32 and f64 — the
//!   tests print it). ε = 1e-6 (f64), 1e-3 (f32). Where v or aω is subnormal only a few bits
//!   are left and ε moves them by whole ulps: there finiteness, passivity and N are checked,
//!   not the slope.
#![allow(clippy::excessive_precision)]

use contensou::Real;
use contensou::contact::{Contact, VaryingContact, Wrench};
use contensou::elliptic::Parameter;
use contensou::friction::{
    Best, Constants, Coulomb, Ellipsoid, Exact, Friction, FrictionLaw, Pade, Simplified, Slip,
};
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, HuntCrossley, Modulus, NormalLaw, Undamped};
use contensou::shape::Newton;

/// Bound on |Δ(F/fN)| + |Δ(T/fNa)| per unit relative perturbation of one input.
const SLOPE: f64 = 4.0;

/// Steel on steel, Q = 1/(2 · 6.35 mm).
const ESTAR: f64 = 1.15e11;
const Q: f64 = 78.74015748031496;
const F: f64 = 0.1;

/// P/Q down to the solver's minimum 1e-4 (e² = 0.99998).
const RATIOS: [f64; 6] = [1.0, 0.5, 0.1, 1e-2, 1e-3, 1.0001e-4];
/// u = v/(aω).
const U: [f64; 9] = [0.0, 1e-12, 1e-6, 1e-2, 0.5, 2.0, 1e2, 1e6, 1e12];
/// Slip directions ψ (rad), avoiding the axes so that both components are present.
const PSI: [f64; 2] = [0.3, 2.5];

/// Approaches h (m): from 1e-15 m, plus the smallest subnormal-ish value of each type.
fn approaches<T: Real>() -> Vec<T> {
    let tiny = if T::MANTISSA_DIGITS > 24 {
        1e-310
    } else {
        1e-40
    };
    [tiny, 1e-15, 1e-12, 1e-9, 1e-6, 1e-5]
        .iter()
        .map(|&h| T::from_f64(h))
        .collect()
}

/// Spins ω (rad/s): ordinary, tiny and subnormal (v follows from u, so v is tiny too).
fn spins<T: Real>() -> Vec<f64> {
    let tiny = if T::MANTISSA_DIGITS > 24 {
        1e-300
    } else {
        1e-30
    };
    let sub = if T::MANTISSA_DIGITS > 24 {
        1e-310
    } else {
        1e-40
    };
    vec![100.0, -3.0, tiny, sub]
}

/// Rounding allowance for the continuity check.
fn rounding<T: Real>() -> f64 {
    if T::MANTISSA_DIGITS > 24 { 1e-12 } else { 2e-5 }
}

/// One evaluation: the wrench as f64 numbers.
#[derive(Clone, Copy, Debug)]
struct W {
    n: f64,
    a: f64,
    fx: f64,
    fy: f64,
    tz: f64,
}

fn w64<T: Real, B>(w: &Wrench<T, B>) -> W {
    W {
        n: w.n.to_f64(),
        a: w.patch.a.to_f64(),
        fx: w.fx.to_f64(),
        fy: w.fy.to_f64(),
        tz: w.tz.to_f64(),
    }
}

/// Inputs of one step.
#[derive(Clone, Copy, Debug)]
struct Step {
    h: f64,
    vx: f64,
    vy: f64,
    om: f64,
}

fn check_one(w: W, s: Step, who: &str) {
    let ctx = || format!("{who} at {s:?}: {w:?}");
    for v in [w.n, w.a, w.fx, w.fy, w.tz] {
        assert!(v.is_finite(), "not finite: {}", ctx());
    }
    assert!(w.n >= 0.0 && w.a >= 0.0, "{}", ctx());
    let fnorm = F * w.n;
    assert!(
        w.fx.hypot(w.fy) <= fnorm * (1.0 + 1e-5),
        "|F| > fN: {}",
        ctx()
    );
    assert!(
        w.tz.abs() <= fnorm * w.a * (1.0 + 1e-5),
        "|T| > fNa: {}",
        ctx()
    );
    let (px, py, pz) = (w.fx * s.vx, w.fy * s.vy, w.tz * s.om);
    let scale = px.abs() + py.abs() + pz.abs();
    assert!(
        px + py + pz <= 1e-5 * scale,
        "not passive (power {}): {}",
        px + py + pz,
        ctx()
    );
}

/// The largest |ΔF|/(fN) + |ΔT|/(fNa) − rounding, per unit ε, over one-input perturbations.
fn continuity<T: Real>(
    eval: &dyn Fn(Step) -> W,
    s: Step,
    eps: f64,
    strict: bool,
    who: &str,
) -> f64 {
    let base = eval(s);
    let mut worst: f64 = 0.0;
    let bumps = [
        Step {
            h: s.h * (1.0 + eps),
            ..s
        },
        Step {
            vx: s.vx * (1.0 + eps),
            ..s
        },
        Step {
            vy: s.vy * (1.0 - eps),
            ..s
        },
        Step {
            om: s.om * (1.0 + eps),
            ..s
        },
    ];
    for (i, b) in bumps.into_iter().enumerate() {
        let w = eval(b);
        check_one(w, b, who);
        if base.n == 0.0 {
            // h below the float's resolution of N (subnormal h): N stays 0.
            assert_eq!(w.n, 0.0, "{who} at {b:?}");
            continue;
        }
        let dn = (w.n - base.n).abs() / base.n;
        let dn_max = if i == 0 { 1.5 * eps * (1.0 + eps) } else { 0.0 };
        assert!(
            dn <= dn_max + rounding::<T>(),
            "{who}: N jumps by {dn:e} at {b:?}"
        );
        let fnorm = F * base.n;
        let d = (w.fx - base.fx).abs() / fnorm
            + (w.fy - base.fy).abs() / fnorm
            + (w.tz - base.tz).abs() / (fnorm * base.a);
        let slope = (d - 3.0 * rounding::<T>()).max(0.0) / eps;
        assert!(
            !strict || slope <= SLOPE,
            "{who}: jump {d:e} for ε = {eps:e} at {b:?} (from {s:?})"
        );
        worst = worst.max(slope);
    }
    worst
}

/// Every (g, h, u, ψ, ω) point for one law and one contact form; returns the worst slope.
fn sweep<T: Real + 'static, L: FrictionLaw + Copy + 'static>(
    varying: bool,
    from_complement: bool,
) -> f64 {
    let eps = if T::MANTISSA_DIGITS > 24 { 1e-6 } else { 1e-3 };
    let estar = Modulus::new(T::from_f64(ESTAR)).unwrap();
    let friction = Friction::<T, L>::with_law(T::from_f64(F), T::ZERO).unwrap();
    let mut worst: f64 = 0.0;
    for &g in &RATIOS {
        let curv = Curvatures::new(T::from_f64(g * Q), T::from_f64(Q)).unwrap();
        let who = format!(
            "{} {} {} g={g:e}",
            L::NAME,
            if varying { "VaryingContact" } else { "Contact" },
            if from_complement { "m1=1e-4" } else { "" },
        );
        let eval: Box<dyn Fn(Step) -> W> = if varying {
            let c = VaryingContact::new(estar, Undamped, friction);
            Box::new(move |s: Step| {
                let slip = Slip::new(T::from_f64(s.vx), T::from_f64(s.vy), T::from_f64(s.om));
                w64(&c.wrench(&curv, T::from_f64(s.h), T::ZERO, slip.unwrap()))
            })
        } else if from_complement {
            // e² = 0.9999 built from m₁ = 1e-4 (friction constants) over the Hertz law of the
            // same curvatures, and a Hunt–Crossley damper at ḣ = 0.
            let k =
                Constants::from_parameter(Parameter::from_complement(T::from_f64(1e-4)).unwrap());
            let normal = Hertz::new::<Newton>(&curv, estar).unwrap();
            let hc = HuntCrossley::new(T::from_f64(0.2)).unwrap();
            let c = Contact::from_parts(normal, hc, friction, k);
            Box::new(move |s: Step| {
                let slip = Slip::new(T::from_f64(s.vx), T::from_f64(s.vy), T::from_f64(s.om));
                w64(&c.wrench(T::from_f64(s.h), T::ZERO, slip.unwrap()))
            })
        } else {
            let c = Contact::hertz::<Newton>(&curv, estar, Undamped, friction).unwrap();
            Box::new(move |s: Step| {
                let slip = Slip::new(T::from_f64(s.vx), T::from_f64(s.vy), T::from_f64(s.om));
                w64(&c.wrench(T::from_f64(s.h), T::ZERO, slip.unwrap()))
            })
        };
        for h in approaches::<T>() {
            let h = h.to_f64();
            // a at this h (the slip scale): from the law itself.
            let a = Hertz::new::<Newton>(&curv, estar)
                .unwrap()
                .patch(T::from_f64(h))
                .a
                .to_f64();
            for om in spins::<T>() {
                for &u in &U {
                    for &psi in &PSI {
                        let v = u * a * om.abs();
                        let s = Step {
                            h,
                            vx: v * f64::cos(psi),
                            vy: v * f64::sin(psi),
                            om,
                        };
                        // Values must be representable in T (subnormal products flush to 0).
                        let s = Step {
                            vx: T::from_f64(s.vx).to_f64(),
                            vy: T::from_f64(s.vy).to_f64(),
                            ..s
                        };
                        check_one(eval(s), s, &who);
                        // Subnormal v or aω carry only a few significant bits: a relative
                        // perturbation ε moves them by whole ulps of 2⁻¹⁴⁹ (f32) / 2⁻¹⁰⁷⁴,
                        // so continuity is checked only where they are normal (or 0).
                        let normal = |x: f64| x == 0.0 || x.abs() >= T::MIN_POSITIVE.to_f64();
                        let strict = normal(s.vx) && normal(s.vy) && normal(a * om);
                        let slope = continuity::<T>(&*eval, s, eps, strict, &who);
                        if strict {
                            worst = worst.max(slope);
                        }
                    }
                }
            }
        }
    }
    worst
}

/// Calls the generic `f::<T, L>()` for every friction law `L` in both precisions.
macro_rules! every_law_and_precision {
    ($f:ident) => {
        for_laws!($f, f32);
        for_laws!($f, f64);
    };
}

macro_rules! for_laws {
    ($f:ident, $t:ty) => {
        $f::<$t, Simplified>();
        $f::<$t, Pade>();
        $f::<$t, Ellipsoid>();
        $f::<$t, Coulomb>();
        $f::<$t, Exact>();
        $f::<$t, Best>();
    };
}

fn all_laws<T: Real + 'static>() -> Vec<(&'static str, f64)> {
    let mut out = Vec::new();
    for (varying, compl) in [(false, false), (true, false), (false, true)] {
        out.push(("simplified", sweep::<T, Simplified>(varying, compl)));
        out.push(("pade", sweep::<T, Pade>(varying, compl)));
        out.push(("ellipsoid", sweep::<T, Ellipsoid>(varying, compl)));
        out.push(("coulomb", sweep::<T, Coulomb>(varying, compl)));
        out.push(("exact", sweep::<T, Exact>(varying, compl)));
        out.push(("best", sweep::<T, Best>(varying, compl)));
    }
    out
}

#[test]
fn extremes_f64() {
    let worst = all_laws::<f64>();
    eprintln!("f64 worst continuity slopes: {worst:?}");
}

#[test]
fn extremes_f32() {
    let worst = all_laws::<f32>();
    eprintln!("f32 worst continuity slopes: {worst:?}");
}

/// e² = 0.9999 through `Parameter::from_complement` on its own: the friction constants and
/// the dimensional friction call at u across 1e-12..1e12 for every law, f32 and f64.
#[test]
fn from_complement_constants_are_finite() {
    fn one<T: Real, L: FrictionLaw>() {
        for m1 in [1e-4, 1e-3] {
            let k = Constants::from_parameter(Parameter::from_complement(T::from_f64(m1)).unwrap());
            assert!(k.spin_torque().is_finite() && k.gamma() > T::ZERO);
            let fr = Friction::<T, L>::with_law(T::from_f64(0.3), T::ZERO).unwrap();
            for &u in &U {
                let (a, om) = (T::from_f64(1e-3), T::from_f64(7.0));
                let v = u * 1e-3 * 7.0;
                let slip = Slip::new(T::from_f64(v * 0.6), T::from_f64(v * 0.8), om).unwrap();
                let t = fr.tangential(&k, a, T::from_f64(10.0), slip);
                for x in [t.fx, t.fy, t.tz] {
                    assert!(x.is_finite(), "{} m1={m1} u={u}", L::NAME);
                }
            }
        }
    }
    every_law_and_precision!(one);
}

/// Slip speeds whose sum |v_Px| + |v_Py| + a|ω| or product aω overflows (the slip state's
/// rarely taken `unusual` path, which the fuzzer reaches only partly): every law stays finite
/// and bounded; aω = ±∞ is pure spin.
#[test]
fn overflowing_slip_speeds_stay_finite() {
    fn one<T: Real, L: FrictionLaw>() {
        let k = Constants::from_parameter(Parameter::new(T::from_f64(0.5)).unwrap());
        let big = T::MAX;
        let fr = Friction::<T, L>::with_law(T::from_f64(0.2), T::ZERO).unwrap();
        for (vx, vy, om, a) in [
            (big, big, big, big),
            (big, -big, T::ZERO, T::ONE),
            (T::ZERO, T::ZERO, -big, big),
            (T::ONE, big, big, T::from_f64(1e-3)),
        ] {
            let slip = Slip::new(vx, vy, om).unwrap();
            let t = fr.tangential(&k, a, T::ONE, slip);
            for x in [t.fx, t.fy, t.tz] {
                assert!(x.is_finite(), "{} at {vx:?} {vy:?} {om:?} {a:?}", L::NAME);
            }
            assert!(t.fx.hypot(t.fy) <= T::from_f64(0.2 * (1.0 + 1e-5)));
        }
        // aω = −∞ with v_P = 0: pure spin, T_z = +C·fNa (opposing ω < 0).
        let slip = Slip::new(T::ZERO, T::ZERO, -big).unwrap();
        let t = fr.tangential(&k, big, T::ONE, slip);
        assert!(t.fx == T::ZERO && t.fy == T::ZERO, "{}", L::NAME);
        // (Coulomb has no drilling torque: T_z = 0.)
        assert!(
            t.tz >= T::ZERO && t.tz.is_finite(),
            "{}: {:?}",
            L::NAME,
            t.tz.to_f64()
        );
        assert!(t.tz > T::ZERO || L::NAME == "coulomb", "{}", L::NAME);
        // Zero spin with fN·a past the float range (N near T::MAX, a = 10 m): T_z is 0, not
        // the ∞·0 = NaN of forming fN·a first; the force stays fN-bounded.
        let slip = Slip::new(T::ONE, -T::ONE, T::ZERO).unwrap();
        let t = fr.tangential(&k, T::from_f64(10.0), big, slip);
        assert!(t.tz == T::ZERO, "{}: {:?}", L::NAME, t.tz.to_f64());
        assert!(t.fx.is_finite() && t.fy.is_finite(), "{}", L::NAME);
    }
    every_law_and_precision!(one);
}
