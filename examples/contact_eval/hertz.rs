//! `eccentricity`: g → c; `hertz`: P, Q, E*, h → c, a, b, N.
use std::process::ExitCode;

use contensou::Real;
use contensou::geometry::Curvatures;
use contensou::normal::{Fitted, Hertz, Modulus, NormalLaw, Volumetric};
use contensou::shape::{Eccentricity, HamrockDowson, Linear, Newton, Ratio, Table};

use crate::{Options, run_csv};

/// `eccentricity --method newton|table|linear|hamrock-dowson`.
pub fn run_eccentricity(options: &Options) -> Result<ExitCode, String> {
    let method = options.method.as_deref().unwrap_or("newton");
    Ok(match (method, options.f32) {
        ("newton", false) => eccentricity::<f64, Newton>(),
        ("newton", true) => eccentricity::<f32, Newton>(),
        ("table", false) => eccentricity::<f64, Table>(),
        ("table", true) => eccentricity::<f32, Table>(),
        ("linear", false) => eccentricity::<f64, Linear>(),
        ("linear", true) => eccentricity::<f32, Linear>(),
        ("hamrock-dowson", false) => eccentricity::<f64, HamrockDowson>(),
        ("hamrock-dowson", true) => eccentricity::<f32, HamrockDowson>(),
        (other, _) => {
            return Err(format!(
                "unknown method `{other}` for eccentricity (newton, table, linear, hamrock-dowson)"
            ));
        }
    })
}

fn eccentricity<T: Real, M: Eccentricity>() -> ExitCode {
    run_csv::<T>(&["g"], &["c"], &mut |row| {
        let g = Ratio::new(row[0]).map_err(|e| format!("g = {}: {e}", row[0]))?;
        Ok(vec![M::shape(g).e2()])
    })
}

/// `hertz --method newton|table|linear|volumetric|fitted`.
pub fn run_hertz(options: &Options) -> Result<ExitCode, String> {
    let method = options.method.as_deref().unwrap_or("newton");
    if !["newton", "table", "linear", "volumetric", "fitted"].contains(&method) {
        return Err(format!(
            "unknown method `{method}` for hertz (newton, table, linear, volumetric, fitted)"
        ));
    }
    Ok(if options.f32 {
        hertz::<f32>(method)
    } else {
        hertz::<f64>(method)
    })
}

fn hertz<T: Real>(method: &str) -> ExitCode {
    run_csv::<T>(
        &["P", "Q", "Estar", "h"],
        &["c", "a", "b", "N"],
        &mut |row| {
            let (p, q, estar, h) = (row[0], row[1], row[2], row[3]);
            let curv = Curvatures::new(p, q).map_err(|e| format!("P = {p}, Q = {q}: {e}"))?;
            let estar = Modulus::new(estar).map_err(|e| format!("Estar = {estar}: {e}"))?;
            if !h.is_finite() {
                return Err(format!("h = {h}: h must be finite"));
            }
            let law = |r: Result<Hertz<T>, contensou::Error>| {
                r.map_err(|e| format!("P/Q = {}: {e}", curv.ratio()))
            };
            let patch = match method {
                "newton" => law(Hertz::new::<Newton>(&curv, estar))?.patch(h),
                "table" => law(Hertz::new::<Table>(&curv, estar))?.patch(h),
                "linear" => law(Hertz::new::<Linear>(&curv, estar))?.patch(h),
                "volumetric" => Volumetric::new(&curv, estar).patch(h),
                _ => Fitted::new(&curv, estar)
                    .map_err(|e| format!("P/Q = {}: {e}", curv.ratio()))?
                    .patch(h),
            };
            Ok(vec![patch.e2, patch.a, patch.b, patch.n])
        },
    )
}
