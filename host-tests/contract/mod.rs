//! The wrench contract's test set and its direct evaluation by the generic contacts
//! (`Contact`, `VaryingContact` with a law type): the reference for `contensou::dynamic`
//! (host-tests/dynamic.rs) and for `contact_eval wrench` (host-tests/contact_eval.rs).

use contensou::Real;
use contensou::contact::{Contact, Rolling, VaryingContact};
use contensou::dynamic::{Form, Law, Spec, Step};
use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, RollingLaw, RollingVelocity, Table,
};
use contensou::friction::{
    Best, Coulomb, Ellipsoid, Friction, FrictionLaw, Pade, Simplified, Slip,
};
use contensou::geometry::Curvatures;
use contensou::normal::{HuntCrossley, Modulus};
use contensou::shape::Newton;

/// Contacts: a circle, two ellipses (one near the ratio floor), a near-circle; damped and not.
pub fn specs<T: Real>() -> Vec<Spec<T>> {
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

/// Steps: contact loss, touch, two approaches × rest, slide, spin, both, near rest, fast.
pub fn steps<T: Real>() -> Vec<Step<T>> {
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

/// The contract's row as the generic contacts' validated parts (friction law `L`).
type Parts<T, L> = (
    Curvatures<T>,
    Modulus<T>,
    HuntCrossley<T>,
    Friction<T, L>,
    Slip<T>,
);

fn parts<T: Real, L: FrictionLaw>(spec: &Spec<T>, s: &Step<T>) -> Parts<T, L> {
    (
        Curvatures::new(spec.p, spec.q).unwrap(),
        Modulus::new(spec.estar).unwrap(),
        HuntCrossley::new(spec.cd).unwrap(),
        Friction::<T, L>::with_law(spec.f, spec.delta).unwrap(),
        Slip::new(s.vx, s.vy, s.omega).unwrap(),
    )
}

/// The generic contact's output for law `L`, as the contract's seven numbers.
fn generic_of<T: Real, L: FrictionLaw>(spec: &Spec<T>, form: Form, s: &Step<T>) -> [T; 7] {
    let (c, e, d, fr, slip) = parts::<T, L>(spec, s);
    let w = match form {
        Form::Fixed => Contact::hertz::<Newton>(&c, e, d, fr)
            .unwrap()
            .wrench(s.h, s.hdot, slip),
        Form::Varying => VaryingContact::new(e, d, fr).wrench(&c, s.h, s.hdot, slip),
    };
    [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
}

/// The generic rolling contact's output for rolling law `L` with the default rolling columns
/// (G = E*·(1 − 0.3), ν = 0.3, V = 0), as the contract's seven numbers.
fn generic_rolling_of<T: Real, L: RollingLaw>(spec: &Spec<T>, form: Form, s: &Step<T>) -> [T; 7] {
    let (c, e, d, fr, slip) = parts::<T, Best>(spec, s);
    let nu = T::from_f64(0.3);
    let el = Elasticity::new(spec.estar * (T::ONE - nu), nu).unwrap();
    let v = RollingVelocity::ZERO;
    let w = match form {
        Form::Fixed => {
            let contact = Contact::hertz::<Newton>(&c, e, d, fr).unwrap();
            Rolling::<T, _, L>::new(contact, el)
                .unwrap()
                .wrench(s.h, s.hdot, slip, v)
        }
        Form::Varying => Rolling::<T, _, L>::new(VaryingContact::new(e, d, fr), el)
            .unwrap()
            .wrench(&c, s.h, s.hdot, slip, v),
    };
    [w.n, w.fx, w.fy, w.tz, w.patch.a, w.patch.b, w.patch.e2]
}

/// The values' bits (f32 widened exactly), for bit-for-bit comparison.
pub fn bits<T: Real>(v: [T; 7]) -> [u64; 7] {
    v.map(|x| x.to_f64().to_bits())
}

/// The generic contact of `law` (a law type, not the dispatch), as the contract's seven numbers.
pub fn generic<T: Real>(law: Law, spec: &Spec<T>, form: Form, s: &Step<T>) -> [T; 7] {
    match law {
        Law::Best => generic_of::<T, Best>(spec, form, s),
        Law::Simplified => generic_of::<T, Simplified>(spec, form, s),
        Law::Pade => generic_of::<T, Pade>(spec, form, s),
        Law::Ellipsoid => generic_of::<T, Ellipsoid>(spec, form, s),
        Law::Coulomb => generic_of::<T, Coulomb>(spec, form, s),
        Law::Table => generic_rolling_of::<T, Table>(spec, form, s),
        Law::Blend => generic_rolling_of::<T, Blend>(spec, form, s),
        Law::Fastsim => generic_rolling_of::<T, Fastsim>(spec, form, s),
        Law::Fastsim16 => generic_rolling_of::<T, FastsimGrid<16, 16>>(spec, form, s),
    }
}

/// Runs the built `contact_eval args…` with `input` on stdin (for the tests of the binary).
#[allow(dead_code)] // not every test of the contract runs the binary
pub fn run_contact_eval(args: &[&str], input: &str) -> std::process::Output {
    use std::io::Write;
    use std::process::{Command, Stdio};
    let mut child = Command::new(env!("CARGO_BIN_EXE_contact_eval"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("contact_eval runs");
    // A usage error exits before reading stdin: a broken pipe is part of that outcome.
    let _ = child.stdin.take().unwrap().write_all(input.as_bytes());
    child.wait_with_output().unwrap()
}

/// Runs `contact_eval args…` on `input`, which it must refuse: exit code 1 and exactly
/// `contact_eval: {message}` on stderr (`context` names the case). The output, for more checks.
#[allow(dead_code)] // not every test of the contract runs the binary
pub fn refused(args: &[&str], input: &str, message: &str, context: &str) -> std::process::Output {
    let out = run_contact_eval(args, input);
    assert_eq!(out.status.code(), Some(1), "{context}");
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        format!("contact_eval: {message}\n"),
        "{context}"
    );
    out
}

/// A valid row of the wrench contract (the columns of `contensou::dynamic::INPUTS`).
#[allow(dead_code)] // not every test of the contract runs the binary
pub const GOOD: &str = "10,400,1.15e11,0.3,0.2,1e-4,2e-6,0.01,-3e-3,2e-3,25";

/// Each `(bad, message)` row after the `good` one (under `header`) is refused by every
/// subcommand in `subs`: exit code 1 and `row 2: message` on stderr.
#[allow(dead_code)] // not every test of the contract checks refusals this way
pub fn refuses_after_good(subs: &[&str], header: &str, good: &str, bad_rows: &[(&str, &str)]) {
    for (bad, message) in bad_rows {
        let input = format!("{header}\n{good}\n{bad}\n");
        for sub in subs {
            let context = format!("{sub} {bad}");
            refused(&[sub], &input, &format!("row 2: {message}"), &context);
        }
    }
}

/// The stdout of a successful `contact_eval args…` run on `input` (a failure shows `args` and
/// the stderr).
#[allow(dead_code)] // not every test of the contract runs the binary
pub fn stdout_of(args: &[&str], input: &str) -> String {
    let out = run_contact_eval(args, input);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{args:?}: {stderr}");
    String::from_utf8(out.stdout).unwrap()
}

/// [`stdout_of`] `contact_eval sub --law … --form … --precision …`.
#[allow(dead_code)] // not every test of the contract runs the binary
pub fn stdout_with(sub: &str, law: Law, form: Form, precision: &str, input: &str) -> String {
    let (law, form) = (law.name(), form.name());
    stdout_of(
        &[sub, "--law", law, "--form", form, "--precision", precision],
        input,
    )
}

/// `contact_eval sub` on `input` for every law × form in precision `T`: the header line is
/// `header`, then exactly `rows` lines, each checked by `check(law, form, i, fields, line)`
/// with its fields parsed as `T`.
#[allow(dead_code)] // not every test of the contract runs the binary
pub fn each_law_form<T: Real>(
    sub: &str,
    input: &str,
    header: &str,
    rows: usize,
    mut check: impl FnMut(Law, Form, usize, &[T], &str),
) {
    for law in Law::ALL {
        for form in Form::ALL {
            let stdout = stdout_with(sub, law, form, T::NAME, input);
            let mut lines = stdout.lines();
            assert_eq!(lines.next(), Some(header), "{sub} {law:?} {form:?}");
            let mut n = 0;
            for (i, line) in lines.by_ref().take(rows).enumerate() {
                let got: Vec<T> = line.split(',').map(|f| f.parse().ok().unwrap()).collect();
                check(law, form, i, &got, line);
                n += 1;
            }
            assert_eq!((n, lines.next()), (rows, None), "{sub} {law:?} {form:?}");
        }
    }
}
