//! The C API called from Rust as a C caller would: status codes (one per `contensou::Error`
//! variant), NULL / misaligned / uninitialised pointers, invalid enum values, error columns,
//! and the numbers (bit for bit those of `contensou::dynamic`).
use core::ptr::{null, null_mut};

use contensou::dynamic::{DynContact, Form, Law, Spec, Step};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Material, Modulus};
use contensou::Error;
use contensou_capi::*;

mod common;
use common::{copied, each_null, misaligned, spec_in, storage32, storage64, text, SPEC, STEP};

type S = contensou_status;

#[test]
fn every_library_error_has_its_own_code_and_the_library_message() {
    let all = Error::ALL;
    let mut codes: Vec<u32> = all.iter().map(|&e| S::from(e) as u32).collect();
    for (e, &c) in all.iter().zip(&codes) {
        assert_ne!(c, S::UnknownError as u32, "{e:?} is not mapped");
        assert_eq!(text(contensou_status_message(c)), e.as_str());
    }
    codes.sort();
    codes.dedup();
    assert_eq!(codes.len(), all.len(), "two errors share a code");
    assert_eq!(text(contensou_status_message(0)), "ok");
    assert_eq!(
        text(contensou_status_message(100)),
        "a pointer parameter is NULL"
    );
    assert_eq!(
        text(contensou_status_message(12345)),
        "unknown contensou_status code"
    );
    for code in 100..=108 {
        assert!(!text(contensou_status_message(code)).starts_with("unknown contensou_status"));
    }
}

#[test]
fn column_names_follow_the_contract() {
    let names: Vec<&str> = (0..11).map(|c| text(contensou_column_name(c))).collect();
    assert_eq!(names, contensou::dynamic::INPUTS);
    assert_eq!(text(contensou_column_name(CONTENSOU_COLUMN_OMEGA)), "omega");
    assert_eq!(text(contensou_column_name(CONTENSOU_COLUMN_NONE)), "");
    assert_eq!(text(contensou_column_name(u32::MAX)), "");
}

#[test]
fn names_parse_to_the_constants() {
    let mut law = 99;
    for (name, want) in [
        (c"best", CONTENSOU_LAW_BEST),
        (c"simplified", CONTENSOU_LAW_SIMPLIFIED),
        (c"pade", CONTENSOU_LAW_PADE),
        (c"ellipsoid", CONTENSOU_LAW_ELLIPSOID),
        (c"coulomb", CONTENSOU_LAW_COULOMB),
    ] {
        assert_eq!(
            unsafe { contensou_law_from_name(name.as_ptr(), &mut law) },
            S::Ok
        );
        assert_eq!(law, want);
    }
    let mut form = 99;
    assert_eq!(
        unsafe { contensou_form_from_name(c"varying".as_ptr(), &mut form) },
        S::Ok
    );
    assert_eq!(form, CONTENSOU_FORM_VARYING);
    assert_eq!(
        unsafe { contensou_law_from_name(c"exact".as_ptr(), &mut law) },
        S::UnknownName
    );
    assert_eq!(
        unsafe { contensou_form_from_name(c"\xff".as_ptr(), &mut form) },
        S::UnknownName
    );
    assert_eq!(
        unsafe { contensou_law_from_name(null(), &mut law) },
        S::NullPointer
    );
    assert_eq!(
        unsafe { contensou_form_from_name(c"fixed".as_ptr(), null_mut()) },
        S::NullPointer
    );
    assert_eq!(form, CONTENSOU_FORM_VARYING, "unchanged on error");
}

