//! `rolling`: a,b,G,nu,f,N,V,xi,eta,phi → Fx,Fy,Mz: Kalker's rolling contact
//! (`contensou::friction::rolling`). a along the rolling direction +x, b across (m), G (Pa),
//! ν, f, N (N), V (m/s), creepages ξ, η (dimensionless) and φ (1/m) of body B relative to A;
//! output F_x, F_y (N) and M_z (N·m, about the patch centre) on body B. The wrench depends on
//! V only through its sign (the creepages are given): V < 0 is the mirror image (rolling
//! towards −x), V = 0 is read as the limit V → 0⁺ at these creepages. The rows, their
//! validation and the column an error names are the library's
//! (`contensou::friction::rolling::row`, shared with the C API and the Python package).
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::friction::rolling::row::{COLUMNS, OUTPUTS, RowLaw, Rows};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Precision, by_name, law_option, list, rolling_alias};

/// The help text.
pub fn help() -> String {
    format!(
        "{}  a along the rolling direction (+x), creepages of body B relative to A, Fx,Fy,Mz on B;\n  V < 0 mirrors (rolling towards -x); V = 0 is the limit V -> 0+ at the given creepages\n",
        list("--law", RowLaw::ALL.iter().map(|l| (l.name(), l.about()))) + &rolling_alias()
    )
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(mut args: Args) -> Result<ExitCode, String> {
    let law = by_name("--law", law_option(&mut args), &RowLaw::ALL, |l| l.name())?;
    let law = law.copied().unwrap_or_default();
    let precision = args.precision;
    args.finish()?;
    Ok(per_precision!(precision, T => eval::<T>(law)))
}

fn eval<T: Real + LowerExp>(law: RowLaw) -> ExitCode {
    let mut rows = Rows::<T>::new(law);
    run_csv::<T>(&COLUMNS, &OUTPUTS, &mut |r| {
        let r: &[T; 10] = r.try_into().map_err(|_| "row: 10 columns".to_string())?;
        let w = rows
            .eval(r)
            .map_err(|e| message(e.column.name(), shortest(e.value), e.error))?;
        Ok(vec![w.fx, w.fy, w.mz])
    })
}
