//! The micromath twins (feature `micromath`) against the same references as their libm methods:
//! max and median error of each, side by side, in `f32`; `f64` falls back to libm bit for bit.
//!
//! References: micromath's own functions against `f64` libm (accurate to ~1e-16, far below the
//! 1e-4…6e-2 measured); K, E, B, D against tools/data/elliptic_ref.csv (mpmath, 60 digits);
//! shapes and patches against tools/data/hertz_ref.csv (mpmath); friction against
//! `friction::exact` (Gauss quadrature of the exact integrals, ≤ 1e-13).
//!
//! `cargo test --features micromath --test micromath -- --nocapture` prints the table rows of
//! `bench-results/micromath.md`.
#![allow(clippy::excessive_precision)]

use contensou::elliptic::{Integrals, Method, Parameter, Theta, ThetaMicromath};
use contensou::friction::{
    BestMicromath, BestSeries, Constants, Coulomb, CoulombMicromath, Ellipsoid, EllipsoidMicromath,
    FrictionLaw, Simplified, SimplifiedMicromath, SlipState, Traction, exact,
};
use contensou::geometry::Curvatures;
use contensou::math::{Backend, Libm, Micromath};
use contensou::normal::{Hertz, HertzMicromath, Modulus, NormalLaw};
use contensou::shape::{Eccentricity, HamrockDowson, HamrockDowsonMicromath, Newton, Ratio};

/// (max, median) of a sample.
fn stats(mut v: Vec<f64>) -> (f64, f64) {
    assert!(!v.is_empty() && v.iter().all(|x| x.is_finite()));
    v.sort_by(f64::total_cmp);
    (v[v.len() - 1], v[v.len() / 2])
}

fn rel(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

fn show(what: &str, libm: (f64, f64), mm: (f64, f64)) {
    println!(
        "ROW {what}: libm max {:.2e} median {:.2e} | micromath max {:.2e} median {:.2e}",
        libm.0, libm.1, mm.0, mm.1
    );
}

// ---- the functions themselves ------------------------------------------------------------

/// 2,000 log-spaced x in [1e-6, 1e6].
fn xs() -> Vec<f32> {
    (0..2000)
        .map(|i| 10f64.powf(-6.0 + 12.0 * i as f64 / 1999.0) as f32)
        .collect()
}

#[test]
fn functions() {
    let sq = |b: fn(f32) -> f32| {
        stats(
            xs().iter()
                .map(|&x| rel(b(x) as f64, (x as f64).sqrt()))
                .collect(),
        )
    };
    let (l, m) = (sq(Libm::sqrt::<f32>), sq(Micromath::sqrt::<f32>));
    show("sqrt rel", l, m);
    assert!(l.0 < 1e-7 && m.0 < 0.0607 && m.0 > 0.06 && m.1 > 1e-2);
    // ln: absolute error (relative is meaningless at x = 1)
    let ln = |b: fn(f32) -> f32| {
        stats(
            xs().iter()
                .map(|&x| (b(x) as f64 - (x as f64).ln()).abs())
                .collect(),
        )
    };
    let (l, m) = (ln(Libm::ln::<f32>), ln(Micromath::ln::<f32>));
    show("ln abs", l, m);
    let raw = ln(|x| micromath::F32(x).ln().0);
    show("ln abs (micromath's own, 1/x by bit trick below 1)", l, raw);
    assert!(l.0 < 2e-6 && m.0 < 7e-5 && raw.0 > 0.1);
    // exp: relative error over x ∈ [−20, 20]
    let e = |b: fn(f32) -> f32| {
        stats(
            (0..2001)
                .map(|i| {
                    let x = (-20.0 + 40.0 * i as f64 / 2000.0) as f32;
                    rel(b(x) as f64, (x as f64).exp())
                })
                .collect(),
        )
    };
    let (l, m) = (e(Libm::exp::<f32>), e(Micromath::exp::<f32>));
    show("exp rel", l, m);
    assert!(l.0 < 1e-6 && m.0 < 2.5e-3);
}

// ---- elliptic --------------------------------------------------------------------------

fn elliptic_rows() -> Vec<(Parameter<f32>, [f64; 4])> {
    let text = include_str!("../tools/data/elliptic_ref.csv");
    text.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            let want = [f[2], f[3], f[4], f[5]];
            // f32 rows: the defining input (m up to ½, m₁ above) exact in f32 and in domain
            let p = if f[0] <= 0.5 {
                let m = f[0] as f32;
                (m as f64 == f[0]).then(|| Parameter::new(m).unwrap())
            } else {
                let m1 = f[1] as f32;
                (m1 as f64 == f[1] && m1 >= Parameter::<f32>::min_complement())
                    .then(|| Parameter::from_complement(m1).unwrap())
            };
            p.map(|p| (p, want))
        })
        .collect()
}

