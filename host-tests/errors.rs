//! The guide's "Errors" tables (docs/guide/src/conventions.md and the time-stepping chapter's):
//! together they list every `Error` variant of src/error.rs, and each variant is produced by the
//! inputs the table names, in `f32` and `f64` (the step-aware wrench's in
//! host-tests/step_wrench.rs).

use contensou::batch::{BatchReal, Steps, Wrenches};
use contensou::elliptic::Parameter;
use contensou::friction::{Friction, Simplified, Slip, SlipState};
use contensou::geometry::{Curvatures, Principal, Race};
use contensou::normal::{
    CompressionDamping, Fitted, Hertz, HuntCrossley, Material, Modulus, Undamped,
};
use contensou::shape::{Newton, Ratio};
use contensou::{Error, Real, contact::Contact};

/// Variant names declared in src/error.rs (`    Name,` or `    Name(…),` inside the enum).
fn declared() -> Vec<String> {
    let src = include_str!("../src/error.rs");
    let body = src
        .split("pub enum Error {")
        .nth(1)
        .unwrap()
        .split("\n}")
        .next()
        .unwrap();
    body.lines()
        .map(str::trim)
        .filter(|l| l.chars().next().is_some_and(|c| c.is_ascii_uppercase()))
        .map(|l| l.split([',', '(']).next().unwrap().to_string())
        .collect()
}

/// Variant names in the first column of an "## Errors" table of a markdown file.
fn table(text: &str) -> Vec<String> {
    let section = text
        .split("## Errors")
        .nth(1)
        .unwrap()
        .split("\n## ")
        .next()
        .unwrap();
    section
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l[3..].split(['`', '(']).next().unwrap().to_string())
        .collect()
}

/// Variant names in the Errors tables: the conventions chapter's, then the time-stepping guide chapter's
/// (the step-aware wrench's validation errors).
fn documented() -> Vec<String> {
    let mut names = table(include_str!("../docs/guide/src/conventions.md"));
    names.extend(table(include_str!("../docs/guide/src/time-stepping.md")));
    names
}

#[test]
fn guide_table_lists_every_variant() {
    let (d, r) = (declared(), documented());
    assert_eq!(d.len(), 21, "variants parsed from src/error.rs: {d:?}");
    assert_eq!(d, r, "src/error.rs vs the guide's Errors tables");
}

fn nonfinite<V: std::fmt::Debug>(r: Result<V, Error>, name: &'static str) {
    assert_eq!(r.unwrap_err(), Error::NonFinite(name));
}

