//! `contensou::dynamic`: the run-time-chosen contact returns exactly (bit for bit) what the
//! generic contact of the same law and form returns, and every bad input names its column.

use contensou::contact::{Contact, VaryingContact};
use contensou::dynamic::{self, DynContact, Form, Invalid, Law, Spec, Step};
use contensou::friction::{
    Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Pade, Simplified, Slip,
};
use contensou::geometry::Curvatures;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::shape::Newton;
use contensou::{Error, Real};

fn specs<T: Real>() -> Vec<Spec<T>> {
    let x = T::from_f64;
    [
        (50.0, 50.0, 0.0),
        (10.0, 400.0, 0.3),
        (1.0, 9000.0, 0.0),
        (120.0, 121.0, 0.05),
    ]
    .into_iter()
    .map(|(p, q, cd)| Spec {
        p: x(p),
        q: x(q),
        estar: x(1.15e11),
        cd: x(cd),
        f: x(0.2),
        delta: x(1e-4),
    })
    .collect()
}

fn steps<T: Real>() -> Vec<Step<T>> {
    let x = T::from_f64;
    let mut v = Vec::new();
    for h in [-1e-7, 0.0, 3e-7, 2e-6] {
        for (vx, vy, omega) in [
            (0.0, 0.0, 0.0),
            (0.01, 0.0, 0.0),
            (0.0, 0.0, 40.0),
            (-3e-3, 2e-3, 25.0),
            (1e-6, -1e-6, 1e-3),
            (2.0, 1.0, -300.0),
        ] {
            v.push(Step {
                h: x(h),
                hdot: x(0.01),
                vx: x(vx),
                vy: x(vy),
                omega: x(omega),
            });
        }
    }
    v
}

/// The generic contact's output for law `L`, as the contract's seven numbers.
fn generic<T: Real, L: FrictionLaw>(spec: &Spec<T>, form: Form, s: &Step<T>) -> [T; 7] {
    let c = Curvatures::new(spec.p, spec.q).unwrap();
    let e = Modulus::new(spec.estar).unwrap();
    let d = HuntCrossley::new(spec.cd).unwrap();
    let fr = Friction::<T, L>::new(spec.f, spec.delta).unwrap();
    let slip = Slip::new(s.vx, s.vy, s.omega).unwrap();
    let w = match form {
        Form::Fixed => Contact::hertz::<Newton>(&c, e, d, fr)
            .unwrap()
            .wrench(s.h, s.hdot, slip),
        Form::Varying => VaryingContact::new(e, d, fr).wrench(&c, s.h, s.hdot, slip),
    };
    [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
}

fn bits<T: Real>(v: [T; 7]) -> [u64; 7] {
    v.map(|x| x.to_f64().to_bits())
}

fn same_as_generic<T: Real>() {
    let mut n = 0;
    for spec in specs::<T>() {
        for form in Form::ALL {
            for law in Law::ALL {
                let dc = DynContact::new(&spec, law, form).unwrap();
                for s in steps::<T>() {
                    let want = match law {
                        Law::Best => generic::<T, Best>(&spec, form, &s),
                        Law::Simplified => generic::<T, Simplified>(&spec, form, &s),
                        Law::Pade => generic::<T, Pade>(&spec, form, &s),
                        Law::Ellipsoid => generic::<T, Ellipsoid>(&spec, form, &s),
                        Law::Coulomb => generic::<T, Coulomb>(&spec, form, &s),
                    };
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
    assert_eq!(n, 4 * 2 * 5 * 24);
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