fn elliptic_error<M: Method>() -> (f64, f64) {
    let rows = elliptic_rows();
    assert!(rows.len() >= 300);
    stats(
        rows.iter()
            .map(|(p, want)| {
                let i = M::integrals(*p);
                [i.k, i.e, i.b, i.d]
                    .iter()
                    .zip(want)
                    .map(|(g, w)| rel(*g as f64, *w))
                    .fold(0.0, f64::max)
            })
            .collect(),
    )
}

#[test]
fn theta() {
    let (l, m) = (
        elliptic_error::<Theta>(),
        elliptic_error::<ThetaMicromath>(),
    );
    show("theta K,E,B,D rel", l, m);
    assert!(l.0 < 4e-7);
    assert!(m.0 < 5.5e-5 && m.0 > 1e-5, "{m:?}");
    // m ≤ ½ calls no ln: bit for bit
    for i in 0..=50 {
        let p = Parameter::new(i as f32 / 100.0).unwrap();
        assert_eq!(Theta::integrals(p), ThetaMicromath::integrals(p));
    }
    // f64 is libm
    for m in [0.1, 0.6, 0.999, 1.0 - 1e-9] {
        let p = Parameter::new(m).unwrap();
        let (a, b): (Integrals<f64>, _) = (Theta::integrals(p), ThetaMicromath::integrals(p));
        assert_eq!(a, b);
    }
}

// ---- shape and Hertz -------------------------------------------------------------------

/// (P, Q, E*, h) and the reference (c, m1, K, E, B, D, a, b, N, p0) of the elliptic rows.
fn hertz_rows() -> Vec<([f64; 4], [f64; 10])> {
    include_str!("../tools/data/hertz_ref.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<f64> = l.split(',').skip(1).map(|x| x.parse().unwrap()).collect();
            ([f[0], f[1], f[2], f[3]], core::array::from_fn(|i| f[4 + i]))
        })
        .filter(|(i, _)| i[0] != i[1])
        .collect()
}

/// Max and median over the rows of: c (absolute), and a, b, N (worst relative) of `M` in f32.
fn shape_error<M: Eccentricity>() -> ((f64, f64), (f64, f64)) {
    let mut c = vec![];
    let mut abn = vec![];
    for (input, want) in hertz_rows() {
        let [p, q, estar, h] = input.map(|x| x as f32);
        let curv = Curvatures::new(p, q).unwrap();
        let shape = M::shape(Ratio::of(&curv).unwrap());
        c.push((shape.e2() as f64 - want[0]).abs());
        let law = Hertz::new::<M>(&curv, Modulus::new(estar).unwrap()).unwrap();
        let pt = law.patch(h);
        abn.push(
            [pt.a, pt.b, pt.n]
                .iter()
                .zip(&want[6..9])
                .map(|(g, w)| rel(*g as f64, *w))
                .fold(0.0, f64::max),
        );
    }
    (stats(c), stats(abn))
}

#[test]
fn hamrock_dowson() {
    let (lc, labn) = shape_error::<HamrockDowson>();
    let (mc, mabn) = shape_error::<HamrockDowsonMicromath>();
    show("hamrock-dowson c abs", lc, mc);
    show("hamrock-dowson a,b,N rel", labn, mabn);
    assert!(
        mc.0 < 0.017 && mabn.0 < 0.31 && mc.1 < 2e-4,
        "{mc:?} {mabn:?}"
    );
    // exact at g = 1; f64 is libm
    assert_eq!(
        HamrockDowsonMicromath::shape(Ratio::new(1.0f32).unwrap()).e2(),
        0.0
    );
    for g in [1e-4, 0.3, 0.9] {
        let g = Ratio::new(g).unwrap();
        assert_eq!(HamrockDowson::shape(g), HamrockDowsonMicromath::shape(g));
    }
}

