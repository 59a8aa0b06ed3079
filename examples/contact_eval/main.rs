//! `contact_eval`: the library as a CSV filter, for scripting and for checking it against other
//! tools.
//!
//! ```text
//! cargo run --release --example contact_eval -- <subcommand> [--method M] [--precision f32|f64]
//! ```
//!
//! Reads CSV with a header row from stdin and writes CSV with a header row to stdout: the input
//! columns echoed, then the result columns; one output row per input row, in order; every float
//! in shortest round-trip form (Rust's `Display` for the chosen precision). The header must name
//! exactly the subcommand's input columns, in order. A bad row (wrong field count, a field that
//! is not a number, a value outside the method's domain) stops the run: a message on stderr
//! names the row (1-based, header not counted) and the reason, and the exit code is 1. Nothing
//! is dropped or clamped. Usage errors exit with 2.
//!
//! Subcommands (each a thin shell over the library, in its own file):
//!
//! | subcommand | input | output columns added | `--method` |
//! |---|---|---|---|
//! | `elliptic` | `m` | `K,E` | `agm` (default), `theta`, `table` |
//! | `eccentricity` | `g` | `c` | `newton` (default), `table`, `linear`, `hamrock-dowson` |
//! | `hertz` | `P,Q,Estar,h` | `c,a,b,N` | `newton` (default), `table`, `linear`, `volumetric`, `fitted` |
//! | `friction` | `e2,psi,u` | `Fx,Fy,Tz` (F/(fN), T_z/(fNa); u = v/(aω), ω > 0, δ → 0; `u = inf` allowed) | `--model` `simplified` (default), `pade`, `ellipsoid`, `coulomb`, `exact` |

mod elliptic;
mod friction;
mod hertz;

use std::io::{BufRead, Write};
use std::process::ExitCode;

use contensou::Real;

/// Command-line options shared by every subcommand.
pub struct Options {
    /// `--method` / `--model`, if given.
    pub method: Option<String>,
    /// `--precision`: true for f32.
    pub f32: bool,
}

/// Evaluate one row: the parsed inputs in, the result columns out, or a reason.
pub type RowFn<'a, T> = dyn FnMut(&[T]) -> Result<Vec<T>, String> + 'a;

/// The CSV contract: check the header, then parse, evaluate and print every row.
pub fn run_csv<T: Real>(inputs: &[&str], outputs: &[&str], eval: &mut RowFn<'_, T>) -> ExitCode {
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let mut lines = stdin.lock().lines();
    let header = match lines.next() {
        Some(Ok(h)) => h,
        _ => return fail(0, "missing header row"),
    };
    let names: Vec<&str> = header.trim().split(',').map(str::trim).collect();
    if names != inputs {
        return fail(
            0,
            &format!(
                "header must be `{}`, got `{}`",
                inputs.join(","),
                header.trim()
            ),
        );
    }
    let _ = writeln!(out, "{},{}", inputs.join(","), outputs.join(","));
    for (index, line) in lines.enumerate() {
        let row = index + 1;
        let line = match line {
            Ok(l) => l,
            Err(e) => return fail(row, &format!("unreadable: {e}")),
        };
        if line.trim().is_empty() {
            return fail(row, "empty row");
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != inputs.len() {
            return fail(
                row,
                &format!("expected {} fields, got {}", inputs.len(), fields.len()),
            );
        }
        let mut values = Vec::with_capacity(fields.len());
        for (name, field) in inputs.iter().zip(&fields) {
            match field.parse::<T>() {
                Ok(v) => values.push(v),
                Err(_) => return fail(row, &format!("{name} = `{field}` is not a number")),
            }
        }
        match eval(&values) {
            Ok(results) => {
                let all: Vec<String> = values
                    .iter()
                    .chain(&results)
                    .map(|v| v.to_string())
                    .collect();
                let _ = writeln!(out, "{}", all.join(","));
            }
            Err(reason) => return fail(row, &reason),
        }
    }
    match out.flush() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(0, &format!("cannot write output: {e}")),
    }
}

fn fail(row: usize, reason: &str) -> ExitCode {
    if row == 0 {
        eprintln!("contact_eval: {reason}");
    } else {
        eprintln!("contact_eval: row {row}: {reason}");
    }
    ExitCode::from(1)
}

fn usage(message: &str) -> ExitCode {
    eprintln!("contact_eval: {message}");
    eprintln!(
        "usage: contact_eval <subcommand> [--method M] [--precision f32|f64] < in.csv > out.csv"
    );
    eprintln!("  elliptic: m -> K,E; --method agm (default) | theta | table");
    eprintln!(
        "  eccentricity: g -> c; --method newton (default) | table | linear | hamrock-dowson"
    );
    eprintln!(
        "  hertz: P,Q,Estar,h -> c,a,b,N; --method newton (default) | table | linear | volumetric | fitted"
    );
    eprintln!(
        "  friction: e2,psi,u -> Fx,Fy,Tz; --model simplified (default) | pade | ellipsoid | coulomb | exact"
    );
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let Some(subcommand) = args.next() else {
        return usage("missing subcommand");
    };
    let mut options = Options {
        method: None,
        f32: false,
    };
    while let Some(flag) = args.next() {
        let Some(value) = args.next() else {
            return usage(&format!("{flag} needs a value"));
        };
        match flag.as_str() {
            "--method" | "--model" => options.method = Some(value),
            "--precision" => match value.as_str() {
                "f32" => options.f32 = true,
                "f64" => options.f32 = false,
                other => return usage(&format!("unknown precision `{other}`")),
            },
            other => return usage(&format!("unknown option `{other}`")),
        }
    }
    let result = match subcommand.as_str() {
        "elliptic" => elliptic::run(&options),
        "eccentricity" => hertz::run_eccentricity(&options),
        "hertz" => hertz::run_hertz(&options),
        "friction" => friction::run(&options),
        other => Err(format!("unknown subcommand `{other}`")),
    };
    result.unwrap_or_else(|message| usage(&message))
}