fn each_variant<T: Real>() {
    let x = T::from_f64;
    let nan = x(f64::NAN);
    let inf = x(f64::INFINITY);
    // NonFinite(name): the names the table quotes, and a few more.
    nonfinite(Parameter::new(nan), "m");
    nonfinite(Parameter::from_complement(inf), "m1");
    nonfinite(Slip::new(nan, x(0.0), x(0.0)), "v_Px");
    nonfinite(Slip::new(x(0.0), x(0.0), -inf), "omega");
    nonfinite(Friction::<T, Simplified>::with_law(nan, x(0.0)), "f");
    nonfinite(Friction::<T, Simplified>::with_law(x(0.1), inf), "delta");
    nonfinite(SlipState::new(x(1.0), x(0.0), nan, x(0.0)), "a_omega");
    nonfinite(Curvatures::new(x(1.0), nan), "Q");
    nonfinite(Modulus::new(inf), "E*");
    nonfinite(Ratio::new(nan), "g");

    // EllipticParameterOutOfDomain: m < 0, 1 − m below m₁_min, m₁ outside [m₁_min, 1].
    let min = Parameter::<T>::min_complement().to_f64();
    for m in [-1e-30, -1.0, 1.0, 1.0 - min / 4.0, 2.0] {
        assert_eq!(
            Parameter::new(x(m)),
            Err(Error::EllipticParameterOutOfDomain),
            "m = {m}"
        );
    }
    for m1 in [0.0, min / 2.0, 1.0 + 1e-6, -1.0] {
        assert_eq!(
            Parameter::from_complement(x(m1)),
            Err(Error::EllipticParameterOutOfDomain),
            "m1 = {m1}"
        );
    }
    assert!(Parameter::new(x(1.0 - 2.0 * min)).is_ok());
    assert!(Parameter::from_complement(x(min)).is_ok());

    // CurvatureNotPositive: min(p, q) ≤ 0; a ball larger than its concave seat; a ball not
    // fitting the groove; an inner race made concave; two bodies not convex towards each other.
    let cnp = Err(Error::CurvatureNotPositive);
    assert_eq!(Curvatures::new(x(0.0), x(1.0)), cnp);
    assert_eq!(Curvatures::new(x(2.0), x(-1.0)), cnp);
    assert_eq!(Curvatures::sphere_sphere(x(0.01), x(-0.005)), cnp);
    assert_eq!(
        Curvatures::ball_race(x(0.0127), x(0.006), x(0.065), x(0.0), Race::Outer),
        cnp
    );
    assert_eq!(
        Curvatures::ball_race(x(0.0127), x(0.0066), x(0.01), x(0.0), Race::Inner),
        cnp
    );
    let flat = Principal::plane();
    let cup = Principal {
        k1: x(-1.0),
        k2: x(-1.0),
    };
    assert_eq!(Curvatures::from_bodies(flat, cup, x(0.0)), cnp);

    // CurvatureRatioOutOfRange: g = P/Q < 1e-4, or Ratio::new outside [1e-4, 1].
    let thin = Curvatures::new(x(1e-5), x(1.0)).unwrap();
    let e = Modulus::new(x(1e11)).unwrap();
    let crr = Error::CurvatureRatioOutOfRange;
    assert_eq!(Ratio::of(&thin).unwrap_err(), crr);
    assert_eq!(Hertz::new::<Newton>(&thin, e).unwrap_err(), crr);
    assert_eq!(Fitted::new(&thin, e).unwrap_err(), crr);
    let fr = Friction::<T, Simplified>::with_law(x(0.1), x(0.0)).unwrap();
    assert_eq!(
        Contact::hertz::<Newton>(&thin, e, Undamped, fr).unwrap_err(),
        crr
    );
    for g in [0.0, 9.9e-5, 1.0001, -0.5] {
        assert_eq!(Ratio::new(x(g)).unwrap_err(), crr, "g = {g}");
    }

    // ModulusNotPositive: E ≤ 0, E* ≤ 0, Modulus::of under/overflowing.
    let mnp = Error::ModulusNotPositive;
    assert_eq!(Material::new(x(0.0), x(0.3)).unwrap_err(), mnp);
    assert_eq!(Material::new(x(-2e11), x(0.3)).unwrap_err(), mnp);
    assert_eq!(Modulus::new(x(-0.0)).unwrap_err(), mnp);
    let tiny = if T::MANTISSA_DIGITS > 24 {
        1e-320
    } else {
        1e-44
    };
    let soft = Material::new(x(tiny), x(0.0)).unwrap();
    assert_eq!(Modulus::of(soft, soft).unwrap_err(), mnp);

    // PoissonRatioOutOfRange: ν outside (−1, 0.5].
    for nu in [-1.0, 0.5000001, 2.0] {
        assert_eq!(
            Material::new(x(2e11), x(nu)).unwrap_err(),
            Error::PoissonRatioOutOfRange
        );
    }
    assert!(Material::new(x(2e11), x(0.5)).is_ok());

    // FrictionCoefficientNegative.
    assert_eq!(
        Friction::<T, Simplified>::with_law(x(-0.1), x(0.0)).unwrap_err(),
        Error::FrictionCoefficientNegative
    );

    // LengthNotPositive: radius/diameter/pitch ≤ 0, a zero signed radius, δ < 0.
    let lnp = Error::LengthNotPositive;
    assert_eq!(Curvatures::sphere_plane(x(0.0)).unwrap_err(), lnp);
    assert_eq!(Curvatures::sphere_plane(x(-1.0)).unwrap_err(), lnp);
    assert_eq!(Curvatures::sphere_sphere(x(0.0), x(1.0)).unwrap_err(), lnp);
    assert_eq!(Principal::sphere(x(0.0)).unwrap_err(), lnp);
    for (d, rg, dm) in [
        (0.0, 0.0066, 0.065),
        (0.0127, -0.0066, 0.065),
        (0.0127, 0.0066, 0.0),
    ] {
        let r = Curvatures::ball_race(x(d), x(rg), x(dm), x(0.0), Race::Inner);
        assert_eq!(r.unwrap_err(), lnp, "ball_race({d}, {rg}, {dm})");
    }
    // RegularizationSpeedNegative: δ < 0 (δ = 0 is allowed).
    assert_eq!(
        Friction::<T, Simplified>::with_law(x(0.1), x(-1e-3)).unwrap_err(),
        Error::RegularizationSpeedNegative
    );
    assert!(Friction::<T, Simplified>::with_law(x(0.1), x(0.0)).is_ok());

    // CurvaturesNotOrdered: `ordered` refuses P > Q (where `new` swaps them).
    assert_eq!(
        Curvatures::ordered(x(2.0), x(1.0)).unwrap_err(),
        Error::CurvaturesNotOrdered
    );
    assert_eq!(Curvatures::ordered(x(0.0), x(1.0)), cnp);
    assert_eq!(
        Curvatures::ordered(x(1.0), x(2.0)),
        Curvatures::new(x(1.0), x(2.0))
    );
    // …but a negative signed radius is a concave body, not an error.
    assert!(Principal::sphere(x(-1.0)).is_ok());

    // DampingNegative.
    assert_eq!(
        HuntCrossley::new(x(-0.1)).unwrap_err(),
        Error::DampingNegative
    );
    assert_eq!(
        CompressionDamping::new(x(-1.0)).unwrap_err(),
        Error::DampingNegative
    );

    // Rolling contacts: G ≤ 0, ν outside [0, 0.5], a/b outside [0.01, 100].
    use contensou::friction::rolling::{Elasticity, RollingContact};
    assert_eq!(
        Elasticity::new(x(0.0), x(0.3)).unwrap_err(),
        Error::ShearModulusNotPositive
    );
    assert_eq!(
        Elasticity::new(x(8e10), x(-0.1)).unwrap_err(),
        Error::RollingPoissonRatioOutOfRange
    );
    let el = Elasticity::new(x(8e10), x(0.3)).unwrap();
    assert_eq!(
        RollingContact::new(x(200.0), el).unwrap_err(),
        Error::RollingAspectOutOfRange
    );
}

