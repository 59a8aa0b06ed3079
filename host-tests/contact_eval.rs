//! `contact_eval` (the built binary): `wrench` agrees bit for bit with direct calls of the
//! generic contacts for every law × form × precision, refuses bad rows with
//! `row K: name = value: reason` and a nonzero exit, skips blank lines; `--help` exits 0.

mod contract;
#[macro_use]
#[path = "common/each.rs"]
mod each;

use std::process::Output;

use contensou::Real;
use contensou::dynamic::{Form, INPUTS, Law, OUTPUTS, Spec, Step};
use contensou::friction::rolling::row::RowLaw;

use contract::{
    GOOD, bits, each_law_form, generic, refused, refuses_after_good, specs, stdout_of, steps,
};

/// Runs `contact_eval args…` with `input` on stdin.
fn run(args: &[&str], input: &str) -> Output {
    contract::run_contact_eval(args, input)
}

fn row<T: Real>(spec: &Spec<T>, s: &Step<T>) -> [T; 11] {
    [
        spec.p, spec.q, spec.estar, spec.cd, spec.f, spec.delta, s.h, s.hdot, s.vx, s.vy, s.omega,
    ]
}

fn wrench_matches_the_generic_contacts<T: Real>() {
    let precision = T::NAME;
    // Inputs printed with Rust's shortest round-trip Display: the binary parses the same values.
    let mut input = format!("{}\n", INPUTS.join(","));
    let mut want = Vec::new();
    for spec in specs::<T>() {
        for s in steps::<T>() {
            let r = row(&spec, &s);
            let text: Vec<String> = r.iter().map(|v| v.to_string()).collect();
            input += &text.join(",");
            input += "\n";
            want.push((r, spec, s));
        }
        input += "\n"; // blank lines are skipped
    }
    let header = format!("{},{}", INPUTS.join(","), OUTPUTS.join(","));
    each_law_form::<T>(
        "wrench",
        &input,
        &header,
        want.len(),
        |law, form, i, got, line| {
            let (r, spec, s) = &want[i];
            assert_eq!(got.len(), 18, "{line}");
            let echo = |v: &[T]| v.iter().map(|x| x.to_f64().to_bits()).collect::<Vec<_>>();
            assert_eq!(echo(&got[..11]), echo(r), "{line}");
            let expect = generic(law, spec, form, s);
            assert_eq!(
                bits::<T>(got[11..].try_into().unwrap()),
                bits(expect),
                "{law:?} {form:?} {precision}: {line}"
            );
        },
    );
}

#[test]
fn wrench_is_bit_identical_to_the_library() {
    each!(wrench_matches_the_generic_contacts, [f64, f32]);
}

/// A two-row input whose second row (row 3: a blank line sits before it) is `bad`; the run
/// must print row 1 only, fail, and say exactly `message`.
fn refuses(bad: &str, message: &str) {
    let input = format!("{}\n{GOOD}\n\n{bad}\n{GOOD}\n", INPUTS.join(","));
    for form in Form::ALL {
        for precision in ["f32", "f64"] {
            let out = refused(
                &["wrench", "--form", form.name(), "--precision", precision],
                &input,
                &format!("row 3: {message}"),
                &format!("{bad} {precision}"),
            );
            assert_eq!(String::from_utf8_lossy(&out.stdout).lines().count(), 2);
        }
    }
}

