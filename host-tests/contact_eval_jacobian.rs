//! `contact_eval jacobian` (the built binary): bit for bit [`DynContact::jacobian_rolling`] for
//! every law × form × precision (with and without the rolling columns), its N,Fx,Fy,Tz those
//! of `wrench`; bad rows refused as `wrench` refuses them.

mod contract;
#[macro_use]
#[path = "common/each.rs"]
mod each;

use contensou::Real;
use contensou::dynamic::{DynContact, INPUTS, Law, RollingSpec, RollingStep};
use contensou::jacobian::OUTPUTS;

use contract::{
    GOOD, bits, each_law_form, generic, refuses_after_good, run_contact_eval as run, specs, steps,
};

fn matches_the_library<T: Real>() {
    let precision = T::NAME;
    let x = T::from_f64;
    let velocity = RollingStep {
        vrx: x(1.5),
        vry: x(-0.4),
    };
    let mut input = format!("{},vrx,vry\n", INPUTS.join(","));
    let mut rows = Vec::new();
    for spec in specs::<T>() {
        for s in steps::<T>() {
            let r = [
                spec.p,
                spec.q,
                spec.estar,
                spec.cd,
                spec.f,
                spec.delta,
                s.h,
                s.hdot,
                s.vx,
                s.vy,
                s.omega,
                velocity.vrx,
                velocity.vry,
            ];
            let text: Vec<String> = r.iter().map(|v| v.to_string()).collect();
            input += &(text.join(",") + "\n");
            rows.push((spec, s));
        }
    }
    let header = format!("{},vrx,vry,{}", INPUTS.join(","), OUTPUTS.join(","));
    each_law_form::<T>(
        "jacobian",
        &input,
        &header,
        rows.len(),
        |law, form, i, got, line| {
            let (spec, s) = &rows[i];
            assert_eq!(got.len(), 13 + 24, "{line}");
            let dc = DynContact::new_rolling(spec, &RollingSpec::default(), law, form).unwrap();
            let want = dc.jacobian_rolling(s, &velocity).unwrap().to_array();
            let wrench = dc.wrench_rolling(s, &velocity).unwrap().to_array();
            let raw = |v: &[T]| v.iter().map(|x| x.to_f64().to_bits()).collect::<Vec<_>>();
            assert_eq!(
                raw(&got[13..]),
                raw(&want),
                "{law:?} {form:?} {precision}: {line}"
            );
            assert_eq!(
                raw(&got[13..17]),
                raw(&wrench[..4]),
                "{law:?} {form:?} {precision}: {line}"
            );
            if Law::SLIDING.contains(&law) {
                // the rolling columns are not read: the generic contact's wrench
                let g = bits(generic(law, spec, form, s));
                assert_eq!(
                    raw(&got[13..17]),
                    g[..4].to_vec(),
                    "{law:?} {form:?} {precision}: {line}"
                );
            }
        },
    );
}

#[test]
fn jacobian_is_bit_identical_to_the_library() {
    each!(matches_the_library, [f64, f32]);
}

#[test]
fn jacobian_refuses_bad_rows_as_wrench_does() {
    refuses_after_good(
        &["jacobian", "wrench"],
        &INPUTS.join(","),
        GOOD,
        &[
            (
                "10,400,1.15e11,0.3,0.2,1e-4,NaN,0.01,-3e-3,2e-3,25",
                "h = NaN: not a number (NaN)",
            ),
            (
                "500,400,1.15e11,0.3,0.2,1e-4,2e-6,0.01,-3e-3,2e-3,25",
                "P = 500: curvatures must satisfy P <= Q (x is the major axis)",
            ),
            (
                "10,400,1.15e11,0.3,-0.2,1e-4,2e-6,0.01,-3e-3,2e-3,25",
                "f = -0.2: friction coefficient is negative",
            ),
        ],
    );
    let out = run(&["jacobian", "--help"], "");
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("dTz_domega"));
}
