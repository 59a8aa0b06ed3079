//! `contensou::dynamic`: the run-time-chosen contact returns exactly (bit for bit) what the
//! generic contact of the same law and form returns, and every bad input names its column.

mod contract;

use contensou::contact::Contact;
use contensou::dynamic::{self, DynContact, Form, Invalid, Law, Spec, Step};
use contensou::friction::{Friction, Slip};
use contensou::geometry::Curvatures;
use contensou::normal::Modulus;
use contensou::shape::Newton;
use contensou::{Error, Real};

use contract::{bits, generic, specs, steps};

fn same_as_generic<T: Real>() {
    let mut n = 0;
    for spec in specs::<T>() {
        for form in Form::ALL {
            for law in Law::ALL {
                let dc = DynContact::new(&spec, law, form).unwrap();
                for s in steps::<T>() {
                    let want = generic(law, &spec, form, &s);
                    let got = dc.wrench(&s).unwrap().to_array();
                    assert_eq!(bits(got), bits(want), "{law:?} {form:?} {spec:?} {s:?}");
                    let row = dynamic::wrench(&spec, law, form, &s).unwrap().to_array();
                    assert_eq!(bits(row), bits(want));
                    assert!(got.iter().all(|v| v.is_finite()));
                    n += 1;
                }
            }
        }
    }
    assert_eq!(n, 4 * 2 * Law::ALL.len() * 24);
}

#[test]
fn dispatch_is_bit_identical_to_the_generic_contact() {
    same_as_generic::<f32>();
    same_as_generic::<f64>();
}

#[test]
fn undamped_is_cd_zero_bit_for_bit() {
    use contensou::normal::Undamped;
    let spec = specs::<f64>()[1];
    let c = Curvatures::new(spec.p, spec.q).unwrap();
    let e = Modulus::new(spec.estar).unwrap();
    let fr = Friction::<f64>::new(spec.f, spec.delta).unwrap();
    let undamped = Contact::hertz::<Newton>(&c, e, Undamped, fr).unwrap();
    let dc = DynContact::new(&Spec { cd: 0.0, ..spec }, Law::Best, Form::Fixed).unwrap();
    for s in steps::<f64>() {
        let w = undamped.wrench(s.h, s.hdot, Slip::new(s.vx, s.vy, s.omega).unwrap());
        let want = [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2];
        assert_eq!(bits(dc.wrench(&s).unwrap().to_array()), bits(want));
    }
}

#[test]
fn every_bad_input_names_its_column() {
    let ok = specs::<f64>()[1];
    let bad = |column: &'static str, error: Error| Err::<(), _>(Invalid { column, error });
    let build = |s: Spec<f64>| DynContact::new(&s, Law::Best, Form::Varying).map(|_| ());
    assert_eq!(
        build(Spec { p: f64::NAN, ..ok }),
        bad("P", Error::NonFinite("P"))
    );
    assert_eq!(
        build(Spec {
            q: f64::INFINITY,
            ..ok
        }),
        bad("Q", Error::NonFinite("Q"))
    );
    assert_eq!(
        build(Spec { p: 500.0, ..ok }),
        bad("P", Error::CurvaturesNotOrdered)
    );
    assert_eq!(
        build(Spec { p: 0.0, ..ok }),
        bad("P", Error::CurvatureNotPositive)
    );
    assert_eq!(
        build(Spec { p: 0.01, ..ok }),
        bad("P", Error::CurvatureRatioOutOfRange)
    );
    assert_eq!(
        build(Spec { estar: -1.0, ..ok }),
        bad("estar", Error::ModulusNotPositive)
    );
    assert_eq!(
        build(Spec { cd: -0.1, ..ok }),
        bad("cd", Error::DampingNegative)
    );
    assert_eq!(
        build(Spec { f: -0.1, ..ok }),
        bad("f", Error::FrictionCoefficientNegative)
    );
    assert_eq!(
        build(Spec { f: f64::NAN, ..ok }),
        bad("f", Error::NonFinite("f"))
    );
    assert_eq!(
        build(Spec { delta: -1e-3, ..ok }),
        bad("delta", Error::RegularizationSpeedNegative)
    );
    let dc = DynContact::new(&ok, Law::Simplified, Form::Fixed).unwrap();
    let step = Step {
        h: 1e-6,
        hdot: 0.0,
        vx: 0.0,
        vy: 0.0,
        omega: 1.0,
    };
    for (column, s) in [
        (
            "h",
            Step {
                h: f64::NAN,
                ..step
            },
        ),
        (
            "hdot",
            Step {
                hdot: f64::INFINITY,
                ..step
            },
        ),
        (
            "vx",
            Step {
                vx: f64::NAN,
                ..step
            },
        ),
        (
            "vy",
            Step {
                vy: f64::NEG_INFINITY,
                ..step
            },
        ),
        (
            "omega",
            Step {
                omega: f64::NAN,
                ..step
            },
        ),
    ] {
        let e = dc.wrench(&s).unwrap_err();
        assert_eq!((e.column, e.error), (column, Error::NonFinite(column)));
        assert!(e.to_string().starts_with(&format!("{column}: ")));
    }
}

#[test]
fn set_curvatures_updates_or_rebuilds_and_leaves_the_contact_on_error() {
    let spec = specs::<f64>()[1];
    let step = Step {
        h: 1e-6,
        hdot: 0.0,
        vx: 1e-3,
        vy: 0.0,
        omega: 10.0,
    };
    for form in Form::ALL {
        let mut dc = DynContact::new(&spec, Law::Best, form).unwrap();
        let before = dc;
        assert!(dc.set_curvatures(5.0, 1.0).is_err());
        assert_eq!(dc, before);
        dc.set_curvatures(30.0, 60.0).unwrap();
        let fresh = DynContact::new(
            &Spec {
                p: 30.0,
                q: 60.0,
                ..spec
            },
            Law::Best,
            form,
        )
        .unwrap();
        assert_eq!(dc.wrench(&step), fresh.wrench(&step));
    }
}

#[test]
fn names_round_trip() {
    for l in Law::ALL {
        assert_eq!(Law::from_name(l.name()), Some(l));
    }
    for f in Form::ALL {
        assert_eq!(Form::from_name(f.name()), Some(f));
    }
    assert_eq!(Law::from_name("exact"), None);
    assert_eq!(Law::default(), Law::Best);
}

#[test]
fn rolling_names_the_default_rolling_law() {
    use contensou::friction::rolling::row::RowLaw;
    let law = Law::from_name("rolling").unwrap();
    assert!(law.is_rolling());
    assert_eq!(law.name(), RowLaw::DEFAULT.name());
    assert_eq!(Law::from_name(RowLaw::ALIAS), Some(law));
}
