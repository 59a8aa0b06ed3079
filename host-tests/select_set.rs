// The scene configurations' error measurement, shared verbatim (`include!`) by the test
// `host-tests/select.rs` (moderate grid) and the example `examples/scene_error.rs` (dense grid,
// prints the figures of `bench-results/scenes.csv`).
//
// Reference: exact Hertz with the eccentricity by `shape::Newton` in f64 (validated against
// mpmath in host-tests/hertz.rs) and the exact Contensou–Erismann integrals
// (`friction::exact`, validated against mpmath in host-tests/friction_exact.rs), both fed the
// model's own (rounded) inputs, so that only the model's error is measured.

use contensou::contact::Contact;
use contensou::friction::{Exact, Friction, Slip};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Hertz, Modulus, NormalLaw, Undamped};
use contensou::contact::Wrench;
use contensou::select::{Select, Step};
use contensou::shape::Newton;
use contensou::Real;

/// Effective modulus (steel on steel) and friction coefficient of every scene.
const ESTAR: f64 = 1.142857e11;
const F: f64 = 0.1;

/// (N, a, F_x, F_y, T_z) of a wrench, in f64.
fn parts<T: Real, B>(w: Wrench<T, B>) -> [f64; 5] {
    [w.n, w.patch.a, w.fx, w.fy, w.tz].map(|x| x.to_f64())
}

/// The geometries of each kind (in `T`, then read back exactly into f64 for the reference).
fn geometries<T: Real>(kind: &str) -> Vec<Curvatures<T>> {
    let t = T::from_f64;
    match kind {
        // 6.35 mm and 20 mm balls on a plane; a 10 mm ball in a 12 mm spherical cup.
        "sphere-plane" => vec![
            Curvatures::sphere_plane(t(6.35e-3)).unwrap(),
            Curvatures::sphere_plane(t(20e-3)).unwrap(),
            Curvatures::sphere_sphere(t(5e-3), t(-6e-3)).unwrap(),
        ],
        // The 209 bearing (ball 12.7 mm, groove 6.6 mm, pitch 65 mm): inner race (e² = 0.989)
        // and outer race; a looser groove (7.0 mm) on the inner race.
        "ball-race" => vec![
            Curvatures::ball_race(t(12.7e-3), t(6.6e-3), t(65e-3), T::ZERO, Race::Inner).unwrap(),
            Curvatures::ball_race(t(12.7e-3), t(6.6e-3), t(65e-3), T::ZERO, Race::Outer).unwrap(),
            Curvatures::ball_race(t(12.7e-3), t(7.0e-3), t(65e-3), T::ZERO, Race::Inner).unwrap(),
        ],
        // A contact point wandering over a non-spherical surface: g = P/Q from 1 down to
        // 0.0275 (e² = 0.9899; e² = 0.99 at g = 0.02737), P = 3 m⁻¹.
        _ => [1.0, 0.95, 0.8, 0.6, 0.4, 0.25, 0.15, 0.08, 0.05, 0.035, 0.0275]
            .iter()
            .map(|&g| Curvatures::new(t(3.0), t(3.0 / g)).unwrap())
            .collect(),
    }
}

/// Slip directions ψ (all quadrants and the axes) and ratios u = v/(aω) (0 = pure spin,
/// ∞ = pure translation), `per_decade` log-spaced values in [1e-2, 1e2].
fn slip_grid(per_decade: usize, spins: bool) -> Vec<(f64, f64)> {
    let psis: Vec<f64> = (0..=16).map(|i| -0.1 + i as f64 * std::f64::consts::PI / 8.0).chain([0.0, std::f64::consts::FRAC_PI_2]).collect();
    let mut us: Vec<f64> = (0..=4 * per_decade)
        .map(|i| 10f64.powf(-2.0 + i as f64 / per_decade as f64))
        .collect();
    us.push(f64::INFINITY);
    let mut grid = Vec::new();
    for &psi in &psis {
        if spins {
            grid.extend(us.iter().map(|&u| (psi, u)));
            grid.push((psi, 0.0));
        } else {
            grid.push((psi, f64::INFINITY));
        }
    }
    grid
}

/// Max errors of scene `S` over its geometries, h ∈ {0.1, 1, 1.907, 5} µm and the slip grid:
/// (N relative, a relative, |F − F_ref|/(fN), |T_z − T_ref|/(fNa)).
fn scene_errors<S: Select>(kind: &str, spins: bool, per_decade: usize) -> [f64; 4]
{
    let t = <S::Real as Real>::from_f64;
    let estar = Modulus::new(t(ESTAR)).unwrap();
    let friction = Friction::<S::Real, S::Law>::with_law(t(F), S::Real::ZERO).unwrap();
    let grid = slip_grid(per_decade, spins);
    let mut worst = [0.0f64; 4];
    for curv in geometries::<S::Real>(kind) {
        let model = S::build(&S::geometry(&curv), estar, Undamped, friction).unwrap();
        let curv64 = Curvatures::new(curv.p().to_f64(), curv.q().to_f64()).unwrap();
        let reference = Contact::<f64, Hertz<f64>, Undamped, Exact>::hertz::<Newton>(
            &curv64,
            Modulus::new(t(ESTAR).to_f64()).unwrap(),
            Undamped,
            Friction::with_law(t(F).to_f64(), 0.0).unwrap(),
        )
        .unwrap();
        // 2⁻¹⁹ m ≈ 1.9 µm: where micromath's √h is worst (6.07 % high; Rough budget).
        for h in [1e-7, 1e-6, 1.9073486328125e-6, 5e-6] {
            let h = t(h);
            let a = reference.normal().patch(h.to_f64()).a;
            for &(psi, u) in &grid {
                // ω = 100 rad/s (0 without spin), v = u·a·ω (1 mm/s at u = ∞).
                let (omega, v) = match (spins, u.is_finite()) {
                    (false, _) => (0.0, 1e-3),
                    (true, true) => (100.0, u * a * 100.0),
                    (true, false) => (0.0, 1e-3),
                };
                let slip = Slip::new(t(v * psi.cos()), t(v * psi.sin()), t(omega)).unwrap();
                let slip64 =
                    Slip::new(slip.vx().to_f64(), slip.vy().to_f64(), slip.omega().to_f64())
                        .unwrap();
                let m = parts(model.step(&curv, h, S::Real::ZERO, slip));
                let r = parts(reference.step(&curv64, h.to_f64(), 0.0, slip64));
                let fnr = F * r[0];
                worst[0] = worst[0].max((m[0] - r[0]).abs() / r[0]);
                worst[1] = worst[1].max((m[1] - r[1]).abs() / r[1]);
                worst[2] = worst[2].max((m[2] - r[2]).hypot(m[3] - r[3]) / fnr);
                worst[3] = worst[3].max((m[4] - r[4]).abs() / (fnr * r[1]));
            }
        }
    }
    worst
}
