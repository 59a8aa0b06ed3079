//! `best`'s per-step form (`Best`'s `FrictionLaw::traction`: the seven outside coefficients
//! from one flash table with e² interpolated, what `VaryingContact` calls) against the exact
//! integrals: the independent brute-force reference `tools/data/best_varying_ref.csv`
//! (`tools/gen_best_varying_ref.py`) and a dense set against `friction::exact::traction`
//! (e² at, between and around the table's nodes in s = m₁^⅛, clustered towards the contract's
//! end m₁ = 1.70e-5 (P/Q = 1e-4), u just inside and just outside the ellipse), both precisions;
//! the jump across the ellipse, continuity in e² across the nodes, passivity, and what happens
//! below the contract's end.
#![allow(clippy::excessive_precision)]

#[path = "best_switch/mod.rs"]
mod best_switch;
use best_switch::{switch_jump, thin_grid, worst};
#[path = "common/rng.rs"]
mod rng;

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::best::Branch;
use contensou::friction::{Best, Constants, FrictionLaw, SlipState, Traction, exact};

/// Issue 13's bound: |ΔF| ≤ 1e-4 fN, |ΔT_z| ≤ 1e-4 fNa.
const BOUND: f64 = 1e-4;
/// Issue 21's exact-grade bound over the whole accepted domain: 1e-4 fN, 1e-5 fNa.
const EXACT_GRADE: (f64, f64) = (1e-4, 1e-5);
/// The table's cells in s = m₁^⅛ over [S0, 1], S0 = (1e-5)^⅛ (tools/gen_best_varying_table.py).
const NS: usize = 25;
/// m₁ at the contract's end (P/Q = 1e-4: e² = 0.999982985551773).
const M1_END: f64 = 1.7014448227e-5;

fn s0() -> f64 {
    1e-5f64.powf(0.125)
}

fn node_s(x: f64) -> f64 {
    s0() + (1.0 - s0()) * x / NS as f64
}

fn node_e2(x: f64) -> f64 {
    (1.0 - node_s(x).powi(8)).max(0.0)
}

/// The parameter of e², from its complement (kept exact near e² = 1).
fn param<T: Real>(e2: f64) -> Parameter<T> {
    Parameter::from_complement(T::from_f64(1.0 - e2)).unwrap()
}

fn ub(e2: f64, psi: f64) -> f64 {
    1.0 / (psi.sin().powi(2) + psi.cos().powi(2) / (1.0 - e2)).sqrt()
}

fn per_step<T: Real>(e2: f64, psi: f64, u: f64) -> (Traction<T>, Branch, SlipState<T>) {
    let k = Constants::from_parameter(param::<T>(e2));
    let s = SlipState::<T>::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
    let (t, b) = Best::traction(&k, &s);
    (t, b, s)
}

fn diff<T: Real>(t: &Traction<T>, want: [f64; 3]) -> (f64, f64) {
    let f = (t.fx.to_f64() - want[0])
        .abs()
        .max((t.fy.to_f64() - want[1]).abs());
    (f, (t.tz.to_f64() - want[2]).abs())
}

#[derive(Default)]
struct Worst {
    force: f64,
    torque: f64,
    at_force: (f64, f64, f64),
    at_torque: (f64, f64, f64),
}

impl Worst {
    fn add(&mut self, (f, t): (f64, f64), at: (f64, f64, f64)) {
        if f > self.force {
            self.force = f;
            self.at_force = at;
        }
        if t > self.torque {
            self.torque = t;
            self.at_torque = at;
        }
    }
    fn report(&self, name: &str) {
        println!(
            "{name}: force {:.2e} fN at (e2, psi, u) = {:?}, torque {:.2e} fNa at {:?}",
            self.force, self.at_force, self.torque, self.at_torque
        );
    }
}

