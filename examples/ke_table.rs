//! Main job (for now): a table of K(m), E(m) by every method, with the relative error against
//! the committed mpmath reference (tools/data/elliptic_ref.csv), then the max relative error of
//! K, E, B, D per method × precision over the whole reference set, beside the `ellip` crate.
//!
//! ```text
//! cargo run --release --example ke_table              # both sections
//! cargo run --release --example ke_table -- --summary # only the max-error table (markdown)
//! ```
//!
//! Near m = 1 every method gets m₁ = 1 − m exactly (`Parameter::from_complement`); `ellip`
//! takes m (exact in f64 for these rows).
use contensou::Real;
use contensou::elliptic::{Agm, Method, Table, Theta, paper_k_e};

#[path = "../host-tests/common/elliptic_ref.rs"]
mod elliptic_ref;
use elliptic_ref::{Row, max_errors, param, reference, values};

fn rel(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

fn ours<T: Real, M: Method>(r: &Row) -> Option<[f64; 4]> {
    param::<T>(r).map(|p| values(M::integrals(p)))
}

/// `ellip` (Boost's piecewise polynomials): K, E and D; B = K − D. m as given (exact here).
macro_rules! ellip_eval {
    ($name:ident, $t:ty) => {
        fn $name(r: &Row) -> Option<[f64; 4]> {
            param::<$t>(r)?;
            let m = r.m as $t;
            let k = ellip::ellipk(m).ok()?;
            let e = ellip::ellipe(m).ok()?;
            let d = ellip::ellipd(m).ok()?;
            Some([k as f64, e as f64, (k - d) as f64, d as f64])
        }
    };
}
ellip_eval!(ellip_f64, f64);
ellip_eval!(ellip_f32, f32);

fn summary(rows: &[Row]) {
    type Eval = fn(&Row) -> Option<[f64; 4]>;
    let lines: [(&str, &str, Eval); 8] = [
        ("agm", "f64", ours::<f64, Agm>),
        ("theta", "f64", ours::<f64, Theta>),
        ("table", "f64", ours::<f64, Table>),
        ("ellip", "f64", ellip_f64),
        ("agm", "f32", ours::<f32, Agm>),
        ("theta", "f32", ours::<f32, Theta>),
        ("table", "f32", ours::<f32, Table>),
        ("ellip", "f32", ellip_f32),
    ];
    println!("| method | precision | rows | K | E | B | D |");
    println!("|---|---|---|---|---|---|---|");
    for (name, prec, eval) in lines {
        let (w, _, n) = max_errors(rows, eval);
        println!(
            "| {name} | {prec} | {n} | {:.1e} | {:.1e} | {:.1e} | {:.1e} |",
            w[0], w[1], w[2], w[3]
        );
    }
    for (prec, cut) in [("f64", 0.87), ("f32", 0.99)] {
        let eval = |r: &Row| -> Option<[f64; 2]> {
            let (k, e) = if prec == "f64" {
                let (k, e) = paper_k_e(param::<f64>(r)?);
                (k, e)
            } else {
                let (k, e) = paper_k_e(param::<f32>(r)?);
                (k as f64, e as f64)
            };
            Some([rel(k, r.want[0]), rel(e, r.want[1])])
        };
        let worst = |keep: &dyn Fn(&Row) -> bool| {
            rows.iter()
                .filter(|r| keep(r))
                .filter_map(&eval)
                .fold(0.0f64, |a, [k, e]| a.max(k).max(e))
        };
        println!(
            "| paper form (K, E only) | {prec} | | m ≤ {cut}: {:.1e} | m = 0.99: {:.1e} | m₁ ≤ 1e-6: {:.1e} | |",
            worst(&|r| r.m <= cut),
            worst(&|r| r.m == 0.99 || (r.m - 0.99).abs() < 1e-7),
            worst(&|r| r.m1 <= 1e-6),
        );
    }
}

fn main() {
    let rows = reference();
    if std::env::args().any(|a| a == "--summary") {
        summary(&rows);
        return;
    }
    println!("K(m), E(m) in f64 by each method; relative error against mpmath (60 digits)\n");
    println!(
        "{:>16} {:>20} {:>20} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8}",
        "m", "K", "E", "agm K", "agm E", "theta K", "theta E", "table K", "table E"
    );
    let picks = [
        0.0,
        1e-6,
        0.1,
        0.3,
        0.5,
        0.7,
        0.9,
        0.99,
        0.999,
        1.0 - 1e-4,
        1.0 - 1e-6,
        1.0 - 1e-9,
        1.0 - 1e-12,
    ];
    for target in picks {
        let Some(r) = rows.iter().min_by(|a, b| {
            let d = |r: &Row| (r.m - target).abs();
            d(a).total_cmp(&d(b))
        }) else {
            continue;
        };
        let Some(p) = param::<f64>(r) else { continue };
        let errs: Vec<String> = [Agm::integrals(p), Theta::integrals(p), Table::integrals(p)]
            .iter()
            .flat_map(|i| [rel(i.k, r.want[0]), rel(i.e, r.want[1])])
            .map(|e| format!("{e:8.1e}"))
            .collect();
        let m = if r.m1 < 1e-3 {
            format!("1-{:.3e}", r.m1)
        } else {
            format!("{:.6}", r.m)
        };
        println!(
            "{m:>16} {:>20.15} {:>20.15} {}",
            r.want[0],
            r.want[1],
            errs.join(" ")
        );
    }
    println!(
        "\nMax relative error over all {} reference rows (f32: rows exact in f32):\n",
        rows.len()
    );
    summary(&rows);
}
