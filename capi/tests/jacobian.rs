//! The Jacobian's C functions (`contensou_contact_jacobian_*`, `…_jacobian_rolling_*`) called
//! as a C caller would: bit for bit `DynContact::jacobian_rolling` for every law, form and
//! precision; the wrench's pointer, tag and column errors; nothing written on error.
use core::ptr::{null, null_mut};

use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
use contensou_capi::*;

mod common;
use common::{each_null, misaligned, spec_in, storage32, storage64, SPEC, STEP};

type S = contensou_status;

const ROLL: contensou_rolling_step<f64> = contensou_rolling_step { vrx: 2.0, vry: 0.3 };

/// The C struct as the contract's 24 outputs (`Jacobian::to_array` order), as bits.
fn bits<T: Copy + Into<f64>>(j: &contensou_jacobian<T>) -> Vec<u64> {
    let mut v = vec![j.n.into(), j.fx.into(), j.fy.into(), j.tz.into()];
    v.extend(j.d.iter().flatten().map(|&x| x.into()));
    v.into_iter().map(f64::to_bits).collect()
}

fn lib_bits<T: Copy + Into<f64>>(j: &contensou::jacobian::Jacobian<T>) -> Vec<u64> {
    j.to_array().iter().map(|&x| x.into().to_bits()).collect()
}

#[test]
fn the_numbers_are_the_contracts_bit_for_bit() {
    let laws = [
        CONTENSOU_LAW_BEST,
        CONTENSOU_LAW_SIMPLIFIED,
        CONTENSOU_LAW_PADE,
        CONTENSOU_LAW_ELLIPSOID,
        CONTENSOU_LAW_COULOMB,
        CONTENSOU_LAW_TABLE,
        CONTENSOU_LAW_BLEND,
        CONTENSOU_LAW_FASTSIM,
        CONTENSOU_LAW_FASTSIM_16,
    ];
    let rolling = RollingSpec::default();
    let roll = RollingStep {
        vrx: ROLL.vrx,
        vry: ROLL.vry,
    };
    for &law in &laws {
        for form in [CONTENSOU_FORM_FIXED, CONTENSOU_FORM_VARYING] {
            let (l, f) = (
                Law::ALL.iter().find(|x| {
                    let mut code = 99;
                    let name = std::ffi::CString::new(x.name()).unwrap();
                    unsafe { contensou_law_from_name(name.as_ptr(), &mut code) };
                    code == law
                }),
                if form == CONTENSOU_FORM_FIXED {
                    Form::Fixed
                } else {
                    Form::Varying
                },
            );
            let l = *l.unwrap();
            // f64
            let mut c = storage64();
            let mut j = contensou_jacobian::<f64>::default();
            let mut col = 77;
            unsafe {
                assert_eq!(
                    contensou_contact_new_f64(&mut *c, &SPEC, law, form, null_mut()),
                    S::Ok
                );
                assert_eq!(
                    contensou_contact_jacobian_f64(&*c, &STEP, &mut j, &mut col),
                    S::Ok
                );
            }
            assert_eq!(col, CONTENSOU_COLUMN_NONE);
            let lib = DynContact::new_rolling(&Spec::from(SPEC), &rolling, l, f).unwrap();
            let want = lib.jacobian(&Step::from(STEP)).unwrap();
            assert_eq!(bits(&j), lib_bits(&want), "{l:?} {f:?} f64");
            unsafe {
                assert_eq!(
                    contensou_contact_jacobian_rolling_f64(&*c, &STEP, &ROLL, &mut j, null_mut()),
                    S::Ok
                );
            }
            let want = lib.jacobian_rolling(&Step::from(STEP), &roll).unwrap();
            assert_eq!(bits(&j), lib_bits(&want), "{l:?} {f:?} f64 rolling");
            // f32
            let to = |x: f64| x as f32;
            let (spec, step) = (
                spec_in(to),
                contensou_step {
                    h: to(STEP.h),
                    hdot: to(STEP.hdot),
                    vx: to(STEP.vx),
                    vy: to(STEP.vy),
                    omega: to(STEP.omega),
                },
            );
            let roll32 = contensou_rolling_step {
                vrx: to(ROLL.vrx),
                vry: to(ROLL.vry),
            };
            let mut c = storage32();
            let mut j = contensou_jacobian::<f32>::default();
            unsafe {
                assert_eq!(
                    contensou_contact_new_f32(&mut *c, &spec, law, form, null_mut()),
                    S::Ok
                );
                assert_eq!(
                    contensou_contact_jacobian_rolling_f32(&*c, &step, &roll32, &mut j, null_mut()),
                    S::Ok
                );
            }
            let lib =
                DynContact::new_rolling(&Spec::from(spec), &RollingSpec::default(), l, f).unwrap();
            let want = lib
                .jacobian_rolling(
                    &Step::from(step),
                    &RollingStep {
                        vrx: roll32.vrx,
                        vry: roll32.vry,
                    },
                )
                .unwrap();
            assert_eq!(bits(&j), lib_bits(&want), "{l:?} {f:?} f32 rolling");
            // The Jacobian's wrench is the wrench's, bit for bit.
            let mut w = contensou_wrench::<f32>::default();
            unsafe {
                assert_eq!(
                    contensou_contact_wrench_rolling_f32(&*c, &step, &roll32, &mut w, null_mut()),
                    S::Ok
                );
            }
            let wrench = [w.n, w.fx, w.fy, w.tz].map(f32::to_bits);
            assert_eq!(
                wrench,
                [j.n, j.fx, j.fy, j.tz].map(f32::to_bits),
                "{l:?} {f:?}"
            );
        }
    }
}

