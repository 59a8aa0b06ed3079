//! The stability map's guards: for every region where a method fails or degrades, the library's
//! behaviour at and past the edge (a typed error, or a fallback that stays accurate; always
//! finite). References: mpmath (`tools/gen_stability_ref.py` → `tools/data/stability_*.csv`),
//! `tools/data/friction_ref.csv`, and the exact friction integrals. The measured charts are
//! written by `examples/stability.rs`.
#![allow(clippy::excessive_precision)]

#[path = "stability/shared.rs"]
mod shared;

use contensou::elliptic::{Agm, Method, Parameter, Table as KeTable, Theta, paper_k_e};
use contensou::friction::best::{ramp_stiffness, spin_stiffness};
use contensou::friction::exact::{self, SERIES_MIN_U};
use contensou::friction::{Best, Constants, Coulomb, Explicit, Friction, Simplified};
use contensou::geometry::Curvatures;
use contensou::normal::{Hertz, Modulus, NormalLaw, Volumetric};
use contensou::shape::{Eccentricity, Linear, Newton, Ratio};
use contensou::{Error, Real};
use shared::{
    BestCase, best_case_step, best_stiffness_row, best_stiffness_rows, eig_euler, elliptic_rows,
    measured_step, rel, series, shape_rows, spin_probes, spin_stiffness_row, spin_stiffness_rows,
};

// ---- 1. theta series near m → 1 -------------------------------------------------------------

/// Max relative error of K and E of `Theta` and of the paper's form over the m₁ rows accepted
/// by `T`'s parameter domain, as (fixed, paper, paper's error at the smallest m₁).
fn theta_errors<T: Real>(paper_domain: f64) -> (f64, f64, f64) {
    let (mut fixed, mut paper, mut at_min) = (0.0f64, 0.0f64, 0.0);
    for r in elliptic_rows("m1") {
        let Ok(p) = Parameter::from_complement(T::from_f64(r[0])) else {
            continue;
        };
        let err = |k: T, e: T| rel(k.to_f64(), r[1]).max(rel(e.to_f64(), r[2]));
        let i = Theta::integrals(p);
        fixed = fixed.max(err(i.k, i.e));
        let (k, e) = paper_k_e(p);
        assert!(
            k.is_finite() && e.is_finite(),
            "paper form not finite at m1 = {}",
            r[0]
        );
        if r[0] >= paper_domain {
            paper = paper.max(err(k, e));
        }
        at_min = err(k, e);
    }
    (fixed, paper, at_min)
}

#[test]
fn theta_fix_holds_to_the_domain_edge_where_the_paper_form_fails() {
    // f64: Theta 2.8e-16 measured; the paper's form within 1e-14 for m ≤ 0.867 only, 0.32 at
    // m₁ = 1e-12.
    let (fixed, paper, at_min) = theta_errors::<f64>(0.133);
    assert!(fixed <= 3e-16, "Theta f64 K/E error {fixed:e}");
    assert!(
        paper <= 1e-14,
        "paper form f64 inside m <= 0.867: {paper:e}"
    );
    assert!(
        at_min > 0.1,
        "paper form f64 at m1 = 1e-12 unexpectedly good: {at_min:e}"
    );
    // f32: Theta within its documented 3.3e-7; the paper's form off by 6.6e-2 at m₁ = 2⁻²⁴.
    let (fixed, paper, at_min) = theta_errors::<f32>(0.133);
    assert!(fixed <= 3.3e-7, "Theta f32 K/E error {fixed:e}");
    assert!(paper <= 1e-6, "paper form f32 inside m <= 0.867: {paper:e}");
    assert!(at_min > 1e-2, "paper form f32 at m1 = 2^-24: {at_min:e}");
}

// ---- 3. (K − E)/m at small m -----------------------------------------------------------------

#[test]
fn d_is_free_of_cancellation_at_small_m() {
    let mut worst = [0.0f64; 4];
    let mut naive_worst = 0.0f64;
    for r in elliptic_rows("m") {
        let (m, d) = (r[0], r[3]);
        let p32 = Parameter::new(m as f32).unwrap();
        let p64 = Parameter::new(m).unwrap();
        let e = [
            rel(Agm::integrals(p32).d as f64, d),
            rel(Theta::integrals(p32).d as f64, d),
            rel(KeTable::integrals(p32).d as f64, d),
            rel(Agm::integrals(p64).d, d),
        ];
        for (w, v) in worst.iter_mut().zip(e) {
            *w = w.max(v);
        }
        // The region the guard exists for: the quotient from K and E in f32.
        let i = Agm::integrals(p32);
        let naive = rel(((i.k - i.e) / p32.m()) as f64, d);
        if m <= 1.1e-4 {
            naive_worst = naive_worst.max(naive);
        }
        if m <= 1e-8 {
            assert!(
                naive > 0.5,
                "naive (K - E)/m at m = {m:e} only {naive:e} off"
            );
        }
    }
    assert!(
        naive_worst > 1e-2,
        "naive (K - E)/m below m = 1e-4: {naive_worst:e}"
    );
    assert!(
        worst[..3].iter().all(|&w| w <= 3.3e-7),
        "f32 D errors {worst:?}"
    );
    assert!(worst[3] <= 1e-15, "f64 D error {:e}", worst[3]);
}

// ---- 2. Newton as g → 0: the Ratio guard -----------------------------------------------------

