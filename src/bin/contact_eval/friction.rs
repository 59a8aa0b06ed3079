//! `friction`: e2, psi, u → Fx, Fy, Tz (dimensionless: F/(fN), T_z/(fNa); u = v/(aω), ω > 0,
//! x along the major axis, δ → 0). `u` may be `inf` (pure translation).
use std::fmt::LowerExp;
use std::marker::PhantomData;
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::Parameter;
use contensou::friction::{
    Best, BestSeries, Constants, Coulomb, Ellipsoid, Exact, Friction, FrictionLaw, Pade,
    Simplified, SlipState, Traction,
};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Model, Precision, list_models, run_model};

/// The models, the library's default law first (`Friction<T>` without a law parameter; the
/// unit test `default_is_the_librarys` keeps it so).
pub const MODELS: &[Model] = models! {
    "best" => prepared::<Best>,
        "exact grade, per-contact tables (prepare at e2, then traction_prepared)";
    "best-varying" => per_call::<Best>,
        "best, per-step form (one flash table, e2 interpolated: the shape varies every call)";
    "best-series" => per_call::<BestSeries>,
        "best, the per-call fitted series (the per-step form's predecessor and fallback)";
    "simplified" => prepared::<Simplified>, "the paper's simplified model";
    "pade" => prepared::<Pade>, "Pade approximants";
    "ellipsoid" => prepared::<Ellipsoid>, "ellipsoidal pressure fit";
    "coulomb" => prepared::<Coulomb>, "point contact (no drilling torque)";
    "exact" => prepared::<Exact>, "the reference integrals (slow)";
    #[cfg(feature = "micromath")]
    "best-micromath" => prepared::<contensou::friction::BestMicromath>,
        "best with micromath's f32 functions";
    #[cfg(feature = "micromath")]
    "simplified-micromath" => prepared::<contensou::friction::SimplifiedMicromath>,
        "simplified with micromath's f32 functions";
    #[cfg(feature = "micromath")]
    "ellipsoid-micromath" => prepared::<contensou::friction::EllipsoidMicromath>,
        "ellipsoid with micromath's f32 functions";
    #[cfg(feature = "micromath")]
    "coulomb-micromath" => prepared::<contensou::friction::CoulombMicromath>,
        "coulomb with micromath's f32 functions";
};

/// The name of the law `Friction<T>` defaults to.
pub fn default_law() -> &'static str {
    fn name<T, L: FrictionLaw>(_: PhantomData<Friction<T, L>>) -> &'static str {
        L::NAME
    }
    name(PhantomData::<Friction<f64>>)
}

/// The help text.
pub fn help() -> String {
    format!(
        "{}  (default: `{}`, the law `Friction<T>` uses when none is named)\n",
        list_models("--model", MODELS),
        default_law()
    )
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    run_model(MODELS, &["--model", "--method"], args)
}

/// Each row through the law's per-contact form (`prepare` at the row's e², then
/// `traction_prepared`): what a contact of fixed shape evaluates every step.
fn prepared<L: FrictionLaw>(precision: Precision) -> ExitCode {
    per_precision!(precision, T => rows::<T>(|k, s| L::traction_prepared(&L::prepare(k), s).0))
}

/// Each row through the law's per-call form (`traction`, nothing precomputed).
fn per_call<L: FrictionLaw>(precision: Precision) -> ExitCode {
    per_precision!(precision, T => rows::<T>(|k, s| L::traction(k, s).0))
}

fn rows<T: Real + LowerExp>(law: impl Fn(&Constants<T>, &SlipState<T>) -> Traction<T>) -> ExitCode {
    run_csv::<T>(&["e2", "psi", "u"], &["Fx", "Fy", "Tz"], &mut |row| {
        let (e2, psi, u) = (row[0], row[1], row[2]);
        let p = Parameter::new(e2).map_err(|e| message("e2", shortest(e2), e))?;
        if u < T::ZERO || !(u.is_finite() || u > T::ONE) {
            return Err(message("u", shortest(u), "must be >= 0 (inf allowed)"));
        }
        let s = SlipState::from_polar(psi, u).map_err(|e| message("psi", shortest(psi), e))?;
        let t = law(&Constants::from_parameter(p), &s);
        Ok(vec![t.fx, t.fy, t.tz])
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn default_is_the_librarys() {
        assert_eq!(super::MODELS[0].name, super::default_law());
    }
}
