//! `elliptic`: m → K, E (complete elliptic integrals), `--method`.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::{Agm, Method, Parameter, Table, Theta};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Model, Precision, list_models, run_model};

/// The methods, the default first.
pub const METHODS: &[Model] = &[
    Model {
        name: "agm",
        about: "arithmetic-geometric mean (exact grade)",
        run: by::<Agm>,
    },
    Model {
        name: "theta",
        about: "theta-function series (fixed terms)",
        run: by::<Theta>,
    },
    Model {
        name: "table",
        about: "interpolated table",
        run: by::<Table>,
    },
    #[cfg(feature = "micromath")]
    Model {
        name: "theta-micromath",
        about: "theta series with micromath's f32 functions",
        run: by::<contensou::elliptic::ThetaMicromath>,
    },
];

/// The help text.
pub fn help() -> String {
    list_models("--method", METHODS)
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    run_model(METHODS, &["--method"], args)
}

fn by<M: Method>(precision: Precision) -> ExitCode {
    match precision {
        Precision::F32 => eval::<f32, M>(),
        Precision::F64 => eval::<f64, M>(),
    }
}

fn eval<T: Real + LowerExp, M: Method>() -> ExitCode {
    run_csv::<T>(&["m"], &["K", "E"], &mut |row| {
        let p = Parameter::new(row[0]).map_err(|e| message("m", shortest(row[0]), e))?;
        let i = M::integrals(p);
        Ok(vec![i.k, i.e])
    })
}
