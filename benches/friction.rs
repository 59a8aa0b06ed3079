//! criterion: the friction laws' dimensionless core, per law × precision, on a fixed mixed input
//! set (64 states: u log-uniform in [0.01, 100], ψ uniform, e² = 0.5, ω > 0, δ = 0; the same set as the QEMU stage `friction`), with the patch
//! constants given. Afterwards measures each law's max error against the exact integrals on a
//! dense grid and writes both into `bench-results/friction.csv`:
//!
//! ```text
//! cargo bench --bench friction
//! ```
//!
//! With `--features micromath` also `friction/<law>_micromath_f32` for simplified, ellipsoid,
//! coulomb and best (per call); their errors are in bench-results/micromath.md.
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::{
    Best, BestContact, Constants, Coulomb, Ellipsoid, Exact, FrictionLaw, Pade, Simplified,
    SlipState, Traction,
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
    bench_law_as::<T, L>(c, &format!("friction/{}-{}", L::NAME, T::NAME));
}

fn bench_law_as<T: Real, L: FrictionLaw>(c: &mut Criterion, id: &str) {
    let k = Constants::from_parameter(Parameter::new(T::from_f64(0.5)).unwrap());
    let set = inputs::<T>();
    c.bench_function(id, |b| b.iter(|| run::<T, L>(&k, black_box(&set))));
}

