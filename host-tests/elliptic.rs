//! Complete elliptic integrals against mpmath references (tools/data/elliptic_ref.csv, written
//! by tools/gen_elliptic_ref.py at 60 digits).
//!
//! Every method × precision is checked on every reference row in its domain: dense near m = 0
//! (down to 1e-12, and exactly 0), uniform over [0, 1], dense near m = 1 (m₁ from the domain
//! edge 1e-12 resp. 2⁻²⁴ up to 0.1, log-spaced, built with `Parameter::from_complement`).
#![allow(clippy::excessive_precision)]

use contensou::Error;
use contensou::elliptic::{Agm, Method, Parameter, Table, Theta, paper_k_e};

#[path = "common/elliptic_ref.rs"]
mod elliptic_ref;
use elliptic_ref::{Row, max_errors, param, reference, values};

/// The f64 parameter of every row.
fn param64(r: &Row) -> Parameter<f64> {
    param(r).unwrap()
}

fn fmt(w: [f64; 4]) -> String {
    w.map(|x| format!("{x:.2e}")).join(" ")
}

/// Method `M`'s worst errors on every row in f64 and on the rows exact in f32 (more than 150),
/// within each precision's bound.
fn check<M: Method>(bound64: f64, bound32: f64) {
    let rows = reference();
    for (precision, (w, at, n), bound) in [
        (
            "f64",
            max_errors(&rows, |r| Some(values(M::integrals(param64(r))))),
            bound64,
        ),
        (
            "f32",
            max_errors(&rows, |r| param::<f32>(r).map(|p| values(M::integrals(p)))),
            bound32,
        ),
    ] {
        println!(
            "{} {precision} ({n} rows): K,E,B,D max rel err {} at m = {at:?}",
            M::NAME,
            fmt(w)
        );
        assert!(n > 150, "too few {precision} rows: {n}");
        for (j, name) in ["K", "E", "B", "D"].iter().enumerate() {
            assert!(
                w[j] <= bound,
                "{} {precision} {name}: {:.3e} at m = {}",
                M::NAME,
                w[j],
                at[j]
            );
        }
    }
}

#[test]
fn agm_accuracy() {
    check::<Agm>(1e-14, 5e-7);
}

#[test]
fn theta_accuracy() {
    check::<Theta>(1e-14, 5e-7);
}

#[test]
fn table_accuracy() {
    check::<Table>(Table::F64_MAX_REL_ERROR, 5e-7);
}

#[test]
fn reference_covers_both_ends_densely() {
    let rows = reference();
    let near0 = rows.iter().filter(|r| r.m > 0.0 && r.m < 1e-3).count();
    let near1 = rows.iter().filter(|r| r.m1 < 1e-3).count();
    assert!(rows.iter().any(|r| r.m == 0.0));
    assert!(
        rows.iter()
            .any(|r| r.m1 == 1e-12 || (r.m1 > 1e-12 && r.m1 < 1.001e-12))
    );
    assert!(rows.iter().any(|r| r.m1 == 2f64.powi(-24)));
    assert!(near0 >= 60 && near1 >= 60, "{near0} {near1}");
    // Dense where the f64 errors peak (m₁ → its floor), so the stated maxima are maxima.
    let edge = rows
        .iter()
        .filter(|r| r.m1 >= 1e-12 && r.m1 <= 1e-9)
        .count();
    assert!(edge >= 1000, "{edge} rows at m1 in [1e-12, 1e-9]");
}

#[test]
fn m_zero_is_exact() {
    for i in [
        Agm::integrals(Parameter::new(0.0f64).unwrap()),
        Theta::integrals(Parameter::new(0.0f64).unwrap()),
    ] {
        let pi = core::f64::consts::PI;
        assert!((i.k - pi / 2.0).abs() <= 2e-16 && (i.e - pi / 2.0).abs() <= 2e-16);
        assert!((i.b - pi / 4.0).abs() <= 2e-16 && (i.d - pi / 4.0).abs() <= 2e-16);
    }
}

/// The paper's unfixed theta form: fine at small m, fails near 1 (documented in `paper_k_e`).
#[test]
fn paper_form_fails_near_one() {
    let rows = reference();
    let err = |r: &Row| {
        let (k, e) = paper_k_e(param64(r));
        ((k - r.want[0]) / r.want[0])
            .abs()
            .max(((e - r.want[1]) / r.want[1]).abs())
    };
    let low = rows
        .iter()
        .filter(|r| r.m <= 0.85)
        .map(err)
        .fold(0.0, f64::max);
    assert!(low <= 1e-14, "{low:e}");
    let high = rows
        .iter()
        .filter(|r| r.m1 < 1e-9)
        .map(err)
        .fold(0.0, f64::max);
    assert!(high > 1e-3, "{high:e}");
}

#[test]
fn parameter_domain_errors() {
    assert_eq!(
        Parameter::new(-1e-300f64),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::new(-0.5f32),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::new(1.0f64),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::new(1.0 - 1e-13f64),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::new(1.0f32 - 2f32.powi(-24)).map(|p| p.m1()),
        Ok(2f32.powi(-24))
    );
    assert_eq!(
        Parameter::from_complement(1e-12f64).map(|p| p.m1()),
        Ok(1e-12)
    );
    assert_eq!(
        Parameter::from_complement(9e-13f64),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::from_complement(1e-8f32),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::from_complement(1.5f64),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(
        Parameter::from_complement(-0.0f64).map(|_| ()),
        Err(Error::EllipticParameterOutOfDomain)
    );
    assert_eq!(Parameter::new(f64::NAN), Err(Error::NonFinite("m")));
    assert_eq!(Parameter::new(f32::INFINITY), Err(Error::NonFinite("m")));
    assert_eq!(
        Parameter::from_complement(f64::NAN),
        Err(Error::NonFinite("m1"))
    );
    // m = -0.0 is m = 0
    assert_eq!(Parameter::new(-0.0f64).map(|p| p.m1()), Ok(1.0));
}
