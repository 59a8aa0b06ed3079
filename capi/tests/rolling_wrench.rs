//! The rolling laws in the wrench contract through the C API: the optional columns `G, nu`
//! (`contensou_contact_new_rolling_*`, NULL = default) and `vrx, vry`
//! (`contensou_contact_wrench_rolling_*`, `_many_rolling_*`), bit for bit
//! `DynContact::new_rolling` / `wrench_rolling`; errors naming the column; the existing
//! functions unchanged (the defaults).
use core::ptr::{null, null_mut};

use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
use contensou_capi::*;

mod common;
use common::{spec_of, step_at, step_columns, storage64 as storage, wrench_columns, SPEC};

type S = contensou_status;

fn spec() -> Spec<f64> {
    spec_of(&SPEC)
}

/// Through C: G, ν optional, the rolling step optional.
fn c(
    law: u32,
    form: u32,
    g: Option<f64>,
    nu: Option<f64>,
    step: &contensou_step<f64>,
    roll: Option<contensou_rolling_step<f64>>,
) -> Result<[f64; 7], (S, u32)> {
    let mut st = storage();
    let mut col = 99;
    let (gp, np) = (
        g.as_ref().map_or(null(), |x| x as *const f64),
        nu.as_ref().map_or(null(), |x| x as *const f64),
    );
    let s =
        unsafe { contensou_contact_new_rolling_f64(&mut *st, &SPEC, gp, np, law, form, &mut col) };
    if s != S::Ok {
        return Err((s, col));
    }
    let mut w = contensou_wrench::default();
    let rp = roll.as_ref().map_or(null(), |r| r as *const _);
    match unsafe { contensou_contact_wrench_rolling_f64(&*st, step, rp, &mut w, &mut col) } {
        S::Ok => Ok([w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2]),
        s => Err((s, col)),
    }
}

#[test]
fn rolling_columns_are_the_contracts_bit_for_bit() {
    let mut n = 0;
    for (k, law) in Law::ALL.into_iter().enumerate() {
        for (f, form) in Form::ALL.into_iter().enumerate() {
            for (g, nu) in [
                (None, None),
                (Some(8e10), Some(0.28)),
                (None, Some(0.0)),
                (Some(1e9), None),
            ] {
                for (vrx, vry) in [(0.0, 0.0), (2.0, 0.0), (-0.3, 1.5), (1e-6, -1e-6)] {
                    for (vx, omega) in [(0.0, 0.0), (1e-3, 5.0), (-0.05, -200.0)] {
                        let step = contensou_step {
                            h: 1e-6,
                            hdot: 0.01,
                            vx,
                            vy: 2e-4,
                            omega,
                        };
                        let roll = contensou_rolling_step { vrx, vry };
                        let got = c(k as u32, f as u32, g, nu, &step, Some(roll)).unwrap();
                        let contact =
                            DynContact::new_rolling(&spec(), &RollingSpec { g, nu }, law, form)
                                .unwrap();
                        let s = Step {
                            h: step.h,
                            hdot: step.hdot,
                            vx,
                            vy: step.vy,
                            omega,
                        };
                        let want = contact
                            .wrench_rolling(&s, &RollingStep { vrx, vry })
                            .unwrap()
                            .to_array();
                        assert_eq!(
                            got.map(f64::to_bits),
                            want.map(f64::to_bits),
                            "{law:?} {form:?} {g:?} {nu:?} {vrx} {vry}"
                        );
                        n += 1;
                        if !law.is_rolling() {
                            // the sliding laws ignore the rolling columns
                            let plain = c(k as u32, f as u32, None, None, &step, None).unwrap();
                            assert_eq!(got.map(f64::to_bits), plain.map(f64::to_bits));
                        }
                    }
                }
            }
        }
    }
    assert_eq!(n, 9 * 2 * 4 * 4 * 3);
    // A rolling contact's rolling velocity matters: far smaller creep force than full slip.
    let step = contensou_step {
        h: 1e-6,
        hdot: 0.0,
        vx: 1e-4,
        vy: 0.0,
        omega: 0.0,
    };
    let slip = c(CONTENSOU_LAW_TABLE, 0, None, None, &step, None).unwrap();
    let roll = c(
        CONTENSOU_LAW_TABLE,
        0,
        None,
        None,
        &step,
        Some(contensou_rolling_step { vrx: 3.0, vry: 0.0 }),
    )
    .unwrap();
    assert!(
        roll[1].abs() < 0.5 * slip[1].abs() && roll[1] < 0.0,
        "{roll:?} {slip:?}"
    );
}

