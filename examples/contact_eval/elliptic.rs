//! `elliptic`: m → K, E.
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::{Agm, Method, Parameter};

use crate::{Options, run_csv};

/// Run the subcommand, or say why the options are wrong.
pub fn run(options: &Options) -> Result<ExitCode, String> {
    match (options.method.as_deref().unwrap_or("agm"), options.f32) {
        ("agm", false) => Ok(eval::<f64, Agm>()),
        ("agm", true) => Ok(eval::<f32, Agm>()),
        (other, _) => Err(format!("unknown method `{other}` for elliptic (agm)")),
    }
}

fn eval<T: Real, M: Method>() -> ExitCode {
    run_csv::<T>(&["m"], &["K", "E"], &mut |row| {
        let p = Parameter::new(row[0]).map_err(|e| format!("m = {}: {e}", row[0]))?;
        let i = M::integrals(p);
        Ok(vec![i.k, i.e])
    })
}
