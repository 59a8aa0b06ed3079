//! The ball bearing scene (feature `scenes`): the paper's race eccentricities (exact 0.687,
//! G* ≈ 0.643), pure rolling at the start keeps the cage speed, and a short loaded run keeps
//! the balls orbiting at ω_c = (ω_i/2)(1 − D/d_m) within 2 % with a finite, loaded state.

use contensou::contact::Contact;
use contensou::friction::{Friction, Simplified, Slip};
use contensou::geometry::Race;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::scenes::bearing::{BALLS, Bearing, Geometry, State};
use contensou::scenes::integrate::rk4;
use contensou::shape::{Linear, Newton};

fn e2<M: contensou::shape::Eccentricity>(g: &Geometry<f64>, race: Race) -> f64 {
    let c = Contact::hertz::<M>(
        &g.curvatures(race).unwrap(),
        Modulus::new(1.142857e11).unwrap(),
        HuntCrossley::new(0.3).unwrap(),
        Friction::<f64, Simplified>::with_law(0.07, 0.05).unwrap(),
    )
    .unwrap();
    c.wrench(1e-6, 0.0, Slip::default()).patch.e2
}

#[test]
fn paper_eccentricities() {
    let g = Geometry::paper_e2();
    assert!((e2::<Newton>(&g, Race::Inner) - 0.687).abs() < 5e-4);
    assert!((e2::<Linear>(&g, Race::Inner) - 0.643).abs() < 1e-3);
}

#[test]
fn rolls_at_the_cage_speed_under_load() {
    let g = Geometry::bearing_209();
    let c = |race| {
        Contact::hertz::<Newton>(
            &g.curvatures(race).unwrap(),
            Modulus::new(1.142857e11).unwrap(),
            HuntCrossley::new(0.3).unwrap(),
            Friction::<f64, Simplified>::with_law(0.07, 0.05).unwrap(),
        )
        .unwrap()
    };
    let b = Bearing::new(&g, c(Race::Inner), c(Race::Outer)).unwrap();
    // 5 ms: the load ramps up to 2 kN radial.
    let y = rk4(&b, 0.0, b.initial_state(), 5e-7, 10_000, |_, _, _| {});
    assert!(y.iter().all(|v| v.is_finite()));
    let mut n_sum = 0.0;
    for i in 0..BALLS {
        let p = &y[6 + 9 * i..12 + 9 * i];
        let orbit = (p[0] * p[4] - p[1] * p[3]) / (p[0] * p[0] + p[1] * p[1]);
        let (inner, _) = b.contacts(&y, i);
        n_sum += inner.n;
        if inner.n > 100.0 {
            assert!(
                (orbit / g.cage_speed() - 1.0).abs() < 0.02,
                "ball {i}: {orbit}"
            );
        }
    }
    // The inner ring has moved down towards the load, and the balls carry at least the load.
    assert!(y[1] < -5e-6, "{}", y[1]);
    assert!(n_sum > 2000.0 && n_sum < 4000.0, "{n_sum}");
}

// --- Rolling velocity V = v_P − ½(u_A + u_B) at the races (issue 20 item 5) ---

type BestRace = Contact<f64, contensou::normal::Hertz<f64>, HuntCrossley<f64>>;

fn best_bearing(g: &Geometry<f64>) -> Bearing<f64, BestRace> {
    let c = |race| {
        Contact::hertz::<Newton>(
            &g.curvatures(race).unwrap(),
            Modulus::new(1.142857e11).unwrap(),
            HuntCrossley::new(0.3).unwrap(),
            Friction::new(0.07, 0.05).unwrap(),
        )
        .unwrap()
    };
    Bearing::new(g, c(Race::Inner), c(Race::Outer)).unwrap()
}

/// Balls orbiting at ω_c on a circle of radius ρ_b, spinning about the bearing axis at w_b.
fn orbiting(b: &Bearing<f64, BestRace>, rho_b: f64, wc: f64, wb: f64) -> State<f64> {
    let mut y = b.initial_state();
    for i in 0..BALLS {
        let (s, c) = (std::f64::consts::TAU * i as f64 / BALLS as f64).sin_cos();
        let ball = [
            rho_b * c,
            rho_b * s,
            0.0,
            -wc * rho_b * s,
            wc * rho_b * c,
            0.0,
            0.0,
            0.0,
            wb,
        ];
        y[6 + 9 * i..15 + 9 * i].copy_from_slice(&ball);
    }
    y
}