#[test]
fn bad_pointers_and_values_are_codes_and_write_nothing() {
    let mut c = storage64();
    let mut col = 77;
    let mut w = contensou_wrench::<f64>::default();
    unsafe {
        assert_eq!(
            contensou_contact_new_f64(null_mut(), &SPEC, 0, 0, &mut col),
            S::NullPointer
        );
        assert_eq!(col, CONTENSOU_COLUMN_NONE);
        assert_eq!(
            contensou_contact_new_f64(&mut *c, null(), 0, 0, null_mut()),
            S::NullPointer
        );
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, 42, 0, null_mut()),
            S::InvalidLaw
        );
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, CONTENSOU_LAW_LINEAR, 0, null_mut()),
            S::InvalidLaw,
            "full-slip and linear are rolling-evaluator laws only"
        );
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, 0, 2, null_mut()),
            S::InvalidForm
        );
        // Storage no constructor wrote (zeroed, as static memory is) is refused.
        assert_eq!(
            contensou_contact_wrench_f64(&*c, &STEP, &mut w, null_mut()),
            S::NotInitialized
        );
        assert_eq!(
            contensou_contact_set_curvatures_f64(&mut *c, 1.0, 2.0, null_mut()),
            S::NotInitialized
        );
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, 0, 0, null_mut()),
            S::Ok
        );
        let wrench = |c, s, o| contensou_contact_wrench_f64(c, s, o, null_mut());
        assert_eq!(each_null(&*c, &STEP, wrench), [S::NullPointer; 3]);
        assert_eq!(w, contensou_wrench::default(), "nothing written on error");
        // Misaligned storage (4 bytes off the required 8) and a misaligned step.
        let off = misaligned::<contensou_contact_f64, _>(c.opaque.as_mut_ptr());
        assert_eq!(
            contensou_contact_new_f64(off, &SPEC, 0, 0, null_mut()),
            S::Misaligned
        );
        assert_eq!(
            contensou_contact_wrench_f64(off, &STEP, &mut w, null_mut()),
            S::Misaligned
        );
        let steps = [0.0_f64; 8];
        let odd = misaligned::<contensou_step<f64>, _>(steps.as_ptr());
        assert_eq!(
            contensou_contact_wrench_f64(&*c, odd, &mut w, null_mut()),
            S::Misaligned
        );
        // An f32 contact is not an f64 one (the tag differs).
        let mut c32 = storage32();
        let spec32 = spec_in(|x| x as f32);
        assert_eq!(
            contensou_contact_new_f32(&mut *c32, &spec32, 0, 0, null_mut()),
            S::Ok
        );
        let big = copied::<_, contensou_contact_f64>(&*c32);
        assert_eq!(
            contensou_contact_wrench_f64(&*big, &STEP, &mut w, null_mut()),
            S::NotInitialized
        );
        // Helpers.
        let mut k = contensou_curvatures::<f32>::default();
        assert_eq!(
            contensou_curvatures_sphere_plane_f32(1.0, null_mut()),
            S::NullPointer
        );
        assert_eq!(
            contensou_curvatures_ball_race_f32(1.0, 0.52, 5.0, 0.0, 2, &mut k),
            S::InvalidRace
        );
        assert_eq!(
            contensou_curvatures_sphere_plane_f32(-1.0, &mut k),
            S::LengthNotPositive
        );
        assert_eq!(
            contensou_curvatures_sphere_sphere_f32(1.0, -0.5, &mut k),
            S::CurvatureNotPositive
        );
        assert_eq!(
            contensou_curvatures_new_f32(f32::NAN, 1.0, &mut k),
            S::NonFinite
        );
        assert_eq!(k, contensou_curvatures::default());
        let mut e = 0.0_f64;
        assert_eq!(
            contensou_modulus_of_f64(2e11, 0.6, 2e11, 0.3, &mut e),
            S::PoissonRatioOutOfRange
        );
        assert_eq!(
            contensou_modulus_of_f64(0.0, 0.3, 2e11, 0.3, &mut e),
            S::ModulusNotPositive
        );
        assert_eq!(
            contensou_modulus_of_f64(2e11, 0.3, 2e11, 0.3, null_mut()),
            S::NullPointer
        );
        assert_eq!(e, 0.0);
    }
}

