//! The wrench's Jacobian ([`contensou::jacobian`]) against central differences of the wrench
//! itself (`f64`), for every law, form, normal and damping law; its value against the wrench
//! bit for bit; the sliding laws' damping block positive semidefinite; `f32` against `f64`.
//!
//! Scaled units, so that one tolerance fits every entry: the derivative ∂wᵢ/∂qⱼ times the
//! input's scale σⱼ over the output's scale Wᵢ, with σ = (h, 1 cm/s, s, s, s/a) (s = |v_x| +
//! |v_y| + a|ω| the slip speed, a the major semi-axis) and W = (N, fN, fN, fNa); the error is
//! relative to max(1, |scaled derivative|).
//!
//! Kinks (branch switches, table pieces, FASTSIM's cells) are recognised by the central
//! differences at ε and ε/2 disagreeing; those states are counted and skipped.

use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
use contensou::friction::Slip;
use contensou::friction::rolling::RollingVelocity;
use contensou::jacobian::{Jacobian, Linearize, State};

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.next()).exp()
    }
    fn sign(&mut self) -> f64 {
        if self.next() < 0.5 { -1.0 } else { 1.0 }
    }
}

/// A random contact of the contract: P ≤ Q, steel-like E*, damped or not, δ = 0 or not.
fn spec(rng: &mut Rng) -> Spec<f64> {
    let p = rng.log(5.0, 500.0);
    Spec {
        p,
        q: p * rng.log(1.0, 50.0),
        estar: rng.log(1e10, 2e11),
        cd: if rng.next() < 0.5 {
            0.0
        } else {
            rng.range(0.05, 1.0)
        },
        f: rng.range(0.05, 0.5),
        delta: if rng.next() < 0.5 {
            0.0
        } else {
            rng.log(1e-5, 1e-3)
        },
    }
}

/// A random step in contact: h ∈ [1e-7, 1e-5] m, slips of random sign over three decades,
/// aω comparable to v (u = v/(aω) from 0.03 to 30).
fn step(rng: &mut Rng, a_guess: f64) -> Step<f64> {
    let v = rng.log(1e-4, 1e-1);
    let (c, s) = rng.range(0.0, std::f64::consts::TAU).sin_cos();
    let u = rng.log(0.03, 30.0);
    Step {
        h: rng.log(1e-7, 1e-5),
        hdot: rng.range(-0.01, 0.01),
        vx: v * c,
        vy: v * s,
        omega: rng.sign() * v / (u * a_guess),
    }
}

fn q_of(s: &Step<f64>) -> [f64; 5] {
    [s.h, s.hdot, s.vx, s.vy, s.omega]
}
fn step_of(q: [f64; 5]) -> Step<f64> {
    Step {
        h: q[0],
        hdot: q[1],
        vx: q[2],
        vy: q[3],
        omega: q[4],
    }
}

/// The check's outcome for one state: the worst scaled error against the central differences
/// (Richardson-extrapolated from ε = 1e-5 and ε/2 of each input's scale), relative to
/// max(1, |derivative|), or `None` at a kink (the two central differences disagree by more
/// than 1e-6 in that measure: not smooth within ±ε).
fn check(
    q: [f64; 5],
    a: f64,
    f: f64,
    wrench: &dyn Fn([f64; 5]) -> [f64; 4],
    jac: &Jacobian<f64>,
) -> Option<f64> {
    let w = wrench(q);
    let s = q[2].abs() + q[3].abs() + a * q[4].abs();
    let sigma = [q[0], 1e-2, s, s, s / a];
    let big = [
        w[0].abs(),
        f * w[0].abs(),
        f * w[0].abs(),
        f * w[0].abs() * a,
    ];
    let mut worst: f64 = 0.0;
    for j in 0..5 {
        let fd = |e: f64| {
            let (mut qp, mut qm) = (q, q);
            qp[j] += e * sigma[j];
            qm[j] -= e * sigma[j];
            let (wp, wm) = (wrench(qp), wrench(qm));
            [0, 1, 2, 3].map(|i| (wp[i] - wm[i]) / (2.0 * e * big[i]))
        };
        let (d1, d2) = (fd(1e-5), fd(5e-6));
        for i in 0..4 {
            let scale = d2[i].abs().max(1.0);
            if (d1[i] - d2[i]).abs() > 1e-6 * scale {
                return None;
            }
            let richardson = d2[i] + (d2[i] - d1[i]) / 3.0;
            let got = jac.d[i][j] * sigma[j] / big[i];
            worst = worst.max((got - richardson).abs() / scale);
        }
    }
    Some(worst)
}

/// One law and form of the contract over `n` random states: (max scaled error, skipped).
fn contract_law(law: Law, form: Form, n: usize, seed: u64) -> (f64, usize) {
    let mut rng = Rng(seed);
    let (mut worst, mut skipped): (f64, usize) = (0.0, 0);
    let rolling = Law::ROLLING.contains(&law);
    for _ in 0..n {
        let sp = spec(&mut rng);
        let dc = DynContact::new_rolling(&sp, &RollingSpec::default(), law, form).unwrap();
        let a_guess = (1e-6 / sp.p).sqrt();
        let st = step(&mut rng, a_guess);
        let rs = if rolling {
            let v = rng.log(0.1, 10.0);
            let th = if rng.next() < 0.5 {
                0.0
            } else {
                rng.range(0.0, std::f64::consts::TAU)
            };
            RollingStep {
                vrx: v * th.cos(),
                vry: v * th.sin(),
            }
        } else {
            RollingStep::default()
        };
        let out = dc.wrench_rolling(&st, &rs).unwrap();
        let jac = dc.jacobian_rolling(&st, &rs).unwrap();
        // the value part is the wrench, bit for bit
        let want = [out.n, out.fx, out.fy, out.tz];
        assert_eq!(
            jac.value.map(f64::to_bits),
            want.map(f64::to_bits),
            "{law:?} {form:?} {sp:?} {st:?}"
        );
        assert!(jac.d.iter().flatten().all(|x| x.is_finite()));
        if !(out.n > 0.0 && sp.f * out.n > 0.0) {
            continue;
        }
        let w = |q: [f64; 5]| {
            let o = dc.wrench_rolling(&step_of(q), &rs).unwrap();
            [o.n, o.fx, o.fy, o.tz]
        };
        match check(q_of(&st), out.a, sp.f, &w, &jac) {
            Some(e) => {
                if e > 1e-6 {
                    eprintln!("{law:?} {form:?} {e:.2e} {sp:?} {st:?} {rs:?}");
                }
                worst = worst.max(e)
            }
            None => skipped += 1,
        }
    }
    (worst, skipped)
}

