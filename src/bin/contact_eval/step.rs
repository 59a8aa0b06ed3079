//! `step`: the step-aware wrench of [`contensou::step::contract`] — the wrench's contract plus
//! `dt`, W's upper triangle and the optional free end-of-step velocity. No formula here: each
//! row is [`contract::step_row`] on the contact built from the row.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::dynamic::{DynContact, Form, INPUTS, Law, ROLLING_INPUTS};
use contensou::step::contract::{self, FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS};

use crate::csv::run_csv_optional;
use crate::wrench::{self, parts, refusal};
use crate::{Args, Precision, list, rolling_alias};

const COLUMNS: &str =
    "  columns: those of `wrench` (P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega; SI, contact frame),
  then
    dt         the step (s), > 0
    w_nn,w_nx,w_ny,w_nw,w_xx,w_xy,w_xw,w_yy,w_yw,w_ww
               the contact's inverse mass W, upper triangle over u = (v_n, v_x, v_y, w)
               (v_n = -hdot; w = spin): an impulse dt*(N,Fx,Fy,Tz) on B changes u by
               dt*W*(N,Fx,Fy,Tz); symmetric positive semidefinite
    -> N,Fx,Fy,Tz   the wrench to apply over the whole step (semi-implicit Euler), on B
  optional columns, after those, any of:
    G,nu,vrx,vry    as `wrench` (rolling laws)
    un_free,ux_free,uy_free,uw_free
               the end-of-step velocity without this contact (gravity and every other force
               over the step); each absent one: the start velocity's (-hdot, vx, vy, omega)
";

/// The help text.
pub fn help() -> String {
    let laws = list("--law", Law::ALL.iter().map(|&l| (l.name(), ""))) + &rolling_alias();
    let forms = list("--form", Form::ALL.iter().map(|&f| (f.name(), "")));
    format!("{COLUMNS}{laws}{forms}")
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    let (law, form, precision) = wrench::options(args)?;
    Ok(per_precision!(precision, T => rows::<T>(law, form)))
}

fn rows<T: Real + LowerExp>(law: Law, form: Form) -> ExitCode {
    let inputs: Vec<&str> = INPUTS.iter().chain(&STEP_INPUTS).copied().collect();
    let optional: Vec<&str> = ROLLING_INPUTS.iter().chain(&FREE_INPUTS).copied().collect();
    run_csv_optional::<T>(&inputs, &optional, &STEP_OUTPUTS, &mut |r, o| {
        let (spec, step, rolling_spec, rolling_step) = parts(r, o);
        let mut w = [T::ZERO; 10];
        w.copy_from_slice(&r[12..22]);
        let get = |i: usize| o.get(i).copied().flatten();
        let u_free = [get(4), get(5), get(6), get(7)];
        DynContact::new_rolling(&spec, &rolling_spec, law, form)
            .and_then(|c| contract::step_row(&c, &step, &rolling_step, r[11], w, u_free))
            .map(|out| out.to_vec())
            .map_err(|e| refusal(e, &inputs, r, &optional, o))
    })
}