#[test]
fn wrench_refuses_bad_rows_naming_the_column() {
    let with = |column: &str, value: &str| {
        let i = INPUTS.iter().position(|c| *c == column).unwrap();
        let mut fields: Vec<&str> = GOOD.split(',').collect();
        fields[i] = value;
        fields.join(",")
    };
    for (column, value, reason) in [
        ("P", "x1", "not a number"),
        ("h", "NaN", "not a number (NaN)"),
        (
            "P",
            "500",
            "curvatures must satisfy P <= Q (x is the major axis)",
        ),
        (
            "P",
            "0",
            "curvature must be positive (P and Q, or the sum of the two bodies' curvatures)",
        ),
        (
            "P",
            "0.01",
            "curvature ratio P/Q below the solver's range (g >= 1e-4; volumetric law: g >= 0.5)",
        ),
        ("Q", "inf", "input must be finite"),
        ("estar", "-1", "elastic modulus must be positive"),
        ("cd", "-0.1", "damping coefficient is negative"),
        ("f", "-0.2", "friction coefficient is negative"),
        (
            "delta",
            "-1e-3",
            "regularization speed delta must be >= 0 (m/s; 0 = no regularization)",
        ),
        ("omega", "-inf", "input must be finite"),
    ] {
        refuses(
            &with(column, value),
            &format!("{column} = {value}: {reason}"),
        );
    }
    refuses(
        "1,2,3",
        "fields = 3: expected 11 (P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega)",
    );
}

#[test]
fn usage_errors_name_the_value_and_exit_2() {
    let header = format!("{}\n", INPUTS.join(","));
    for (args, message) in [
        (
            &["wrench", "--law", "exact"][..],
            "--law = exact: unknown (one of best, simplified, pade, ellipsoid, coulomb, table, blend, fastsim, fastsim-16)",
        ),
        (
            &["wrench", "--form", "x"],
            "--form = x: unknown (one of fixed, varying)",
        ),
        (
            &["wrench", "--precision", "f16"],
            "--precision = f16: must be f32 or f64",
        ),
        (
            &["wrench", "--model", "best"],
            "--model = best: unknown option for this subcommand",
        ),
        (
            &["nope"],
            "subcommand = nope: unknown (one of wrench, elliptic, eccentricity, hertz, friction, rolling, jacobian, step)",
        ),
    ] {
        let out = run(args, &header);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(
            stderr.lines().next(),
            Some(&*format!("contact_eval: {message}"))
        );
    }
    let out = run(&["wrench"], "P,Q\n");
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with(
        "contact_eval: header = P,Q: must be `P,Q,estar,cd,f,delta,h,hdot,vx,vy,omega`"
    ));
}

#[test]
fn help_lists_every_model_and_exits_0() {
    let top = run(&["--help"], "");
    assert!(top.status.success());
    let text = String::from_utf8(top.stdout).unwrap();
    for name in [
        "wrench",
        "elliptic",
        "eccentricity",
        "hertz",
        "friction",
        "best-varying",
        "rolling",
        "table",
        "blend",
        "fastsim-16",
    ] {
        assert!(text.contains(name), "{name} missing from --help");
    }
    for law in Law::ALL {
        assert!(text.contains(law.name()));
    }
    for sub in [
        "wrench",
        "elliptic",
        "eccentricity",
        "hertz",
        "friction",
        "rolling",
    ] {
        for flag in ["--help", "-h"] {
            let out = run(&[sub, flag], "");
            assert!(out.status.success(), "{sub} {flag}");
            assert!(
                String::from_utf8_lossy(&out.stdout)
                    .starts_with(&format!("usage: contact_eval {sub}"))
            );
        }
    }
}

#[test]
fn floats_print_in_shortest_form() {
    let input = format!("{}\n{GOOD}\n", INPUTS.join(","));
    let out = run(&["wrench"], &input);
    let stdout = String::from_utf8(out.stdout).unwrap();
    let line = stdout.lines().nth(1).unwrap();
    assert!(
        line.starts_with("10,400,1.15e11,0.3,0.2,1e-4,2e-6,0.01,-3e-3,2e-3,25,"),
        "{line}"
    );
}