#[test]
fn errors_are_the_wrenchs_and_write_nothing() {
    let mut c = storage64();
    let mut j = contensou_jacobian::<f64>::default();
    let mut col = 77;
    unsafe {
        assert_eq!(
            contensou_contact_jacobian_f64(&*c, &STEP, &mut j, &mut col),
            S::NotInitialized
        );
        assert_eq!(col, CONTENSOU_COLUMN_NONE);
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, CONTENSOU_LAW_TABLE, 0, null_mut()),
            S::Ok
        );
        let jacobian = |c, s, o| contensou_contact_jacobian_f64(c, s, o, null_mut());
        assert_eq!(each_null(&*c, &STEP, jacobian), [S::NullPointer; 3]);
        let bad = contensou_step {
            omega: f64::NAN,
            ..STEP
        };
        assert_eq!(
            contensou_contact_jacobian_f64(&*c, &bad, &mut j, &mut col),
            S::NonFinite
        );
        assert_eq!(col, CONTENSOU_COLUMN_OMEGA);
        let bad_roll = contensou_rolling_step {
            vry: f64::INFINITY,
            ..ROLL
        };
        assert_eq!(
            contensou_contact_jacobian_rolling_f64(&*c, &STEP, &bad_roll, &mut j, &mut col),
            S::NonFinite
        );
        assert_eq!(col, CONTENSOU_COLUMN_VRY);
        // A misaligned rolling step, and an f64 contact asked in f32 (the tag differs).
        let raw = [0.0_f64; 4];
        let odd = misaligned::<contensou_rolling_step<f64>, _>(raw.as_ptr());
        assert_eq!(
            contensou_contact_jacobian_rolling_f64(&*c, &STEP, odd, &mut j, null_mut()),
            S::Misaligned
        );
        let mut j32 = contensou_jacobian::<f32>::default();
        let step32 = contensou_step::<f32>::default();
        let as32 = (&*c as *const contensou_contact_f64).cast::<contensou_contact_f32>();
        assert_eq!(
            contensou_contact_jacobian_f32(as32, &step32, &mut j32, null_mut()),
            S::NotInitialized
        );
        // NULL rolling is V = 0: the plain call's bits.
        let mut plain = contensou_jacobian::<f64>::default();
        assert_eq!(
            contensou_contact_jacobian_rolling_f64(&*c, &STEP, null(), &mut j, null_mut()),
            S::Ok
        );
        assert_eq!(
            contensou_contact_jacobian_f64(&*c, &STEP, &mut plain, null_mut()),
            S::Ok
        );
        assert_eq!(bits(&j), bits(&plain));
    }
    let mut untouched = contensou_jacobian::<f64>::default();
    let bad = contensou_step {
        h: f64::NAN,
        ..STEP
    };
    unsafe {
        assert_eq!(
            contensou_contact_jacobian_f64(&*c, &bad, &mut untouched, null_mut()),
            S::NonFinite
        );
    }
    assert_eq!(
        untouched,
        contensou_jacobian::default(),
        "nothing written on error"
    );
}