/// With several bad pointers the wrench reports the first in the order storage (NULL,
/// alignment, initialisation), step, output; `*column` is NONE after a refused pointer and
/// after a success, the step's column after a refused step; `*out` is written on success only.
#[test]
fn wrench_statuses_follow_the_documented_order() {
    unsafe {
        let mut c = storage64();
        let zeroed = storage64();
        assert_eq!(
            contensou_contact_new_f64(&mut *c, &SPEC, 0, 0, null_mut()),
            S::Ok
        );
        let off = misaligned::<contensou_contact_f64, _>(c.opaque.as_ptr()).cast_const();
        let words = [0.0_f64; 8];
        let odd_step = misaligned::<contensou_step<f64>, _>(words.as_ptr()).cast_const();
        let odd_out = misaligned(words.as_ptr());
        let mut w = contensou_wrench::default();
        let (good, zeroed) = (&*c as *const _, &*zeroed as *const _);
        let cases = [
            (null(), odd_step, odd_out, S::NullPointer),
            (off, null(), null_mut(), S::Misaligned),
            (zeroed, odd_step, null_mut(), S::NotInitialized),
            (good, odd_step, null_mut(), S::Misaligned),
            (good, null(), odd_out, S::NullPointer),
            (good, &STEP, odd_out, S::Misaligned),
            (good, &STEP, null_mut(), S::NullPointer),
        ];
        for (storage, step, out, status) in cases {
            let mut col = CONTENSOU_COLUMN_OMEGA;
            assert_eq!(
                contensou_contact_wrench_f64(storage, step, out, &mut col),
                status
            );
            assert_eq!(col, CONTENSOU_COLUMN_NONE);
        }
        let bad = contensou_step {
            vx: f64::NAN,
            ..STEP
        };
        let mut col = CONTENSOU_COLUMN_NONE;
        assert_eq!(
            contensou_contact_wrench_f64(good, &bad, &mut w, &mut col),
            S::NonFinite
        );
        assert_eq!((col, w), (CONTENSOU_COLUMN_VX, contensou_wrench::default()));
        assert_eq!(
            contensou_contact_wrench_f64(good, &STEP, &mut w, &mut col),
            S::Ok
        );
        assert_eq!(col, CONTENSOU_COLUMN_NONE);
        assert!(w.n > 0.0);
    }
}

#[test]
fn errors_name_their_column() {
    let mut c = storage64();
    let mut col = 0;
    let cases: [(contensou_spec<f64>, S, u32); 7] = [
        (
            contensou_spec { p: 60.0, ..SPEC },
            S::CurvaturesNotOrdered,
            CONTENSOU_COLUMN_P,
        ),
        (
            contensou_spec {
                q: f64::INFINITY,
                ..SPEC
            },
            S::NonFinite,
            CONTENSOU_COLUMN_Q,
        ),
        (
            contensou_spec { p: 1e-4, ..SPEC },
            S::CurvatureRatioOutOfRange,
            CONTENSOU_COLUMN_P,
        ),
        (
            contensou_spec { estar: 0.0, ..SPEC },
            S::ModulusNotPositive,
            CONTENSOU_COLUMN_ESTAR,
        ),
        (
            contensou_spec { cd: -1.0, ..SPEC },
            S::DampingNegative,
            CONTENSOU_COLUMN_CD,
        ),
        (
            contensou_spec { f: -0.1, ..SPEC },
            S::FrictionCoefficientNegative,
            CONTENSOU_COLUMN_F,
        ),
        (
            contensou_spec {
                delta: -1e-4,
                ..SPEC
            },
            S::RegularizationSpeedNegative,
            CONTENSOU_COLUMN_DELTA,
        ),
    ];
    for (spec, status, column) in cases {
        assert_eq!(
            unsafe { contensou_contact_new_f64(&mut *c, &spec, 0, 1, &mut col) },
            status
        );
        assert_eq!(col, column, "{spec:?}");
    }
    assert_eq!(
        unsafe { contensou_contact_new_f64(&mut *c, &SPEC, 0, 1, &mut col) },
        S::Ok
    );
    assert_eq!(col, CONTENSOU_COLUMN_NONE);
    let mut w = contensou_wrench::default();
    let bad = contensou_step {
        omega: f64::NEG_INFINITY,
        ..STEP
    };
    assert_eq!(
        unsafe { contensou_contact_wrench_f64(&*c, &bad, &mut w, &mut col) },
        S::NonFinite
    );
    assert_eq!(col, CONTENSOU_COLUMN_OMEGA);
    assert_eq!(
        unsafe { contensou_contact_set_curvatures_f64(&mut *c, 60.0, 50.0, &mut col) },
        S::CurvaturesNotOrdered
    );
    assert_eq!(col, CONTENSOU_COLUMN_P);
}

