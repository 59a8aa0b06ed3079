//! The ball bearing scene (feature `scenes`): the paper's race eccentricities (exact 0.687,
//! G* ≈ 0.643), pure rolling at the start keeps the cage speed, and a short loaded run keeps
//! the balls orbiting at ω_c = (ω_i/2)(1 − D/d_m) within 2 % with a finite, loaded state.

use contensou::contact::Contact;
use contensou::friction::{Friction, Simplified, Slip};
use contensou::geometry::Race;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::scenes::bearing::{BALLS, Bearing, Geometry};
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