/// Pure rolling, contact angle 0: the balls pressed 1 µm into one race, orbiting at the cage
/// speed ω_c and spinning so that the ball's material at P moves with the race's. The contact
/// point runs along the circumference at ω_c(ρ_b + r_b) over the fixed outer race, and at
/// (ω_i − ω_c)(ρ_b − r_b) backwards relative to the faster inner ring. The 209's major axis is
/// across the groove, so the contact frame's y is −e_θ and V has no x component.
#[test]
fn rolling_velocity_of_pure_rolling_is_the_rolling_speed() {
    let g = Geometry::bearing_209();
    let b = best_bearing(&g);
    let (rp, rb, wc, wi) = (
        g.pitch_diameter / 2.0,
        g.ball_diameter / 2.0,
        g.cage_speed(),
        g.omega_inner,
    );
    // Outer race: ball material at P at rest, ω_c ρ_b + w_b r_b = 0.
    let rho = rp + 1e-6;
    let y = orbiting(&b, rho, wc, -wc * rho / rb);
    let outer = wc * (rho + rb);
    // Inner race: ω_c ρ_b − w_b r_b = ω_i (ρ_b − r_b).
    let rho_i = rp - 1e-6;
    let yi = orbiting(&b, rho_i, wc, (wc * rho_i - wi * (rho_i - rb)) / rb);
    let inner = (wi - wc) * (rho_i - rb);
    assert!(outer > 2.0 && inner > 2.0, "{outer} {inner}");
    for i in 0..BALLS {
        let (ci, co) = (b.contacts(&yi, i).0, b.contacts(&y, i).1);
        assert!(ci.h > 0.0 && co.h > 0.0);
        // The slip vanishes (pure rolling) and V_y = −V·e_θ.
        assert!(ci.fx.abs() + ci.fy.abs() < 1e-9 && co.fx.abs() + co.fy.abs() < 1e-9);
        assert!(ci.rolling[0].abs() < 1e-12, "{:?}", ci.rolling);
        assert!(
            (ci.rolling[1] - inner).abs() < 1e-12 * inner,
            "{:?} {inner}",
            ci.rolling
        );
        assert!(co.rolling[0].abs() < 1e-12, "{:?}", co.rolling);
        assert!(
            (co.rolling[1] + outer).abs() < 1e-12 * outer,
            "{:?} {outer}",
            co.rolling
        );
    }
}

/// A ball pivoting in place about its contact normal (centre at rest pressed 1 µm into the
/// race, ring at rest, spin about the radial direction): V = 0 while the spin is not.
#[test]
fn rolling_velocity_of_a_pivoting_ball_is_zero() {
    let g = Geometry {
        omega_inner: 0.0,
        ..Geometry::bearing_209()
    };
    let b = best_bearing(&g);
    for (dr, inner) in [(-1e-6, true), (1e-6, false)] {
        let mut y = orbiting(&b, g.pitch_diameter / 2.0 + dr, 0.0, 0.0);
        for i in 0..BALLS {
            let (s, c) = (std::f64::consts::TAU * i as f64 / BALLS as f64).sin_cos();
            y[12 + 9 * i..15 + 9 * i].copy_from_slice(&[300.0 * c, 300.0 * s, 0.0]);
        }
        for i in 0..BALLS {
            let (ci, co) = b.contacts(&y, i);
            let k = if inner { ci } else { co };
            assert!(k.h > 0.0 && (k.spin.abs() - 300.0).abs() < 1e-9, "{k:?}");
            assert!(k.rolling.iter().all(|v| v.abs() < 1e-12), "{:?}", k.rolling);
        }
    }
}

