//! `contact_eval`: the library as a CSV filter, for scripting and for checking it against other
//! tools (the C API and the Python package mirror its `wrench` subcommand column for column).
//!
//! ```text
//! cargo run --release --bin contact_eval -- <subcommand> [options] < in.csv > out.csv
//! cargo run --release --bin contact_eval -- --help          # every subcommand and model
//! cargo run --release --bin contact_eval -- wrench --help   # one subcommand
//! ```
//!
//! A binary of the package that depends on the library only (no dev-dependency is built).
//! Reads CSV with a header row from stdin and writes CSV with a header row to stdout: the input
//! columns echoed, then the result columns; one output row per input row, in order; blank lines
//! are skipped. Every float is printed in its shortest round-trip form, with an exponent where
//! that is shorter (`1.15e11`, `1e-6`, `0.5`). The header must name exactly the subcommand's
//! input columns, in order. A bad row (wrong field count, a field that is not a number or is
//! NaN, a value outside the method's domain) stops the run with `row K: name = value: reason`
//! on stderr (row K = line K + 1 of the input) and exit code 1. Nothing is dropped or clamped.
//! Usage errors (`name = value: reason` too) exit with 2; `--help` prints usage and exits 0.
//!
//! Each subcommand is a thin shell over the library, in its own file, with its models in one
//! table (the help text is generated from it).

