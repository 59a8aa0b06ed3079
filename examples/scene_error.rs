//! Max error of every `contensou::select` scene configuration against the exact references
//! (f64 Newton Hertz + the exact Contensou–Erismann integrals), on a dense grid: 40 ratios u
//! per decade in [1e-2, 1e2] plus u = 0 and ∞, 19 directions ψ, 4 approaches h, 3–11
//! geometries per kind. Prints CSV (read by `tools/scene-bench.sh`): `scene,precision,
//! contact,normal,law,n_rel,a_rel,force_fn,torque_fna,force_bound_fn,torque_bound_fna`.
//! Run: `cargo run --release --example scene_error` (every configuration, libm), and
//! `cargo run --release --features micromath --example scene_error` (only the `f32`
//! configurations that resolve to a micromath twin, keys ending `-micromath`).

use contensou::friction::FrictionLaw;
use contensou::select::*;

include!("../host-tests/select_set.rs");

/// `scenes!(fn_name: key, patch, geometry, motion, budget, kind; …)`: a function printing one
/// row per configuration in precision `T`.
macro_rules! scenes {
    ($f:ident: $($key:literal, $p:ty, $g:ty, $s:ty, $b:ty, $kind:literal;)*) => {
        fn $f<T: Precision>() {$(
            {
                type S<T> = Scene<$p, $g, $s, $b, T>;
                let e = scene_errors::<S<T>>($kind, <$s as Motion>::SPINS, 40);
                let normal = std::any::type_name::<NormalOf<S<T>>>();
                let micro = normal.contains("Micromath");
                let (contact, normal) = match (S::<T>::GEOMETRY, micro) {
                    ("sphere-plane", false) => ("Contact", "Hertz::circular"),
                    ("sphere-plane", true) => ("Contact", "HertzMicromath from Hertz::circular"),
                    ("ball-race", false) => ("Contact", "Hertz by shape::Table at construction"),
                    ("ball-race", true) => ("Contact", "HertzMicromath by shape::Table at construction"),
                    _ => ("VaryingContact", "Hertz by shape::Table per step"),
                };
                let law = <LawOf<S<T>> as FrictionLaw>::NAME;
                let (bf, bt) = (S::<T>::FORCE, S::<T>::TORQUE);
                println!(
                    "{},{},{contact},{normal},{law},{:.2e},{:.2e},{:.2e},{:.2e},{bf:e},{bt:e}",
                    $key, T::NAME, e[0], e[1], e[2], e[3]
                );
            }
        )*}
    };
}

#[cfg(not(feature = "micromath"))]
scenes! { libm:
    "sphere-plane-spin-coarse", Circular, Fixed, Spin, Coarse, "sphere-plane";
    "sphere-plane-spin-exact", Circular, Fixed, Spin, ExactGrade, "sphere-plane";
    "sphere-plane-nospin", Circular, Fixed, NoSpin, ExactGrade, "sphere-plane";
    "ball-race-spin-coarse", Elliptic, Fixed, Spin, Coarse, "ball-race";
    "ball-race-spin-exact", Elliptic, Fixed, Spin, ExactGrade, "ball-race";
    "ball-race-nospin", Elliptic, Fixed, NoSpin, ExactGrade, "ball-race";
    "varying-spin-coarse", Elliptic, Varying, Spin, Coarse, "varying";
    "varying-spin-exact", Elliptic, Varying, Spin, ExactGrade, "varying";
    "varying-nospin", Elliptic, Varying, NoSpin, ExactGrade, "varying";
}

// With the feature: the f32 configurations that resolve to a micromath twin.
#[cfg(feature = "micromath")]
scenes! { micromath:
    "sphere-plane-spin-rough-micromath", Circular, Fixed, Spin, Rough, "sphere-plane";
    "sphere-plane-nospin-rough-micromath", Circular, Fixed, NoSpin, Rough, "sphere-plane";
    "ball-race-spin-rough-micromath", Elliptic, Fixed, Spin, Rough, "ball-race";
    "ball-race-nospin-rough-micromath", Elliptic, Fixed, NoSpin, Rough, "ball-race";
    "varying-spin-exact-micromath", Elliptic, Varying, Spin, ExactGrade, "varying";
}

fn main() {
    println!(
        "scene,precision,contact,normal,law,n_rel,a_rel,force_fn,torque_fna,force_bound_fn,torque_bound_fna"
    );
    // Without the feature: every configuration as it resolves without micromath. With it:
    // only the f32 rows whose declaration resolves to a micromath twin (keys `…-micromath`).
    #[cfg(not(feature = "micromath"))]
    {
        libm::<f32>();
        libm::<f64>();
    }
    #[cfg(feature = "micromath")]
    micromath::<f32>();
}
