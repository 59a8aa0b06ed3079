//! `friction`: e2, psi, u → Fx, Fy, Tz (dimensionless: F/(fN), T_z/(fNa); u = v/(aω), ω > 0,
//! x along the major axis, δ → 0). `u` may be `inf` (pure translation).
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::{
    Best, BestSeries, Constants, Coulomb, Ellipsoid, Exact, FrictionLaw, Pade, Simplified,
    SlipState, Traction,
};

use crate::{Options, run_csv};

/// Run the subcommand, or say why the options are wrong.
pub fn run(options: &Options) -> Result<ExitCode, String> {
    let model = options.method.as_deref().unwrap_or("simplified");
    let f32 = options.f32;
    Ok(match model {
        "simplified" if f32 => eval::<f32, Simplified>(),
        "simplified" => eval::<f64, Simplified>(),
        "pade" if f32 => eval::<f32, Pade>(),
        "pade" => eval::<f64, Pade>(),
        "ellipsoid" if f32 => eval::<f32, Ellipsoid>(),
        "ellipsoid" => eval::<f64, Ellipsoid>(),
        "coulomb" if f32 => eval::<f32, Coulomb>(),
        "coulomb" => eval::<f64, Coulomb>(),
        "best" if f32 => eval::<f32, Best>(),
        "best" => eval::<f64, Best>(),
        "best-varying" if f32 => eval_per_call::<f32, Best>(),
        "best-varying" => eval_per_call::<f64, Best>(),
        "best-series" if f32 => eval_per_call::<f32, BestSeries>(),
        "best-series" => eval_per_call::<f64, BestSeries>(),
        "exact" if f32 => eval::<f32, Exact>(),
        "exact" => eval::<f64, Exact>(),
        other => {
            return Err(format!(
                "unknown model `{other}` for friction (exact, simplified, pade, ellipsoid, coulomb, best, best-varying, best-series)"
            ));
        }
    })
}

/// Each row through the law's per-contact form (`prepare` at the row's e², then
/// `traction_prepared`): what a contact of fixed shape evaluates every step.
fn eval<T: Real, L: FrictionLaw>() -> ExitCode {
    rows::<T>(|k, s| L::traction_prepared(&L::prepare(k), s).0)
}

/// Each row through the law's per-call form (`traction`, nothing precomputed).
fn eval_per_call<T: Real, L: FrictionLaw>() -> ExitCode {
    rows::<T>(|k, s| L::traction(k, s).0)
}

fn rows<T: Real>(law: impl Fn(&Constants<T>, &SlipState<T>) -> Traction<T>) -> ExitCode {
    run_csv::<T>(&["e2", "psi", "u"], &["Fx", "Fy", "Tz"], &mut |row| {
        let (e2, psi, u) = (row[0], row[1], row[2]);
        let p = Parameter::new(e2).map_err(|e| format!("e2 = {e2}: {e}"))?;
        if u < T::ZERO || !(u.is_finite() || u > T::ONE) {
            return Err(format!("u = {u}: must be >= 0 (inf allowed)"));
        }
        let s = SlipState::from_polar(psi, u).map_err(|e| format!("{e}"))?;
        let t = law(&Constants::from_parameter(p), &s);
        Ok(vec![t.fx, t.fy, t.tz])
    })
}
