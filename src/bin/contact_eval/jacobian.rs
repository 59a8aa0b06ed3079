//! `jacobian`: the wrench of the contract ([`contensou::dynamic`]) and its derivatives with
//! respect to (h, ḣ, v_x, v_y, ω), [`DynContact::jacobian_rolling`] per row: the same input
//! columns, laws and forms as `wrench`, the same errors.
use std::process::ExitCode;

use contensou::dynamic::{DynContact, Form, Law};
use contensou::jacobian::OUTPUTS;

use crate::wrench::{Eval, help_options, options, rows};
use crate::{Args, Precision};

const COLUMNS: &str = "  columns: those of `wrench` (the 11, then any of G,nu,vrx,vry), its errors;
    -> N,Fx,Fy,Tz and the 20 derivatives dN_dh,dN_dhdot,dN_dvx,dN_dvy,dN_domega,
       dFx_dh,...,dTz_domega (SI; the rolling velocity vrx,vry is held fixed)
  forward-mode dual numbers through the wrench's own code: N,Fx,Fy,Tz are `wrench`'s bit for
  bit; at a branch switch the derivative is that of the branch the value takes; h <= 0 gives
  zeros; at exact rest with delta > 0 a ramp law gives its slopes along the axes
";

/// The help text.
pub fn help() -> String {
    format!("{COLUMNS}{}", help_options())
}

/// One row of the contract: its contact built, the Jacobian of one step.
fn eval<T: contensou::Real>(law: Law, form: Form) -> Box<Eval<'static, T>> {
    Box::new(move |c, rs, s, rv| {
        DynContact::new_rolling(c, rs, law, form)?
            .jacobian_rolling(s, rv)
            .map(|j| j.to_array().to_vec())
    })
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    let (law, form, precision) = options(args)?;
    Ok(per_precision!(precision, T => rows::<T>(&OUTPUTS, &*eval(law, form))))
}
