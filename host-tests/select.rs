//! `contensou::select`: each scene declaration resolves to the types its table row names, and
//! each configuration's error against the exact references (f64 Newton Hertz + the exact
//! Contensou–Erismann integrals) is within its budget's bounds. With `--features micromath`
//! (run by .ci/run) the `f32` declarations that resolve to a micromath twin are checked too.

use std::any::TypeId;

use contensou::contact::VaryingContact;
use contensou::friction::{Best, Coulomb, Ellipsoid};
#[cfg(feature = "micromath")]
use contensou::normal::HertzMicromath;
use contensou::normal::{Damping, HuntCrossley};
use contensou::select::*;

include!("select_set.rs");

/// The law of a varying exact-grade `f32` contact: `Best` (its per-step flash-table form),
/// with or without the feature `micromath`.
type VaryingBestF32 = Best;

/// `ContactOf<S, D>` is `C` and `LawOf<S>` is `L`.
fn resolves<S: Select + 'static, D: Damping<S::Real> + 'static, C: 'static, L: 'static>()
where
    S::Contact<D>: 'static,
    S::Law: 'static,
{
    assert_eq!(TypeId::of::<ContactOf<S, D>>(), TypeId::of::<C>());
    assert_eq!(TypeId::of::<LawOf<S>>(), TypeId::of::<L>());
}