fn ratio_guard<T: Real>() {
    let min = T::from_f64(Ratio::<T>::MIN);
    assert_eq!(Ratio::new(min).unwrap().get(), min);
    let below = T::from_f64(Ratio::<T>::MIN * (1.0 - 1e-6));
    for g in [
        below,
        T::from_f64(1e-6),
        T::from_f64(1e-8),
        T::ZERO,
        -T::ONE,
    ] {
        assert_eq!(Ratio::new(g), Err(Error::CurvatureRatioOutOfRange));
        assert_eq!(Ratio::clamped(g).get(), min);
    }
    assert_eq!(
        Ratio::new(T::from_f64(f64::NAN)),
        Err(Error::NonFinite("g"))
    );
    assert_eq!(Ratio::clamped(T::from_f64(f64::NAN)).get(), min);
    assert_eq!(Ratio::clamped(T::from_f64(2.0)).get(), T::ONE);
    // Curvatures past the edge are refused by every constructor that solves for the shape.
    let c = Curvatures::new(T::from_f64(1e-6), T::ONE).unwrap();
    let estar = Modulus::new(T::ONE).unwrap();
    assert_eq!(Ratio::of(&c), Err(Error::CurvatureRatioOutOfRange));
    assert_eq!(
        Hertz::new::<Newton>(&c, estar).err(),
        Some(Error::CurvatureRatioOutOfRange)
    );
}

#[test]
fn ratio_refuses_below_its_minimum_and_clamps_to_it() {
    ratio_guard::<f32>();
    ratio_guard::<f64>();
}

/// Relative m₁ error of Newton's solve at g, raw (no domain check) with the default count.
fn newton_m1_error<T: Real>(g: f64, m1: f64) -> f64 {
    let (c, got) = Newton::solve_unchecked(T::from_f64(g), Newton::iterations::<T>());
    assert!(c.is_finite() && got.is_finite());
    rel(got.to_f64(), m1)
}

#[test]
fn newton_is_exact_at_the_edge_and_degrades_only_past_the_elliptic_floor() {
    for r in shape_rows() {
        if r.g >= 0.8 {
            continue;
        }
        let (e64, e32) = (
            newton_m1_error::<f64>(r.g, r.m1),
            newton_m1_error::<f32>(r.g, r.m1),
        );
        // inside the domain and below it, while m₁ stays above the elliptic floor m₁_min:
        // the documented figures (m₁ 3.4e-15 f64, 1.6e-6 f32) — the guard keeps a 200× margin
        for (err, floor, clamped) in [
            (e64, 1e-12, Newton::solve_unchecked(r.g, 6).1),
            (
                e32,
                Parameter::<f32>::min_complement() as f64,
                Newton::solve_unchecked(r.g as f32, 4).1 as f64,
            ),
        ] {
            // below the domain f64 is held to 1e-14 (the iteration's figure, not the
            // in-domain 3.4e-15)
            let bound = match (floor < 1e-9, r.g >= 1e-4) {
                (true, true) => 3.4e-15,
                (true, false) => 1e-14,
                (false, _) => 1.6e-6,
            };
            if r.m1 >= floor {
                assert!(err <= bound, "g = {:e}: m1 error {err:e}", r.g);
            } else {
                // past the floor m₁ is clamped there: wrong but finite
                assert_eq!(clamped, floor, "g = {:e}", r.g);
            }
        }
        if r.g >= 1e-4 {
            assert!(r.m1 >= 1e-5);
        }
    }
    // Total on garbage.
    for g in [f64::NAN, -1.0, 0.0, f64::MIN_POSITIVE, 2.0, f64::INFINITY] {
        let (c, m1) = Newton::solve_unchecked(g, 6);
        assert!(c.is_finite() && m1.is_finite() && m1 > 0.0, "g = {g}");
    }
}

// ---- 4. the large-u series -------------------------------------------------------------------

#[test]
fn large_u_series_is_used_only_past_its_switch() {
    let p = Parameter::new(0.687).unwrap();
    for psi in [0.0, 0.4, 1.0, std::f64::consts::FRAC_PI_2] {
        let at = |u: f64| exact::traction(p, u * f64::cos(psi), u * f64::sin(psi), 1.0);
        // continuous across the switch (quadrature below, series above)
        let (lo, hi) = (
            at(SERIES_MIN_U * (1.0 - 1e-9)),
            at(SERIES_MIN_U * (1.0 + 1e-9)),
        );
        for (a, b) in [(lo.fx, hi.fx), (lo.fy, hi.fy), (lo.tz, hi.tz)] {
            assert!((a - b).abs() <= 1e-14, "jump {:e} at psi = {psi}", a - b);
        }
        // just below the switch the series agrees with the quadrature to rounding
        let s = series(0.687, psi, 0.99 * SERIES_MIN_U);
        let q = at(0.99 * SERIES_MIN_U);
        assert!(
            (s[0] - q.fx)
                .abs()
                .max((s[1] - q.fy).abs())
                .max((s[2] - q.tz).abs())
                <= 1e-14
        );
    }
    // Where the exact path uses quadrature (1 ≤ u ≤ 1e3 here), it matches the independent
    // reference to 5e-15 while the series alone is far off: the series is not what is used.
    let mut far = 0usize;
    for l in include_str!("../tools/data/friction_ref.csv")
        .lines()
        .skip(1)
    {
        let v: Vec<f64> = l.split(',').map(|f| f.parse().unwrap()).collect();
        let (e2, psi, u) = (v[0], v[1], v[2]);
        if !(1.0..=100.0).contains(&u) || e2 > 0.99 {
            continue;
        }
        let t = exact::traction(
            Parameter::new(e2).unwrap(),
            u * psi.cos(),
            u * psi.sin(),
            1.0,
        );
        let err = (t.fx - v[3])
            .abs()
            .max((t.fy - v[4]).abs())
            .max((t.tz - v[5]).abs());
        assert!(
            err <= 5e-15,
            "exact at e2 = {e2}, psi = {psi}, u = {u}: {err:e}"
        );
        let s = series(e2, psi, u);
        if (s[0] - v[3])
            .abs()
            .max((s[1] - v[4]).abs())
            .max((s[2] - v[5]).abs())
            > 1e-12
        {
            far += 1;
        }
    }
    assert!(
        far > 20,
        "only {far} reference points where the series is off"
    );
}

// ---- 5. the volumetric law -------------------------------------------------------------------