fn contract_laws(laws: &[Law], n: usize) {
    for &law in laws {
        for form in Form::ALL {
            let (worst, skipped) = contract_law(law, form, n, 17 + law as u64);
            println!(
                "{:>10} {:>7}: max scaled error {worst:.2e}, {skipped} of {n} at a kink",
                law.name(),
                form.name()
            );
            assert!(worst <= 1e-6, "{law:?} {form:?}: {worst:.2e}");
            assert!(
                skipped * 20 <= n,
                "{law:?} {form:?}: {skipped} kinks of {n}"
            );
        }
    }
}

#[test]
fn default_law_matches_central_differences() {
    contract_laws(&[Law::Best], 60);
}

#[test]
fn sliding_laws_match_central_differences() {
    contract_laws(&Law::SLIDING, 40);
}

#[test]
fn rolling_laws_match_central_differences() {
    contract_laws(&[Law::Table, Law::Blend], 20);
}

/// Every law and form on 2,000 states each (release: `--include-ignored`).
#[test]
#[ignore = "release-only: 36,000 Jacobians against central differences"]
fn every_law_matches_central_differences_on_many_states() {
    contract_laws(&Law::ALL, 2000);
}

/// The normal laws (exact Hertz, volumetric, fitted) and damping laws (none, Hunt–Crossley,
/// compression-only) through the generic [`Contact`](contensou::contact::Contact).
#[test]
fn normal_and_damping_laws_match_central_differences() {
    use contensou::contact::Contact;
    use contensou::friction::{Best, Friction};
    use contensou::geometry::Curvatures;
    use contensou::normal::{
        CompressionDamping, Fitted, Hertz, HuntCrossley, Modulus, NormalLaw, Undamped, Volumetric,
    };
    use contensou::shape::Newton;

    fn run<N: NormalLaw<f64>, D, C: Linearize<f64>>(c: &C, normal: &N, name: &str) {
        let mut rng = Rng(5);
        let (mut worst, mut skipped): (f64, usize) = (0.0, 0);
        for _ in 0..40 {
            let st = step(&mut rng, 1e-4);
            let s = State {
                h: st.h,
                hdot: st.hdot,
                slip: Slip::new(st.vx, st.vy, st.omega).unwrap(),
                rolling: RollingVelocity::ZERO,
            };
            let jac = c.linearize(&s);
            assert_eq!(
                jac.value.map(f64::to_bits),
                c.wrench4(&s).map(f64::to_bits),
                "{name}"
            );
            let w = |q: [f64; 5]| {
                c.wrench4(&State {
                    h: q[0],
                    hdot: q[1],
                    slip: Slip::new(q[2], q[3], q[4]).unwrap(),
                    rolling: RollingVelocity::ZERO,
                })
            };
            let a = normal.patch(st.h).a;
            match check(q_of(&st), a, 0.3, &w, &jac) {
                Some(e) => worst = worst.max(e),
                None => skipped += 1,
            }
        }
        println!("{name}: max scaled error {worst:.2e}, {skipped} of 40 at a kink");
        assert!(
            worst <= 1e-6 && skipped <= 2,
            "{name}: {worst:.2e}, {skipped}"
        );
        let _ = core::marker::PhantomData::<D>;
    }

    let curv = Curvatures::new(40.0, 160.0).unwrap();
    let estar = Modulus::new(1.15e11).unwrap();
    let friction = Friction::<f64, Best>::with_law(0.3, 1e-4).unwrap();
    let hertz = Hertz::new::<Newton>(&curv, estar).unwrap();
    let c = Contact::hertz::<Newton>(&curv, estar, Undamped, friction).unwrap();
    run::<_, Undamped, _>(&c, &hertz, "hertz, undamped");
    let hc = HuntCrossley::new(0.4).unwrap();
    let c = Contact::hertz::<Newton>(&curv, estar, hc, friction).unwrap();
    run::<_, HuntCrossley<f64>, _>(&c, &hertz, "hertz, hunt-crossley");
    let cd = CompressionDamping::new(3e7).unwrap();
    let c = Contact::hertz::<Newton>(&curv, estar, cd, friction).unwrap();
    run::<_, CompressionDamping<f64>, _>(&c, &hertz, "hertz, compression damping");
    let k = *c.constants();
    let vol = Volumetric::new(&curv, estar);
    let c = Contact::from_parts(vol, hc, friction, k);
    run::<_, HuntCrossley<f64>, _>(&c, &vol, "volumetric, hunt-crossley");
    let fit = Fitted::new(&curv, estar).unwrap();
    let c = Contact::from_parts(fit, cd, friction, k);
    run::<_, CompressionDamping<f64>, _>(&c, &fit, "fitted, compression damping");
}
