//! `contact_eval step` (the built binary): bit for bit the library's step contract
//! ([`contensou::step::contract::step_row`]) for every law, both forms and precisions, with and
//! without the optional free velocity; a bad `dt` or W is refused naming the column; `--help`.

use contensou::Real;
use contensou::dynamic::{DynContact, Form, INPUTS, Law, RollingSpec, RollingStep, from_inputs};
use contensou::step::contract::{FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS, step_row};

#[allow(dead_code)] // the binary's runners only
mod contract;
use contract::{run_contact_eval as run, stdout_with};

/// A 20 mm steel ball on a plane (W = diag(1/m, 3.5/m, 3.5/m, 1/I)), in a few start states.
const ROWS: [&str; 4] = [
    "50,50,1.15e11,0,0.1,1e-4,7.6e-8,0,0.5,0,0,1e-3,30.609,0,0,0,107.13,0,0,107.13,0,7.6522e5",
    "50,50,1.15e11,0.3,0.2,1e-4,2e-7,1e-3,0.01,-0.02,30,2e-3,30.609,0,0,0,107.13,0,0,107.13,0,7.6522e5",
    "25,100,1.15e11,0,0.1,1e-5,1e-7,0,1e-5,2e-5,0.5,5e-3,30.609,1,0,0,107.13,2,0,107.13,0,7.6522e5",
    "50,50,1.15e11,0,0.1,1e-4,-1e-7,0,0.5,0,0,1e-3,30.609,0,0,0,107.13,0,0,107.13,0,7.6522e5",
];

fn parse<T: Real>(s: &str) -> Vec<T> {
    s.split(',').map(|x| x.parse::<T>().ok().unwrap()).collect()
}

fn library<T: Real>(law: Law, form: Form, r: &[T], u_free: [Option<T>; 4]) -> [T; 4] {
    let (spec, step) = from_inputs(core::array::from_fn(|i| r[i]));
    let c = DynContact::new_rolling(&spec, &RollingSpec::default(), law, form).unwrap();
    let mut w = [T::ZERO; 10];
    w.copy_from_slice(&r[12..22]);
    step_row(&c, &step, &RollingStep::default(), r[11], w, u_free).unwrap()
}

fn header() -> String {
    let columns: Vec<&str> = INPUTS.iter().chain(&STEP_INPUTS).copied().collect();
    columns.join(",")
}

fn matches<T: Real>(precision: &str) {
    let header = header();
    for law in Law::ALL {
        for form in Form::ALL {
            // without, then with the free velocity (gravity on v_n)
            for free in [false, true] {
                let mut input = header.clone();
                if free {
                    input += &format!(",{}", FREE_INPUTS[0]);
                }
                input += "\n";
                for r in ROWS {
                    input += r;
                    if free {
                        input += ",-9.81e-3";
                    }
                    input += "\n";
                }
                let text = stdout_with("step", law, form, precision, &input);
                let mut lines = text.lines();
                assert!(lines.next().unwrap().ends_with(&STEP_OUTPUTS.join(",")));
                for (r, line) in ROWS.iter().zip(lines) {
                    let vals: Vec<T> = parse(line);
                    let n_in = vals.len() - 4;
                    let got = &vals[n_in..];
                    let u = [
                        if free {
                            Some(T::from_f64(-9.81e-3))
                        } else {
                            None
                        },
                        None,
                        None,
                        None,
                    ];
                    let want = library::<T>(law, form, &parse::<T>(r), u);
                    for k in 0..4 {
                        assert_eq!(
                            got[k].to_f64().to_bits(),
                            want[k].to_f64().to_bits(),
                            "{law:?} {form:?} {r}: {k}"
                        );
                    }
                    assert!(got[0] >= T::ZERO);
                }
            }
        }
    }
}

#[test]
fn step_is_bit_identical_to_the_library_f64() {
    matches::<f64>("f64");
}

#[test]
fn step_is_bit_identical_to_the_library_f32() {
    matches::<f32>("f32");
}

#[test]
fn step_refuses_a_bad_step_or_w_naming_the_column() {
    let header = header();
    let good = ROWS[0];
    let fields: Vec<&str> = good.split(',').collect();
    for (col, value, reason) in [
        (11, "0", "dt = 0: time step dt must be > 0"),
        (11, "-1e-3", "dt = -1e-3: time step dt must be > 0"),
        (11, "inf", "dt = inf: input must be finite"),
        (
            13,
            "100",
            "W = ?: inverse-mass matrix W is not positive semidefinite",
        ),
        (
            12,
            "-1",
            "W = ?: inverse-mass matrix W is not positive semidefinite",
        ),
    ] {
        let mut f = fields.clone();
        f[col] = value;
        let out = run(&["step"], &format!("{header}\n{}\n", f.join(",")));
        assert_eq!(out.status.code(), Some(1), "{value}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(&format!("row 1: {reason}")), "{err}");
    }
    let out = run(&["step", "--help"], "");
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("usage: contact_eval step"));
}
