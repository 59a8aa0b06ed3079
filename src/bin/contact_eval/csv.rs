//! The CSV contract shared by every subcommand: header check, row parsing, shortest float
//! output and the "name = value: reason" messages.
use std::fmt::{Display, LowerExp};
use std::io::{BufRead, Write};
use std::process::ExitCode;

use contensou::Real;

/// Evaluate one row: the parsed inputs in, the result columns out, or the message
/// `"name = value: reason"` naming the offending input.
pub type RowFn<'a, T> = dyn FnMut(&[T]) -> Result<Vec<T>, String> + 'a;

/// A float in the shortest form that reads back to the same value: Rust's shortest
/// round-trip digits, positional (`Display`) or with an exponent (`LowerExp`), whichever is
/// shorter (positional on a tie): `1.15e11`, `0.5`, `1e-6`, `inf`, `NaN`.
pub fn shortest<T: Display + LowerExp>(x: T) -> String {
    let plain = x.to_string();
    let exp = format!("{x:e}");
    if exp.len() < plain.len() { exp } else { plain }
}

/// `"name = value: reason"`, the form of every message.
pub fn message(name: &str, value: impl Display, reason: impl Display) -> String {
    format!("{name} = {value}: {reason}")
}

/// The CSV filter: checks the header (exactly `inputs`, in order), then parses, evaluates and
/// prints every row (inputs echoed, then `outputs`). Blank lines are skipped; row K is line
/// K + 1 of the input (blank lines counted, so K locates the line). The first bad row stops
/// the run with `row K: name = value: reason` on stderr and exit code 1.
pub fn run_csv<T: Real + LowerExp>(
    inputs: &[&str],
    outputs: &[&str],
    eval: &mut RowFn<'_, T>,
) -> ExitCode {
    run_csv_optional(inputs, &[], outputs, &mut |r, _| eval(r))
}

/// Evaluate one row with optional columns: the required inputs, then the optional ones by
/// their index in the optional list (`None`: absent from the header).
pub type OptionalRowFn<'a, T> = dyn FnMut(&[T], &[Option<T>]) -> Result<Vec<T>, String> + 'a;

/// [`run_csv`] whose header may add, after `inputs`, any of the `optional` columns (each at
/// most once, in any order); they are echoed as given. With none of them the output is that of
/// [`run_csv`] byte for byte.
pub fn run_csv_optional<T: Real + LowerExp>(
    inputs: &[&str],
    optional: &[&str],
    outputs: &[&str],
    eval: &mut OptionalRowFn<'_, T>,
) -> ExitCode {
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let mut lines = stdin.lock().lines();
    let header = match lines.next() {
        Some(Ok(h)) => h,
        Some(Err(e)) => return fail(&message("header", "?", format!("unreadable: {e}"))),
        None => return fail(&message("header", "(none)", "missing header row")),
    };
    let names: Vec<&str> = header.trim().split(',').map(str::trim).collect();
    // the optional columns of the header, as indices into `optional`
    let extra: Option<Vec<usize>> = names.get(inputs.len()..).and_then(|rest| {
        let idx: Option<Vec<usize>> = rest
            .iter()
            .map(|n| optional.iter().position(|o| o == n))
            .collect();
        idx.filter(|v| (0..v.len()).all(|i| !v[..i].contains(&v[i])))
    });
    let extra = match extra {
        Some(extra) if names.get(..inputs.len()) == Some(inputs) => extra,
        _ => {
            let allowed = if optional.is_empty() {
                format!("must be `{}`", inputs.join(","))
            } else {
                format!(
                    "must be `{}` then any of `{}`",
                    inputs.join(","),
                    optional.join(",")
                )
            };
            return fail(&message("header", header.trim(), allowed));
        }
    };
    if writeln!(out, "{},{}", names.join(","), outputs.join(",")).is_err() {
        return fail("stdout = ?: cannot write output");
    }
    for (index, line) in lines.enumerate() {
        let row = index + 1;
        let line = match line {
            Ok(l) => l,
            Err(e) => return fail_row(row, &message("line", "?", format!("unreadable: {e}"))),
        };
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            return fail_row(
                row,
                &message(
                    "fields",
                    fields.len(),
                    format!("expected {} ({})", names.len(), names.join(",")),
                ),
            );
        }
        let mut values = Vec::with_capacity(fields.len());
        for (name, field) in names.iter().zip(&fields) {
            match field.parse::<T>() {
                // NaN: the one value not ordered against itself.
                Ok(v) if v.partial_cmp(&v).is_none() => {
                    return fail_row(row, &message(name, field, "not a number (NaN)"));
                }
                Ok(v) => values.push(v),
                Err(_) => return fail_row(row, &message(name, field, "not a number")),
            }
        }
        let mut opt = vec![None; optional.len()];
        for (k, &i) in extra.iter().enumerate() {
            if let (Some(slot), Some(&v)) = (opt.get_mut(i), values.get(inputs.len() + k)) {
                *slot = Some(v);
            }
        }
        match eval(values.get(..inputs.len()).unwrap_or(&[]), &opt) {
            Ok(results) => {
                let all: Vec<String> = values
                    .iter()
                    .chain(&results)
                    .map(|&v| shortest(v))
                    .collect();
                if writeln!(out, "{}", all.join(",")).is_err() {
                    return fail("stdout = ?: cannot write output");
                }
            }
            Err(reason) => return fail_row(row, &reason),
        }
    }
    match out.flush() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(&message("stdout", "?", format!("cannot write output: {e}"))),
    }
}

fn fail(text: &str) -> ExitCode {
    eprintln!("contact_eval: {text}");
    ExitCode::from(1)
}

fn fail_row(row: usize, text: &str) -> ExitCode {
    fail(&format!("row {row}: {text}"))
}

#[cfg(test)]
mod tests {
    use super::shortest;

    #[test]
    fn shortest_picks_the_shorter_round_trip_form() {
        assert_eq!(shortest(1.15e11_f64), "1.15e11");
        assert_eq!(shortest(0.5_f64), "0.5");
        assert_eq!(shortest(1e-6_f64), "1e-6");
        assert_eq!(shortest(100.0_f64), "100");
        assert_eq!(shortest(1000.0_f64), "1e3");
        assert_eq!(shortest(123456.0_f64), "123456");
        assert_eq!(shortest(-2.5e-7_f32), "-2.5e-7");
        assert_eq!(shortest(f64::INFINITY), "inf");
        assert_eq!(shortest(0.0_f64), "0");
        for x in [0.1_f64, 1.0 / 3.0, 6.02e23, 5e-324, f64::MAX, -1e-300] {
            assert_eq!(shortest(x).parse::<f64>().unwrap().to_bits(), x.to_bits());
        }
        for x in [0.1_f32, 1.0 / 3.0, 1.15e11, f32::MIN_POSITIVE / 8.0] {
            assert_eq!(shortest(x).parse::<f32>().unwrap().to_bits(), x.to_bits());
        }
    }
}
