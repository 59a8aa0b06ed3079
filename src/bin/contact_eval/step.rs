//! `step`: the step-aware wrench of [`contensou::step::contract`] — the wrench's contract plus
//! `dt`, W's upper triangle and the optional free end-of-step velocity. No formula here: each
//! row is [`contract::step_row`] on the contact built from the row.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::dynamic::{
    DynContact, Form, INPUTS, Invalid, Law, ROLLING_INPUTS, RollingSpec, RollingStep, Spec, Step,
};
use contensou::step::contract::{self, FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS};

use crate::csv::{message, run_csv_optional, shortest};
use crate::{Args, Precision, by_name, list};

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
    let laws = list("--law", Law::ALL.iter().map(|&l| (l.name(), "")));
    let forms = list("--form", Form::ALL.iter().map(|&f| (f.name(), "")));
    format!("{COLUMNS}{laws}{forms}")
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(mut args: Args) -> Result<ExitCode, String> {
    let law = by_name("--law", args.take(&["--law"]), &Law::ALL, |l| l.name())?;
    let form = by_name("--form", args.take(&["--form"]), &Form::ALL, |f| f.name())?;
    let (law, form) = (
        law.copied().unwrap_or_default(),
        form.copied().unwrap_or_default(),
    );
    let precision = args.precision;
    args.finish()?;
    Ok(match precision {
        Precision::F32 => rows::<f32>(law, form),
        Precision::F64 => rows::<f64>(law, form),
    })
}

/// The contract's columns of a row: the contact (`r[0..6]`), the step (`r[6..11]`), and the
/// optional rolling columns `G, nu, vrx, vry` (`o[0..4]`; absent: the defaults).
fn parts<T: Real>(r: &[T], o: &[Option<T>]) -> (Spec<T>, Step<T>, RollingSpec<T>, RollingStep<T>) {
    let get = |i: usize| o.get(i).copied().flatten();
    let spec = Spec {
        p: r[0],
        q: r[1],
        estar: r[2],
        cd: r[3],
        f: r[4],
        delta: r[5],
    };
    let step = Step {
        h: r[6],
        hdot: r[7],
        vx: r[8],
        vy: r[9],
        omega: r[10],
    };
    let rolling_spec = RollingSpec {
        g: get(0),
        nu: get(1),
    };
    let vr = (get(2).unwrap_or(T::ZERO), get(3).unwrap_or(T::ZERO));
    (
        spec,
        step,
        rolling_spec,
        RollingStep {
            vrx: vr.0,
            vry: vr.1,
        },
    )
}

/// `column = value: reason` for a rejected row, the value looked up among the row's columns.
fn refusal<T: Real + LowerExp>(
    e: Invalid,
    inputs: &[&str],
    r: &[T],
    optional: &[&str],
    o: &[Option<T>],
) -> String {
    let Invalid { column, error } = e;
    let at = |i: usize| o.get(i).copied().flatten();
    let value = match inputs.iter().position(|&c| c == column) {
        Some(i) => r.get(i).copied(),
        None => optional.iter().position(|&c| c == column).and_then(at),
    };
    message(
        column,
        value.map_or_else(|| "?".into(), shortest),
        error.as_str(),
    )
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