fn volumetric_edge<T: Real>() {
    let estar = Modulus::new(T::ONE).unwrap();
    let mut checked_rows = 0;
    for r in shape_rows() {
        let c = Curvatures::new(T::from_f64(r.g), T::ONE).unwrap();
        let loose = Volumetric::new(&c, estar).patch(T::ONE).n.to_f64();
        assert!(loose.is_finite() && loose > 0.0);
        let err = rel(loose, r.n);
        if c.ratio() >= T::from_f64(Volumetric::<T>::MIN_RATIO) {
            let v = Volumetric::checked(&c, estar).unwrap();
            assert!(err <= Volumetric::<T>::MAX_ERROR, "g = {:e}: {err:e}", r.g);
            assert_eq!(v.patch(T::ONE).n.to_f64(), loose);
            checked_rows += 1;
        } else {
            assert_eq!(
                Volumetric::checked(&c, estar).err(),
                Some(Error::CurvatureRatioOutOfRange)
            );
            // past the edge `new` keeps working, with the documented error (−66.5 % at 1e-4)
            if r.g >= 1e-4 {
                assert!(err <= 0.666, "g = {:e}: {err:e}", r.g);
            }
        }
    }
    assert!(checked_rows >= 6);
    // the edge itself: 0.5 accepted, the next value below refused
    let at = |g: f64| Curvatures::new(T::from_f64(g), T::ONE).unwrap();
    assert!(Volumetric::checked(&at(0.5), estar).is_ok());
    assert!(Volumetric::checked(&at(0.5 * (1.0 - 1e-6)), estar).is_err());
}

#[test]
fn volumetric_checked_refuses_past_its_error_bound() {
    volumetric_edge::<f32>();
    volumetric_edge::<f64>();
}

// ---- 6. the paper's linear G* ----------------------------------------------------------------

fn linear_errors<T: Real>() {
    let estar = Modulus::new(T::ONE).unwrap();
    let mut worst = [0.0f64; 4];
    for r in shape_rows() {
        let Ok(g) = Ratio::new(T::from_f64(r.g)) else {
            assert!(r.g < 1e-4);
            continue;
        };
        let s = Linear::shape(g);
        let c = Curvatures::new(T::from_f64(r.g), T::ONE).unwrap();
        let p = Hertz::from_shape(&c, &s, estar).patch(T::ONE);
        let e = [
            (s.e2().to_f64() - r.c).abs(),
            rel(p.a.to_f64(), r.a),
            rel(p.b.to_f64(), r.b),
            rel(p.n.to_f64(), r.n),
        ];
        assert!(e.iter().all(|v| v.is_finite()));
        if (0.69..=0.71).contains(&r.g) {
            // at the knee: c error 0.022, N 0.62 %
            assert!(e[0] <= 0.022 && e[3] <= 0.0063, "knee g = {}: {e:?}", r.g);
        }
        for (w, v) in worst.iter_mut().zip(e) {
            *w = w.max(v);
        }
    }
    // the documented maxima over [1e-4, 1], reached past the knee / at Ratio::MIN
    assert!(worst[0] <= 0.055 && worst[1] <= 0.022, "{worst:?}");
    assert!(worst[2] <= 1.23 && worst[3] <= 0.123, "{worst:?}");
    assert!(
        worst[2] >= 1.1,
        "b error at Ratio::MIN smaller than documented: {worst:?}"
    );
}

#[test]
fn linear_gstar_is_continuous_at_the_knee_and_bounded_to_the_domain_edge() {
    linear_errors::<f32>();
    linear_errors::<f64>();
    // the two segments meet at g = 0.7 (c = c₁ = 0.4)
    let c = |g: f64| Linear::solve(Ratio::new(g).unwrap()).0;
    assert!((c(0.7 * (1.0 + 1e-12)) - c(0.7 * (1.0 - 1e-12))).abs() <= 1e-11);
    assert!((c(0.7) - 0.4).abs() <= 1e-15);
    // and as g → Ratio::MIN: m₁ = (6/7)·g, finite
    let (c_min, m1_min) = Linear::solve(Ratio::<f32>::clamped(0.0));
    assert!(c_min.is_finite() && (m1_min / (6.0 / 7.0 * 1e-4) - 1.0).abs() < 1e-6);
}

// ---- 7. the regularized Coulomb law: stable explicit step -----------------------------------

#[test]
fn stable_step_matches_the_measured_bisection() {
    let (mass, f) = (0.006, 0.3);
    let n = mass * 9.81;
    for delta in [1e-3, 1e-5] {
        let law = Friction::<f64, Coulomb>::with_law(f, delta).unwrap();
        for scheme in [Explicit::Euler, Explicit::Rk4] {
            let h = law.stable_step(&Constants::circle(), mass, n, scheme);
            assert!((h / (scheme.limit() * mass * delta / (f * n)) - 1.0).abs() < 1e-15);
            let measured = measured_step(&law, mass, n, scheme, false, h);
            assert!(
                rel(measured, h) <= 1e-3,
                "{scheme:?} delta {delta}: {measured:e} vs {h:e}"
            );
            // the simplified law without spin is the same ramp
            let simple = Friction::<f64, Simplified>::with_law(f, delta).unwrap();
            assert_eq!(simple.stable_step(&Constants::circle(), mass, n, scheme), h);
            let measured = measured_step(&simple, mass, n, scheme, false, h);
            assert!(
                rel(measured, h) <= 1e-3,
                "simplified {scheme:?}: {measured:e} vs {h:e}"
            );
        }
        // Euler oscillates (sign flips) from half the stable step
        let h = law.stable_step(&Constants::circle(), mass, n, Explicit::Euler);
        let osc = measured_step(&law, mass, n, Explicit::Euler, true, h);
        assert!(rel(osc, 0.5 * h) <= 1e-3, "{osc:e} vs {:e}", 0.5 * h);
    }
}