/// A table of `resolves` checks, a row each (under its optional `cfg`):
/// `geometry motion spin budget precision, damping => contact type, law;`.
macro_rules! resolve {
    ($($(#[$m:meta])* $p:ident $g:ident $s:ident $b:ident $t:ty, $d:ty => $c:ty, $l:ty;)*) => {
        $($(#[$m])* resolves::<Scene<$p, $g, $s, $b, $t>, $d, $c, $l>();)*
    };
}

/// Every declaration resolves to the contact and law its table row names.
#[test]
fn declarations_resolve_to_the_tabled_types() {
    type U = Undamped;
    type H = HuntCrossley<f32>;
    type Vb = VaryingBestF32;
    #[cfg(feature = "micromath")]
    type M = HertzMicromath<f32>;
    resolve! {
        // Sphere on plane: circular Hertz, fixed contact.
        Circular Fixed Spin Coarse f32, U => Contact<f32, Hertz<f32>, U, Ellipsoid>, Ellipsoid;
        Circular Fixed Spin ExactGrade f64, U => Contact<f64, Hertz<f64>, U, Best>, Best;
        Circular Fixed NoSpin Coarse f32, U => Contact<f32, Hertz<f32>, U, Coulomb>, Coulomb;
        Circular Fixed NoSpin ExactGrade f32, U => Contact<f32, Hertz<f32>, U, Coulomb>, Coulomb;
        // Ball–race: fixed elliptic contact.
        Elliptic Fixed Spin Coarse f64, U => Contact<f64, Hertz<f64>, U, Ellipsoid>, Ellipsoid;
        Elliptic Fixed Spin ExactGrade f32, U => Contact<f32, Hertz<f32>, U, Best>, Best;
        Elliptic Fixed NoSpin ExactGrade f64, U => Contact<f64, Hertz<f64>, U, Coulomb>, Coulomb;
        // Varying geometry: the table-per-step contact.
        Elliptic Varying Spin Coarse f32, U => VaryingContact<f32, U, Ellipsoid>, Ellipsoid;
        Elliptic Varying Spin ExactGrade f64, U => VaryingContact<f64, U, Best>, Best;
        Elliptic Varying NoSpin Coarse f32, U => VaryingContact<f32, U, Coulomb>, Coulomb;
        // A varying exact-grade contact takes `Best` with or without the feature `micromath`
        // (its per-step form calls no `ln`), as a fixed one does.
        Elliptic Varying Spin ExactGrade f32, U => VaryingContact<f32, U, Vb>, Vb;
        Elliptic Varying NoSpin ExactGrade f32, U => VaryingContact<f32, U, Coulomb>, Coulomb;
        // The damping law passes through.
        Elliptic Fixed Spin Coarse f32, H => Contact<f32, Hertz<f32>, H, Ellipsoid>, Ellipsoid;
        Elliptic Varying Spin ExactGrade f32, H => VaryingContact<f32, H, Vb>, Vb;
        // `Rough` resolves to `Coarse`'s types where no micromath twin applies: `f64`, varying
        // geometry, and `f32` without the feature.
        Circular Fixed Spin Rough f64, U => Contact<f64, Hertz<f64>, U, Ellipsoid>, Ellipsoid;
        Elliptic Fixed NoSpin Rough f64, U => Contact<f64, Hertz<f64>, U, Coulomb>, Coulomb;
        Elliptic Varying Spin Rough f32, U => VaryingContact<f32, U, Ellipsoid>, Ellipsoid;
        #[cfg(not(feature = "micromath"))]
        Circular Fixed Spin Rough f32, U => Contact<f32, Hertz<f32>, U, Ellipsoid>, Ellipsoid;
        #[cfg(not(feature = "micromath"))]
        Elliptic Fixed NoSpin Rough f32, U => Contact<f32, Hertz<f32>, U, Coulomb>, Coulomb;
        // With the feature, `Rough` fixed `f32` contacts take micromath's √h in Hertz.
        #[cfg(feature = "micromath")]
        Circular Fixed Spin Rough f32, U => Contact<f32, M, U, Ellipsoid>, Ellipsoid;
        #[cfg(feature = "micromath")]
        Circular Fixed NoSpin Rough f32, U => Contact<f32, M, U, Coulomb>, Coulomb;
        #[cfg(feature = "micromath")]
        Elliptic Fixed Spin Rough f32, U => Contact<f32, M, U, Ellipsoid>, Ellipsoid;
        #[cfg(feature = "micromath")]
        Elliptic Fixed NoSpin Rough f32, U => Contact<f32, M, U, Coulomb>, Coulomb;
    }
}

/// With the feature, `Rough` fixed `f32` contacts take micromath's √h in Hertz (the contact
/// rows above) and name it as their normal law.
#[cfg(feature = "micromath")]
#[test]
fn rough_f32_takes_micromath_hertz() {
    assert_eq!(
        TypeId::of::<NormalOf<Scene<Circular, Fixed, Spin, Rough, f32>>>(),
        TypeId::of::<HertzMicromath<f32>>()
    );
}

#[test]
fn names_and_bounds() {
    type Ball = Scene<Circular, Fixed, Spin, Coarse, f32>;
    assert_eq!(Ball::GEOMETRY, "sphere-plane");
    assert_eq!((Ball::FORCE, Ball::TORQUE), (0.25, 0.15));
    type Race = Scene<Elliptic, Fixed, Spin, ExactGrade, f64>;
    assert_eq!(Race::GEOMETRY, "ball-race");
    assert_eq!((Race::FORCE, Race::TORQUE), (5e-4, 5e-4));
    type Wander = Scene<Elliptic, Varying, NoSpin, Coarse, f32>;
    assert_eq!(Wander::GEOMETRY, "varying");
    assert_eq!(
        (Wander::FORCE, Wander::TORQUE),
        (NOSPIN_BOUND, NOSPIN_BOUND)
    );
    assert_eq!(
        (Ball::NORMAL, Race::NORMAL, Wander::NORMAL),
        (NORMAL_BOUND, NORMAL_BOUND, NORMAL_BOUND)
    );
    type Rolling = Scene<Circular, Fixed, Spin, Rough, f32>;
    assert_eq!(
        (Rolling::NORMAL, Rolling::FORCE, Rolling::TORQUE),
        (ROUGH_NORMAL_BOUND, 0.25, 0.17)
    );
    type Sliding = Scene<Elliptic, Fixed, NoSpin, Rough, f32>;
    assert_eq!(
        (Sliding::FORCE, Sliding::TORQUE),
        (ROUGH_NORMAL_BOUND, ROUGH_NORMAL_BOUND)
    );
}

/// micromath's √h is at most 6.07 % high: the rough bound must not be vacuous — the rough
/// scenes' N is measured off by more than 5 % at h = 2⁻¹⁹ m (so the twin is really used),
/// and within 6.5 %.
#[cfg(feature = "micromath")]
#[test]
fn rough_normal_error_is_micromaths() {
    let e = scene_errors::<Scene<Circular, Fixed, NoSpin, Rough, f32>>("sphere-plane", false, 8);
    assert!(e[0] > 0.05 && e[0] <= ROUGH_NORMAL_BOUND, "{e:?}");
}

#[test]
fn circular_rejects_an_elliptic_patch() {
    let curv = Curvatures::new(3.0f64, 4.0).unwrap();
    let built = Scene::<Circular, Fixed, Spin, Coarse, f64>::build(
        &curv,
        Modulus::new(ESTAR).unwrap(),
        Undamped,
        Friction::with_law(F, 0.0).unwrap(),
    );
    assert_eq!(
        built.unwrap_err(),
        contensou::Error::CurvatureRatioOutOfRange
    );
}

/// Every configuration × precision within its bounds (8 ratios u per decade).
macro_rules! within_bounds {
    ($($name:ident: $p:ty, $g:ty, $s:ty, $b:ty, $kind:literal;)*) => {$(
        #[test]
        fn $name() {
            fn check<T: Precision>() {
                type S<T> = Scene<$p, $g, $s, $b, T>;
                let e = scene_errors::<S<T>>($kind, <$s as Motion>::SPINS, 8);
                let ctx = format!("{} {} {}: {e:?}", $kind, stringify!($s $b), T::NAME);
                let normal = S::<T>::NORMAL;
                assert!(e[0] <= normal && e[1] <= normal, "normal {ctx}");
                assert!(e[2] <= S::<T>::FORCE, "force {ctx}");
                assert!(e[3] <= S::<T>::TORQUE, "torque {ctx}");
            }
            check::<f32>();
            check::<f64>();
        }
    )*};
}

within_bounds! {
    sphere_plane_spin_coarse: Circular, Fixed, Spin, Coarse, "sphere-plane";
    sphere_plane_spin_exact: Circular, Fixed, Spin, ExactGrade, "sphere-plane";
    sphere_plane_nospin: Circular, Fixed, NoSpin, ExactGrade, "sphere-plane";
    ball_race_spin_coarse: Elliptic, Fixed, Spin, Coarse, "ball-race";
    ball_race_spin_exact: Elliptic, Fixed, Spin, ExactGrade, "ball-race";
    ball_race_nospin: Elliptic, Fixed, NoSpin, ExactGrade, "ball-race";
    varying_spin_coarse: Elliptic, Varying, Spin, Coarse, "varying";
    varying_spin_exact: Elliptic, Varying, Spin, ExactGrade, "varying";
    varying_nospin: Elliptic, Varying, NoSpin, ExactGrade, "varying";
    // Micromath's √h in f32 with the feature; Coarse's types otherwise.
    sphere_plane_spin_rough: Circular, Fixed, Spin, Rough, "sphere-plane";
    sphere_plane_nospin_rough: Circular, Fixed, NoSpin, Rough, "sphere-plane";
    ball_race_spin_rough: Elliptic, Fixed, Spin, Rough, "ball-race";
    ball_race_nospin_rough: Elliptic, Fixed, NoSpin, Rough, "ball-race";
    varying_spin_rough: Elliptic, Varying, Spin, Rough, "varying";
}

// --- `Rolls`: the patch rolls → `contact::Rolling<…, rolling::Table>` (issue 20 item 5) ---

mod rolls {
    use super::resolves;
    use contensou::contact::{Contact, Rolling, VaryingContact};
    use contensou::friction::rolling::{Elasticity, Kalker, RollingVelocity, Table};
    use contensou::friction::{Best, Friction, Slip};
    use contensou::geometry::Curvatures;
    use contensou::normal::{Hertz, Modulus, Undamped};
    use contensou::select::*;

    #[test]
    fn rolls_resolves_to_the_default_rolling_law() {
        type U = Undamped;
        resolve! {
            Elliptic Fixed Rolls ExactGrade f64, U
                => Rolling<f64, Contact<f64, Hertz<f64>, U, Best>, Table>, Best;
            Circular Fixed Rolls Coarse f32, U
                => Rolling<f32, Contact<f32, Hertz<f32>, U, Best>, Table>, Best;
            Elliptic Varying Rolls Rough f32, U
                => Rolling<f32, VaryingContact<f32, U, Best>, Table>, Best;
        }
        type S = Scene<Elliptic, Fixed, Rolls, Coarse, f64>;
        assert_eq!(<S as Select>::GEOMETRY, "ball-race");
        const { assert!(<S as Select>::SPINS) };
        assert_eq!(
            (<S as Select>::FORCE, <S as Select>::TORQUE),
            (ROLLING_FORCE, ROLLING_TORQUE)
        );
    }

    const ESTAR: f64 = 1.142857e11;

    /// An elliptic patch rolling along its minor axis (contact y) at 3 m/s: at small creepage
    /// the force along V and the spin moment are Kalker's linear theory on the ellipse with
    /// a_r = b along V (F = −Gc²C₁₁ξ, M_z = −Gc⁴C₃₃φ; `Kalker` holds Table E3, checked in
    /// host-tests/rolling.rs) within 1 %; at V = 0 the wrench is the full-slip `best`
    /// contact's with δ = 0, bit for bit; `build` is `build_rolling` with G = E*(1 − ν),
    /// ν = 0.3. Fixed and varying forms agree within 1e-3.
    #[test]
    fn rolls_is_kalker_at_small_creepage_and_best_at_full_slip() {
        type Fixed64 = Scene<Elliptic, Fixed, Rolls, ExactGrade, f64>;
        type Varying64 = Scene<Elliptic, Varying, Rolls, ExactGrade, f64>;
        let curv = Curvatures::new(25.0, 100.0).unwrap();
        let estar = Modulus::new(ESTAR).unwrap();
        let friction = Friction::new(0.1, 0.0).unwrap();
        let c = Fixed64::build(&curv, estar, Undamped, friction).unwrap();
        let el = Elasticity::new(ESTAR * 0.7, 0.3).unwrap();
        let c2 = Fixed64::build_rolling(&curv, estar, Undamped, friction, el).unwrap();
        let cv = Varying64::build(&(), estar, Undamped, friction).unwrap();
        let (h, v) = (2e-6, 3.0);
        let rv = RollingVelocity::new(0.0, v).unwrap();
        let xi = 2e-6;
        let w = c.step_rolling(&curv, h, 0.0, Slip::new(0.0, xi * v, 0.0).unwrap(), rv);
        assert_eq!(
            w,
            c2.step_rolling(&curv, h, 0.0, Slip::new(0.0, xi * v, 0.0).unwrap(), rv)
        );
        let (a, b) = (w.patch.a, w.patch.b);
        assert!(a > 1.5 * b, "{a} {b}");
        let k = Kalker::<f64>::new(b / a, 0.3);
        let g = ESTAR * 0.7;
        let c2ab = a * b;
        let f_lin = -g * c2ab * k.c11 * xi;
        assert!(f_lin.abs() < 0.05 * 0.1 * w.n, "{f_lin} {}", w.n);
        assert!((w.fy / f_lin - 1.0).abs() < 0.01, "{} vs {f_lin}", w.fy);
        assert!(w.fx.abs() < 1e-9 * f_lin.abs(), "{}", w.fx);
        let phi = 1e-3; // 1/m
        let ws = c.step_rolling(&curv, h, 0.0, Slip::new(0.0, 0.0, phi * v).unwrap(), rv);
        let m_lin = -g * c2ab * c2ab * k.c33 * phi;
        assert!((ws.tz / m_lin - 1.0).abs() < 0.01, "{} vs {m_lin}", ws.tz);
        let wv = cv.step_rolling(&curv, h, 0.0, Slip::new(0.0, 0.0, phi * v).unwrap(), rv);
        // The varying form interpolates the creep shape per step (within 9.2e-4 fNc of the
        // fixed form's f64 shape, host-tests/rolling_wrench.rs): here 8e-5 of M_z.
        assert!((wv.tz / ws.tz - 1.0).abs() < 1e-3, "{} vs {}", wv.tz, ws.tz);
        // V = 0: full slip, the `best` contact with δ = 0.
        let best =
            Contact::<f64, Hertz<f64>, Undamped, Best>::hertz_with::<contensou::shape::Table>(
                &curv, estar, Undamped, friction,
            )
            .unwrap();
        for slip in [
            Slip::new(0.01, -0.02, 5.0).unwrap(),
            Slip::new(0.0, 1e-3, 0.0).unwrap(),
        ] {
            let full = c.step_rolling(&curv, h, 0.0, slip, RollingVelocity::ZERO);
            let b = best.wrench(h, 0.0, slip);
            let scale = 0.1 * b.n;
            assert!(
                (full.fx - b.fx).abs() + (full.fy - b.fy).abs() < 1e-12 * scale,
                "{full:?} {b:?}"
            );
            assert!((full.tz - b.tz).abs() < 1e-12 * scale * a, "{full:?} {b:?}");
            // `Step::step` of a rolling contact is that limit.
            assert_eq!(c.step(&curv, h, 0.0, slip), full);
        }
    }
}