/// The numbers of a reference CSV's rows (its header skipped).
fn csv_rows(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

#[test]
fn matches_the_independent_reference() {
    let rows = csv_rows(include_str!("../tools/data/best_varying_ref.csv"));
    assert!(rows.len() > 400);
    let (mut w64, mut w32) = (Worst::default(), Worst::default());
    for r in &rows {
        let (e2, psi, u) = (r[0], r[1], r[2]);
        assert!(r[6] < 1e-12, "reference not converged at {r:?}");
        let want = [r[3], r[4], r[5]];
        w64.add(diff(&per_step::<f64>(e2, psi, u).0, want), (e2, psi, u));
        w32.add(diff(&per_step::<f32>(e2, psi, u).0, want), (e2, psi, u));
    }
    w64.report("reference f64");
    w32.report("reference f32");
    for w in [&w64, &w32] {
        assert!(w.force <= Best::ERROR.0 && w.torque <= Best::ERROR.1);
    }
}

/// The thin patches (e² from 0.992 to the contract's end, the table's mid-cells there) against
/// the independent brute-force reference `tools/data/best_thin_ref.csv`
/// (`tools/gen_best_varying_ref.py --thin`): both forms of `best`, both precisions, within the
/// exact-grade bound.
#[test]
fn thin_patches_match_the_independent_reference() {
    use contensou::friction::BestContact;
    let rows = csv_rows(include_str!("../tools/data/best_thin_ref.csv"));
    assert!(rows.len() > 300);
    let mut w = [
        Worst::default(),
        Worst::default(),
        Worst::default(),
        Worst::default(),
    ];
    for r in &rows {
        let (e2, psi, u) = (r[0], r[1], r[2]);
        assert!(r[6] < 1e-12, "reference not converged at {r:?}");
        let want = [r[3], r[4], r[5]];
        // the exact integrals (the dense sets' reference) agree with the brute force here too
        let s = SlipState::from_polar(psi, u).unwrap();
        let x = exact::traction(param::<f64>(e2), s.x(), s.y(), s.w());
        let (ef, et) = diff(&x, want);
        assert!(ef <= 1e-12 && et <= 1e-12, "exact at {r:?}: {ef:e} {et:e}");
        w[0].add(diff(&per_step::<f64>(e2, psi, u).0, want), (e2, psi, u));
        w[1].add(diff(&per_step::<f32>(e2, psi, u).0, want), (e2, psi, u));
        let k = Constants::from_parameter(param::<f64>(e2));
        let s = SlipState::from_polar(psi, u).unwrap();
        w[2].add(
            diff(&BestContact::new(&k).traction(&s).0, want),
            (e2, psi, u),
        );
        let k = Constants::from_parameter(param::<f32>(e2));
        let s = SlipState::from_polar(psi as f32, u as f32).unwrap();
        w[3].add(
            diff(&BestContact::new(&k).traction(&s).0, want),
            (e2, psi, u),
        );
    }
    for (w, name) in w
        .iter()
        .zip(["Best f64", "Best f32", "BestContact f64", "BestContact f32"])
    {
        w.report(&format!("thin reference, {name}"));
        assert!(
            w.force <= EXACT_GRADE.0 && w.torque <= EXACT_GRADE.1,
            "{name}"
        );
    }
}

/// e² at every node, mid-cell and quarter-cell of the table (except the node at the thin end,
/// below the contract) and at 0.99, 0.985, 0.989, clustered towards e² → 1: 0.995, 0.999,
/// 0.9995, 0.9999, 0.99995, 0.99999 and the contract's end;
/// ψ on the axes and off them; u on a log grid, at u_b(1 ± δ) down to δ = 1e-7, near 1, ∞.
fn dense<T: Real>() -> Worst {
    let mut e2s: Vec<f64> = (1..=4 * NS).map(|i| node_e2(i as f64 / 4.0)).collect();
    e2s.extend([0.99, 0.989, 0.985, 1e-6]);
    e2s.extend([0.995, 0.999, 0.9995, 0.9999, 0.99995, 0.99999, 1.0 - M1_END]);
    let psis = [
        0.0,
        1e-4,
        0.0131,
        0.3,
        0.62,
        std::f64::consts::FRAC_PI_4,
        1.0,
        1.3,
        1.5,
        std::f64::consts::FRAC_PI_2,
        2.0,
        2.5,
        3.0,
        3.6,
        4.4,
        5.9,
    ];
    let mut w = Worst::default();
    for &e2 in &e2s {
        let p = param::<T>(e2);
        let k = Constants::from_parameter(p);
        let p64 = Parameter::from_complement(p.m1().to_f64()).unwrap();
        for psi in psis {
            let b = ub(e2, psi);
            let mut us: Vec<f64> = (0..=40)
                .map(|i| 10f64.powf(-2.0 + 4.0 * i as f64 / 40.0))
                .collect();
            for d in [
                1e-7, 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 0.02, 0.03, 0.05, 0.1, 0.2, 0.3, 0.6,
            ] {
                us.push(b * (1.0 + d));
                us.push(b * (1.0 - d));
            }
            us.extend([b, 1.0, 1.1, 2.0, 1e4, f64::INFINITY]);
            for u in us {
                let s = SlipState::<T>::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
                let r = exact::traction(p64, s.x().to_f64(), s.y().to_f64(), s.w().to_f64());
                let t = Best::traction(&k, &s).0;
                w.add(diff(&t, [r.fx, r.fy, r.tz]), (e2, psi, u));
            }
        }
    }
    w
}

#[test]
fn dense_set_against_exact() {
    let w64 = dense::<f64>();
    w64.report("dense f64");
    let w32 = dense::<f32>();
    w32.report("dense f32");
    for w in [&w64, &w32] {
        assert!(w.force <= EXACT_GRADE.0 && w.torque <= EXACT_GRADE.1);
        assert!(w.force <= Best::ERROR.0 && w.torque <= Best::ERROR.1);
    }
}

/// Bisect the inside/outside switch along u to adjacent floats: the ends of the table are the
/// exact quartic's, so the jump is rounding.
fn boundary_jump<T: Real>(next_up: impl Fn(T) -> T) -> f64 {
    let mut worst = 0.0f64;
    let mut e2s: Vec<f64> = (1..=2 * NS).map(|i| node_e2(i as f64 / 2.0)).collect();
    e2s.extend([0.99, 0.999, 0.9999, 1.0 - M1_END]);
    for e2 in e2s {
        let k = Constants::from_parameter(Parameter::new(T::from_f64(e2)).unwrap());
        for i in 0..24 {
            let psi = T::from_f64(0.05 + i as f64 * 0.262);
            let at = |u: T| Best::traction(&k, &SlipState::from_polar(psi, u).unwrap());
            worst = worst.max(switch_jump(at, &next_up));
        }
    }
    worst
}

#[test]
fn no_jump_across_the_ellipse() {
    let j64 = boundary_jump::<f64>(f64::next_up);
    let j32 = boundary_jump::<f32>(f32::next_up);
    println!("jump across the ellipse: f64 {j64:.1e}, f32 {j32:.1e}");
    assert!(j64 <= 8.0 * f64::EPSILON && j32 <= 8.0 * f32::EPSILON as f64);
    assert!(j64.max(j32) <= BOUND);
}

/// At each interior node of the table the stencil changes: the law is continuous there (the
/// interpolation is exact at the node from both sides). Compare e² a hair below and above each
/// node (s ± 1e-9 in f64, ± 2e-6 in f32, where the law itself moves by ≈ slope × Δs).
fn node_jump<T: Real>(ds: f64) -> f64 {
    let mut worst = 0.0f64;
    for n in 1..NS {
        let s = node_s(n as f64);
        let (e_lo, e_hi) = (1.0 - (s + ds).powi(8), 1.0 - (s - ds).powi(8));
        for psi in [0.0131, 0.7, 1.3, 2.5] {
            for f in [1.001, 1.01, 1.03, 1.1, 1.5, 3.0] {
                let u = f * ub(node_e2(n as f64), psi);
                let (a, _, _) = per_step::<T>(e_lo, psi, u);
                let (b, _, _) = per_step::<T>(e_hi, psi, u);
                let d = |p: T, q: T| (p.to_f64() - q.to_f64()).abs();
                worst = worst.max(d(a.fx, b.fx).max(d(a.fy, b.fy)).max(d(a.tz, b.tz)));
            }
        }
    }
    worst
}

#[test]
fn continuous_in_e2_across_the_nodes() {
    let j64 = node_jump::<f64>(1e-9);
    let j32 = node_jump::<f32>(2e-6);
    println!("change across the nodes: f64 {j64:.1e}, f32 {j32:.1e}");
    assert!(j64 <= 1e-7, "{j64}");
    assert!(j32 <= 1e-4, "{j32}");
}

/// Random states over the whole domain and past it (m₁ down to 1e-7): finite, each component
/// opposing its own velocity, |F| ≤ 1.
fn passive<T: Real>(seed: u64) {
    let mut rng = rng::Lcg(seed);
    for i in 0..40_000 {
        let p = if i % 5 == 0 {
            Parameter::from_complement(T::from_f64(10f64.powf(-7.0 + 5.0 * rng.next()))).unwrap()
        } else {
            Parameter::new(T::from_f64(0.99 * rng.next())).unwrap()
        };
        let k = Constants::from_parameter(p);
        let psi = 2.0 * std::f64::consts::PI * rng.next();
        let u = match i % 10 {
            0 => 0.0,
            1 => f64::INFINITY,
            _ => (rng.next() * 10.0 - 5.0).exp(),
        };
        let s = SlipState::<T>::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
        let t = Best::traction(&k, &s).0;
        let (fx, fy, tz) = (t.fx.to_f64(), t.fy.to_f64(), t.tz.to_f64());
        assert!(fx.is_finite() && fy.is_finite() && tz.is_finite());
        assert!(fx * s.x().to_f64() <= 0.0 && fy * s.y().to_f64() <= 0.0);
        assert!(tz * s.w().to_f64() <= 0.0);
        assert!(fx.hypot(fy) <= 1.0 + 1e-6);
    }
}

#[test]
fn passive_bounded_and_finite() {
    passive::<f64>(13);
    passive::<f32>(14);
}

/// The thin end: every m₁ from 1e-2 down to the contract's end (P/Q = 1e-4) within the
/// exact-grade bound on a ψ × u grid (log-spaced m₁, both precisions); below it (m₁ < 1e-5,
/// only through a `Parameter` built directly) the first node's remainder between exact ends.
#[test]
fn thin_patches_to_the_contract_end() {
    for i in 0..=16 {
        let m1 = 0.01 * (M1_END / 0.01).powf(i as f64 / 16.0);
        let p = Parameter::from_complement(m1).unwrap();
        let k = Constants::from_parameter(p);
        let k32 = Constants::from_parameter(Parameter::from_complement(m1 as f32).unwrap());
        let p32 = Parameter::from_complement(k32.m1() as f64).unwrap();
        let mut e = (0.0, 0.0);
        for (psi, u) in thin_grid() {
            let s = SlipState::from_polar(psi, u).unwrap();
            let r = exact::traction(p, s.x(), s.y(), s.w());
            worst(&mut e, &Best::traction(&k, &s).0, &r);
            let s32 = SlipState::from_polar(psi as f32, u as f32).unwrap();
            let r = exact::traction(p32, s32.x() as f64, s32.y() as f64, s32.w() as f64);
            worst(&mut e, &Best::traction(&k32, &s32).0, &r);
        }
        let (ef, et) = e;
        println!("m1 {m1:.3e}: force {ef:.2e}, torque {et:.2e}");
        assert!(
            ef <= EXACT_GRADE.0 && et <= EXACT_GRADE.1,
            "m1 {m1}: {ef} {et}"
        );
    }
}

/// RAM per varying contact: nothing per contact but the modulus, damping and f, δ (issue 13:
/// ≤ 128 B); the table lives in flash (a `static`).
#[test]
fn a_varying_contact_is_small() {
    use contensou::contact::VaryingContact;
    use contensou::normal::{HuntCrossley, Undamped};
    let plain = size_of::<VaryingContact<f32, Undamped>>();
    let damped = size_of::<VaryingContact<f32, HuntCrossley<f32>>>();
    println!("VaryingContact<f32, Undamped> {plain} B, with Hunt–Crossley {damped} B");
    assert!(plain <= 16 && damped <= 128);
}
