//! A stand-in for `contact_eval wrench` until that subcommand lands (branch `cli`): the same
//! CSV contract — header `P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega`, every row through
//! `contensou::dynamic::wrench`, the inputs echoed, then `N,Fx,Fy,Tz,a,b,e2`, floats in
//! shortest round-trip form (`Display`). `--law L --form F --precision f32|f64`.
//! Used only by python/tests/test_bit_identity.py.

use std::fmt::Display;
use std::io::{BufRead, Write};
use std::str::FromStr;

use contensou::Real;
use contensou::dynamic::{self, Form, INPUTS, Law, OUTPUTS, Spec, Step};

fn rows<T: Real + Display + FromStr>(law: Law, form: Form) -> Result<(), String> {
    let stdin = std::io::stdin();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let mut lines = stdin.lock().lines();
    let header = lines
        .next()
        .ok_or("missing header")?
        .map_err(|e| e.to_string())?;
    if header.trim() != INPUTS.join(",") {
        return Err(format!("header must be {}", INPUTS.join(",")));
    }
    writeln!(out, "{},{}", INPUTS.join(","), OUTPUTS.join(",")).map_err(|e| e.to_string())?;
    for (row, line) in lines.enumerate() {
        let line = line.map_err(|e| e.to_string())?;
        let r = line
            .split(',')
            .map(|s| {
                s.trim()
                    .parse::<T>()
                    .map_err(|_| format!("row {}: bad number {s:?}", row + 1))
            })
            .collect::<Result<Vec<T>, String>>()?;
        if r.len() != INPUTS.len() {
            return Err(format!("row {}: expected {} fields", row + 1, INPUTS.len()));
        }
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
        let w = dynamic::wrench(&spec, law, form, &step)
            .map_err(|e| format!("row {}: {e}", row + 1))?;
        let all: Vec<String> = r
            .iter()
            .chain(w.to_array().iter())
            .map(T::to_string)
            .collect();
        writeln!(out, "{}", all.join(",")).map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str, default: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1).cloned())
            .unwrap_or_else(|| default.to_string())
    };
    let (Some(law), Some(form)) = (
        Law::from_name(&value("--law", "best")),
        Form::from_name(&value("--form", "fixed")),
    ) else {
        eprintln!("unknown --law or --form");
        return std::process::ExitCode::from(2);
    };
    let result = match value("--precision", "f64").as_str() {
        "f32" => rows::<f32>(law, form),
        _ => rows::<f64>(law, form),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{e}");
            std::process::ExitCode::from(1)
        }
    }
}
