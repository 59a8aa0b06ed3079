//! `contensou_contact_wrench_many_*` as a C caller uses it: bit for bit the per-row
//! `contensou_contact_wrench_*` on every law and form, the first bad row and its column, and
//! bad pointers refused before anything is written.
use core::ptr::{null, null_mut};

use contensou_capi::*;

mod common;
use common::{spec_in, step_at, step_columns, wrench_columns};

type S = contensou_status;

const ROWS: usize = 1003;

/// Deterministic rows mixing contact, loss, rest, spin and slip.
fn columns() -> [Vec<f64>; 5] {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut unit = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut c: [Vec<f64>; 5] = Default::default();
    for i in 0..ROWS {
        let row = [
            2e-6 * unit() + 5e-7,
            0.1 * unit(),
            if i % 7 == 0 { 0.0 } else { 0.02 * unit() },
            if i % 5 == 0 { 0.0 } else { 0.02 * unit() },
            if i % 3 == 0 { 0.0 } else { 200.0 * unit() },
        ];
        for (c, v) in c.iter_mut().zip(row) {
            c.push(v);
        }
    }
    c
}

macro_rules! precision {
    ($name:ident, $t:ty, $storage:ident, $size:ident, $new:ident, $one:ident, $many:ident) => {
        #[test]
        fn $name() {
            let cols: [Vec<$t>; 5] = columns().map(|c| c.iter().map(|&x| x as $t).collect());
            let [h, hdot, vx, vy, omega] = &cols;
            let spec = spec_in(|x| x as $t);
            for law in [
                CONTENSOU_LAW_BEST,
                CONTENSOU_LAW_SIMPLIFIED,
                CONTENSOU_LAW_PADE,
                CONTENSOU_LAW_ELLIPSOID,
                CONTENSOU_LAW_COULOMB,
            ] {
                for form in [CONTENSOU_FORM_FIXED, CONTENSOU_FORM_VARYING] {
                    let mut storage = Box::new($storage {
                        opaque: [0; $size / 8],
                    });
                    let mut column = 99;
                    assert_eq!(
                        unsafe { $new(&mut *storage, &spec, law, form, &mut column) },
                        S::Ok
                    );
                    let mut out: [Vec<$t>; 7] = core::array::from_fn(|_| vec![-7.0; ROWS]);
                    let steps = step_columns([h, hdot, vx, vy, omega].map(|c| &c[..]));
                    let ptrs = wrench_columns::<$t>;
                    let mut row = 0;
                    let cols_out = ptrs(&mut out);
                    assert_eq!(
                        unsafe { $many(&*storage, ROWS, &steps, &cols_out, &mut row, &mut column) },
                        S::Ok
                    );
                    assert_eq!((row, column), (ROWS, CONTENSOU_COLUMN_NONE));
                    for i in 0..ROWS {
                        let step = step_at([h, hdot, vx, vy, omega].map(|c| &c[..]), i);
                        let mut w = contensou_wrench::<$t>::default();
                        assert_eq!(unsafe { $one(&*storage, &step, &mut w, null_mut()) }, S::Ok);
                        let one = [w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2];
                        for (c, v) in one.iter().enumerate() {
                            assert_eq!(
                                out[c][i].to_bits(),
                                v.to_bits(),
                                "law {law} form {form} row {i} column {c}"
                            );
                        }
                    }
                    // A NaN at row 517 in omega: rows before written, the row and column reported.
                    let mut bad = omega.clone();
                    bad[517] = <$t>::NAN;
                    let steps_bad = contensou_step_columns {
                        omega: bad.as_ptr(),
                        ..steps
                    };
                    let mut out2: [Vec<$t>; 7] = core::array::from_fn(|_| vec![-7.0; ROWS]);
                    let cols2 = ptrs(&mut out2);
                    assert_eq!(
                        unsafe {
                            $many(&*storage, ROWS, &steps_bad, &cols2, &mut row, &mut column)
                        },
                        S::NonFinite
                    );
                    assert_eq!((row, column), (517, CONTENSOU_COLUMN_OMEGA));
                    assert_eq!(out2[0][..517], out[0][..517]);
                    assert_eq!(out2[0][517], -7.0);
                    // Bad pointers: refused, nothing written; NULL row/column allowed.
                    let mut out3: [Vec<$t>; 7] = core::array::from_fn(|_| vec![-7.0; ROWS]);
                    let mut cols3 = ptrs(&mut out3);
                    cols3.e2 = null_mut();
                    assert_eq!(
                        unsafe { $many(&*storage, ROWS, &steps, &cols3, null_mut(), null_mut()) },
                        S::NullPointer
                    );
                    let cols3 = ptrs(&mut out3);
                    let steps_null = contensou_step_columns {
                        vy: null(),
                        ..steps
                    };
                    assert_eq!(
                        unsafe {
                            $many(&*storage, ROWS, &steps_null, &cols3, &mut row, &mut column)
                        },
                        S::NullPointer
                    );
                    assert_eq!((row, column), (ROWS, CONTENSOU_COLUMN_NONE));
                    let steps_odd = contensou_step_columns {
                        h: unsafe { h.as_ptr().cast::<u8>().add(1).cast() },
                        ..steps
                    };
                    assert_eq!(
                        unsafe {
                            $many(&*storage, ROWS, &steps_odd, &cols3, &mut row, &mut column)
                        },
                        S::Misaligned
                    );
                    assert_eq!(
                        unsafe {
                            $many(&*storage, usize::MAX, &steps, &cols3, &mut row, &mut column)
                        },
                        S::NullPointer
                    );
                    assert_eq!(
                        unsafe { $many(&*storage, ROWS, null(), &cols3, &mut row, &mut column) },
                        S::NullPointer
                    );
                    assert!(out3.iter().all(|c| c.iter().all(|&x| x == -7.0)));
                    // Zero rows: nothing read, success.
                    let nothing = contensou_step_columns {
                        h: null(),
                        hdot: null(),
                        vx: null(),
                        vy: null(),
                        omega: null(),
                    };
                    let none = contensou_wrench_columns {
                        n: null_mut(),
                        fx: null_mut(),
                        fy: null_mut(),
                        tz: null_mut(),
                        a: null_mut(),
                        b: null_mut(),
                        e2: null_mut(),
                    };
                    assert_eq!(
                        unsafe { $many(&*storage, 0, &nothing, &none, &mut row, &mut column) },
                        S::Ok
                    );
                    // Uninitialised storage.
                    let blank = Box::new($storage {
                        opaque: [0; $size / 8],
                    });
                    assert_eq!(
                        unsafe { $many(&*blank, ROWS, &steps, &cols3, &mut row, &mut column) },
                        S::NotInitialized
                    );
                }
            }
        }
    };
}

precision!(
    many_f32_is_the_row_calls_bit_for_bit,
    f32,
    contensou_contact_f32,
    CONTENSOU_CONTACT_F32_SIZE,
    contensou_contact_new_f32,
    contensou_contact_wrench_f32,
    contensou_contact_wrench_many_f32
);
precision!(
    many_f64_is_the_row_calls_bit_for_bit,
    f64,
    contensou_contact_f64,
    CONTENSOU_CONTACT_F64_SIZE,
    contensou_contact_new_f64,
    contensou_contact_wrench_f64,
    contensou_contact_wrench_many_f64
);
