//! criterion: the friction laws' dimensionless core, per law × precision, on a fixed mixed input
//! set (64 states: u log-uniform in [0.01, 100], ψ uniform, e² = 0.5, ω > 0, δ = 0; the same set as the QEMU stage `friction`), with the patch
//! constants given. Afterwards measures each law's max error against the exact integrals on a
//! dense grid and writes both into `bench-results/friction.csv`:
//!
//! ```text
//! cargo bench --bench friction
//! ```
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::{
    Constants, Coulomb, Ellipsoid, FrictionLaw, Pade, Simplified, SlipState, Traction,
};
use criterion::Criterion;

include!("friction_set.rs");

fn inputs<T: Real>() -> Vec<SlipState<T>> {
    mixed_set()
        .iter()
        .map(|&(u, psi)| SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap())
        .collect()
}

#[inline(never)]
fn run<T: Real, L: FrictionLaw>(k: &Constants<T>, set: &[SlipState<T>]) -> T {
    let mut acc = T::ZERO;
    for s in set {
        let (t, _) = L::traction(black_box(k), black_box(s));
        acc += t.fx + t.fy + t.tz;
    }
    acc
}

fn bench_law<T: Real, L: FrictionLaw>(c: &mut Criterion) {
    let k = Constants::from_parameter(Parameter::new(T::from_f64(0.5)).unwrap());
    let set = inputs::<T>();
    c.bench_function(&format!("friction/{}-{}", L::NAME, T::NAME), |b| {
        b.iter(|| run::<T, L>(&k, black_box(&set)))
    });
}

fn criterion_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/criterion")
}

/// Mean ns per call from criterion's estimates file, if present.
fn ns_per_call(law: &str, precision: &str) -> Option<f64> {
    let path = criterion_dir()
        .join(format!("friction_{law}-{precision}"))
        .join("new/estimates.json");
    let text = std::fs::read_to_string(path).ok()?;
    let mean = &text[text.find("\"mean\"")?..];
    let pe = &mean[mean.find("\"point_estimate\":")? + 17..];
    let end = pe.find([',', '}'])?;
    pe[..end]
        .trim()
        .parse::<f64>()
        .ok()
        .map(|ns| ns / SET as f64)
}

/// Max (|ΔF|, |ΔT|) against `reference` over e² ∈ [0, 0.99], ψ ∈ [0, π/2] (the symmetries
/// cover the rest), u ∈ {0, 1e-4 … 1e4 (50 per decade), ∞}.
fn max_error<T: Real, L: FrictionLaw>(
    reference: &dyn Fn(f64, f64, f64) -> Traction<f64>,
) -> (f64, f64) {
    let (mut ef, mut et) = (0.0f64, 0.0f64);
    for i in 0..=33 {
        let m = 0.99 * i as f64 / 33.0;
        let k = Constants::from_parameter(Parameter::new(T::from_f64(m)).unwrap());
        for j in 0..=48 {
            let psi = std::f64::consts::FRAC_PI_2 * j as f64 / 48.0;
            for n in 0..=402 {
                let u = match n {
                    0 => 0.0,
                    402 => f64::INFINITY,
                    _ => 10f64.powf(-4.0 + (n - 1) as f64 / 50.0),
                };
                let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
                let (t, _) = L::traction(&k, &s);
                let r = reference(m, psi, u);
                let (dx, dy) = (t.fx.to_f64() - r.fx, t.fy.to_f64() - r.fy);
                ef = ef.max(dx.hypot(dy));
                et = et.max((t.tz.to_f64() - r.tz).abs());
            }
        }
    }
    (ef, et)
}

fn main() {
    let mut c = Criterion::default()
        .output_directory(&criterion_dir())
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(1000))
        .sample_size(20)
        .configure_from_args();
    bench_law::<f32, Simplified>(&mut c);
    bench_law::<f64, Simplified>(&mut c);
    bench_law::<f32, Pade>(&mut c);
    bench_law::<f64, Pade>(&mut c);
    bench_law::<f32, Ellipsoid>(&mut c);
    bench_law::<f64, Ellipsoid>(&mut c);
    bench_law::<f32, Coulomb>(&mut c);
    bench_law::<f64, Coulomb>(&mut c);
    c.final_summary();

    let mut csv = String::from(
        "# cargo bench --bench friction: ns per call of the dimensionless core (patch constants given; host CPU), max error vs exact over e2 in [0,0.99], all psi, u in [0,inf]\nmodel,precision,ns_per_call,max_force_error_fN,max_torque_error_fNa\n",
    );
    let reference = |_: f64, _: f64, _: f64| Traction::<f64>::default();
    macro_rules! row {
        ($t:ty, $l:ty) => {{
            let ns =
                ns_per_call(<$l>::NAME, <$t>::NAME).map_or("".to_string(), |ns| format!("{ns:.2}"));
            let (ef, et) = max_error::<$t, $l>(&reference);
            let _ = writeln!(csv, "{},{},{ns},{ef:.4},{et:.4}", <$l>::NAME, <$t>::NAME);
        }};
    }
    row!(f32, Simplified);
    row!(f64, Simplified);
    row!(f32, Pade);
    row!(f64, Pade);
    row!(f32, Ellipsoid);
    row!(f64, Ellipsoid);
    row!(f32, Coulomb);
    row!(f64, Coulomb);
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("bench-results/friction.csv");
    let _ = std::fs::create_dir_all(out.parent().unwrap());
    std::fs::write(&out, csv).unwrap();
    println!("wrote {}", out.display());
}
