//! The exact Contensou–Erismann integrals against the independent brute-force reference
//! (tools/data/friction_ref.csv, tools/gen_friction_ref.py), plus symmetries, homogeneity,
//! limits, continuity, passivity and the confocal-coordinate structure (notes §3).
#![allow(clippy::excessive_precision)]
use contensou::elliptic::{Agm, Method, Parameter};
use contensou::friction::{Traction, exact::traction};
use std::f64::consts::{FRAC_PI_2, PI};

struct Row {
    e2: f64,
    psi: f64,
    u: f64,
    want: [f64; 3],
}

/// The structured set (friction_ref.csv) followed by the random one (friction_ref_random.csv).
fn reference() -> Vec<Row> {
    let mut rows = parse(include_str!("../tools/data/friction_ref.csv"));
    rows.extend(parse(include_str!("../tools/data/friction_ref_random.csv")));
    rows
}

fn parse(text: &str) -> Vec<Row> {
    text.lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
            Row {
                e2: v[0],
                psi: v[1],
                u: v[2],
                want: [v[3], v[4], v[5]],
            }
        })
        .collect()
}

/// (vx, vy, aω) for u = v/(aω) along ψ; u = ∞ is pure translation.
fn state(psi: f64, u: f64) -> (f64, f64, f64) {
    if u.is_infinite() {
        (psi.cos(), psi.sin(), 0.0)
    } else {
        (u * psi.cos(), u * psi.sin(), 1.0)
    }
}

fn t64(m: f64, vx: f64, vy: f64, w: f64) -> Traction<f64> {
    traction(Parameter::new(m).unwrap(), vx, vy, w)
}

fn err(t: Traction<f64>, want: [f64; 3]) -> f64 {
    (t.fx - want[0])
        .abs()
        .max((t.fy - want[1]).abs())
        .max((t.tz - want[2]).abs())
}

#[test]
fn matches_reference_f64() {
    let rows = reference();
    assert!(rows.len() > 800);
    let mut worst = (0.0, 0.0, 0.0, 0.0);
    for r in &rows {
        let (vx, vy, w) = state(r.psi, r.u);
        let e = err(t64(r.e2, vx, vy, w), r.want);
        if e > worst.0 {
            worst = (e, r.e2, r.psi, r.u);
        }
    }
    println!("f64 max abs error vs reference: {worst:?}");
    assert!(worst.0 <= 1e-9, "{worst:?}");
}

#[test]
fn matches_reference_f32() {
    let mut worst = (0.0f64, 0.0, 0.0, 0.0);
    for r in &reference() {
        let (vx, vy, w) = state(r.psi, r.u);
        // e² = 1 − 1e-8 and closer round to 1 in f32: outside f32's domain (m₁ ≥ 2⁻²⁴)
        let Ok(p) = Parameter::new(r.e2 as f32) else {
            assert!(r.e2 > 0.9999);
            continue;
        };
        let t = traction(p, vx as f32, vy as f32, w as f32);
        let t = Traction {
            fx: t.fx as f64,
            fy: t.fy as f64,
            tz: t.tz as f64,
        };
        let e = err(t, r.want);
        if e > worst.0 {
            worst = (e, r.e2, r.psi, r.u);
        }
    }
    println!("f32 max abs error vs reference: {worst:?}");
    assert!(worst.0 <= 1e-5, "{worst:?}");
}

/// Deterministic pseudo-random states (xorshift), log-uniform speeds, all quadrants.
fn states(n: usize) -> impl Iterator<Item = (f64, f64, f64, f64)> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(move |_| {
        let m = [0.0, 0.3, 0.687, 0.9, 0.99, 0.9999][(next() * 6.0) as usize];
        let psi = (next() * 2.0 - 1.0) * PI;
        let u = 10f64.powf(next() * 6.0 - 3.0);
        let w = if next() < 0.5 { 1.0 } else { -1.0 } * 10f64.powf(next() * 4.0 - 2.0);
        (m, u * w.abs() * psi.cos(), u * w.abs() * psi.sin(), w)
    })
}