#[test]
fn hertz_per_step() {
    // Same constants (Newton, f32); the reference patch of each row, and h over 12 decades
    // against the libm patch scaled from the row's h.
    let mut libm = vec![];
    let mut mm = vec![];
    for (input, want) in hertz_rows() {
        let [p, q, estar, h] = input.map(|x| x as f32);
        let curv = Curvatures::new(p, q).unwrap();
        let law = Hertz::new::<Newton>(&curv, Modulus::new(estar).unwrap()).unwrap();
        let twin = HertzMicromath::from(law);
        for (l, out) in [(&law.patch(h), &mut libm), (&twin.patch(h), &mut mm)] {
            out.push(
                [l.a, l.b, l.n, l.p0]
                    .iter()
                    .zip(&want[6..10])
                    .map(|(g, w)| rel(*g as f64, *w))
                    .fold(0.0, f64::max),
            );
        }
    }
    let (l, m) = (stats(libm), stats(mm));
    show("hertz per_step a,b,N,p0 rel", l, m);
    assert!(l.0 < 1e-6 && m.0 < 0.061 && m.0 > 0.05);
    // dense in h: N = k_H·h·√h against the exact value, h from 1e-12 to 1 m
    let curv = Curvatures::new(3.0f32, 30.0).unwrap();
    let law = Hertz::new::<Newton>(&curv, Modulus::new(1.1e11).unwrap()).unwrap();
    let twin = HertzMicromath::new::<Newton>(&curv, Modulus::new(1.1e11).unwrap()).unwrap();
    assert_eq!(twin, HertzMicromath::from(law));
    let n = stats(
        (0..4000)
            .map(|i| {
                let h = 10f64.powf(-12.0 + 12.0 * i as f64 / 3999.0) as f32;
                let exact = law.stiffness() as f64 * (h as f64).powf(1.5);
                rel(twin.patch(h).n as f64, exact)
            })
            .collect(),
    );
    println!(
        "ROW hertz per_step N over h: micromath max {:.2e} median {:.2e}",
        n.0, n.1
    );
    assert!(n.0 < 0.0607 && n.1 > 1e-2);
    assert!(twin.patch(-1.0).is_empty());
    // f64 is libm
    let law64 = Hertz::new::<Newton>(
        &Curvatures::new(3.0, 30.0).unwrap(),
        Modulus::new(1.1e11).unwrap(),
    )
    .unwrap();
    assert_eq!(law64.patch(3e-6), HertzMicromath::from(law64).patch(3e-6));
}

// ---- friction --------------------------------------------------------------------------

/// A thinned version of host-tests/friction_best.rs' set: e² clustered to 0.99, ψ in all
/// quadrants, u log-spaced plus around the ellipse and ∞.
fn friction_set() -> Vec<(f64, f64, f64)> {
    let mut v = vec![];
    for i in 0..=8 {
        let e2 = 0.99 * (i as f64 / 8.0).sqrt();
        for j in 0..13 {
            let psi = 0.0131 + j as f64 * std::f64::consts::PI / 6.5;
            let ub = 1.0 / (psi.sin().powi(2) + psi.cos().powi(2) / (1.0 - e2)).sqrt();
            for k in 0..=30 {
                v.push((e2, psi, 10f64.powf(-2.0 + 4.5 * k as f64 / 30.0)));
            }
            for d in [-0.1, -1e-3, 1e-3, 0.03, 0.3] {
                v.push((e2, psi, ub * (1.0 + d)));
            }
            v.push((e2, psi, f64::INFINITY));
        }
    }
    v
}

struct FrictionErrors {
    force: (f64, f64),
    torque: (f64, f64),
    /// max |F| (fN)
    max_force: f64,
}

/// Errors of law `L` in f32 against the exact integrals: |F − F_exact| (vector, fN) and
/// |T − T_exact| (fNa); also checks finiteness and passivity.
fn friction_error<L: FrictionLaw>(set: &[(f64, f64, f64, Traction<f64>)]) -> FrictionErrors {
    let (mut f, mut t, mut max_force) = (vec![], vec![], 0.0f64);
    let mut last = (
        f64::NAN,
        Constants::<f32>::from_parameter(Parameter::new(0.0).unwrap()),
    );
    for &(e2, psi, u, r) in set {
        if e2 != last.0 {
            last = (
                e2,
                Constants::from_parameter(Parameter::new(e2 as f32).unwrap()),
            );
        }
        let s = SlipState::<f32>::from_polar(psi as f32, u as f32).unwrap();
        let (g, _) = L::traction(&last.1, &s);
        let (fx, fy, tz) = (g.fx as f64, g.fy as f64, g.tz as f64);
        assert!(
            fx.is_finite() && fy.is_finite() && tz.is_finite(),
            "{} {e2} {psi} {u}",
            L::NAME
        );
        // passive: each component opposes its own velocity component
        let (x, y, w) = (s.x() as f64, s.y() as f64, s.w() as f64);
        assert!(
            fx * x + fy * y + tz * w <= 1e-6,
            "{} active at {e2} {psi} {u}",
            L::NAME
        );
        max_force = max_force.max(fx.hypot(fy));
        f.push((fx - r.fx).hypot(fy - r.fy));
        t.push((tz - r.tz).abs());
    }
    FrictionErrors {
        force: stats(f),
        torque: stats(t),
        max_force,
    }
}

