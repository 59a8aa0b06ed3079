//! The frame helper (`contensou::frame`) against hand computations: axes at a given angle,
//! rotation equivariance (an independent Rodrigues rotation), the power identity of the loads on
//! both bodies (lever arms and signs), passivity, and continuity of the world force where the
//! curvatures cross (e² = 0, the major axis jumps by 90°).

use contensou::contact::Contact;
use contensou::frame::{ContactFrame, Frame, MajorAxis, Vector, WorldAxes, point_velocity};
use contensou::friction::{Best, Friction, Simplified};
use contensou::geometry::{Curvatures, Principal};
use contensou::normal::{Hertz, Modulus, Undamped};
use contensou::shape::Newton;
use std::f64::consts::PI;

fn close(a: Vector<f64>, b: Vector<f64>, tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

fn dot(a: Vector<f64>, b: Vector<f64>) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: Vector<f64>) -> f64 {
    dot(a, a).sqrt()
}

fn cross(a: Vector<f64>, b: Vector<f64>) -> Vector<f64> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Rodrigues: v rotated by `angle` about the unit `axis`.
fn rotate(axis: Vector<f64>, angle: f64, v: Vector<f64>) -> Vector<f64> {
    let (s, c) = angle.sin_cos();
    let k = dot(axis, v) * (1.0 - c);
    let kv = cross(axis, v);
    [0, 1, 2].map(|i| v[i] * c + kv[i] * s + axis[i] * k)
}

/// A small deterministic generator (xorshift) of values in [−1, 1].
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    fn vector(&mut self) -> Vector<f64> {
        [self.next(), self.next(), self.next()]
    }
    fn unit(&mut self) -> Vector<f64> {
        let v = self.vector();
        let n = norm(v);
        v.map(|c| c / n)
    }
}

/// The tests' contact: exact Hertz (E* = 1.15e11 Pa), undamped, `best` at f = 0.1, δ = 1e-6.
fn contact_on(curv: &Curvatures<f64>) -> Contact<f64, Hertz<f64>, Undamped, Best> {
    let friction = Friction::new(0.1, 1e-6).unwrap();
    Contact::hertz::<Newton>(curv, Modulus::new(1.15e11).unwrap(), Undamped, friction).unwrap()
}

/// [`contact_on`] the curvatures (P, Q).
fn contact(p: f64, q: f64) -> Contact<f64, Hertz<f64>, Undamped, Best> {
    contact_on(&Curvatures::new(p, q).unwrap())
}

#[test]
fn axes_by_hand() {
    // Normal up, reference world x, major axis at 30°: x = (cos 30°, sin 30°, 0),
    // y = (−sin 30°, cos 30°, 0).
    let (c, s) = (0.75f64.sqrt(), 0.5);
    let f = Frame::new(
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
        MajorAxis::from_angle(PI / 6.0),
    );
    assert!(close(f.x(), [c, s, 0.0], 1e-15));
    assert!(close(f.y(), [-s, c, 0.0], 1e-15));
    assert_eq!(f.z(), [0.0, 0.0, 1.0]);
    // v_rel = (1, 2, −0.5): v_Px = c + 2s, v_Py = −s + 2c, ḣ = 0.5; ω = ω_rel·z = 7.
    let slip = f.slip([1.0, 2.0, -0.5], [0.3, 0.1, 7.0]).unwrap();
    assert!((slip.vx() - (c + 2.0 * s)).abs() < 1e-15);
    assert!((slip.vy() - (2.0 * c - s)).abs() < 1e-15);
    assert_eq!(slip.omega(), 7.0);
    assert_eq!(f.approach_rate([1.0, 2.0, -0.5]), 0.5);

    // A wall: normal −y (A behind, B in front), reference x: t₂ = z × t₁ = +z.
    let wall = Frame::new([0.0, -1.0, 0.0], [1.0, 0.0, 0.0], MajorAxis::ACROSS);
    assert_eq!(wall.x(), [0.0, 0.0, 1.0]);
    assert_eq!(wall.y(), [-1.0, 0.0, 0.0]);

    // Exact angles of `Curvatures::new`.
    assert_eq!(
        MajorAxis::of(&Curvatures::new(2.0, 1.0).unwrap()),
        MajorAxis::ACROSS
    );
    assert_eq!(
        MajorAxis::of(&Curvatures::new(1.0, 2.0).unwrap()),
        MajorAxis::ALONG
    );
}