/// `rolling` rows (a, b, G, ν, f, N, V, ξ, η, φ): shapes on both sides of the circle, from
/// tiny creepage to full slip, spin, V < 0 and V = 0.
const ROLLING: [[f64; 10]; 6] = [
    [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-4, 0.0, 0.0],
    [2e-3, 5e-3, 8e10, 0.25, 0.3, 5e3, 10.0, -2e-3, 1e-3, 0.5],
    [1e-4, 1e-4, 1e9, 0.5, 0.5, 1.0, -1.0, 1e-2, -3e-3, 40.0],
    [3e-3, 3e-4, 8e10, 0.0, 0.2, 1e3, 0.0, 0.3, 0.2, -100.0],
    [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 0.0, 0.0, 0.0],
    [6e-3, 4e-3, 8e10, 0.28, 0.0, 8e4, 30.0, 1e-3, 0.0, 1.0],
];

fn rolling_direct<T: Real, L: contensou::friction::rolling::RollingLaw>(r: [T; 10]) -> [T; 3] {
    use contensou::friction::rolling::{Elasticity, Patch, RollingContact, RollingSlip};
    let el = Elasticity::new(r[2], r[3]).unwrap();
    let c = RollingContact::new(r[0] / r[1], el).unwrap();
    let p = Patch::new(r[0], r[1], r[5], r[4]).unwrap();
    let v = if r[6] == T::ZERO { T::ONE } else { r[6] };
    let s = RollingSlip::from_creepages(r[7], r[8], r[9], v).unwrap();
    let w = c.wrench::<L>(&p, &s);
    [w.fx, w.fy, w.mz]
}

fn rolling_matches_the_library<T: Real>() {
    let precision = T::NAME;
    use contensou::friction::rolling::{Blend, Fastsim, FastsimGrid, FullSlip, Linear, Table};
    let rows: Vec<[T; 10]> = ROLLING.iter().map(|r| r.map(T::from_f64)).collect();
    let mut input = "a,b,G,nu,f,N,V,xi,eta,phi\n".to_string();
    for r in &rows {
        input += &r
            .iter()
            .map(|v| v.to_string())
            .collect::<Vec<_>>()
            .join(",");
        input += "\n";
    }
    type Direct<T> = fn([T; 10]) -> [T; 3];
    let laws: [(&str, Direct<T>); 6] = [
        ("table", rolling_direct::<T, Table>),
        ("blend", rolling_direct::<T, Blend>),
        ("fastsim", rolling_direct::<T, Fastsim>),
        ("fastsim-16", rolling_direct::<T, FastsimGrid<16, 16>>),
        ("full-slip", rolling_direct::<T, FullSlip>),
        ("linear", rolling_direct::<T, Linear>),
    ];
    for (name, direct) in laws {
        let stdout = stdout_of(
            &["rolling", "--law", name, "--precision", precision],
            &input,
        );
        let mut lines = stdout.lines();
        assert_eq!(lines.next().unwrap(), "a,b,G,nu,f,N,V,xi,eta,phi,Fx,Fy,Mz");
        for (line, r) in lines.zip(&rows) {
            let got: Vec<T> = line.split(',').map(|f| f.parse().ok().unwrap()).collect();
            let want = direct(*r);
            let b = |v: &[T]| v.iter().map(|x| x.to_f64().to_bits()).collect::<Vec<_>>();
            assert_eq!(b(&got[10..]), b(&want), "{name} {precision}: {line}");
        }
    }
    // the default law is table
    let out = run(&["rolling", "--precision", precision], &input);
    let first = String::from_utf8(out.stdout).unwrap();
    let blend = run(
        &["rolling", "--law", "table", "--precision", precision],
        &input,
    );
    assert_eq!(first, String::from_utf8(blend.stdout).unwrap());
    // `--law rolling` names the default rolling law (the library's RowLaw::DEFAULT)
    let alias = run(
        &["rolling", "--law", "rolling", "--precision", precision],
        &input,
    );
    assert!(alias.status.success());
    assert_eq!(first, String::from_utf8(alias.stdout).unwrap());
}

#[test]
fn rolling_is_bit_identical_to_the_library() {
    each!(rolling_matches_the_library, [f64, f32]);
}