/// Every rolling constructor (issue 20 item 7): bad G, ν, a/b, patch, non-finite slip or
/// rolling velocity → the documented variant, naming the input for `NonFinite`; the domain's
/// ends accepted.
fn rolling_errors<T: Real>() {
    use contensou::friction::rolling::{Elasticity, Patch, RollingContact, RollingSlip};
    let x = T::from_f64;
    let (nan, inf) = (x(f64::NAN), x(f64::INFINITY));
    let (g, nu) = (x(8e10), x(0.3));
    // G: ≤ 0 (−0 included) → ShearModulusNotPositive, NaN/±∞ → NonFinite("G"); a tiny G is valid
    for bad in [x(0.0), x(-0.0), x(-1e9), -x(f64::MIN_POSITIVE)] {
        let e = Error::ShearModulusNotPositive;
        assert_eq!(Elasticity::new(bad, nu).unwrap_err(), e);
        assert_eq!(Elasticity::dissimilar(bad, nu, g, nu).unwrap_err(), e);
        assert_eq!(Elasticity::dissimilar(g, nu, bad, nu).unwrap_err(), e);
    }
    assert!(Elasticity::new(T::MIN_POSITIVE, nu).is_ok());
    for bad in [nan, inf, -inf] {
        nonfinite(Elasticity::new(bad, nu), "G");
        nonfinite(Elasticity::dissimilar(g, nu, bad, nu), "G");
        nonfinite(Elasticity::new(g, bad), "nu");
        nonfinite(Elasticity::dissimilar(g, bad, g, nu), "nu");
    }
    // ν outside [0, 0.5] → RollingPoissonRatioOutOfRange; both ends valid
    for bad in [x(-0.01), x(0.5000001), x(1.0), x(-1.0)] {
        let e = Error::RollingPoissonRatioOutOfRange;
        assert_eq!(Elasticity::new(g, bad).unwrap_err(), e);
        assert_eq!(Elasticity::dissimilar(g, nu, g, bad).unwrap_err(), e);
    }
    for ok in [x(0.0), x(0.5)] {
        assert_eq!(Elasticity::new(g, ok).unwrap().nu(), ok);
    }
    // a/b outside [0.01, 100] → RollingAspectOutOfRange, NaN/±∞ → NonFinite("a/b")
    let el = Elasticity::new(g, nu).unwrap();
    for bad in [x(0.0), x(-1.0), x(0.0099), x(100.01), x(1e30)] {
        assert_eq!(
            RollingContact::new(bad, el).unwrap_err(),
            Error::RollingAspectOutOfRange
        );
    }
    for ok in [x(0.01), x(1.0), x(100.0)] {
        assert!(RollingContact::new(ok, el).is_ok());
    }
    for bad in [nan, inf, -inf] {
        nonfinite(RollingContact::new(bad, el), "a/b");
    }
    // patch: a, b ≤ 0 → LengthNotPositive, f < 0 → FrictionCoefficientNegative, names
    let one = x(1.0);
    for (a, b) in [(x(0.0), one), (one, x(-1.0)), (x(-0.0), one)] {
        assert_eq!(
            Patch::new(a, b, one, x(0.3)).unwrap_err(),
            Error::LengthNotPositive
        );
    }
    assert_eq!(
        Patch::new(one, one, one, x(-0.1)).unwrap_err(),
        Error::FrictionCoefficientNegative
    );
    assert!(Patch::new(one, one, x(-5.0), x(0.0)).is_ok()); // N ≤ 0: no contact, not an error
    nonfinite(Patch::new(nan, one, one, one), "a");
    nonfinite(Patch::new(one, inf, one, one), "b");
    nonfinite(Patch::new(one, one, -inf, one), "N");
    nonfinite(Patch::new(one, one, one, nan), "f");
    // rolling slip and velocity: every non-finite input named (V = the rolling velocity)
    let z = x(0.0);
    for bad in [nan, inf, -inf] {
        nonfinite(RollingSlip::new(bad, z, z, one), "v_x");
        nonfinite(RollingSlip::new(z, bad, z, one), "v_y");
        nonfinite(RollingSlip::new(z, z, bad, one), "omega");
        nonfinite(RollingSlip::new(z, z, z, bad), "V");
        nonfinite(RollingSlip::from_creepages(z, z, z, bad), "v_x");
        nonfinite(RollingSlip::from_creepages(z, bad, z, one), "v_y");
    }
    // creepage × V overflowing is non-finite too
    let big = T::MAX.sqrt() * x(2.0);
    nonfinite(RollingSlip::from_creepages(big, z, z, big), "v_x");
    nonfinite(RollingSlip::from_creepages(z, z, big, -big), "omega");
    // V = 0 (full slip) and V < 0 (mirrored) are valid
    assert!(RollingSlip::new(one, z, z, z).is_ok() && RollingSlip::new(one, z, z, -one).is_ok());
}

