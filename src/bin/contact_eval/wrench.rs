//! `wrench`: the full per-step wrench of the contract of [`contensou::dynamic`] — the C API
//! and the Python package evaluate the same module, so all three agree bit for bit. No formula
//! here: each row is [`dynamic::wrench`] (the contact built from the row, one step).
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::Real;
use contensou::dynamic::{
    self, Form, INPUTS, Invalid, Law, OUTPUTS, ROLLING_INPUTS, RollingSpec, RollingStep, Spec,
    Step, from_inputs,
};

use crate::csv::{message, run_csv_optional, shortest};
use crate::{Args, Precision, by_name, law_option, list, rolling_alias};

/// One line per law for `--help`.
fn about_law(law: Law) -> &'static str {
    match law {
        Law::Best => "exact grade, fast (the library's default law)",
        Law::Simplified => "the paper's simplified model",
        Law::Pade => "Pade approximants",
        Law::Ellipsoid => "ellipsoidal pressure fit",
        Law::Coulomb => "point contact (no drilling torque)",
        Law::Table => "rolling: Kalker's creep, blend + residual tables (default rolling law)",
        Law::Blend => "rolling: Kalker's linear theory joined to the exact full slip",
        Law::Fastsim => "rolling: FASTSIM, elliptic traction bound, 32 x 32",
        Law::Fastsim16 => "rolling: FASTSIM, elliptic traction bound, 16 x 16",
    }
}

/// One line per form for `--help`.
fn about_form(form: Form) -> &'static str {
    match form {
        Form::Fixed => "Contact built per row, exact eccentricity (Newton)",
        Form::Varying => "VaryingContact, eccentricity and shape constants by table each step",
    }
}

const COLUMNS: &str =
    "  columns (SI, contact frame x = major axis, z from A into B; forces on B from A):
    P,Q        curvatures, z = P x^2 + Q y^2, 0 < P <= Q (P > Q is refused, never swapped)
    estar      effective modulus E* (Pa)
    cd         Hunt-Crossley c_d (s/m), 0 = undamped
    f,delta    friction coefficient, regularization speed (m/s, 0 allowed)
    h,hdot     approach (m, <= 0: no contact), its rate (m/s, > 0: compression)
    vx,vy      slip of B relative to A at the patch centre (m/s)
    omega      spin about z (rad/s)
    -> N,Fx,Fy,Tz,a,b,e2   normal force, friction force, drilling torque, semi-axes, e^2
  optional columns, after those, any of (read by the rolling laws only; echoed):
    G          combined shear modulus (Pa), > 0; default estar*(1 - nu)
    nu         Poisson ratio of the tangential problem, in [0, 0.5]; default 0.3
    vrx,vry    rolling velocity of the contact in the contact frame (m/s): the velocity of
               the contact point over both surfaces, averaged; default 0 (full slip)
";

/// The help text.
pub fn help() -> String {
    format!("{COLUMNS}{}", help_options())
}

/// The `--law` and `--form` lists (shared with the subcommands of the same contract).
pub fn help_options() -> String {
    let laws = list("--law", Law::ALL.iter().map(|&l| (l.name(), about_law(l))));
    let laws = laws + &rolling_alias();
    let forms = list(
        "--form",
        Form::ALL.iter().map(|&f| (f.name(), about_form(f))),
    );
    format!("{laws}{forms}")
}

/// Run the subcommand, or say why the options are wrong.
pub fn run(args: Args) -> Result<ExitCode, String> {
    let (law, form, precision) = options(args)?;
    Ok(
        per_precision!(precision, T => rows::<T>(&OUTPUTS, &|c, rs, s, rv| {
            dynamic::wrench_rolling(c, rs, law, form, s, rv).map(|o| o.to_array().to_vec())
        })),
    )
}

/// The options of the contract's subcommands: `--law`, `--form` and the precision.
pub fn options(mut args: Args) -> Result<(Law, Form, Precision), String> {
    let law = by_name("--law", law_option(&mut args), &Law::ALL, |l| l.name())?;
    let form = by_name("--form", args.take(&["--form"]), &Form::ALL, |f| f.name())?;
    let (law, form) = (
        law.copied().unwrap_or_default(),
        form.copied().unwrap_or_default(),
    );
    let precision = args.precision;
    args.finish()?;
    Ok((law, form, precision))
}

/// One row's evaluation: the contact and rolling columns, the step and rolling-step columns →
/// the output columns, or the rejected column.
pub type Eval<'a, T> =
    dyn Fn(&Spec<T>, &RollingSpec<T>, &Step<T>, &RollingStep<T>) -> Result<Vec<T>, Invalid> + 'a;

/// The contract's rows (the 11 columns, the optional rolling ones) through `eval`; a rejected
/// column is reported with its value.
pub fn rows<T: Real + LowerExp>(outputs: &[&str], eval: &Eval<'_, T>) -> ExitCode {
    run_csv_optional::<T>(&INPUTS, &ROLLING_INPUTS, outputs, &mut |r, o| {
        let (spec, step, rolling_spec, rolling_step) = parts(r, o);
        eval(&spec, &rolling_spec, &step, &rolling_step)
            .map_err(|e| refusal(e, &INPUTS, r, &ROLLING_INPUTS, o))
    })
}

/// The contract's columns of a row: the contact (`r[0..6]`), the step (`r[6..11]`), and the
/// optional rolling columns `G, nu, vrx, vry` (`o[0..4]`; absent: the defaults).
pub fn parts<T: Real>(
    r: &[T],
    o: &[Option<T>],
) -> (Spec<T>, Step<T>, RollingSpec<T>, RollingStep<T>) {
    let get = |i: usize| o.get(i).copied().flatten();
    let (spec, step) = from_inputs(core::array::from_fn(|i| r[i]));
    let rolling_spec = RollingSpec {
        g: get(0),
        nu: get(1),
    };
    let rolling_step = RollingStep {
        vrx: get(2).unwrap_or(T::ZERO),
        vry: get(3).unwrap_or(T::ZERO),
    };
    (spec, step, rolling_spec, rolling_step)
}

/// `column = value: reason` for a rejected row, the value looked up among the row's columns
/// (`inputs`, then the `optional` ones).
pub fn refusal<T: Real + LowerExp>(
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