/// A model table: `name => run, "about";` a row (optionally under attributes such as `cfg`),
/// the default first.
macro_rules! models {
    ($($(#[$m:meta])* $name:literal => $run:expr, $about:literal;)*) => {
        &[$($(#[$m])* Model { name: $name, about: $about, run: $run },)*]
    };
}

/// `$body` with the type `$t` the run's precision (`f32` or `f64`).
macro_rules! per_precision {
    ($precision:expr, $t:ident => $body:expr) => {
        match $precision {
            Precision::F32 => {
                type $t = f32;
                $body
            }
            Precision::F64 => {
                type $t = f64;
                $body
            }
        }
    };
}

mod csv;
mod elliptic;
mod friction;
mod hertz;
mod jacobian;
mod rolling;
mod step;
mod wrench;

use std::process::ExitCode;

use contensou::friction::rolling::row::RowLaw;

/// Floating-point precision of a run (`--precision f32|f64`, default f64).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// `f32`.
    F32,
    /// `f64`.
    F64,
}

/// One choice of a subcommand's model option: its name, a one-line description and the run
/// in either precision. The first entry of a table is the default.
pub struct Model {
    /// The option's value.
    pub name: &'static str,
    /// One line for `--help`.
    pub about: &'static str,
    /// Reads stdin, writes stdout.
    pub run: fn(Precision) -> ExitCode,
}

/// The options after the subcommand: `--name value` pairs, consumed by the subcommand.
pub struct Args {
    pairs: Vec<(String, String)>,
    /// `--precision`.
    pub precision: Precision,
}

impl Args {
    /// The value of the first of `names` given, removed from the remaining options.
    pub fn take(&mut self, names: &[&str]) -> Option<String> {
        let i = self
            .pairs
            .iter()
            .position(|(k, _)| names.contains(&k.as_str()))?;
        Some(self.pairs.remove(i).1)
    }

    /// Refuses any option the subcommand did not take.
    pub fn finish(self) -> Result<(), String> {
        match self.pairs.first() {
            Some((k, v)) => Err(csv::message(k, v, "unknown option for this subcommand")),
            None => Ok(()),
        }
    }
}

/// The entry of `all` whose `name` is `value` (`None`: `None`, the caller's default), or the
/// message `option = value: unknown (one of …)`.
pub fn by_name<'a, X>(
    option: &str,
    value: Option<String>,
    all: &'a [X],
    name: impl Fn(&X) -> &str,
) -> Result<Option<&'a X>, String> {
    let Some(value) = value else { return Ok(None) };
    match all.iter().find(|x| name(x) == value) {
        Some(x) => Ok(Some(x)),
        None => {
            let names: Vec<&str> = all.iter().map(name).collect();
            Err(csv::message(
                option,
                &value,
                format!("unknown (one of {})", names.join(", ")),
            ))
        }
    }
}

/// Runs the model of `models` named by the first of `options` given (default: the first
/// model), refusing any other option.
pub fn run_model(models: &[Model], options: &[&str], mut args: Args) -> Result<ExitCode, String> {
    let name = args.take(options);
    let model = by_name(options[0], name, models, |m| m.name)?.unwrap_or(&models[0]);
    let precision = args.precision;
    args.finish()?;
    Ok((model.run)(precision))
}

/// `option` then one line per model, the default marked.
pub fn list_models(option: &str, models: &[Model]) -> String {
    list(option, models.iter().map(|m| (m.name, m.about)))
}

/// `option` then one line per (name, description), the first marked as the default.
pub fn list<'a>(option: &str, entries: impl Iterator<Item = (&'a str, &'a str)>) -> String {
    let mut s = format!("  {option}:\n");
    for (i, (name, about)) in entries.enumerate() {
        let default = if i == 0 { " (default)" } else { "" };
        s += &format!("    {name:<22} {about}{default}\n");
    }
    s
}

/// The `--law` help line of the alias `rolling` ([`RowLaw::ALIAS`]).
pub fn rolling_alias() -> String {
    let about = format!("the default rolling law ({})", RowLaw::DEFAULT.name());
    format!("    {:<22} {about}\n", RowLaw::ALIAS)
}

/// The `--law` value, the alias `rolling` resolved to the default rolling law's name
/// ([`RowLaw::resolve`], the library's one place).
pub fn law_option(args: &mut Args) -> Option<String> {
    args.take(&["--law"])
        .map(|v| RowLaw::resolve(&v).to_owned())
}

/// A subcommand: name, columns, description, help text and run.
struct Subcommand {
    name: &'static str,
    columns: &'static str,
    help: fn() -> String,
    run: fn(Args) -> Result<ExitCode, String>,
}

const SUBCOMMANDS: [Subcommand; 8] = [
    Subcommand {
        name: "wrench",
        columns: "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega -> N,Fx,Fy,Tz,a,b,e2",
        help: wrench::help,
        run: wrench::run,
    },
    Subcommand {
        name: "elliptic",
        columns: "m -> K,E",
        help: elliptic::help,
        run: elliptic::run,
    },
    Subcommand {
        name: "eccentricity",
        columns: "g -> c",
        help: hertz::help_eccentricity,
        run: hertz::run_eccentricity,
    },
    Subcommand {
        name: "hertz",
        columns: "P,Q,Estar,h -> c,a,b,N",
        help: hertz::help_hertz,
        run: hertz::run_hertz,
    },
    Subcommand {
        name: "friction",
        columns: "e2,psi,u -> Fx,Fy,Tz",
        help: friction::help,
        run: friction::run,
    },
    Subcommand {
        name: "rolling",
        columns: "a,b,G,nu,f,N,V,xi,eta,phi -> Fx,Fy,Mz",
        help: rolling::help,
        run: rolling::run,
    },
    Subcommand {
        name: "jacobian",
        columns: "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega -> N,Fx,Fy,Tz,dN_dh,...,dTz_domega",
        help: jacobian::help,
        run: jacobian::run,
    },
    Subcommand {
        name: "step",
        columns: "P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega,dt,w_nn,w_nx,w_ny,w_nw,w_xx,w_xy,w_xw,w_yy,w_yw,w_ww -> N,Fx,Fy,Tz",
        help: step::help,
        run: step::run,
    },
];

const USAGE: &str =
    "usage: contact_eval <subcommand> [options] [--precision f32|f64] < in.csv > out.csv";

const CONTRACT: &str = "\
CSV with a header row on stdin (exactly the input columns, in order); CSV on stdout: the inputs
echoed, then the results, floats in shortest round-trip form. Blank lines are skipped. A bad row
stops the run: `row K: name = value: reason` on stderr (row K = line K + 1), exit 1. Usage
errors exit 2. --precision f32|f64 (default f64) for every subcommand.";

fn top_help() -> String {
    let mut s = format!(
        "contact_eval: the contensou library as a CSV filter\n\n{USAGE}\n       contact_eval <subcommand> --help\n\n{CONTRACT}\n\nsubcommands:\n"
    );
    for c in &SUBCOMMANDS {
        s += &format!("  {:<13} {}\n", c.name, c.columns);
    }
    s += "\n";
    for c in &SUBCOMMANDS {
        s += &format!("{}: {}\n{}\n", c.name, c.columns, (c.help)());
    }
    s
}

fn sub_help(c: &Subcommand) -> String {
    format!(
        "usage: contact_eval {} [options] [--precision f32|f64] < in.csv > out.csv\n\n{}\n\n{}",
        c.name,
        c.columns,
        (c.help)()
    )
}

fn usage_error(text: &str) -> ExitCode {
    eprintln!("contact_eval: {text}");
    eprintln!("{USAGE}  (contact_eval --help for the subcommands and their models)");
    ExitCode::from(2)
}

fn is_help(arg: &str) -> bool {
    arg == "--help" || arg == "-h"
}

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    let Some(first) = argv.first() else {
        return usage_error("subcommand = (none): missing subcommand");
    };
    if is_help(first) || first == "help" {
        print!("{}", top_help());
        return ExitCode::SUCCESS;
    }
    let sub = match by_name("subcommand", Some(first.clone()), &SUBCOMMANDS, |c| c.name) {
        Ok(sub) => sub.unwrap_or(&SUBCOMMANDS[0]),
        Err(message) => return usage_error(&message),
    };
    if argv[1..].iter().any(|a| is_help(a)) {
        print!("{}", sub_help(sub));
        return ExitCode::SUCCESS;
    }
    let mut pairs = Vec::new();
    let mut rest = argv[1..].iter();
    while let Some(flag) = rest.next() {
        if !flag.starts_with("--") {
            return usage_error(&csv::message("argument", flag, "expected an option --name"));
        }
        let Some(value) = rest.next() else {
            return usage_error(&csv::message(flag, "(none)", "needs a value"));
        };
        pairs.push((flag.clone(), value.clone()));
    }
    let mut args = Args {
        pairs,
        precision: Precision::F64,
    };
    match args.take(&["--precision"]).as_deref() {
        None | Some("f64") => {}
        Some("f32") => args.precision = Precision::F32,
        Some(other) => {
            return usage_error(&csv::message("--precision", other, "must be f32 or f64"));
        }
    }
    (sub.run)(args).unwrap_or_else(|m| usage_error(&m))
}