/// The wrench through the C API, or the status (one function per precision).
macro_rules! c_wrench {
    ($name:ident: $T:ty, $storage:ident, $new:ident, $wrench:ident) => {
        fn $name(
            spec: &contensou_spec<$T>,
            law: u32,
            form: u32,
            step: &contensou_step<$T>,
        ) -> Result<[$T; 7], S> {
            let mut c = $storage();
            let mut w = contensou_wrench::default();
            let s = unsafe { $new(&mut *c, spec, law, form, null_mut()) };
            if s != S::Ok {
                return Err(s);
            }
            match unsafe { $wrench(&*c, step, &mut w, null_mut()) } {
                S::Ok => Ok([w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2]),
                s => Err(s),
            }
        }
    };
}
c_wrench!(c_wrench64: f64, storage64, contensou_contact_new_f64, contensou_contact_wrench_f64);
c_wrench!(c_wrench32: f32, storage32, contensou_contact_new_f32, contensou_contact_wrench_f32);

/// One state through the C API and through `DynContact`: the same bits.
macro_rules! same_as_contract {
    ($T:ty, $c_wrench:ident, $law:expr, $form:expr, $p:expr, $h:expr, $vx:expr, $omega:expr) => {{
        let spec = contensou_spec::<$T> {
            p: $p as $T,
            q: 50.0,
            estar: 1.15e11,
            cd: 0.1,
            f: 0.1,
            delta: 1e-4,
        };
        let step = contensou_step::<$T> {
            h: $h as $T,
            hdot: 0.01,
            vx: $vx as $T,
            vy: -0.002,
            omega: $omega as $T,
        };
        let r = Spec {
            p: spec.p,
            q: spec.q,
            estar: spec.estar,
            cd: spec.cd,
            f: spec.f,
            delta: spec.delta,
        };
        let s = Step {
            h: step.h,
            hdot: step.hdot,
            vx: step.vx,
            vy: step.vy,
            omega: step.omega,
        };
        let want = DynContact::new(&r, $law.1, $form.1)
            .unwrap()
            .wrench(&s)
            .unwrap()
            .to_array();
        let got = $c_wrench(&spec, $law.0 as u32, $form.0 as u32, &step).unwrap();
        assert_eq!(got.map(<$T>::to_bits), want.map(<$T>::to_bits));
    }};
}

#[test]
fn the_numbers_are_the_contracts_bit_for_bit() {
    let mut n = 0;
    for law in Law::ALL.into_iter().enumerate() {
        for form in Form::ALL.into_iter().enumerate() {
            for p in [50.0, 10.0, 0.02] {
                for h in [-1e-7, 0.0, 1e-9, 2e-6] {
                    for (vx, omega) in [(0.0, 0.0), (0.01, 50.0), (-3.0, 0.5), (1e-7, -2e3)] {
                        same_as_contract!(f64, c_wrench64, law, form, p, h, vx, omega);
                        same_as_contract!(f32, c_wrench32, law, form, p, h, vx, omega);
                        n += 1;
                    }
                }
            }
        }
    }
    assert_eq!(n, Law::ALL.len() * 2 * 3 * 4 * 4);
}

#[test]
fn set_curvatures_is_a_fresh_contact_and_an_error_changes_nothing() {
    for form in [CONTENSOU_FORM_FIXED, CONTENSOU_FORM_VARYING] {
        let mut c = storage64();
        let mut w = contensou_wrench::default();
        unsafe {
            assert_eq!(
                contensou_contact_new_f64(&mut *c, &SPEC, CONTENSOU_LAW_BEST, form, null_mut()),
                S::Ok
            );
            assert_eq!(
                contensou_contact_set_curvatures_f64(&mut *c, 20.0, 30.0, null_mut()),
                S::Ok
            );
            assert_eq!(
                contensou_contact_wrench_f64(&*c, &STEP, &mut w, null_mut()),
                S::Ok
            );
        }
        let fresh = c_wrench64(
            &contensou_spec {
                p: 20.0,
                q: 30.0,
                ..SPEC
            },
            0,
            form,
            &STEP,
        )
        .unwrap();
        assert_eq!(
            [w.n, w.fx, w.fy, w.tz, w.a, w.b, w.e2].map(f64::to_bits),
            fresh.map(f64::to_bits)
        );
        let before = c.opaque;
        let s = unsafe { contensou_contact_set_curvatures_f64(&mut *c, 30.0, 1e-3, null_mut()) };
        assert_eq!(s, S::CurvaturesNotOrdered);
        assert_eq!(c.opaque, before);
    }
}

