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

#[test]
fn declarations_resolve_to_the_tabled_types() {
    type U = Undamped;
    // Sphere on plane: circular Hertz, fixed contact.
    resolves::<
        Scene<Circular, Fixed, Spin, Coarse, f32>,
        U,
        Contact<f32, Hertz<f32>, U, Ellipsoid>,
        Ellipsoid,
    >();
    resolves::<
        Scene<Circular, Fixed, Spin, ExactGrade, f64>,
        U,
        Contact<f64, Hertz<f64>, U, Best>,
        Best,
    >();
    resolves::<
        Scene<Circular, Fixed, NoSpin, Coarse, f32>,
        U,
        Contact<f32, Hertz<f32>, U, Coulomb>,
        Coulomb,
    >();
    resolves::<
        Scene<Circular, Fixed, NoSpin, ExactGrade, f32>,
        U,
        Contact<f32, Hertz<f32>, U, Coulomb>,
        Coulomb,
    >();
    // Ball–race: fixed elliptic contact.
    resolves::<
        Scene<Elliptic, Fixed, Spin, Coarse, f64>,
        U,
        Contact<f64, Hertz<f64>, U, Ellipsoid>,
        Ellipsoid,
    >();
    resolves::<
        Scene<Elliptic, Fixed, Spin, ExactGrade, f32>,
        U,
        Contact<f32, Hertz<f32>, U, Best>,
        Best,
    >();
    resolves::<
        Scene<Elliptic, Fixed, NoSpin, ExactGrade, f64>,
        U,
        Contact<f64, Hertz<f64>, U, Coulomb>,
        Coulomb,
    >();
    // Varying geometry: the table-per-step contact.
    resolves::<
        Scene<Elliptic, Varying, Spin, Coarse, f32>,
        U,
        VaryingContact<f32, U, Ellipsoid>,
        Ellipsoid,
    >();
    resolves::<
        Scene<Elliptic, Varying, Spin, ExactGrade, f64>,
        U,
        VaryingContact<f64, U, Best>,
        Best,
    >();
    resolves::<
        Scene<Elliptic, Varying, NoSpin, Coarse, f32>,
        U,
        VaryingContact<f32, U, Coulomb>,
        Coulomb,
    >();
    // The damping law passes through.
    type H = HuntCrossley<f32>;
    resolves::<
        Scene<Elliptic, Fixed, Spin, Coarse, f32>,
        H,
        Contact<f32, Hertz<f32>, H, Ellipsoid>,
        Ellipsoid,
    >();
    resolves::<
        Scene<Elliptic, Varying, Spin, ExactGrade, f32>,
        H,
        VaryingContact<f32, H, VaryingBestF32>,
        VaryingBestF32,
    >();
}

/// `Rough` resolves to `Coarse`'s types where no micromath twin applies: `f64`, varying
/// geometry, and `f32` without the feature.
#[test]
fn rough_without_a_twin_is_coarse() {
    type U = Undamped;
    resolves::<
        Scene<Circular, Fixed, Spin, Rough, f64>,
        U,
        Contact<f64, Hertz<f64>, U, Ellipsoid>,
        Ellipsoid,
    >();
    resolves::<
        Scene<Elliptic, Fixed, NoSpin, Rough, f64>,
        U,
        Contact<f64, Hertz<f64>, U, Coulomb>,
        Coulomb,
    >();
    resolves::<
        Scene<Elliptic, Varying, Spin, Rough, f32>,
        U,
        VaryingContact<f32, U, Ellipsoid>,
        Ellipsoid,
    >();
    #[cfg(not(feature = "micromath"))]
    {
        resolves::<
            Scene<Circular, Fixed, Spin, Rough, f32>,
            U,
            Contact<f32, Hertz<f32>, U, Ellipsoid>,
            Ellipsoid,
        >();
        resolves::<
            Scene<Elliptic, Fixed, NoSpin, Rough, f32>,
            U,
            Contact<f32, Hertz<f32>, U, Coulomb>,
            Coulomb,
        >();
    }
}

/// A varying exact-grade contact takes `Best` with or without the feature `micromath` (its
/// per-step form calls no `ln`), as a fixed one does.
#[test]
fn varying_exact_law_by_feature() {
    type U = Undamped;
    resolves::<
        Scene<Elliptic, Varying, Spin, ExactGrade, f32>,
        U,
        VaryingContact<f32, U, VaryingBestF32>,
        VaryingBestF32,
    >();
    resolves::<
        Scene<Elliptic, Varying, Spin, ExactGrade, f64>,
        U,
        VaryingContact<f64, U, Best>,
        Best,
    >();
    resolves::<
        Scene<Elliptic, Fixed, Spin, ExactGrade, f32>,
        U,
        Contact<f32, Hertz<f32>, U, Best>,
        Best,
    >();
    resolves::<
        Scene<Elliptic, Varying, NoSpin, ExactGrade, f32>,
        U,
        VaryingContact<f32, U, Coulomb>,
        Coulomb,
    >();
}

/// With the feature, `Rough` fixed `f32` contacts take micromath's √h in Hertz.
#[cfg(feature = "micromath")]
#[test]
fn rough_f32_takes_micromath_hertz() {
    type U = Undamped;
    type M = HertzMicromath<f32>;
    resolves::<Scene<Circular, Fixed, Spin, Rough, f32>, U, Contact<f32, M, U, Ellipsoid>, Ellipsoid>(
    );
    resolves::<Scene<Circular, Fixed, NoSpin, Rough, f32>, U, Contact<f32, M, U, Coulomb>, Coulomb>(
    );
    resolves::<Scene<Elliptic, Fixed, Spin, Rough, f32>, U, Contact<f32, M, U, Ellipsoid>, Ellipsoid>(
    );
    resolves::<Scene<Elliptic, Fixed, NoSpin, Rough, f32>, U, Contact<f32, M, U, Coulomb>, Coulomb>(
    );
    assert_eq!(
        TypeId::of::<NormalOf<Scene<Circular, Fixed, Spin, Rough, f32>>>(),
        TypeId::of::<M>()
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
