//! Hunt–Crossley's coefficient of restitution: e ≈ 1 − c_d·v for a small impact speed v (the
//! guidance on `normal::HuntCrossley`), checked by integrating head-on impacts through the
//! library's damped Hertz law (RK4, 20,000 steps per contact) against the first-order
//! derivation (energy lost ∮ k_H h^{3/2}·(3/2)c_d·ḣ dh = c_d·m·v³ to first order, so
//! 1 − e² = 2c_d·v), and against the closer fit e ≈ 1/(1 + c_d·v).

use contensou::normal::{Hertz, HuntCrossley, Modulus, NormalLaw};

/// The rebound speed over the impact speed `v` of a mass `m` on a Hertz contact with
/// Hunt–Crossley damping `cd`.
fn restitution(cd: f64, v: f64) -> f64 {
    let (m, r, estar) = (0.0327, 0.01, 1.15e11);
    let law = Hertz::circular(0.5 / r, Modulus::new(estar).unwrap());
    let damping = HuntCrossley::new(cd).unwrap();
    // Contact time of the elastic impact, 2.94·(m²/(R E*² v))^{1/5}.
    let duration = 2.94 * (m * m / (r * estar * estar * v)).powf(0.2);
    let dt = duration / 20_000.0;
    let accel = |h: f64, hdot: f64| -law.damped_patch(h, hdot, &damping).n / m;
    let (mut h, mut hdot) = (0.0, v);
    loop {
        let k1 = (hdot, accel(h, hdot));
        let k2 = (
            hdot + 0.5 * dt * k1.1,
            accel(h + 0.5 * dt * k1.0, hdot + 0.5 * dt * k1.1),
        );
        let k3 = (
            hdot + 0.5 * dt * k2.1,
            accel(h + 0.5 * dt * k2.0, hdot + 0.5 * dt * k2.1),
        );
        let k4 = (hdot + dt * k3.1, accel(h + dt * k3.0, hdot + dt * k3.1));
        h += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        hdot += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        if h <= 0.0 && hdot < 0.0 {
            return -hdot / v;
        }
    }
}

#[test]
fn restitution_is_one_minus_cd_v_for_small_speeds() {
    let mut worst: f64 = 0.0;
    for (cd, v) in [
        (0.3, 3e-3),
        (0.3, 3e-2),
        (5.0, 2e-3),
        (5.0, 2e-2),
        (1.0, 0.1),
    ] {
        let x = cd * v;
        let e = restitution(cd, v);
        // Relative error of the first-order loss 1 − e ≈ c_d·v: O(c_d·v).
        let err = ((1.0 - e) / x - 1.0).abs();
        println!(
            "c_d·v = {x:.1e}: e = {e:.6}, 1 − c_d·v = {:.6}, (1 − e)/(c_d·v) − 1 = {err:.2e}",
            1.0 - x
        );
        assert!(err <= 1.5 * x, "c_d·v = {x}: e = {e}");
        // Closer still: e ≈ 1/(1 + c_d·v) (measured within 7.5e-5 up to c_d·v = 0.1).
        assert!((e - 1.0 / (1.0 + x)).abs() <= 1e-4, "c_d·v = {x}: e = {e}");
        worst = worst.max(err / x);
    }
    // e depends on c_d·v only (not on the mass, the stiffness or c_d and v apart).
    assert!((restitution(5.0, 2e-2) - restitution(1.0, 0.1)).abs() < 1e-9);
    // Undamped: e = 1 to the integration's accuracy.
    assert!((restitution(0.0, 1e-2) - 1.0).abs() < 1e-9);
    println!("max |(1 − e)/(c_d·v) − 1| / (c_d·v) = {worst:.3}");
}