/// [`states`] with their traction at e² = m.
fn tractions(n: usize) -> impl Iterator<Item = ((f64, f64, f64, f64), Traction<f64>)> {
    states(n).map(|(m, vx, vy, w)| ((m, vx, vy, w), t64(m, vx, vy, w)))
}

#[test]
fn symmetries() {
    for ((m, vx, vy, w), t) in tractions(300) {
        let mirror_x = t64(m, vx, -vy, -w); // y → −y
        assert_eq!(
            (mirror_x.fx, mirror_x.fy, mirror_x.tz),
            (t.fx, -t.fy, -t.tz)
        );
        let mirror_y = t64(m, -vx, vy, -w); // x → −x
        assert_eq!(
            (mirror_y.fx, mirror_y.fy, mirror_y.tz),
            (-t.fx, t.fy, -t.tz)
        );
        let psi_neg = t64(m, vx, -vy, w); // ψ → −ψ
        assert_eq!((psi_neg.fx, psi_neg.fy, psi_neg.tz), (t.fx, -t.fy, t.tz));
        let psi_pi = t64(m, -vx, -vy, w); // ψ → ψ + π
        assert_eq!((psi_pi.fx, psi_pi.fy, psi_pi.tz), (-t.fx, -t.fy, t.tz));
        let spin = t64(m, vx, vy, -w); // ω → −ω flips T_z only
        assert_eq!((spin.fx, spin.fy, spin.tz), (t.fx, t.fy, -t.tz));
        let all = t64(m, -vx, -vy, -w); // reversing the slip reverses the traction
        assert_eq!((all.fx, all.fy, all.tz), (-t.fx, -t.fy, -t.tz));
    }
}

#[test]
fn circle_is_isotropic() {
    // e² = 0: rotating v_P rotates F and leaves T_z unchanged (not built into the code).
    let mut worst = 0.0f64;
    for (_, vx, vy, w) in states(200) {
        let t = t64(0.0, vx, vy, w);
        for th in [0.3f64, 1.1, 2.0, -2.7] {
            let (s, c) = th.sin_cos();
            let r = t64(0.0, c * vx - s * vy, s * vx + c * vy, w);
            let (fx, fy) = (c * t.fx - s * t.fy, s * t.fx + c * t.fy);
            worst = worst.max(err(r, [fx, fy, t.tz]));
        }
    }
    println!("circle isotropy max deviation {worst:e}");
    assert!(worst < 1e-13, "{worst}");
}

#[test]
fn homogeneous_of_degree_zero() {
    for ((m, vx, vy, w), t) in tractions(200) {
        for l in [1e-300, 3.7e-9, 0.37, 2.9e7, 1e300] {
            let s = t64(m, l * vx, l * vy, l * w);
            assert!(err(s, [t.fx, t.fy, t.tz]) < 1e-14, "{m} {vx} {vy} {w} {l}");
        }
    }
}

#[test]
fn zero_and_non_finite_states() {
    for m in [0.0, 0.5, 0.99] {
        assert_eq!(t64(m, 0.0, 0.0, 0.0), Traction::default());
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(t64(m, bad, 1.0, 1.0), Traction::default());
            assert_eq!(t64(m, 1.0, 1.0, bad), Traction::default());
        }
    }
}

#[test]
fn limits_spin_and_translation() {
    for m1 in [1.0f64, 0.7, 0.313, 0.1, 0.01, 1e-4, 1e-12] {
        let p = Parameter::from_complement(m1).unwrap();
        let e = Agm::integrals(p).e;
        for w in [1.0, -2.5, 1e-200] {
            let t = traction(p, 0.0, 0.0, w);
            assert_eq!((t.fx, t.fy), (0.0, 0.0));
            assert!(
                (t.tz + 0.375 * e * w.signum()).abs() < 1e-15,
                "{m1} {}",
                t.tz
            );
        }
        for psi in [0.0, 0.4, FRAC_PI_2, 2.0, -1.0] {
            let t = traction(p, 3.0 * psi.cos(), 3.0 * psi.sin(), 0.0);
            assert!((t.fx + psi.cos()).abs() < 3e-16 && (t.fy + psi.sin()).abs() < 3e-16);
            assert_eq!(t.tz, 0.0);
        }
    }
}