#[test]
fn rolling_errors_name_their_column() {
    let step = contensou_step {
        h: 1e-6,
        hdot: 0.0,
        vx: 1e-3,
        vy: 0.0,
        omega: 1.0,
    };
    let roll = |vrx, vry| Some(contensou_rolling_step { vrx, vry });
    let t = CONTENSOU_LAW_TABLE;
    let cases = [
        (
            c(t, 0, Some(0.0), None, &step, None),
            S::ShearModulusNotPositive,
            CONTENSOU_COLUMN_G,
        ),
        (
            c(t, 1, Some(f64::NAN), None, &step, None),
            S::NonFinite,
            CONTENSOU_COLUMN_G,
        ),
        (
            c(t, 0, None, Some(0.6), &step, None),
            S::RollingPoissonRatioOutOfRange,
            CONTENSOU_COLUMN_NU,
        ),
        (
            c(t, 0, Some(8e10), Some(-0.1), &step, None),
            S::RollingPoissonRatioOutOfRange,
            CONTENSOU_COLUMN_NU,
        ),
        (
            c(t, 0, None, None, &step, roll(f64::INFINITY, 0.0)),
            S::NonFinite,
            CONTENSOU_COLUMN_VRX,
        ),
        (
            c(t, 1, None, None, &step, roll(0.0, f64::NAN)),
            S::NonFinite,
            CONTENSOU_COLUMN_VRY,
        ),
    ];
    for (got, status, column) in cases {
        assert_eq!(got.unwrap_err(), (status, column));
    }
    for (column, name) in [
        (CONTENSOU_COLUMN_G, "G"),
        (CONTENSOU_COLUMN_NU, "nu"),
        (CONTENSOU_COLUMN_VRX, "vrx"),
        (CONTENSOU_COLUMN_VRY, "vry"),
        (CONTENSOU_COLUMN_NONE, ""),
    ] {
        let s = unsafe { core::ffi::CStr::from_ptr(contensou_column_name(column)) };
        assert_eq!(s.to_str().unwrap(), name);
    }
    // The sliding laws neither read nor validate them.
    assert!(c(
        CONTENSOU_LAW_BEST,
        0,
        Some(-1.0),
        Some(9.0),
        &step,
        roll(f64::NAN, 0.0)
    )
    .is_ok());
}

/// Output columns over seven vectors.
#[test]
fn many_rolling_is_the_scalar_call_per_row() {
    let rows = 64;
    let col = |f: fn(usize) -> f64| (0..rows).map(f).collect::<Vec<f64>>();
    let h = col(|i| {
        if i % 9 == 0 {
            -1e-7
        } else {
            1e-6 * (1.0 + i as f64 / 10.0)
        }
    });
    let hdot = col(|i| 0.01 * (i as f64 - 30.0));
    let vx = col(|i| 1e-3 * ((i * 7) % 13) as f64 - 6e-3);
    let vy = col(|i| 1e-4 * ((i * 5) % 11) as f64);
    let omega = col(|i| (i as f64 - 20.0) * 3.0);
    let vrx = col(|i| {
        if i % 4 == 0 {
            0.0
        } else {
            2.0 - i as f64 / 16.0
        }
    });
    let vry = col(|i| 0.1 * ((i * 3) % 7) as f64);
    for law in [
        CONTENSOU_LAW_TABLE,
        CONTENSOU_LAW_FASTSIM_16,
        CONTENSOU_LAW_BEST,
    ] {
        let mut st = storage();
        let g = 7e10;
        let s = unsafe {
            contensou_contact_new_rolling_f64(&mut *st, &SPEC, &g, null(), law, 1, null_mut())
        };
        assert_eq!(s, S::Ok);
        let mut out: [Vec<f64>; 7] = core::array::from_fn(|_| vec![0.0; rows]);
        let cols = wrench_columns(&mut out);
        let steps = step_columns([&h, &hdot, &vx, &vy, &omega]);
        let rolling = contensou_rolling_step_columns {
            vrx: vrx.as_ptr(),
            vry: vry.as_ptr(),
        };
        // The batch call with the rolling columns `rolling`: (status, row, column).
        let many = |rolling: *const contensou_rolling_step_columns<f64>| {
            let (mut row, mut column) = (0, 0);
            let s = unsafe {
                contensou_contact_wrench_many_rolling_f64(
                    &*st,
                    rows,
                    &steps,
                    rolling,
                    &cols,
                    &mut row,
                    &mut column,
                )
            };
            (s, row, column)
        };
        assert_eq!(many(&rolling), (S::Ok, rows, CONTENSOU_COLUMN_NONE));
        for i in 0..rows {
            let step = step_at([&h[..], &hdot[..], &vx[..], &vy[..], &omega[..]], i);
            let r = contensou_rolling_step {
                vrx: vrx[i],
                vry: vry[i],
            };
            let mut w = contensou_wrench::default();
            assert_eq!(
                unsafe {
                    contensou_contact_wrench_rolling_f64(&*st, &step, &r, &mut w, null_mut())
                },
                S::Ok
            );
            let got = out.each_ref().map(|c| c[i].to_bits());
            assert_eq!(
                got,
                [w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2].map(f64::to_bits),
                "row {i}"
            );
        }
        // NULL rolling columns: exactly contensou_contact_wrench_many_f64 (V = 0).
        let mut plain: [Vec<f64>; 7] = core::array::from_fn(|_| vec![0.0; rows]);
        let pcols = wrench_columns(&mut plain);
        let s = unsafe {
            contensou_contact_wrench_many_f64(&*st, rows, &steps, &pcols, null_mut(), null_mut())
        };
        assert_eq!(s, S::Ok);
        assert_eq!(many(null()), (S::Ok, rows, CONTENSOU_COLUMN_NONE));
        assert_eq!(
            out.each_ref()
                .map(|c| c.iter().map(|x| x.to_bits()).collect::<Vec<_>>()),
            plain
                .each_ref()
                .map(|c| c.iter().map(|x| x.to_bits()).collect::<Vec<_>>())
        );
        // A bad rolling value: stops at its row, naming the column.
        let mut bad = vry.clone();
        bad[17] = f64::NAN;
        let rolling = contensou_rolling_step_columns {
            vrx: vrx.as_ptr(),
            vry: bad.as_ptr(),
        };
        let (s, row, column) = many(&rolling);
        if law == CONTENSOU_LAW_BEST {
            assert_eq!(s, S::Ok, "sliding laws do not read vry");
        } else {
            assert_eq!((s, row, column), (S::NonFinite, 17, CONTENSOU_COLUMN_VRY));
        }
        let rolling = contensou_rolling_step_columns {
            vrx: null(),
            vry: vry.as_ptr(),
        };
        assert_eq!(many(&rolling).0, S::NullPointer);
    }
}
