//! `eccentricity`: g → c; `hertz`: P, Q, E*, h → c, a, b, N.
use std::fmt::LowerExp;
use std::process::ExitCode;

use contensou::geometry::Curvatures;
use contensou::normal::{Fitted, Hertz, Modulus, NormalLaw, Volumetric};
use contensou::shape::{Eccentricity, HamrockDowson, Linear, Newton, Ratio, Table};
use contensou::{Error, Real};

use crate::csv::{message, run_csv, shortest};
use crate::{Args, Model, Precision, list_models, run_model};

/// The eccentricity methods, the default first.
pub const ECCENTRICITY: &[Model] = models! {
    "newton" => eccentricity::<Newton>, "exact (Newton on the Hertz shape equation)";
    "table" => eccentricity::<Table>, "per-step table in g (exact grade)";
    "linear" => eccentricity::<Linear>, "the paper's G* (c1 = 0.4)";
    "hamrock-dowson" => eccentricity::<HamrockDowson>, "k = (Q/P)^(2/pi)";
    #[cfg(feature = "micromath")]
    "hamrock-dowson-micromath" => eccentricity::<contensou::shape::HamrockDowsonMicromath>,
        "hamrock-dowson with micromath's f32 functions";
};

/// The normal laws, the default first.
pub const HERTZ: &[Model] = models! {
    "newton" => hertz_by::<Newton>, "Hertz, exact eccentricity";
    "table" => hertz_by::<Table>, "Hertz, eccentricity by table";
    "linear" => hertz_by::<Linear>, "Hertz, the paper's G*";
    "hamrock-dowson" => hertz_by::<HamrockDowson>, "Hertz, Hamrock-Dowson eccentricity";
    "volumetric" => volumetric,
        "Hertz circle of the Gaussian radius; stated domain P/Q >= 0.5 (error <= 1 %), refused below";
    "fitted" => fitted, "eccentricity-free fitted Hertz (P/Q >= 1e-4)";
};

/// `eccentricity` help.
pub fn help_eccentricity() -> String {
    list_models("--method", ECCENTRICITY)
}

/// `hertz` help.
pub fn help_hertz() -> String {
    list_models("--method", HERTZ)
}

/// `eccentricity --method M`.
pub fn run_eccentricity(args: Args) -> Result<ExitCode, String> {
    run_model(ECCENTRICITY, &["--method"], args)
}

/// `hertz --method M`.
pub fn run_hertz(args: Args) -> Result<ExitCode, String> {
    run_model(HERTZ, &["--method"], args)
}

fn eccentricity<M: Eccentricity>(precision: Precision) -> ExitCode {
    fn eval<T: Real + LowerExp, M: Eccentricity>() -> ExitCode {
        run_csv::<T>(&["g"], &["c"], &mut |row| {
            let g = Ratio::new(row[0]).map_err(|e| message("g", shortest(row[0]), e))?;
            Ok(vec![M::shape(g).e2()])
        })
    }
    per_precision!(precision, T => eval::<T, M>())
}

fn hertz_by<M: Eccentricity>(precision: Precision) -> ExitCode {
    per_precision!(precision, T => hertz::<T, _>(Hertz::new::<M>))
}

fn volumetric(precision: Precision) -> ExitCode {
    per_precision!(precision, T => hertz::<T, _>(Volumetric::checked))
}

fn fitted(precision: Precision) -> ExitCode {
    per_precision!(precision, T => hertz::<T, _>(Fitted::new))
}

/// Every row through the law built by `build` from the row's curvatures and modulus.
fn hertz<T: Real + LowerExp, N: NormalLaw<T>>(
    build: fn(&Curvatures<T>, Modulus<T>) -> Result<N, Error>,
) -> ExitCode {
    run_csv::<T>(
        &["P", "Q", "Estar", "h"],
        &["c", "a", "b", "N"],
        &mut |row| {
            let (p, q, estar, h) = (row[0], row[1], row[2], row[3]);
            let curv = Curvatures::new(p, q).map_err(|e| {
                let (name, value) = match e {
                    Error::NonFinite("Q") => ("Q", q),
                    Error::NonFinite(_) => ("P", p),
                    _ if q < p => ("Q", q),
                    _ => ("P", p),
                };
                message(name, shortest(value), e)
            })?;
            let estar = Modulus::new(estar).map_err(|e| message("Estar", shortest(estar), e))?;
            if !h.is_finite() {
                return Err(message("h", shortest(h), "must be finite"));
            }
            let law = build(&curv, estar).map_err(|e| message("P/Q", shortest(curv.ratio()), e))?;
            let patch = law.patch(h);
            Ok(vec![patch.e2, patch.a, patch.b, patch.n])
        },
    )
}
