//! `elliptic`: m → K, E, by `--method agm|theta|table` (default agm) in `--precision f32|f64`.
use std::process::ExitCode;

use contensou::Real;
use contensou::elliptic::{Agm, Method, Parameter, Table, Theta};

use crate::{Options, run_csv};

/// Run the subcommand, or say why the options are wrong.
pub fn run(options: &Options) -> Result<ExitCode, String> {
    match (options.method.as_deref().unwrap_or("agm"), options.f32) {
        ("agm", false) => Ok(eval::<f64, Agm>()),
        ("agm", true) => Ok(eval::<f32, Agm>()),
        ("theta", false) => Ok(eval::<f64, Theta>()),
        ("theta", true) => Ok(eval::<f32, Theta>()),
        ("table", false) => Ok(eval::<f64, Table>()),
        ("table", true) => Ok(eval::<f32, Table>()),
        (other, _) => Err(format!(
            "unknown method `{other}` for elliptic (agm, theta, table)"
        )),
    }
}

fn eval<T: Real, M: Method>() -> ExitCode {
    run_csv::<T>(&["m"], &["K", "E"], &mut |row| {
        let p = Parameter::new(row[0]).map_err(|e| format!("m = {}: {e}", row[0]))?;
        let i = M::integrals(p);
        Ok(vec![i.k, i.e])
    })
}