fn exact_set() -> Vec<(f64, f64, f64, Traction<f64>)> {
    friction_set()
        .into_iter()
        .map(|(e2, psi, u)| {
            // the reference at the f32 inputs the laws see
            let s = SlipState::<f32>::from_polar(psi as f32, u as f32).unwrap();
            let p = Parameter::new(e2 as f32 as f64).unwrap();
            let r = exact::traction(p, s.x() as f64, s.y() as f64, s.w() as f64);
            (e2, psi, u, r)
        })
        .collect()
}

/// Max |F_M − F_L| (fN) and |T_M − T_L| (fNa) of the twin `M` against its libm law `L`, f32.
fn deviation<L: FrictionLaw, M: FrictionLaw>(set: &[(f64, f64, f64, Traction<f64>)]) -> (f64, f64) {
    let (mut f, mut t) = (0.0f64, 0.0f64);
    for &(e2, psi, u, _) in set {
        let k = Constants::from_parameter(Parameter::new(e2 as f32).unwrap());
        let s = SlipState::<f32>::from_polar(psi as f32, u as f32).unwrap();
        let (a, b) = (L::traction(&k, &s).0, M::traction(&k, &s).0);
        f = f.max(((a.fx - b.fx) as f64).hypot((a.fy - b.fy) as f64));
        t = t.max(((a.tz - b.tz) as f64).abs());
    }
    println!(
        "ROW {} twin vs libm law: force {f:.3e} fN, torque {t:.3e} fNa",
        L::NAME
    );
    (f, t)
}

fn compare<L: FrictionLaw, M: FrictionLaw>(
    set: &[(f64, f64, f64, Traction<f64>)],
) -> (FrictionErrors, (f64, f64)) {
    let (l, m) = (friction_error::<L>(set), friction_error::<M>(set));
    let dev = deviation::<L, M>(set);
    show(&format!("{} force fN", L::NAME), l.force, m.force);
    show(&format!("{} torque fNa", L::NAME), l.torque, m.torque);
    println!(
        "ROW {} max |F|: libm {:.5} micromath {:.5}",
        L::NAME,
        l.max_force,
        m.max_force
    );
    // f64 is libm
    let k = Constants::from_parameter(Parameter::new(0.7f64).unwrap());
    for &(psi, u) in &[(0.3, 0.2), (2.0, 1.5), (-1.0, 40.0)] {
        let s = SlipState::from_polar(psi, u).unwrap();
        assert_eq!(L::traction(&k, &s).0, M::traction(&k, &s).0);
    }
    (m, dev)
}

#[test]
fn friction_laws() {
    let set = exact_set();
    let (m, dev) = compare::<Simplified, SimplifiedMicromath>(&set);
    assert!(dev.0 < 0.058 && dev.1 < 0.027);
    assert!(m.force.0 < 0.33 && m.torque.0 < 0.336 && m.max_force <= 1.0);
    assert!(
        m.force.1 < 0.035 && m.torque.1 < 1.2e-3,
        "simplified median"
    );
    let (m, dev) = compare::<Coulomb, CoulombMicromath>(&set);
    // 1 − 1/1.0607: the square root is at most 6.07 % high
    assert!(dev.0 < 0.0573 && dev.1 == 0.0);
    assert!(m.force.0 < 0.99 && m.max_force <= 1.0, "coulomb");
    let (m, dev) = compare::<Ellipsoid, EllipsoidMicromath>(&set);
    assert!(dev.0 < 0.0573 && dev.1 < 0.022);
    assert!(m.force.0 < 0.22 && m.torque.0 < 0.125 && m.max_force <= 1.0);
    assert!(m.force.1 < 0.045 && m.torque.1 < 9e-3, "ellipsoid median");
    let (m, dev) = compare::<BestSeries, BestMicromath>(&set);
    assert!(dev.0 < 3e-6 && dev.1 < 3e-7);
    assert!(m.force.0 < 3e-6 && m.torque.0 < 1e-6, "best");
}