#[test]
fn helpers_are_the_library_constructors_in_contract_order() {
    let mut k = contensou_curvatures::<f64>::default();
    for race in [CONTENSOU_RACE_INNER, CONTENSOU_RACE_OUTER] {
        let s = unsafe {
            contensou_curvatures_ball_race_f64(12.7e-3, 6.6e-3, 65e-3, 0.2, race, &mut k)
        };
        assert_eq!(s, S::Ok);
        let r = if race == CONTENSOU_RACE_INNER {
            Race::Inner
        } else {
            Race::Outer
        };
        let want = Curvatures::ball_race(12.7e-3, 6.6e-3, 65e-3, 0.2, r).unwrap();
        assert_eq!(
            (k.p, k.q, k.major_angle),
            (want.p(), want.q(), want.major_angle())
        );
        assert!(k.p <= k.q && k.major_angle == core::f64::consts::FRAC_PI_2);
        // P, Q go straight into a contract contact.
        let spec = contensou_spec {
            p: k.p,
            q: k.q,
            ..SPEC
        };
        assert!(c_wrench64(&spec, 0, 0, &STEP).is_ok());
    }
    assert_eq!(
        unsafe { contensou_curvatures_new_f64(3.0, 2.0, &mut k) },
        S::Ok
    );
    assert_eq!(
        (k.p, k.q, k.major_angle),
        (2.0, 3.0, core::f64::consts::FRAC_PI_2)
    );
    assert_eq!(
        unsafe { contensou_curvatures_sphere_sphere_f64(0.01, -0.02, &mut k) },
        S::Ok
    );
    assert_eq!((k.p, k.q), (25.0, 25.0));
    let mut k32 = contensou_curvatures::<f32>::default();
    assert_eq!(
        unsafe { contensou_curvatures_sphere_plane_f32(0.01, &mut k32) },
        S::Ok
    );
    assert_eq!((k32.p, k32.q, k32.major_angle), (50.0, 50.0, 0.0));
    let mut e = 0.0_f32;
    assert_eq!(
        unsafe { contensou_modulus_of_f32(2.1e11, 0.3, 7e10, 0.33, &mut e) },
        S::Ok
    );
    let want = Modulus::of(
        Material::new(2.1e11_f32, 0.3).unwrap(),
        Material::new(7e10, 0.33).unwrap(),
    )
    .unwrap();
    assert_eq!(e.to_bits(), want.get().to_bits());
}

/// The storage type `$st` has the size the crate and the header declare as `$size`, and the
/// header's alignment.
macro_rules! assert_storage {
    ($st:ty, $size:ident) => {{
        let name = stringify!($size);
        assert_eq!(core::mem::size_of::<$st>(), $size, "{name}");
        assert_eq!(
            core::mem::align_of::<$st>(),
            CONTENSOU_CONTACT_ALIGN,
            "{name}"
        );
        let header = include_str!("../include/contensou.h");
        assert!(
            header.contains(&format!("#define {name} {}", $size)),
            "{name}"
        );
    }};
}

#[test]
fn storage_sizes_are_the_headers() {
    assert_storage!(contensou_contact_f32, CONTENSOU_CONTACT_F32_SIZE);
    assert_storage!(contensou_contact_f64, CONTENSOU_CONTACT_F64_SIZE);
    assert_storage!(contensou_rolling_f32, CONTENSOU_ROLLING_F32_SIZE);
    assert_storage!(contensou_rolling_f64, CONTENSOU_ROLLING_F64_SIZE);
}