#[test]
fn the_load_by_hand() {
    // Ball on a floor, frame = world. N = 3, F = (−0.2, 0.1), T_z = −0.01; arm G → P = (0, 0, −R).
    let f = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::ALONG);
    let mut w = contact(50.0, 50.0).wrench(1e-6, 0.0, f.slip([1.0, 0.0, 0.0], [0.0; 3]).unwrap());
    (w.n, w.fx, w.fy, w.tz) = (3.0, -0.2, 0.1, -0.01);
    let r = 0.01;
    let b = f.on_b(&w, [0.0, 0.0, -r]);
    assert_eq!(b.force, [-0.2, 0.1, 3.0]);
    // (0, 0, −R) × (Fx, Fy, N) = (R·Fy, −R·Fx, 0), plus T_z about z.
    assert!(close(b.torque, [r * 0.1, r * 0.2, -0.01], 1e-17));
    // The floor (A) about a point C_A with P − C_A = (1, 0, 0): −F, (1,0,0) × (−F) − T_z·z.
    let a = f.on_a(&w, [1.0, 0.0, 0.0]);
    assert_eq!(a.force, [0.2, -0.1, -3.0]);
    assert!(close(a.torque, [0.0, 3.0, -0.1 + 0.01], 1e-16));
}

#[test]
fn frames_are_orthonormal_and_right_handed() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..1000 {
        let n = rng.unit();
        let axis = MajorAxis::from_angle(PI * rng.next());
        let f = Frame::from_reference(n, rng.vector(), axis);
        let (x, y, z) = (f.x(), f.y(), f.z());
        for (u, v, want) in [
            (x, x, 1.0),
            (y, y, 1.0),
            (x, y, 0.0),
            (x, z, 0.0),
            (y, z, 0.0),
        ] {
            assert!((dot(u, v) - want).abs() < 1e-14);
        }
        assert!(close(cross(x, y), z, 1e-14));
        // Round trip.
        let v = rng.vector();
        assert!(close(f.to_world(f.to_contact(v)), v, 1e-14));
    }
    // Degenerate references (along the normal, zero): still an orthonormal frame.
    for n in [[0.0, 0.0, 1.0], [0.6, 0.0, -0.8], [1.0, 0.0, 0.0]] {
        for r in [n, [0.0; 3], n.map(|c| -3.0 * c)] {
            let f = Frame::from_reference(n, r, MajorAxis::ALONG);
            assert!((norm(f.x()) - 1.0).abs() < 1e-15 && dot(f.x(), n).abs() < 1e-15);
            assert!(close(cross(f.x(), f.y()), n, 1e-15));
        }
    }
}

/// Rotating the whole scene (normal, reference tangent, velocities) rotates the frame and the
/// world load and leaves the slip unchanged.
#[test]
fn rotation_equivariance() {
    let mut rng = Rng(12345);
    let c = contact(40.0, 55.0);
    for _ in 0..200 {
        let n = rng.unit();
        let f = Frame::from_reference(n, rng.vector(), MajorAxis::from_angle(rng.next()));
        let (axis, angle) = (rng.unit(), PI * rng.next());
        let rot = |v| rotate(axis, angle, v);
        let g = Frame::new(rot(f.z()), rot(f.x()), MajorAxis::ALONG);
        assert!(close(g.y(), rot(f.y()), 1e-14));
        let (v, w, arm) = (rng.vector(), rng.vector().map(|c| 100.0 * c), rng.vector());
        let (sf, sg) = (f.slip(v, w).unwrap(), g.slip(rot(v), rot(w)).unwrap());
        assert!((sf.vx() - sg.vx()).abs() < 1e-14 && (sf.vy() - sg.vy()).abs() < 1e-14);
        assert!((sf.omega() - sg.omega()).abs() < 1e-12);
        let wf = c.wrench(1e-6, f.approach_rate(v), sf);
        let wg = c.wrench(1e-6, g.approach_rate(rot(v)), sg);
        let (lf, lg) = (f.on_b(&wf, arm), g.on_b(&wg, rot(arm)));
        let scale = wf.n.max(1e-30);
        assert!(close(rot(lf.force), lg.force, 1e-12 * scale));
        assert!(close(rot(lf.torque), lg.torque, 1e-12 * scale));
    }
}