/// ColumnLengthMismatch: a batch call whose columns differ in length (here `vy`).
fn column_length_mismatch<T: BatchReal>() {
    let x = T::from_f64;
    let sphere = Curvatures::new(x(50.0), x(50.0)).unwrap();
    let fr = Friction::<T, Simplified>::with_law(x(0.1), x(0.0)).unwrap();
    let e = Modulus::new(x(1e11)).unwrap();
    let contact = Contact::hertz::<Newton>(&sphere, e, Undamped, fr).unwrap();
    let (three, two) = ([x(1e-6); 3], [x(0.0); 2]);
    let steps = Steps {
        h: &three,
        hdot: &three,
        vx: &three,
        vy: &two,
        omega: &three,
    };
    let mut o = [[x(0.0); 3]; 7];
    let [n, fx, fy, tz, a, b, e2] = &mut o;
    let mut out = Wrenches {
        n,
        fx,
        fy,
        tz,
        a,
        b,
        e2,
    };
    let err = contact.wrench_many(&steps, &mut out).unwrap_err();
    assert_eq!((err.column, err.error), ("vy", Error::ColumnLengthMismatch));
}

#[test]
fn each_variant_is_produced_by_the_documented_input() {
    each_variant::<f32>();
    each_variant::<f64>();
    rolling_errors::<f32>();
    rolling_errors::<f64>();
    column_length_mismatch::<f32>();
    column_length_mismatch::<f64>();
}

#[test]
fn messages_are_nonempty_and_name_the_input() {
    let e = Parameter::<f64>::new(f64::NAN).unwrap_err();
    assert_eq!(e.to_string(), "m must be finite");
    // `NonFinite("input")` too: its message names the input, "input must be finite".
    for v in Error::ALL {
        assert!(!v.as_str().is_empty() && v.to_string() == v.as_str());
    }
}
