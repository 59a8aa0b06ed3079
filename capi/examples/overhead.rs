//! The cost of the C boundary on the host, in instructions (run by `tests/overhead.sh` under
//! valgrind's callgrind, which counts the instructions inside `contensou_contact_wrench_*`
//! and inside `rust_step_*`, the direct `DynContact::wrench` call): every law × form ×
//! precision over the same 1,024 states, `CALLS` calls each. The contact is built once per
//! configuration; both paths see it only through a pointer (no constant folding of the law).
use std::hint::black_box;
use std::ptr::null_mut;

use contensou::dynamic::{DynContact, Form, Law, Output, Step};
use contensou::Real;
use contensou_capi::*;

#[path = "../tests/common/mod.rs"]
mod common;
use common::{spec_in, spec_of};

/// Calls per path and configuration (tests/overhead.sh divides by it).
pub const CALLS: usize = 1024;

#[inline(never)]
fn rust_step_f32(c: &DynContact<f32>, s: &Step<f32>) -> Output<f32> {
    c.wrench(s).unwrap_or_default()
}

#[inline(never)]
fn rust_step_f64(c: &DynContact<f64>, s: &Step<f64>) -> Output<f64> {
    c.wrench(s).unwrap_or_default()
}

fn steps<T: Real>() -> Vec<contensou_step<T>> {
    (0..CALLS)
        .map(|i| {
            let x = i as f64 / CALLS as f64;
            contensou_step {
                h: T::from_f64(2e-6 * x),
                hdot: T::from_f64(0.01 * (x - 0.5)),
                vx: T::from_f64(0.02 * (x - 0.3)),
                vy: T::from_f64(-0.01 * x),
                omega: T::from_f64(100.0 * (0.5 - x)),
            }
        })
        .collect()
}

macro_rules! run {
    ($T:ty, $storage:expr, $new:ident, $wrench:ident, $rust:ident, $law:expr, $form:expr) => {{
        let c_spec = spec_in(|x| x as $T);
        let spec = spec_of(&c_spec);
        let rust = black_box(DynContact::new(&spec, $law.1, $form.1).unwrap());
        let mut storage = Box::new($storage);
        let s = unsafe {
            $new(
                &mut *storage,
                &c_spec,
                $law.0 as u32,
                $form.0 as u32,
                null_mut(),
            )
        };
        assert_eq!(s, contensou_status::Ok);
        let cs = steps::<$T>();
        let rs: Vec<Step<$T>> = cs.iter().map(|&c| Step::from(c)).collect();
        let mut w = contensou_wrench::default();
        let (mut c_sum, mut r_sum) = (0.0, 0.0);
        for (c, r) in cs.iter().zip(&rs) {
            unsafe { $wrench(black_box(&*storage), black_box(c), &mut w, null_mut()) };
            let o = $rust(black_box(&rust), black_box(r));
            c_sum += f64::from(w.n + w.fx + w.tz);
            r_sum += f64::from(o.n + o.fx + o.tz);
        }
        assert_eq!(c_sum.to_bits(), r_sum.to_bits());
    }};
}

fn main() {
    let law = std::env::args()
        .nth(1)
        .and_then(|n| Law::from_name(&n))
        .expect("law");
    let form = std::env::args()
        .nth(2)
        .and_then(|n| Form::from_name(&n))
        .expect("form");
    let (law, form) = (
        (Law::ALL.iter().position(|l| *l == law).unwrap(), law),
        (Form::ALL.iter().position(|f| *f == form).unwrap(), form),
    );
    run!(
        f32,
        contensou_contact_f32 {
            opaque: [0; CONTENSOU_CONTACT_F32_SIZE / 8]
        },
        contensou_contact_new_f32,
        contensou_contact_wrench_f32,
        rust_step_f32,
        law,
        form
    );
    run!(
        f64,
        contensou_contact_f64 {
            opaque: [0; CONTENSOU_CONTACT_F64_SIZE / 8]
        },
        contensou_contact_new_f64,
        contensou_contact_wrench_f64,
        rust_step_f64,
        law,
        form
    );
}
