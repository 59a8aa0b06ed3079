//! `elliptic`: m → K, E (complete elliptic integrals), `--method`.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::{Agm, Method, Parameter, Table, Theta};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Model, Precision, list_models, run_model};

/// The methods, the default first.
pub const METHODS: &[Model] = models! {
    "agm" => by::<Agm>, "arithmetic-geometric mean (exact grade)";
    "theta" => by::<Theta>, "theta-function series (fixed terms)";
    "table" => by::<Table>, "interpolated table";
    #[cfg(feature = "micromath")]
    "theta-micromath" => by::<contensou::elliptic::ThetaMicromath>,
        "theta series with micromath's f32 functions";
};

/// The help text.
pub fn help() -> String {
    list_models("--method", METHODS)
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    run_model(METHODS, &["--method"], args)
}

fn by<M: Method>(precision: Precision) -> ExitCode {
    per_precision!(precision, T => eval::<T, M>())
}

fn eval<T: Real + LowerExp, M: Method>() -> ExitCode {
    run_csv::<T>(&["m"], &["K", "E"], &mut |row| {
        let p = Parameter::new(row[0]).map_err(|e| message("m", shortest(row[0]), e))?;
        let i = M::integrals(p);
        Ok(vec![i.k, i.e])
    })
}