#[test]
fn stable_step_edge_cases_are_total() {
    let law = Friction::<f32, Coulomb>::with_law(0.3, 1e-4).unwrap();
    let e = Explicit::Euler;
    assert_eq!(
        Friction::<f32, Coulomb>::with_law(0.3, 0.0)
            .unwrap()
            .stable_step(&Constants::circle(), 1.0, 1.0, e),
        0.0
    );
    assert_eq!(law.stable_step(&Constants::circle(), 0.0, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&Constants::circle(), -1.0, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&Constants::circle(), f32::NAN, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&Constants::circle(), 1.0, 0.0, e), f32::MAX);
    assert_eq!(
        law.stable_step(&Constants::circle(), 1.0, f32::NAN, e),
        f32::MAX
    );
    assert_eq!(
        law.stable_step(&Constants::circle(), f32::MAX, 1e-30, e),
        f32::MAX
    );
    assert_eq!(
        Friction::<f32, Coulomb>::with_law(0.0, 1e-4)
            .unwrap()
            .stable_step(&Constants::circle(), 1.0, 1.0, e),
        f32::MAX
    );
    // the RK4 limit: |R(−x)| = 1 for R(z) = 1 + z + z²/2 + z³/6 + z⁴/24
    let x = -Explicit::Rk4.limit();
    let r = 1.0 + x + x * x / 2.0 + x * x * x / 6.0 + x * x * x * x / 24.0;
    assert!((r - 1.0).abs() < 1e-12, "R = {r}");
}

// ---- 8. the `best` law's ramp: stable explicit step -------------------------------------------

#[test]
fn best_ramp_stiffness_bounds_the_maximisation() {
    // κ(e²) against tools/gen_ramp_stiffness.py (mpmath)
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    let (mut lo32, mut hi32) = (f64::INFINITY, 0.0f64);
    for [m1, a, b, kappa] in best_stiffness_rows() {
        let p = Parameter::from_complement(m1).unwrap();
        let k = Constants::from_parameter(p);
        assert!(
            rel(k.slope_x(), a) < 1e-13 && rel(k.slope_y(), b) < 1e-13,
            "A, B at m1 {m1}"
        );
        let r = ramp_stiffness(&k) / kappa;
        (lo, hi) = (lo.min(r), hi.max(r));
        if let Ok(p) = Parameter::<f32>::from_complement(m1 as f32) {
            // f32 reads m₁ rounded: compare with the reference at the rounded m₁ only where it
            // is exact in f32 (the grid's powers of ten are not)
            if f64::from(m1 as f32) == m1 {
                let r = f64::from(ramp_stiffness(&Constants::from_parameter(p))) / kappa;
                (lo32, hi32) = (lo32.min(r), hi32.max(r));
            }
        }
    }
    println!("kappa/ref f64 {lo} … {hi}, f32 {lo32} … {hi32}");
    assert!(
        lo >= 1.0 - 1e-12 && hi <= 1.0 + 1e-12,
        "f64 kappa/ref in [{lo}, {hi}]"
    );
    assert!(
        lo32 >= 1.0 - 1e-6 && hi32 <= 1.0 + 1e-6,
        "f32 kappa/ref in [{lo32}, {hi32}]"
    );
}

#[test]
fn best_stiffness_is_largest_inside_the_ramp_and_the_ellipse() {
    // Scan the whole direction sphere (first octant: the law's symmetries mirror the rest)
    // just inside the ramp (dissipation p = 0.999·3δ/8) and just past it (p = 1.001·3δ/8,
    // where the stiffness is fN/p times the core's): the Jacobian's largest eigenvalue (Euler's
    // |λ|²/Re λ for a complex pair) never exceeds κ, for the exact law and for `best`, and the
    // scan comes within 1 % of it. The maximisation covers only the IC inside the ellipse.
    let delta = 1.0;
    // through the thin patches to the contract's end (P/Q = 1e-4: m₁ = 1.70e-5; issue 21)
    for e2 in [0.0, 0.5, 0.9, 0.99, 0.999, 0.9999, 1.0 - 1.7014448227e-5] {
        let p = Parameter::from_complement(1.0 - e2).unwrap();
        let k = Constants::from_parameter(p);
        let kappa = ramp_stiffness(&k);
        let best = shared::BestBlock::new(&k, 1.0, delta, 1.0, 1.0, 0.0);
        let n = 24;
        let mut worst = [0.0f64; 2];
        for scale in [0.999, 1.001] {
            for (x, y, w) in shared::octant(n, 1.0) {
                let r = scale * 0.375 * delta / shared::dissipation(p, [x, y, w]);
                let (x, y, w) = (r * x, r * y, r * w);
                let ramped = |vx: f64, vy: f64| {
                    let t = exact::traction(p, vx, vy, w);
                    let r = (shared::dissipation(p, [vx, vy, w]) / (0.375 * delta)).min(1.0);
                    [r * t.fx, r * t.fy]
                };
                let h = 1e-7;
                let (f0, fx, fy) = (ramped(x, y), ramped(x + h, y), ramped(x, y + h));
                let jac = [
                    [-(fx[0] - f0[0]) / h, -(fy[0] - f0[0]) / h],
                    [-(fx[1] - f0[1]) / h, -(fy[1] - f0[1]) / h],
                ];
                worst[0] = worst[0].max(eig_euler(jac));
                let b = shared::BestBlock { aw: w, ..best };
                worst[1] = worst[1].max(b.stiffness([x, y]));
            }
        }
        println!(
            "e2 {e2}: kappa {kappa:.5}, sup exact {:.5}, best {:.5}",
            worst[0], worst[1]
        );
        assert!(
            worst[0] <= kappa && worst[1] <= kappa * (1.0 + 1e-6) && worst[0] >= 0.99 * kappa,
            "e2 {e2}: {worst:?} vs {kappa}"
        );
        // neither pure translation (8/3) nor rest with spin ((8/3)·C·A) is the maximum
        let gain = 8.0 / 3.0;
        assert!(worst[0] > gain && worst[0] > gain * k.spin_torque() * k.slope_x());
    }
}

