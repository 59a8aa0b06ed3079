//! The committed mpmath references (tools/data/) and each stage's error measure.

use contensou::Real;
use contensou::contact::{Contact, VaryingContact};
use contensou::elliptic::{Method as KeMethod, Parameter};
use contensou::friction::{Constants, Friction, FrictionLaw, Slip, SlipState, Traction, exact};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Fitted, Hertz, Modulus, NormalLaw, Patch, Undamped, Volumetric};
use contensou::shape::{Eccentricity, Newton, Ratio, Table};

include!("../../benches/friction_set.rs");

/// Every reference table, parsed once.
pub struct Refs {
    /// m, m₁, [K, E, B, D].
    pub elliptic: Vec<(f64, f64, [f64; 4])>,
    /// case, [P, Q, E*, h], [c, m1, K, E, B, D, a, b, N, p0].
    pub hertz: Vec<(String, [f64; 4], [f64; 10])>,
    /// e², ψ, u, exact traction.
    pub friction: Vec<(f64, f64, f64, Traction<f64>)>,
}

fn data(name: &str) -> String {
    let path = format!("{}/tools/data/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn numbers(line: &str) -> Vec<f64> {
    line.split(',')
        .map(|x| x.trim().parse().unwrap_or(f64::NAN))
        .collect()
}

impl Refs {
    pub fn load() -> Self {
        let elliptic = data("elliptic_ref.csv")
            .lines()
            .skip(1)
            .map(|l| {
                let f = numbers(l);
                (f[0], f[1], [f[2], f[3], f[4], f[5]])
            })
            .collect();
        let hertz = data("hertz_ref.csv")
            .lines()
            .skip(1)
            .map(|l| {
                let case = l.split(',').next().unwrap_or("").to_string();
                let f = numbers(l);
                (
                    case,
                    [f[1], f[2], f[3], f[4]],
                    core::array::from_fn(|i| f[5 + i]),
                )
            })
            .collect();
        let mut friction = Vec::new();
        for file in ["friction_ref.csv", "friction_ref_random.csv"] {
            for l in data(file).lines().skip(1) {
                let f = numbers(l);
                let t = Traction {
                    fx: f[3],
                    fy: f[4],
                    tz: f[5],
                };
                friction.push((f[0], f[1], f[2], t));
            }
        }
        Refs {
            elliptic,
            hertz,
            friction,
        }
    }
}

/// Relative error; absolute when the reference is 0.
pub fn rel(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

/// Force and torque error of a traction against the reference (fN, fNa).
pub fn traction_error<T: Real>(got: &Traction<T>, want: &Traction<f64>) -> (f64, f64) {
    (
        (got.fx.to_f64() - want.fx).hypot(got.fy.to_f64() - want.fy),
        (got.tz.to_f64() - want.tz).abs(),
    )
}

/// The parameter a careful caller builds from an exact row (m ≤ ½ from m, else from m₁), if
/// the row is exact in `T` and inside its domain.
fn parameter<T: Real>(m: f64, m1: f64) -> Option<Parameter<T>> {
    let x = if m <= 0.5 { m } else { m1 };
    let t = T::from_f64(x);
    if t.to_f64() != x {
        return None;
    }
    if m <= 0.5 {
        Parameter::new(t).ok()
    } else {
        Parameter::from_complement(t).ok()
    }
}

/// K, E, B, D of method `M` in `T`: max relative error of the four per reference row.
pub fn elliptic<T: Real, M: KeMethod>(r: &Refs) -> Vec<Vec<f64>> {
    r.elliptic
        .iter()
        .filter_map(|&(m, m1, want)| {
            let i = M::integrals(parameter::<T>(m, m1)?);
            let got = [i.k, i.e, i.b, i.d].map(T::to_f64);
            Some(vec![
                (0..4).map(|j| rel(got[j], want[j])).fold(0.0, f64::max),
            ])
        })
        .collect()
}

/// Errors of a patch against a Hertz row: [N rel, max(a, b) rel] (+ |Δc| if `with_c`).
fn patch_errors<T: Real>(p: &Patch<T>, want: &[f64; 10], with_c: bool) -> Vec<f64> {
    let mut v = vec![
        rel(p.n.to_f64(), want[8]),
        rel(p.a.to_f64(), want[6]).max(rel(p.b.to_f64(), want[7])),
    ];
    if with_c {
        v.push((p.e2.to_f64() - want[0]).abs());
    }
    v
}

/// Every Hertz row through `law` (None: the row is outside the method's domain, skipped).
fn hertz_rows<T: Real, L: NormalLaw<T>>(
    r: &Refs,
    with_c: bool,
    law: impl Fn(&Curvatures<T>, Modulus<T>) -> Option<L>,
) -> Vec<Vec<f64>> {
    r.hertz
        .iter()
        .filter_map(|(_, input, want)| {
            let [p, q, estar, h] = input.map(T::from_f64);
            let curv = Curvatures::new(p, q).ok()?;
            let law = law(&curv, Modulus::new(estar).ok()?)?;
            Some(patch_errors(&law.patch(h), want, with_c))
        })
        .collect()
}

/// Shape method `M` solved once (`Hertz::new::<M>`): N, a/b relative and c absolute.
pub fn shape<T: Real, M: Eccentricity>(r: &Refs) -> Vec<Vec<f64>> {
    hertz_rows::<T, _>(r, true, |c, e| Hertz::new::<M>(c, e).ok())
}

/// Geometry solved once with Newton; the per-step patch.
pub fn hertz_newton<T: Real>(r: &Refs) -> Vec<Vec<f64>> {
    hertz_rows::<T, _>(r, false, |c, e| Hertz::new::<Newton>(c, e).ok())
}

/// As [`hertz_newton`], the per-step square root by micromath (feature `micromath`).
#[cfg(feature = "micromath")]
pub fn hertz_newton_micromath<T: Real>(r: &Refs) -> Vec<Vec<f64>> {
    use contensou::normal::HertzMicromath;
    hertz_rows::<T, _>(r, false, |c, e| HertzMicromath::new::<Newton>(c, e).ok())
}

/// e² by table from g every step (`Hertz::from_shape`).
pub fn hertz_table_each_step<T: Real>(r: &Refs) -> Vec<Vec<f64>> {
    hertz_rows::<T, _>(r, false, |c, e| {
        let shape = Table::shape(Ratio::clamped(c.ratio()));
        Some(Hertz::from_shape(c, &shape, e))
    })
}

/// The fitted law from g every step.
pub fn hertz_fitted<T: Real>(r: &Refs) -> Vec<Vec<f64>> {
    hertz_rows::<T, _>(r, false, |c, e| Some(Fitted::clamped(c, e)))
}

/// The volumetric law.
pub fn hertz_volumetric<T: Real>(r: &Refs) -> Vec<Vec<f64>> {
    hertz_rows::<T, _>(r, false, |c, e| Some(Volumetric::new(c, e)))
}

/// The contract's thinnest patch: e² at P/Q = 1e-4 (`contact_eval eccentricity`).
const E2_CONTRACT_END: f64 = 0.999982985551773;

/// Every friction reference row through `law` (given the constants at the row's e²):
/// [|ΔF|, |ΔT_z|] if e² is one the contract accepts (up to the e² of P/Q = 1e-4; else NaN:
/// not counted), then [|ΔF|, |ΔT_z|] on every row.
fn friction_rows<T: Real>(
    r: &Refs,
    mut law: impl FnMut(&Constants<T>, &SlipState<T>) -> Traction<T>,
) -> Vec<Vec<f64>> {
    r.friction
        .iter()
        .filter_map(|&(e2, psi, u, want)| {
            let k = Constants::from_parameter(Parameter::new(T::from_f64(e2)).ok()?);
            let s = SlipState::from_polar(T::from_f64(psi), T::from_f64(u)).ok()?;
            let (f, t) = traction_error(&law(&k, &s), &want);
            let (fd, td) = if e2 <= E2_CONTRACT_END {
                (f, t)
            } else {
                (f64::NAN, f64::NAN)
            };
            Some(vec![fd, td, f, t])
        })
        .collect()
}

/// Law `L` in its per-contact form (`prepare` once per e², cached across consecutive rows).
pub fn law_prepared<T: Real, L: FrictionLaw>(r: &Refs) -> Vec<Vec<f64>> {
    let mut cache: Option<(Constants<T>, L::Prepared<T>)> = None;
    friction_rows::<T>(r, |k, s| {
        let p = match cache {
            Some((kk, p)) if kk == *k => p,
            _ => {
                let p = L::prepare(k);
                cache = Some((*k, p));
                p
            }
        };
        L::traction_prepared(&p, s).0
    })
}

/// Law `L` in its per-call form (nothing precomputed).
pub fn law_per_call<T: Real, L: FrictionLaw>(r: &Refs) -> Vec<Vec<f64>> {
    friction_rows::<T>(r, |k, s| L::traction(k, s).0)
}

/// The 209 bearing rows (race, E*, h, [c, m1, …, a, b, N, p0]) and the friction coefficient.
fn bearing_rows(r: &Refs) -> impl Iterator<Item = (Race, f64, f64, &[f64; 10])> {
    r.hertz.iter().filter_map(|(case, input, want)| {
        let race = match case.as_str() {
            "bearing209_inner" => Race::Inner,
            "bearing209_outer" => Race::Outer,
            _ => return None,
        };
        Some((race, input[2], input[3], want))
    })
}

const F: f64 = 0.07;
const OMEGA: f64 = 100.0;

/// The full wrench at every bearing row × mixed-set slip, through `step` (curvatures,
/// modulus, friction, h, slip → N, F_x, F_y, T_z); errors N rel, |ΔF|/(fN), |ΔT_z|/(fNa).
fn wrench_rows<T: Real, L: FrictionLaw>(
    r: &Refs,
    step: impl Fn(&Curvatures<T>, Modulus<T>, Friction<T, L>, T, Slip<T>) -> Option<[T; 4]>,
) -> Vec<Vec<f64>> {
    let mut out = Vec::new();
    for (race, estar, h, want) in bearing_rows(r) {
        let Ok(curv) = Curvatures::<T>::ball_race(
            T::from_f64(12.7e-3),
            T::from_f64(6.6e-3),
            T::from_f64(65e-3),
            T::ZERO,
            race,
        ) else {
            continue;
        };
        let (Ok(modulus), Ok(friction)) = (
            Modulus::new(T::from_f64(estar)),
            Friction::<T, L>::with_law(T::from_f64(F), T::ZERO),
        ) else {
            continue;
        };
        let (m1, a, n) = (want[1], want[6], want[8]);
        let Ok(p) = Parameter::<f64>::from_complement(m1) else {
            continue;
        };
        for (u, psi) in mixed_set() {
            let v = u * a * OMEGA;
            let (vx, vy) = (v * psi.cos(), v * psi.sin());
            let Ok(slip) = Slip::new(T::from_f64(vx), T::from_f64(vy), T::from_f64(OMEGA)) else {
                continue;
            };
            let Some([gn, fx, fy, tz]) = step(&curv, modulus, friction, T::from_f64(h), slip)
            else {
                continue;
            };
            let t = exact::traction(p, vx, vy, a * OMEGA);
            let want = Traction {
                fx: t.fx * F * n,
                fy: t.fy * F * n,
                tz: t.tz * F * n * a,
            };
            let got = Traction { fx, fy, tz };
            let (ef, et) = traction_error(&got, &want);
            out.push(vec![rel(gn.to_f64(), n), ef / (F * n), et / (F * n * a)]);
        }
    }
    out
}

/// `Contact` (geometry solved once with Newton) with law `L`.
pub fn wrench_fixed<T: Real, L: FrictionLaw>(r: &Refs) -> Vec<Vec<f64>> {
    wrench_rows::<T, L>(r, |curv, e, f, h, slip| {
        let c = Contact::hertz::<Newton>(curv, e, Undamped, f).ok()?;
        let w = c.wrench(h, T::ZERO, slip);
        Some([w.n, w.fx, w.fy, w.tz])
    })
}

/// `VaryingContact` (e² by table every step) with law `L`.
pub fn wrench_varying<T: Real, L: FrictionLaw>(r: &Refs) -> Vec<Vec<f64>> {
    wrench_rows::<T, L>(r, |curv, e, f, h, slip| {
        let w = VaryingContact::new(e, Undamped, f).wrench(curv, h, T::ZERO, slip);
        Some([w.n, w.fx, w.fy, w.tz])
    })
}