/// The loads on both bodies do the power F·v_rel(P) + T_z·(ω_rel·z): checks every lever arm and
/// sign; the friction part is ≤ 0 (passive), the normal part is −N·ḣ.
#[test]
fn power_of_the_loads_and_passivity() {
    let mut rng = Rng(777);
    let c = contact(30.0, 80.0);
    for _ in 0..500 {
        let f = Frame::from_reference(rng.unit(), rng.vector(), MajorAxis::from_angle(rng.next()));
        // Bodies: centres' velocities, angular velocities, arms centre → P.
        let (va, wa, arm_a) = (rng.vector(), rng.vector().map(|c| 50.0 * c), rng.vector());
        let (vb, wb, arm_b) = (rng.vector(), rng.vector().map(|c| 50.0 * c), rng.vector());
        let v_rel =
            [0, 1, 2].map(|i| point_velocity(vb, wb, arm_b)[i] - point_velocity(va, wa, arm_a)[i]);
        let w_rel = [0, 1, 2].map(|i| wb[i] - wa[i]);
        let hdot = f.approach_rate(v_rel);
        let w = c.wrench(1e-6, hdot, f.slip(v_rel, w_rel).unwrap());
        let (lb, la) = (f.on_b(&w, arm_b), f.on_a(&w, arm_a));
        let power = dot(lb.force, vb) + dot(lb.torque, wb) + dot(la.force, va) + dot(la.torque, wa);
        let friction = power + w.n * hdot;
        let direct = w.fx * dot(v_rel, f.x()) + w.fy * dot(v_rel, f.y()) + w.tz * dot(w_rel, f.z());
        let scale = w.n * (norm(v_rel) + norm(w_rel));
        assert!(
            (friction - direct).abs() <= 1e-12 * scale,
            "{friction} vs {direct}"
        );
        assert!(friction <= 1e-12 * scale, "friction power {friction} > 0");
    }
}

/// Where P and Q cross, `Curvatures` turns the major axis by 90°: the contact-frame force jumps
/// by O(fN), the world force by O(ε·fN) only (ε = |1 − P/Q|), and the jump vanishes with ε.
#[test]
fn continuous_across_the_crossing() {
    let mut rng = Rng(4242);
    for law in ["best", "simplified"] {
        let mut worst: f64 = 0.0;
        for eps in [1e-2, 1e-3, 1e-4, 1e-6] {
            for _ in 0..50 {
                // Curvatures given in a frame (t₁, t₂) that is the same on both sides.
                let n = rng.unit();
                let t1 = rng.vector();
                let (v_rel, w_rel) = (rng.vector(), rng.vector().map(|c| 200.0 * c));
                let q = 50.0;
                let mut force = Vec::new();
                let mut local = Vec::new();
                for p in [q * (1.0 - eps), q * (1.0 + eps)] {
                    let curv = Curvatures::new(p, q).unwrap();
                    let frame = Frame::from_reference(n, t1, MajorAxis::of(&curv));
                    let slip = frame.slip(v_rel, w_rel).unwrap();
                    let (mu, fn_) = (Modulus::new(1.15e11).unwrap(), 1e-6);
                    let w = if law == "best" {
                        let c = Contact::hertz::<Newton>(
                            &curv,
                            mu,
                            Undamped,
                            Friction::<f64>::new(0.1, 1e-6).unwrap(),
                        )
                        .unwrap();
                        let w = c.wrench(fn_, 0.0, slip);
                        (w.n, w.fx, w.fy, w.tz, frame.on_b(&w, [0.0; 3]).force)
                    } else {
                        let c = Contact::hertz::<Newton>(
                            &curv,
                            mu,
                            Undamped,
                            Friction::<f64, Simplified>::with_law(0.1, 1e-6).unwrap(),
                        )
                        .unwrap();
                        let w = c.wrench(fn_, 0.0, slip);
                        (w.n, w.fx, w.fy, w.tz, frame.on_b(&w, [0.0; 3]).force)
                    };
                    force.push((w.0, w.4));
                    local.push([w.1, w.2]);
                }
                let fn_ = 0.1 * force[0].0;
                let tangential = |k: usize| {
                    let (n_k, f_k) = force[k];
                    let z = Frame::from_reference(n, t1, MajorAxis::ALONG).z();
                    [0, 1, 2].map(|i| f_k[i] - n_k * z[i])
                };
                let jump = norm([0, 1, 2].map(|i| tangential(1)[i] - tangential(0)[i])) / fn_;
                worst = worst.max(jump / eps);
                assert!(jump <= 0.6 * eps, "{law} ε = {eps}: world jump {jump} fN");
                // The contact-frame components do jump (by ~|F|): the frame turned.
                let local_jump = norm([local[1][0] - local[0][0], local[1][1] - local[0][1], 0.0]);
                let size = norm([local[0][0], local[0][1], 0.0]);
                assert!(local_jump > 0.5 * size, "{law}: the frame did not turn");
            }
        }
        println!("{law}: max world-force jump across the crossing = {worst:.3}·ε·fN");
    }
}