/// The stiffness at a probe predicts the step measured there (measured/predicted within
/// 0.3 %), and at the probe named `…tight` the bound h* is tight (measured/h* ≤ `bound`).
fn predicted_and_tight(name: &str, ratio: f64, vs_pred: f64, tight: &str, bound: f64) {
    assert!(
        (vs_pred - 1.0).abs() <= 3e-3,
        "{name}: measured/predicted = {vs_pred}"
    );
    if name.ends_with(tight) {
        assert!(ratio <= bound, "{name}: h* not tight: {ratio}");
    }
}

#[test]
fn best_stable_step_is_conservative_and_tight() {
    // A 6 g block, f = 0.3, δ = 0.1 mm/s, 2-D velocity and fixed spin (a = 1 m), held at probe
    // slips across the ramp by a constant drive; the bisected step at which a perturbation
    // stops decaying, against h* = stable_step (Euler and RK4).
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_8};
    let (mass, f, delta) = (0.006, 0.3, 1e-4);
    let n = mass * 9.81;
    let run = |e2: f64, m1: f64| {
        let mut lines = Vec::new();
        let (_, vstar) = best_stiffness_row(m1).unwrap();
        for scheme in [Explicit::Euler, Explicit::Rk4] {
            for psi in [0.0, FRAC_PI_8, FRAC_PI_4, FRAC_PI_2] {
                for spin in [0.0, 0.3, 1.0, 3.0] {
                    let case = BestCase { e2, psi, spin };
                    let (h, h_star, lam) =
                        best_case_step(&case, &[], f, delta, mass, n, scheme, 6, 1000, 22);
                    let predicted = scheme.limit() * mass * delta / (lam * f * n);
                    lines.push((
                        format!("e2 {e2} {scheme:?} psi {psi:.3} spin {spin}"),
                        h / h_star,
                        h / predicted,
                    ));
                }
            }
            // the derivation's stiffest slip (generator's maximiser), at aω = 0.3δ
            let case = BestCase {
                e2,
                psi: vstar[1].atan2(vstar[0]),
                spin: 0.3,
            };
            let v = [0.3 * delta * vstar[0], 0.3 * delta * vstar[1]];
            let (h, h_star, lam) =
                best_case_step(&case, &[v], f, delta, mass, n, scheme, 0, 1000, 22);
            let predicted = scheme.limit() * mass * delta / (lam * f * n);
            lines.push((
                format!("e2 {e2} {scheme:?} maximiser"),
                h / h_star,
                h / predicted,
            ));
        }
        lines
    };
    let all: Vec<_> = per_shape(run);
    for (name, ratio, vs_pred) in &all {
        println!("{name}: measured/h* {ratio:.4}, measured/predicted {vs_pred:.4}");
        // conservative, and loose at most by κ over the case's own stiffness (largest: the
        // circle with aω = 3δ, where the ramp is inactive and the stiffness is A·fN/(aω):
        // κ/(A/3) = 8.16)
        assert!(
            *ratio >= 1.0 && *ratio <= 8.3,
            "{name}: measured/h* = {ratio}"
        );
        // the Jacobian at the probe predicts the measured step; h* is tight at the maximiser
        predicted_and_tight(name, *ratio, *vs_pred, "maximiser", 1.01);
    }
}

/// The edge-case tests' contact: the circle, `best` at f = 0.3, δ = 1e-4 in f32, Euler.
fn circle_best() -> (Constants<f32>, Friction<f32, Best>, Explicit) {
    let law = Friction::<f32, Best>::with_law(0.3, 1e-4).unwrap();
    (Constants::circle(), law, Explicit::Euler)
}

#[test]
fn best_stable_step_edge_cases_are_total() {
    let (k, law, e) = circle_best();
    let kappa = ramp_stiffness(&k);
    assert!(
        (law.stable_step(&k, 2.0, 3.0, e) / (2.0 * 2.0 * 1e-4 / (kappa * 0.3 * 3.0)) - 1.0).abs()
            < 1e-6
    );
    assert_eq!(
        Friction::<f32, Best>::with_law(0.3, 0.0)
            .unwrap()
            .stable_step(&k, 1.0, 1.0, e),
        0.0
    );
    assert_eq!(law.stable_step(&k, 0.0, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&k, -1.0, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&k, f32::NAN, 1.0, e), 0.0);
    assert_eq!(law.stable_step(&k, 1.0, 0.0, e), f32::MAX);
    assert_eq!(law.stable_step(&k, 1.0, f32::NAN, e), f32::MAX);
    assert_eq!(law.stable_step(&k, f32::MAX, 1e-30, e), f32::MAX);
    assert_eq!(
        Friction::<f32, Best>::with_law(0.0, 1e-4)
            .unwrap()
            .stable_step(&k, 1.0, 1.0, e),
        f32::MAX
    );
    // κ over the whole f32 and f64 parameter domains: finite, ≥ the circle's
    for m1 in [1.0, 0.5, 1e-3, 5.960464477539063e-8] {
        let k = Constants::from_parameter(Parameter::<f32>::from_complement(m1).unwrap());
        let kappa = ramp_stiffness(&k);
        assert!(kappa.is_finite() && kappa >= 3.2, "f32 m1 {m1}: {kappa}");
    }
    let k = Constants::from_parameter(Parameter::<f64>::from_complement(1e-12).unwrap());
    assert!(ramp_stiffness(&k).is_finite());
}

// ---- 9. the spin about the normal: stable explicit step of the torque ramp --------------------