#[test]
fn rolling_refuses_bad_rows_naming_the_column() {
    let good = "6e-3,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0,0";
    let header = "a,b,G,nu,f,N,V,xi,eta,phi";
    refuses_after_good(
        &["rolling"],
        header,
        good,
        &[
            (
                "6e-3,4e-3,0,0.28,0.3,8e4,30,1e-3,0,0",
                "G = 0: shear modulus G must be positive (Pa)",
            ),
            (
                "6e-3,4e-3,8e10,0.6,0.3,8e4,30,1e-3,0,0",
                "nu = 0.6: Poisson's ratio of a rolling contact outside [0, 0.5] (Kalker's table)",
            ),
            (
                "0,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0,0",
                "a = 0: length must be positive",
            ),
            (
                "6e-3,4e-3,8e10,0.28,-0.3,8e4,30,1e-3,0,0",
                "f = -0.3: friction coefficient is negative",
            ),
            (
                "1,4e-3,8e10,0.28,0.3,8e4,30,1e-3,0,0",
                "a/b = 250: semi-axis ratio a/b of a rolling contact outside [0.01, 100]",
            ),
        ],
    );
}

/// The optional rolling columns: echoed, read by the rolling laws bit for bit as
/// `dynamic::wrench_rolling`, ignored by the sliding laws (same bits as without them); a bad
/// value names its column; an unknown or repeated extra column is a header error.
#[test]
fn wrench_takes_the_optional_rolling_columns() {
    use contensou::dynamic::{RollingSpec, RollingStep, wrench_rolling};
    let base = "25,100,1.15e11,0,0.3,1e-4,2e-6,0,0.003,-0.001,20";
    let input = format!("{},vry,G,vrx\n{base},2,8e10,1.5\n", INPUTS.join(","));
    let spec = Spec {
        p: 25.0,
        q: 100.0,
        estar: 1.15e11,
        cd: 0.0,
        f: 0.3,
        delta: 1e-4,
    };
    let step = Step {
        h: 2e-6,
        hdot: 0.0,
        vx: 0.003,
        vy: -0.001,
        omega: 20.0,
    };
    for law in Law::ALL {
        let out = run(
            &["wrench", "--law", law.name(), "--precision", "f64"],
            &input,
        );
        assert_eq!(out.status.code(), Some(0), "{law:?}");
        let text = String::from_utf8(out.stdout).unwrap();
        let mut lines = text.lines();
        assert_eq!(
            lines.next().unwrap(),
            format!("{},vry,G,vrx,{}", INPUTS.join(","), OUTPUTS.join(","))
        );
        let fields: Vec<f64> = lines
            .next()
            .unwrap()
            .split(',')
            .map(|f| f.parse().unwrap())
            .collect();
        let want = wrench_rolling(
            &spec,
            &RollingSpec {
                g: Some(8e10),
                nu: None,
            },
            law,
            Form::Fixed,
            &step,
            &RollingStep { vrx: 1.5, vry: 2.0 },
        )
        .unwrap()
        .to_array();
        assert_eq!(
            bits(fields[14..].try_into().unwrap()),
            bits(want),
            "{law:?}"
        );
    }
    // `--law rolling` is the default rolling law, bit for bit
    let default = RowLaw::DEFAULT.name();
    let [by_alias, by_name] = ["rolling", default].map(|law| {
        let out = run(&["wrench", "--law", law, "--precision", "f64"], &input);
        assert_eq!(out.status.code(), Some(0), "{law}");
        out.stdout
    });
    assert_eq!(by_alias, by_name);
    let bad = format!("{},nu\n{base},0.7\n", INPUTS.join(","));
    let out = run(&["wrench", "--law", "table"], &bad);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).lines().next(),
        Some(
            "contact_eval: row 1: nu = 0.7: Poisson's ratio of a rolling contact outside [0, 0.5] (Kalker's table)"
        )
    );
    for header in ["vrx,vrx", "speed"] {
        let out = run(&["wrench"], &format!("{},{header}\n", INPUTS.join(",")));
        assert_eq!(out.status.code(), Some(1), "{header}");
    }
}
