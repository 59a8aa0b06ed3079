//! Max error of every `contensou::select` scene configuration against the exact references
//! (f64 Newton Hertz + the exact Contensou–Erismann integrals), on a dense grid: 40 ratios u
//! per decade in [1e-2, 1e2] plus u = 0 and ∞, 19 directions ψ, 3 approaches h, 3–11
//! geometries per kind. Prints CSV (read by `tools/scene-bench.sh`): `scene,precision,
//! contact,normal,law,n_rel,a_rel,force_fn,torque_fna,force_bound_fn,torque_bound_fna`.
//! Run: `cargo run --release --example scene_error`.

use contensou::friction::FrictionLaw;
use contensou::select::*;

include!("../host-tests/select_set.rs");

macro_rules! scenes {
    ($($p:ty, $g:ty, $s:ty, $b:ty, $kind:literal;)*) => {
        fn all<T: Real>() {$(
            {
                type S<T> = Scene<$p, $g, $s, $b, T>;
                let spins = <$s as Motion>::SPINS;
                let e = scene_errors::<S<T>>($kind, spins, 40);
                let key = if spins {
                    format!("{}-spin-{}", $kind, <$b as Budget>::NAME)
                } else {
                    format!("{}-nospin", $kind)
                };
                let (contact, normal) = match S::<T>::GEOMETRY {
                    "sphere-plane" => ("Contact", "Hertz::circular"),
                    "ball-race" => ("Contact", "Hertz by shape::Table at construction"),
                    _ => ("VaryingContact", "Hertz by shape::Table per step"),
                };
                let law = <LawOf<S<T>> as FrictionLaw>::NAME;
                let (bf, bt) = (S::<T>::FORCE, S::<T>::TORQUE);
                println!(
                    "{key},{},{contact},{normal},{law},{:.2e},{:.2e},{:.2e},{:.2e},{bf:e},{bt:e}",
                    T::NAME, e[0], e[1], e[2], e[3]
                );
            }
        )*}
    };
}

scenes! {
    Circular, Fixed, Spin, Coarse, "sphere-plane";
    Circular, Fixed, Spin, ExactGrade, "sphere-plane";
    Circular, Fixed, NoSpin, ExactGrade, "sphere-plane";
    Elliptic, Fixed, Spin, Coarse, "ball-race";
    Elliptic, Fixed, Spin, ExactGrade, "ball-race";
    Elliptic, Fixed, NoSpin, ExactGrade, "ball-race";
    Elliptic, Varying, Spin, Coarse, "varying";
    Elliptic, Varying, Spin, ExactGrade, "varying";
    Elliptic, Varying, NoSpin, ExactGrade, "varying";
}

fn main() {
    println!(
        "scene,precision,contact,normal,law,n_rel,a_rel,force_fn,torque_fna,force_bound_fn,torque_bound_fna"
    );
    all::<f32>();
    all::<f64>();
}