#[test]
fn small_u_slopes() {
    // paper (3.5): F_x ≈ −αAu, F_y ≈ −βBu, A = (3/2)D, B = (3/2)B(m)
    for m in [0.0, 0.3, 0.9, 0.99] {
        let i = Agm::integrals(Parameter::new(m).unwrap());
        let (psi, u) = (0.7f64, 1e-7);
        let t = t64(m, u * psi.cos(), u * psi.sin(), 1.0);
        assert!((t.fx / u + psi.cos() * 1.5 * i.d).abs() < 1e-6);
        assert!((t.fy / u + psi.sin() * 1.5 * i.b).abs() < 1e-6);
    }
}

#[test]
fn large_u_series_and_switch() {
    // F − (F₀ + F₂/u²) = O(u⁻⁴), T_z − T₁/u = O(u⁻³); the series branch takes over at u = 1e5
    let mut worst = 0.0f64;
    for m in [0.0, 0.3, 0.9, 0.99, 0.9999] {
        for psi in [0.0, 0.5, 1.2, FRAC_PI_2] {
            let (al, be) = (psi.cos(), psi.sin());
            for u in [30.0, 1e3, 1e4, 1e5 * (1.0 - 1e-9), 1e5 * (1.0 + 1e-9), 1e7] {
                let t = t64(m, u * al, u * be, 1.0);
                let f2x = 0.2 * (0.5 * al + m * ((1.5 * al * al - 0.5) * al - al));
                let f2y = 0.2 * (0.5 * be + m * (1.5 * al * al - 0.5) * be);
                let t1 = -0.2 * (1.0 - m * be * be);
                let df = (t.fx + al - f2x / (u * u))
                    .abs()
                    .max((t.fy + be - f2y / (u * u)).abs());
                let dt = (t.tz - t1 / u).abs();
                assert!(df < 1.0 / u.powi(4) + 1e-15, "{m} {psi} {u} {df}");
                assert!(dt < 1.0 / u.powi(3) + 1e-15, "{m} {psi} {u} {dt}");
                worst = worst.max(dt * u.powi(3));
            }
        }
    }
    println!("max |T_z − T₁/u|·u³ = {worst:e}");
}

fn u_boundary(m: f64, psi: f64) -> f64 {
    1.0 / (psi.sin().powi(2) + psi.cos().powi(2) / (1.0 - m)).sqrt()
}

#[test]
fn continuous_across_the_boundary() {
    let mut worst = 0.0f64;
    for m in [0.0, 0.3, 0.687, 0.9, 0.99, 0.9999] {
        for k in 0..24 {
            let psi = -PI + k as f64 * PI / 12.0 + 0.01;
            let ub = u_boundary(m, psi);
            let a = state(psi, ub * (1.0 - 1e-12));
            let b = state(psi, ub * (1.0 + 1e-12));
            let (ta, tb) = (t64(m, a.0, a.1, a.2), t64(m, b.0, b.1, b.2));
            worst = worst.max(err(ta, [tb.fx, tb.fy, tb.tz]));
        }
    }
    println!("jump across the ellipse boundary (u_b(1 ± 1e-12)): {worst:e}");
    assert!(worst < 1e-9, "{worst}");
}

#[test]
fn passive_and_bounded() {
    for ((m, vx, vy, w), t) in tractions(2000) {
        assert!(t.fx * vx + t.fy * vy + t.tz * w < 0.0, "{m} {vx} {vy} {w}");
        assert!(t.fx.hypot(t.fy) <= 1.0 + 1e-15);
        assert!(t.tz.abs() <= 0.375 * PI / 2.0 + 1e-15);
        let (vx, vy, w) = (vx as f32, vy as f32, w as f32);
        let t = traction(Parameter::new(m as f32).unwrap(), vx, vy, w);
        assert!(
            t.fx * vx + t.fy * vy + t.tz * w < 0.0,
            "f32 {m} {vx} {vy} {w}"
        );
    }
}