#[test]
fn spin_stiffness_matches_the_maximisation() {
    // κ_T(e²) against tools/gen_ramp_stiffness.py (mpmath)
    let (mut worst, mut worst32) = (0.0f64, 0.0f64);
    for [m1, c, kappa_t, _, _] in spin_stiffness_rows() {
        let k = Constants::from_parameter(Parameter::from_complement(m1).unwrap());
        assert!(rel(k.spin_torque(), c) < 1e-13, "C at m1 {m1}");
        worst = worst.max(rel(spin_stiffness(&k), kappa_t));
        if f64::from(m1 as f32) == m1 {
            let k =
                Constants::from_parameter(Parameter::<f32>::from_complement(m1 as f32).unwrap());
            worst32 = worst32.max(rel(f64::from(spin_stiffness(&k)), kappa_t));
        }
    }
    println!("kappa_T rel err f64 {worst:e}, f32 {worst32:e}");
    assert!(worst <= 1e-12, "f64 {worst:e}");
    assert!(worst32 <= 1e-6, "f32 {worst32:e}");
}

#[test]
fn spin_stiffness_is_largest_inside_the_ramp_and_the_ellipse() {
    // −∂T_z/∂ω (δ/(fN·a²) units, a = δ = 1) on the whole direction sphere, first octant,
    // just inside (dissipation p = 0.999·3δ/8) and past (1.001·3δ/8) `best`'s ramp: never above κ_T
    // for the exact law and for `best`, never above 2/5 for `simplified` (which it
    // approaches); the scan comes within 3 % of κ_T.
    for e2 in [0.0, 0.5, 0.9, 0.99, 0.999, 0.9999, 1.0 - 1.7014448227e-5] {
        let p = Parameter::from_complement(1.0 - e2).unwrap();
        let k = Constants::from_parameter(p);
        let kappa_t = spin_stiffness(&k);
        let n = 24;
        let mut worst = [0.0f64; 3];
        for scale in [0.999, 1.001] {
            for (x, y, w) in shared::octant(n, 1.0) {
                let r = scale * 0.375 / shared::dissipation(p, [x, y, w]);
                let (x, y, w) = (r * x, r * y, r * w);
                let ramped = |w: f64| {
                    let p_w = shared::dissipation(p, [x, y, w]) / 0.375;
                    (p_w.min(1.0)) * exact::traction(p, x, y, w).tz
                };
                let h = 1e-7;
                worst[0] = worst[0].max(-(ramped(w + h) - ramped(w)) / h);
                let b = shared::SpinBody::<Best>::new(&k, 1.0, 1.0, 1.0, 1.0, 1.0, [x, y]);
                worst[1] = worst[1].max(b.stiffness(w));
                let s = shared::SpinBody::<Simplified>::new(&k, 1.0, 1.0, 1.0, 1.0, 1.0, [x, y]);
                worst[2] = worst[2].max(s.stiffness(w));
            }
        }
        println!(
            "e2 {e2}: kappa_T {kappa_t:.5}, sup exact {:.5}, best {:.5}; simplified {:.5}",
            worst[0], worst[1], worst[2]
        );
        assert!(
            worst[0] <= kappa_t && worst[1] <= kappa_t * (1.0 + 1e-6) && worst[0] >= 0.97 * kappa_t,
            "e2 {e2}: {worst:?} vs {kappa_t}"
        );
        assert!(
            worst[2] <= 0.4 && worst[2] >= 0.35,
            "simplified e2 {e2}: {}",
            worst[2]
        );
    }
}

#[test]
fn spin_stable_step_is_conservative_and_tight() {
    // A body of inertia 1e-9 kg·m², f = 0.3, N = 0.06 N, δ = 0.1 mm/s, a = 1 m; spin integrated
    // with v_P held, ω held at probes by a drive torque; the bisected step at which a
    // perturbation stops decaying, against h* = stable_spin_step (Euler and RK4).
    let (f, delta, inertia, n) = (0.3, 1e-4, 1e-9, 0.06);
    let run = |e2: f64, m1: f64| {
        let k = Constants::from_parameter(Parameter::new(e2).unwrap());
        let (kappa_t, c, _) = spin_stiffness_row(m1).unwrap();
        let mut lines = Vec::new();
        for scheme in [Explicit::Euler, Explicit::Rk4] {
            let simple = Friction::<f64, Simplified>::with_law(f, delta).unwrap();
            let best = Friction::<f64, Best>::with_law(f, delta).unwrap();
            for (is_best, h_star) in [
                (false, simple.stable_spin_step(&k, 1.0, inertia, n, scheme)),
                (true, best.stable_spin_step(&k, 1.0, inertia, n, scheme)),
            ] {
                for probe in spin_probes(is_best, e2, m1, delta) {
                    let step = if is_best {
                        shared::spin_probe_step::<Best>
                    } else {
                        shared::spin_probe_step::<Simplified>
                    };
                    let (h, lam) =
                        step(&probe, &k, (f, delta, inertia, n), h_star, scheme, 1000, 24);
                    let predicted = scheme.limit() * inertia * delta / (lam * f * n);
                    // the derivation's stiffness at the probe: (8/3)·C² (best) or 1/5 in pure spin,
                    // κ_T or 0.999·2/5 at the stiffest slip
                    let derived = match (is_best, probe.name) {
                        (true, "pure spin") => Some(8.0 / 3.0 * c * c),
                        (true, "stiffest") => Some(kappa_t),
                        (false, "pure spin") => Some(0.2),
                        (false, "stiffest") => Some(0.999 * 0.4),
                        _ => None,
                    };
                    let law = if is_best { "best" } else { "simplified" };
                    lines.push((
                        format!("e2 {e2} {scheme:?} {law} {}", probe.name),
                        h / h_star,
                        h / predicted,
                        derived.map(|d| rel(lam, d)),
                    ));
                }
            }
        }
        lines
    };
    let all: Vec<_> = per_shape(run);
    for (name, ratio, vs_pred, vs_derived) in &all {
        println!(
            "{name}: measured/h* {ratio:.5}, measured/predicted {vs_pred:.5}, stiffness vs derived {vs_derived:?}"
        );
        // conservative everywhere: h* ≤ the bisected threshold, which lies within the
        // bisection's resolution (15.5·h*/2²⁴ = 9.2e-7·h*) above `measured`; in pure spin loose
        // by 2 (simplified) or κ_T/((8/3)·C²) ≤ 2.03 (best)
        assert!(*ratio >= 1.0 - 9.3e-7, "{name}: measured/h* = {ratio}");
        if name.ends_with("pure spin") {
            assert!(*ratio <= 2.04, "{name}: measured/h* = {ratio}");
        }
        if let Some(d) = vs_derived {
            assert!(*d <= 1e-3, "{name}: stiffness vs derivation {d:e}");
        }
        // the stiffness at the probe predicts the measured step; h* is tight at the stiffest slip
        predicted_and_tight(name, *ratio, *vs_pred, "stiffest", 1.002);
    }
}

