//! The complete elliptic integrals' mpmath reference (tools/data/elliptic_ref.csv, written by
//! tools/gen_elliptic_ref.py at 60 digits), read by the test host-tests/elliptic.rs and the
//! example examples/ke_table.rs (`#[path = …] mod elliptic_ref;`), and its error measure.
#![allow(dead_code)]

use contensou::Real;
use contensou::elliptic::{Integrals, Parameter};

/// One reference row: m and m₁ = 1 − m (each exact in f64), and K, E, B, D.
pub struct Row {
    pub m: f64,
    pub m1: f64,
    pub want: [f64; 4],
}

/// Every row of the reference (its header checked, more than 300 rows).
pub fn reference() -> Vec<Row> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tools/data/elliptic_ref.csv");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("m,m1,K,E,B,D"));
    let rows: Vec<Row> = lines
        .map(|l| {
            let f: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            Row {
                m: f[0],
                m1: f[1],
                want: [f[2], f[3], f[4], f[5]],
            }
        })
        .collect();
    assert!(rows.len() > 300);
    rows
}

/// The parameter a careful caller builds (from m up to ½, from m₁ above), if that input is
/// exact in `T` and in `T`'s domain.
pub fn param<T: Real>(r: &Row) -> Option<Parameter<T>> {
    let (x, from_m) = if r.m <= 0.5 {
        (r.m, true)
    } else {
        (r.m1, false)
    };
    let t = T::from_f64(x);
    if t.to_f64() != x {
        return None;
    }
    if from_m {
        Parameter::new(t).ok()
    } else {
        Parameter::from_complement(t).ok()
    }
}

/// K, E, B, D widened to f64.
pub fn values<T: Real>(i: Integrals<T>) -> [f64; 4] {
    [i.k.to_f64(), i.e.to_f64(), i.b.to_f64(), i.d.to_f64()]
}

/// Max relative error of K, E, B, D over the rows `eval` accepts (each value finite), the m
/// where each occurs, and the row count.
pub fn max_errors(
    rows: &[Row],
    eval: impl Fn(&Row) -> Option<[f64; 4]>,
) -> ([f64; 4], [f64; 4], usize) {
    let mut worst = [0.0f64; 4];
    let mut at = [0.0f64; 4];
    let mut n = 0;
    for r in rows {
        let Some(got) = eval(r) else { continue };
        n += 1;
        for j in 0..4 {
            assert!(got[j].is_finite(), "non-finite at m = {}", r.m);
            let err = ((got[j] - r.want[j]) / r.want[j]).abs();
            if err > worst[j] {
                worst[j] = err;
                at[j] = r.m;
            }
        }
    }
    (worst, at, n)
}