/// `best` per contact ([`BestContact`], constants built once outside the loop).
fn bench_best<T: Real>(c: &mut Criterion) {
    let k = Constants::from_parameter(Parameter::new(T::from_f64(0.5)).unwrap());
    let b = BestContact::new(&k);
    let set = inputs::<T>();
    c.bench_function(&format!("friction/best-contact-{}", T::NAME), |bch| {
        bch.iter(|| {
            let mut acc = T::ZERO;
            for s in black_box(&set) {
                let (t, _) = black_box(&b).traction(black_box(s));
                acc += t.fx + t.fy + t.tz;
            }
            acc
        })
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

/// The dense accuracy grid: e² ∈ {0, 0.03, …, 0.99} (34 values), ψ ∈ [0, π/2] (49 values; the
/// symmetries ψ → −ψ, ψ → ψ + π cover the rest), u ∈ {0} ∪ 10^[−4, 4] (100 per decade) ∪ {∞},
/// plus every switch and kink of the laws and of the exact integrals — the knees 1/A, 1/B,
/// u_z*(ψ) = (1 − e²sin²ψ)/(5C) and the ellipse boundary u_b(ψ) — and one part in 1e9 either
/// side of each.
fn grid() -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    for i in 0..=33 {
        let m = 0.99 * i as f64 / 33.0;
        let k = Constants::from_parameter(Parameter::new(m).unwrap());
        for j in 0..=48 {
            let psi = std::f64::consts::FRAC_PI_2 * j as f64 / 48.0;
            let (s, c) = psi.sin_cos();
            out.push((m, psi, 0.0));
            out.push((m, psi, f64::INFINITY));
            for n in 0..=800 {
                out.push((m, psi, 10f64.powf(-4.0 + n as f64 / 100.0)));
            }
            let knees = [
                k.knee_x(),
                k.knee_y(),
                (1.0 - m * s * s) / (5.0 * k.spin_torque()),
                1.0 / (s * s + c * c / k.m1()).sqrt(),
            ];
            for u in knees {
                for f in [1.0 - 1e-9, 1.0, 1.0 + 1e-9] {
                    out.push((m, psi, u * f));
                }
            }
        }
    }
    out
}

/// Max (|ΔF| in fN, |ΔT_z| in fNa) of law `L` in precision `T` against [`Exact`] (f64) over
/// the [`grid`], with the worst (e², ψ, u) for each.
struct Worst {
    force: (f64, (f64, f64, f64)),
    torque: (f64, (f64, f64, f64)),
    circle: (f64, f64),
}

fn accuracy<T: Real, L: FrictionLaw>(exact: &[(f64, f64, f64, Traction<f64>)]) -> Worst {
    let mut worst = Worst {
        force: (0.0, (0.0, 0.0, 0.0)),
        torque: (0.0, (0.0, 0.0, 0.0)),
        circle: (0.0, 0.0),
    };
    let mut k = None;
    for &(m, psi, u, r) in exact {
        let kk = match k {
            Some((km, kk)) if km == m => kk,
            _ => {
                let kk = Constants::from_parameter(Parameter::new(T::from_f64(m)).unwrap());
                k = Some((m, kk));
                kk
            }
        };
        let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).unwrap();
        let (t, _) = L::traction(&kk, &s);
        let ef = (t.fx.to_f64() - r.fx).hypot(t.fy.to_f64() - r.fy);
        let et = (t.tz.to_f64() - r.tz).abs();
        if m == 0.0 {
            worst.circle = (worst.circle.0.max(ef), worst.circle.1.max(et));
        }
        if ef > worst.force.0 {
            worst.force = (ef, (m, psi, u));
        }
        if et > worst.torque.0 {
            worst.torque = (et, (m, psi, u));
        }
    }
    worst
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
    bench_law::<f32, Exact>(&mut c);
    bench_law::<f64, Exact>(&mut c);
    bench_best::<f32>(&mut c);
    bench_best::<f64>(&mut c);
    bench_law::<f32, Best>(&mut c);
    bench_law::<f64, Best>(&mut c);
    #[cfg(feature = "micromath")]
    {
        use contensou::friction::{
            BestMicromath, CoulombMicromath, EllipsoidMicromath, SimplifiedMicromath,
        };
        bench_law_as::<f32, SimplifiedMicromath>(&mut c, "friction/simplified_micromath_f32");
        bench_law_as::<f32, EllipsoidMicromath>(&mut c, "friction/ellipsoid_micromath_f32");
        bench_law_as::<f32, CoulombMicromath>(&mut c, "friction/coulomb_micromath_f32");
        bench_law_as::<f32, BestMicromath>(&mut c, "friction/best_micromath_f32");
    }
    c.final_summary();

    let exact: Vec<(f64, f64, f64, Traction<f64>)> = {
        let mut k = None;
        grid()
            .into_iter()
            .map(|(m, psi, u)| {
                let kk = match k {
                    Some((km, kk)) if km == m => kk,
                    _ => {
                        let kk = Constants::from_parameter(Parameter::new(m).unwrap());
                        k = Some((m, kk));
                        kk
                    }
                };
                let s = SlipState::from_polar(psi, u).unwrap();
                (m, psi, u, Exact::traction(&kk, &s).0)
            })
            .collect()
    };
    let mut csv = String::from(
        "# cargo bench --bench friction: ns per call of the dimensionless core (patch constants given; host CPU, criterion mean), max error vs the exact integrals over e2 in [0,0.99] (34 values), psi in [0,pi/2] (49; symmetries cover the rest), u in {0} + 1e-4..1e4 (100/decade) + {inf} + every knee (1/A, 1/B, u_z*, u_b) and 1e-9 either side, delta = 0; circle = e2 = 0 only; worst point as e2 psi u\nmodel,precision,ns_per_call,max_force_error_fN,max_torque_error_fNa,circle_force_error_fN,circle_torque_error_fNa,worst_force_at,worst_torque_at\n",
    );
    // A row per law (in order), f32 then f64.
    macro_rules! rows {
        ($($l:ty),*) => {$(
            row!(f32, $l);
            row!(f64, $l);
        )*};
    }
    macro_rules! row {
        ($t:ty, $l:ty) => {{
            let ns =
                ns_per_call(<$l>::NAME, <$t>::NAME).map_or("".to_string(), |ns| format!("{ns:.2}"));
            let w = accuracy::<$t, $l>(&exact);
            let at = |(m, psi, u): (f64, f64, f64)| format!("{m:.4} {psi:.4} {u:.4e}");
            let _ = writeln!(
                csv,
                "{},{},{ns},{:.5},{:.5},{:.5},{:.5},{},{}",
                <$l>::NAME,
                <$t>::NAME,
                w.force.0,
                w.torque.0,
                w.circle.0,
                w.circle.1,
                at(w.force.1),
                at(w.torque.1)
            );
        }};
    }
    rows!(Simplified, Pade, Ellipsoid, Coulomb, Exact, Best);
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("bench-results/friction.csv");
    let _ = std::fs::create_dir_all(out.parent().unwrap());
    std::fs::write(&out, csv).unwrap();
    println!("wrote {}", out.display());
}