#[test]
fn spin_stable_step_edge_cases_are_total() {
    let (k, best, e) = circle_best();
    let simple = Friction::<f32, Simplified>::with_law(0.3, 1e-4).unwrap();
    let coulomb = Friction::<f32, Coulomb>::with_law(0.3, 1e-4).unwrap();
    let kt = spin_stiffness(&k);
    // h* = 2·Iδ/(κ·f·N·a²), I = 2, N = 3, a = 0.5
    let want = |kappa: f32| 2.0 * 2.0 * 1e-4 / (kappa * 0.3 * 3.0 * 0.25);
    assert!((best.stable_spin_step(&k, 0.5, 2.0, 3.0, e) / want(kt) - 1.0).abs() < 1e-6);
    assert!((simple.stable_spin_step(&k, 0.5, 2.0, 3.0, e) / want(0.4) - 1.0).abs() < 1e-6);
    for g in [
        &|a: f32, i: f32, n: f32| best.stable_spin_step(&k, a, i, n, e) as f64,
        &|a: f32, i: f32, n: f32| simple.stable_spin_step(&k, a, i, n, e) as f64,
    ] as [&dyn Fn(f32, f32, f32) -> f64; 2]
    {
        assert_eq!(g(1.0, 0.0, 1.0), 0.0);
        assert_eq!(g(1.0, -1.0, 1.0), 0.0);
        assert_eq!(g(1.0, f32::NAN, 1.0), 0.0);
        assert_eq!(g(1.0, 1.0, 0.0), f32::MAX as f64);
        assert_eq!(g(1.0, 1.0, f32::NAN), f32::MAX as f64);
        assert_eq!(g(0.0, 1.0, 1.0), f32::MAX as f64);
        assert_eq!(g(-1.0, 1.0, 1.0), f32::MAX as f64);
        assert_eq!(g(f32::NAN, 1.0, 1.0), f32::MAX as f64);
        assert_eq!(g(1.0, f32::MAX, 1e-30), f32::MAX as f64);
        assert_eq!(g(1e30, 1.0, 1.0), 0.0); // fN·a² overflows: stiffness ∞
        assert_eq!(g(1e30, 1.0, 0.0), f32::MAX as f64);
    }
    assert_eq!(
        Friction::<f32, Best>::with_law(0.3, 0.0)
            .unwrap()
            .stable_spin_step(&k, 1.0, 1.0, 1.0, e),
        0.0
    );
    assert_eq!(
        Friction::<f32, Simplified>::with_law(0.3, 0.0)
            .unwrap()
            .stable_spin_step(&k, 1.0, 1.0, 1.0, e),
        0.0
    );
    assert_eq!(
        Friction::<f32, Best>::with_law(0.0, 1e-4)
            .unwrap()
            .stable_spin_step(&k, 1e30, 1.0, 1.0, e),
        f32::MAX
    );
    // Coulomb: no torque
    assert_eq!(coulomb.stable_spin_step(&k, 1.0, 1.0, 1.0, e), f32::MAX);
    assert_eq!(coulomb.stable_spin_step(&k, 1.0, f32::NAN, 1.0, e), 0.0);
    // κ_T over the whole f32 and f64 parameter domains: finite, ≥ C
    for m1 in [1.0, 0.5, 1e-3, 5.960464477539063e-8] {
        let k = Constants::from_parameter(Parameter::<f32>::from_complement(m1).unwrap());
        let kt = spin_stiffness(&k);
        assert!(kt.is_finite() && kt >= k.spin_torque(), "f32 m1 {m1}: {kt}");
    }
    let k = Constants::from_parameter(Parameter::<f64>::from_complement(1e-12).unwrap());
    assert!(spin_stiffness(&k).is_finite());
}

/// `run(e², m₁)` for the four patch shapes the step tests cover, one thread each; their lines
/// in shape order.
fn per_shape<R: Send>(run: impl Fn(f64, f64) -> Vec<R> + Sync) -> Vec<R> {
    let run = &run;
    std::thread::scope(|s| {
        let hs: Vec<_> = [(0.0, 1.0), (0.5, 0.5), (0.9, 0.1), (0.99, 0.01)]
            .map(|(e2, m1)| s.spawn(move || run(e2, m1)))
            .into_iter()
            .collect();
        hs.into_iter().flat_map(|h| h.join().unwrap()).collect()
    })
}

// ---- the stable steps: one signature for every law, callable from a built contact ---------