type V3 = [f64; 3];
fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn mul(a: V3, k: f64) -> V3 {
    [a[0] * k, a[1] * k, a[2] * k]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The contact point on a torus race (groove centre circle radius `rho_c` about `c`) of a ball
/// centred at `p`: p + r_b u, u the unit vector from the nearest groove centre to p.
fn contact_point(c: V3, p: V3, rho_c: f64, rb: f64) -> (V3, V3) {
    let r = sub(p, c);
    let rho = r[0].hypot(r[1]);
    let centre = add(c, [rho_c * r[0] / rho, rho_c * r[1] / rho, 0.0]);
    let g = sub(p, centre);
    let u = mul(g, 1.0 / dot(g, g).sqrt());
    (add(p, mul(u, rb)), u)
}

/// A general state (ring moving, ball off the groove bottom with a contact angle, every
/// velocity component non-zero): V against v_P from a central difference of the contact
/// point along the motion (independent of the scene's closed-form u̇) and the material
/// velocities of both bodies at P, projected on the contact frame built here.
#[test]
fn rolling_velocity_matches_a_finite_difference_of_the_contact_point() {
    let g = Geometry::bearing_209();
    let b = best_bearing(&g);
    let (rb, dm) = (g.ball_diameter / 2.0, g.pitch_diameter);
    let rho_in = (dm - g.ball_diameter) / 2.0 + g.inner_groove;
    let rho_out = (dm + g.ball_diameter) / 2.0 - g.outer_groove;
    let mut y = b.initial_state();
    let ring_c = [1e-6, -4e-6, 2e-5];
    let ring_v = [0.03, -0.02, 0.05];
    y[..6].copy_from_slice(&[
        ring_c[0], ring_c[1], ring_c[2], ring_v[0], ring_v[1], ring_v[2],
    ]);
    let ball: [f64; 9] = [0.0311, 0.0094, 4e-4, -0.7, 2.1, 0.3, 40.0, -25.0, -480.0];
    y[6..15].copy_from_slice(&ball);
    let (p, v, w) = (
        [ball[0], ball[1], ball[2]],
        [ball[3], ball[4], ball[5]],
        [ball[6], ball[7], ball[8]],
    );
    let (ci, co) = b.contacts(&y, 0);
    assert!(ci.h > 0.0 && co.h > 0.0, "{} {}", ci.h, co.h);
    let dt = 1e-7;
    for (contact, c, vr, wr, rho_c) in [
        (ci, ring_c, ring_v, g.omega_inner, rho_in),
        (co, [0.0; 3], [0.0; 3], 0.0, rho_out),
    ] {
        let at = |s: f64| contact_point(add(c, mul(vr, s)), add(p, mul(v, s)), rho_c, rb);
        let (pt, u) = at(0.0);
        let v_p = mul(sub(at(dt).0, at(-dt).0), 0.5 / dt);
        let u_a = add(vr, cross([0.0, 0.0, wr], sub(pt, c)));
        let u_b = add(v, cross(w, mul(u, rb)));
        let vv = sub(v_p, mul(add(u_a, u_b), 0.5));
        // Contact frame: z = −u, t₁ = e_θ, major axis across the groove: x = z × t₁, y = −t₁.
        let r = sub(p, c);
        let rho = r[0].hypot(r[1]);
        let t1 = [-r[1] / rho, r[0] / rho, 0.0];
        let z = mul(u, -1.0);
        let (x, yy) = (cross(z, t1), mul(t1, -1.0));
        let expect = [dot(vv, x), dot(vv, yy)];
        let scale = dot(vv, vv).sqrt();
        assert!(scale > 1.0, "{scale}");
        for k in 0..2 {
            assert!(
                (contact.rolling[k] - expect[k]).abs() < 1e-7 * scale,
                "{:?} vs {expect:?}",
                contact.rolling
            );
        }
    }
}

// --- The bearing with the rolling law (`select::Rolls` → `contact::Rolling<…, Table>`) ---

use contensou::scenes::integrate::Ode;
use contensou::select::{Elliptic, ExactGrade, Fixed, Rolls, Scene, Select};

type RollingRace = Scene<Elliptic, Fixed, Rolls, ExactGrade, f64>;

fn rolling_bearing(
    g: &Geometry<f64>,
    delta: f64,
) -> Bearing<f64, contensou::select::ContactOf<RollingRace, HuntCrossley<f64>>> {
    let c = |race| {
        RollingRace::build(
            &g.curvatures(race).unwrap(),
            Modulus::new(1.142857e11).unwrap(),
            HuntCrossley::new(0.3).unwrap(),
            Friction::new(0.07, delta).unwrap(),
        )
        .unwrap()
    };
    Bearing::new(g, c(Race::Inner), c(Race::Outer)).unwrap()
}

/// The loaded state of the rolling-law tests: the bearing 209, its full-slip (`best`) scene
/// and that scene's state after 5 ms (10,000 RK4 steps of 0.5 µs from the initial state).
fn loaded() -> (Geometry<f64>, Bearing<f64, BestRace>, State<f64>) {
    let g = Geometry::bearing_209();
    let full = best_bearing(&g);
    let y = rk4(&full, 0.0, full.initial_state(), 5e-7, 10_000, |_, _, _| {});
    (g, full, y)
}

/// At a loaded state (5 ms of the full-slip run: load ramped up, balls rolling with the
/// contact angle the axial load gives): every rolling contact is passive (friction power
/// F·v_P + T_z·ω ≤ 0) and bounded (|F| ≤ fN), its creep force differs from full slip's, δ does
/// not enter (bit-identical derivatives at δ = 0.05 and 0.001 m/s), and 500 RK4 steps of
/// 0.1 µs stay finite with the balls carrying the load.
#[test]
fn rolling_law_in_the_bearing_is_passive_and_ignores_delta() {
    let (g, full, y) = loaded();
    let roll = rolling_bearing(&g, 0.05);
    assert_eq!(roll.rhs(5e-3, &y), rolling_bearing(&g, 1e-3).rhs(5e-3, &y));
    let mut loaded = 0;
    let mut differs = false;
    for i in 0..BALLS {
        let (ri, ro) = roll.contacts(&y, i);
        let (fi, _) = full.contacts(&y, i);
        for c in [ri, ro] {
            if c.n <= 0.0 {
                continue;
            }
            loaded += 1;
            let power = c.fx * c.slip[0] + c.fy * c.slip[1] + c.tz * c.spin;
            assert!(power <= 1e-12 * c.n, "ball {i}: power {power} {c:?}");
            assert!(c.fx.hypot(c.fy) <= 0.07 * c.n * (1.0 + 1e-12), "{c:?}");
            assert!(c.rolling[1].abs() > 2.0, "{:?}", c.rolling);
        }
        differs |= ri.n > 100.0 && (ri.fy - fi.fy).abs() > 1e-3 * ri.n;
    }
    assert!(loaded >= 8 && differs, "{loaded} {differs}");
    let y2 = rk4(&roll, 5e-3, y, 1e-7, 500, |_, _, _| {});
    assert!(y2.iter().all(|v| v.is_finite()));
    let n: f64 = (0..BALLS).map(|i| roll.contacts(&y2, i).0.n).sum();
    assert!(n > 1000.0 && n < 4000.0, "{n}");
}

/// The rolling race law in `f32` (the MCU's precision) at the same loaded state: the normal
/// and creep forces of every loaded contact agree with `f64` within 5e-3 of N and of fN — the
/// f32 scene's own resolution: a ball centre at 32 mm is rounded to 2e-9 m, 1e-3 of a 3 µm
/// approach, and the groove's conformity (d = r_g − r_b + h ≈ 0.1 mm out of ρ ≈ 30 mm) keeps
/// that (measured 1.3e-3 of N, 3.3e-4 of fN).
#[test]
fn rolling_law_in_f32_matches_f64() {
    let (g, _, y) = loaded();
    let roll = rolling_bearing(&g, 0.05);
    let g32 = Geometry::<f32>::bearing_209();
    let c32 = |race| {
        Scene::<Elliptic, Fixed, Rolls, ExactGrade, f32>::build(
            &g32.curvatures(race).unwrap(),
            Modulus::new(1.142857e11_f32).unwrap(),
            HuntCrossley::new(0.3).unwrap(),
            Friction::new(0.07, 0.05).unwrap(),
        )
        .unwrap()
    };
    let roll32 = Bearing::new(&g32, c32(Race::Inner), c32(Race::Outer)).unwrap();
    let y32: State<f32> = y.map(|v| v as f32);
    let mut checked = 0;
    let mut worst = [0.0_f64; 2];
    for i in 0..BALLS {
        let (a, b) = roll.contacts(&y, i);
        let (a32, b32) = roll32.contacts(&y32, i);
        for (c, c32) in [(a, a32), (b, b32)] {
            if c.n < 100.0 {
                continue;
            }
            checked += 1;
            let fnn = 0.07 * c.n;
            worst[0] = worst[0].max((c.n - c32.n as f64).abs() / c.n);
            worst[1] = worst[1].max((c.fx - c32.fx as f64).hypot(c.fy - c32.fy as f64) / fnn);
            assert!((c.n - c32.n as f64).abs() < 5e-3 * c.n, "{c:?} {c32:?}");
            assert!((c.fx - c32.fx as f64).abs() < 5e-3 * fnn, "{c:?} {c32:?}");
            assert!((c.fy - c32.fy as f64).abs() < 5e-3 * fnn, "{c:?} {c32:?}");
        }
    }
    assert!(checked >= 6, "{checked}");
    println!("f32 vs f64: {worst:?}");
}