/// `Curvatures::from_bodies` near the crossing: two cylinders nearly crossed (its eigenvectors
/// swap as ω passes the angle where P = Q); the world force stays continuous there too.
#[test]
fn continuous_across_the_crossing_from_bodies() {
    // Two crossed cylinders, κ_A = (100, 0), κ_B = (100 + d, 0) at ω = 90°:
    // M = ½·diag(100, 100 + d), so P = Q at d = 0 and ε = |1 − P/Q| ≈ |d|/100.
    let n = [0.0, 0.0, 1.0];
    let t1 = [1.0, 0.0, 0.0];
    let (v_rel, w_rel) = ([0.3, -0.7, 0.0], [0.0, 0.0, 150.0]);
    let world = |d: f64| {
        let curv = Curvatures::from_bodies(
            Principal { k1: 100.0, k2: 0.0 },
            Principal {
                k1: 100.0 + d,
                k2: 0.0,
            },
            PI / 2.0,
        )
        .unwrap();
        let frame = Frame::new(n, t1, MajorAxis::of(&curv));
        let w = contact_on(&curv).wrench(1e-6, 0.0, frame.slip(v_rel, w_rel).unwrap());
        (frame.on_b(&w, [0.0; 3]).force, 0.1 * w.n, frame.x())
    };
    for d in [1.0, 1e-2, 1e-4] {
        let (fm, fnm, xm) = world(-d);
        let (fp, _, xp) = world(d);
        assert!(dot(xm, xp).abs() < 1e-6, "the major axis turned by 90°");
        let eps = d / 100.0;
        let jump = norm([fp[0] - fm[0], fp[1] - fm[1], 0.0]) / fnm;
        assert!(jump <= 0.6 * eps, "d = {d}: jump {jump} fN");
    }
}

/// `WorldAxes` is `Frame::new(+z, +x, ALONG)` without the arithmetic: the same slip, ḣ and loads.
#[test]
fn world_axes_is_the_upright_frame() {
    let mut rng = Rng(99);
    let upright = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::ALONG);
    let c = contact(50.0, 50.0);
    for _ in 0..200 {
        let (v, w, arm) = (rng.vector(), rng.vector().map(|c| 100.0 * c), rng.vector());
        let (s1, s2) = (upright.slip(v, w).unwrap(), WorldAxes.slip(v, w).unwrap());
        assert_eq!(s1, s2);
        assert_eq!(upright.approach_rate(v), WorldAxes.approach_rate(v));
        let wr = c.wrench(1e-6, 0.0, s1);
        assert_eq!(upright.on_b(&wr, arm), WorldAxes.on_b(&wr, arm));
        assert_eq!(upright.on_a(&wr, arm), WorldAxes.on_a(&wr, arm));
        assert_eq!(upright.to_contact(v), WorldAxes.to_contact(v));
    }
}