/// Every law answers `stable_step(&Constants, mass, n, scheme)` and
/// `stable_spin_step(&Constants, a, inertia, n, scheme)`; the laws that ignore δ (no ramp)
/// have no stable explicit step where friction acts (0) and no limit where it does not.
#[test]
fn stable_steps_have_one_signature_and_come_from_a_contact() {
    use contensou::contact::Contact;
    use contensou::friction::{Ellipsoid, Exact, FrictionLaw, Pade};
    use contensou::normal::Undamped;
    fn steps<L: FrictionLaw>(k: &Constants<f64>, a: f64, n: f64) -> (f64, f64) {
        let law = Friction::<f64, L>::with_law(0.3, 1e-4).unwrap();
        let e = Explicit::Euler;
        (
            law.stable_step(k, 2.0, n, e),
            law.stable_spin_step(k, a, 3.0, n, e),
        )
    }
    let k = Constants::<f64>::circle();
    for (name, s) in [
        (
            "pade",
            steps::<Pade> as fn(&Constants<f64>, f64, f64) -> (f64, f64),
        ),
        ("ellipsoid", steps::<Ellipsoid>),
        ("exact", steps::<Exact>),
    ] {
        assert_eq!(s(&k, 0.5, 1.0), (0.0, 0.0), "{name}");
        assert_eq!(s(&k, 0.5, 0.0), (f64::MAX, f64::MAX), "{name}: no contact");
        assert_eq!(
            s(&k, 0.0, 1.0).1,
            f64::MAX,
            "{name}: point contact, no torque"
        );
    }
    // Closed forms: h* = 2mδ/(κfN), 2Iδ/(κ_T·fN·a²).
    let want = |kappa: f64, kappa_t: f64| {
        (
            2.0 * 2.0 * 1e-4 / (kappa * 0.3),
            2.0 * 3.0 * 1e-4 / (kappa_t * 0.3 * 0.25),
        )
    };
    let rel2 = |(a, b): (f64, f64), (c, d): (f64, f64)| rel(a, c).max(rel(b, d));
    assert!(rel2(steps::<Simplified>(&k, 0.5, 1.0), want(1.0, 0.4)) < 1e-15);
    assert_eq!(steps::<Coulomb>(&k, 0.5, 1.0), (want(1.0, 1.0).0, f64::MAX));
    let best = steps::<Best>(&k, 0.5, 1.0);
    assert!(rel2(best, want(ramp_stiffness(&k), spin_stiffness(&k))) < 1e-15);

    // From a built contact (the default law `Best` needs the shape's constants): the same
    // numbers as the law's call with the constants of that shape.
    let curv = Curvatures::new(40.0, 90.0).unwrap();
    let contact = Contact::hertz::<Newton>(
        &curv,
        Modulus::new(1e11).unwrap(),
        Undamped,
        Friction::<f64>::new(0.3, 1e-4).unwrap(),
    )
    .unwrap();
    let shape = Constants::from_shape(&Newton::shape(Ratio::of(&curv).unwrap()));
    assert_eq!(*contact.constants(), shape);
    let e = Explicit::Rk4;
    let law = Friction::<f64, Best>::with_law(0.3, 1e-4).unwrap();
    assert_eq!(
        contact.stable_step(2.0, 3.0, e),
        law.stable_step(&shape, 2.0, 3.0, e)
    );
    assert_eq!(
        contact.stable_spin_step(1e-4, 2.0, 3.0, e),
        law.stable_spin_step(&shape, 1e-4, 2.0, 3.0, e)
    );
    assert!(contact.stable_step(2.0, 3.0, e) < 2.785 * 2.0 * 1e-4 / (0.3 * 3.0 * 3.2));
}

// ---- best's per-step form (flash table, what VaryingContact calls) under the ramp ----------

/// The stable explicit step of `Friction::<T, Best>` (κ(e²) = `ramp_stiffness`, derived on the
/// exact quartic) holds for the per-step form too: inside the ramp (S < δ) the largest
/// eigenvalue of the translational Jacobian −(δ/fN)·∂F/∂v_P (complex pairs by |λ|²/Re λ), by
/// central differences at random slip directions with the IC inside and outside the ellipse,
/// never exceeds κ.
#[test]
fn best_ramp_stiffness_bounds_the_per_step_form() {
    use contensou::friction::Slip;
    let mut seed = 77u64;
    let mut unit = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    // the per-step table's nodes in s = m₁^¼ (tools/gen_best_varying_table.py: 20 cells)
    let node_e2 = |x: f64| {
        let s = 0.1f64.sqrt() + (1.0 - 0.1f64.sqrt()) * x / 20.0;
        (1.0 - s.powi(4)).max(0.0)
    };
    let law = Friction::<f64, Best>::new(1.0, 1.0).unwrap();
    let mut worst = 0.0f64;
    for i in 0..20_000 {
        let e2 = if i % 4 == 0 {
            node_e2((unit() * 20.0).round())
        } else {
            0.99 * unit()
        };
        let k = Constants::from_parameter(Parameter::new(e2).unwrap());
        let kappa = ramp_stiffness(&k);
        // a direction (vx, vy, aω) with S = |vx| + |vy| + |aω| = 0.5 (inside the ramp)
        let (a, b, c) = (unit() - 0.5, unit() - 0.5, unit() * 0.5 + 1e-3);
        let s = 0.5 / (a.abs() + b.abs() + c);
        let (vx, vy, w) = (a * s, b * s, c * s);
        let f = |vx: f64, vy: f64| {
            let t = law.tangential(&k, 1.0, 1.0, Slip::new(vx, vy, w).unwrap());
            (t.fx, t.fy)
        };
        let h = 1e-7;
        let (px, mx) = (f(vx + h, vy), f(vx - h, vy));
        let (py, my) = (f(vx, vy + h), f(vx, vy - h));
        let j = [
            [-(px.0 - mx.0) / (2.0 * h), -(py.0 - my.0) / (2.0 * h)],
            [-(px.1 - mx.1) / (2.0 * h), -(py.1 - my.1) / (2.0 * h)],
        ];
        let (tr, det) = (j[0][0] + j[1][1], j[0][0] * j[1][1] - j[0][1] * j[1][0]);
        let disc = 0.25 * tr * tr - det;
        let lam = if disc >= 0.0 {
            0.5 * tr + disc.sqrt()
        } else {
            det / (0.5 * tr)
        };
        worst = worst.max(lam / kappa);
    }
    println!("largest per-step stiffness / κ(e²): {worst:.4}");
    assert!(worst <= 1.0 + 1e-4, "{worst}");
}