/// Notes §3, outside the ellipse: with the IC on the confocal ellipse a_c (X₀ = −a_c sin ν,
/// Y₀ = b_c cos ν, b_c² = a_c² − m), F_x = −cos ν (a_x + b_x q), F_y = −sin ν (a_y + b_y q),
/// T_z = τ (a_T + b_T q + c_T q²), q = sin²ν, τ = (1 + γ)/(a_c + b_c), coefficients depending
/// on (m, a_c) only. Fitted at 2–3 values of ν, checked at 9 others.
#[test]
fn confocal_polynomial_structure() {
    let mut worst = 0.0f64;
    for m in [0.0, 0.3, 0.687, 0.9, 0.99, 0.9999] {
        let gamma = (1.0f64 - m).sqrt();
        for ac in [1.0 + 1e-6, 1.01, 1.2, 1.7, 3.0, 20.0] {
            let bc = (ac * ac - m).sqrt();
            let tau = (1.0 + gamma) / (ac + bc);
            let eval = |nu: f64| {
                let (s, c) = nu.sin_cos();
                // IC (X₀, Y₀) = (−vy, vx)/(aω)
                let t = t64(m, bc * c, ac * s, 1.0);
                (-t.fx / c, -t.fy / s, t.tz / tau, s * s)
            };
            let fit = [0.2, 0.8, 1.3].map(eval);
            let (q0, q1, q2) = (fit[0].3, fit[1].3, fit[2].3);
            let bx = (fit[1].0 - fit[0].0) / (q1 - q0);
            let by = (fit[1].1 - fit[0].1) / (q1 - q0);
            // quadratic through three points (Newton form)
            let d1 = (fit[1].2 - fit[0].2) / (q1 - q0);
            let d2 = ((fit[2].2 - fit[1].2) / (q2 - q1) - d1) / (q2 - q0);
            for nu in [0.05, 0.35, 0.5, 0.65, 0.95, 1.1, 1.25, 1.45, 1.55] {
                let (x, y, t, q) = eval(nu);
                let px = fit[0].0 + bx * (q - q0);
                let py = fit[0].1 + by * (q - q0);
                let pt = fit[0].2 + d1 * (q - q0) + d2 * (q - q0) * (q - q1);
                worst = worst
                    .max((x - px).abs())
                    .max((y - py).abs())
                    .max((t - pt).abs());
            }
        }
    }
    println!("confocal structure: max deviation from the polynomials in sin²ν {worst:e}");
    assert!(worst < 1e-11, "{worst}");
}

#[test]
#[ignore = "timing; run with --release --nocapture"]
fn cost_per_call() {
    let p = Parameter::new(0.687f64).unwrap();
    let mut sink = 0.0;
    for (name, u) in [
        ("inside", 0.3),
        ("outside", 1.5),
        ("outside", 30.0),
        ("series", 1e6),
    ] {
        let n = 20_000;
        let t0 = std::time::Instant::now();
        for k in 0..n {
            let psi = k as f64 * 1e-4;
            let t = traction(p, u * psi.cos(), u * psi.sin(), 1.0);
            sink += t.fx + t.tz;
        }
        let ns = t0.elapsed().as_nanos() as f64 / n as f64;
        println!("{name} u = {u}: {ns:.0} ns/call");
    }
    let thin = Parameter::from_complement(1e-8f64).unwrap();
    let t0 = std::time::Instant::now();
    for k in 0..20_000 {
        let psi = k as f64 * 1e-4;
        sink += traction(thin, 1.5 * psi.cos(), 1.5 * psi.sin(), 1.0).fx;
    }
    println!(
        "m1 = 1e-8 outside u = 1.5: {:.0} ns/call",
        t0.elapsed().as_nanos() as f64 / 2e4
    );
    let p32 = Parameter::new(0.687f32).unwrap();
    let t0 = std::time::Instant::now();
    for k in 0..20_000 {
        let psi = k as f32 * 1e-4;
        sink += traction(p32, 1.5 * psi.cos(), 1.5 * psi.sin(), 1.0).fx as f64;
    }
    println!(
        "f32 outside u = 1.5: {:.0} ns/call",
        t0.elapsed().as_nanos() as f64 / 2e4
    );
    assert!(sink.is_finite());
}
