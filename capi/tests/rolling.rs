//! The rolling evaluator (`contensou_rolling_*`) called as a C caller would: typed errors
//! naming their column (G, ν, a/b, the state's columns), NULL / misaligned / uninitialised
//! pointers, laws it does not take, and the numbers (bit for bit `RollingContact::wrench`,
//! the body of `contact_eval rolling`; tests/compare.sh checks the command itself).
use core::ffi::CStr;
use core::ptr::null_mut;

use contensou::friction::rolling::row::RowLaw;
use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
};
use contensou::Real;
use contensou_capi::*;

mod common;
use common::{copied, each_null, misaligned, rolling32 as storage32, rolling64 as storage64, text};

type S = contensou_status;

const STATE: contensou_rolling_state<f64> = contensou_rolling_state {
    a: 6e-3,
    b: 4e-3,
    f: 0.3,
    n: 8e4,
    v: 30.0,
    xi: 1e-3,
    eta: -2e-4,
    phi: 0.5,
};

const LAWS: [(u32, &CStr); 6] = [
    (CONTENSOU_LAW_TABLE, c"table"),
    (CONTENSOU_LAW_BLEND, c"blend"),
    (CONTENSOU_LAW_FASTSIM, c"fastsim"),
    (CONTENSOU_LAW_FASTSIM_16, c"fastsim-16"),
    (CONTENSOU_LAW_FULL_SLIP, c"full-slip"),
    (CONTENSOU_LAW_LINEAR, c"linear"),
];

#[test]
fn law_names_and_columns() {
    for (code, name) in LAWS {
        let mut law = 99;
        assert_eq!(
            unsafe { contensou_law_from_name(name.as_ptr(), &mut law) },
            S::Ok
        );
        assert_eq!(law, code, "{name:?}");
    }
    // "rolling" names the default rolling law (the library's RowLaw::DEFAULT)
    let default = std::ffi::CString::new(RowLaw::DEFAULT.name()).unwrap();
    let [mut by_alias, mut by_name] = [98, 99];
    for (name, law) in [
        (c"rolling", &mut by_alias),
        (default.as_c_str(), &mut by_name),
    ] {
        assert_eq!(
            unsafe { contensou_law_from_name(name.as_ptr(), law) },
            S::Ok
        );
    }
    assert_eq!(by_alias, by_name);
    assert_eq!(by_alias, CONTENSOU_LAW_TABLE);
    let names: Vec<&str> = (0..=CONTENSOU_ROLLING_COLUMN_NONE)
        .map(|c| text(contensou_rolling_column_name(c)))
        .collect();
    assert_eq!(
        names,
        ["a", "b", "G", "nu", "f", "N", "V", "xi", "eta", "phi", "a/b", ""]
    );
    assert_eq!(text(contensou_rolling_column_name(u32::MAX)), "");
    assert_eq!(
        text(contensou_status_message(S::ShearModulusNotPositive as u32)),
        contensou::Error::ShearModulusNotPositive.as_str()
    );
}

#[test]
fn construction_errors_name_their_column_and_write_nothing() {
    let mut c = storage64();
    let mut col = 99;
    let cases = [
        (
            (1.5, 0.0, 0.28),
            S::ShearModulusNotPositive,
            CONTENSOU_ROLLING_COLUMN_G,
        ),
        (
            (1.5, -8e10, 0.28),
            S::ShearModulusNotPositive,
            CONTENSOU_ROLLING_COLUMN_G,
        ),
        (
            (1.5, f64::INFINITY, 0.28),
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_G,
        ),
        (
            (1.5, f64::NAN, 0.28),
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_G,
        ),
        (
            (1.5, 8e10, 0.51),
            S::RollingPoissonRatioOutOfRange,
            CONTENSOU_ROLLING_COLUMN_NU,
        ),
        (
            (1.5, 8e10, -0.1),
            S::RollingPoissonRatioOutOfRange,
            CONTENSOU_ROLLING_COLUMN_NU,
        ),
        (
            (1.5, 8e10, f64::NAN),
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_NU,
        ),
        (
            (0.009, 8e10, 0.28),
            S::RollingAspectOutOfRange,
            CONTENSOU_ROLLING_COLUMN_A_OVER_B,
        ),
        (
            (101.0, 8e10, 0.28),
            S::RollingAspectOutOfRange,
            CONTENSOU_ROLLING_COLUMN_A_OVER_B,
        ),
        (
            (-1.0, 8e10, 0.28),
            S::RollingAspectOutOfRange,
            CONTENSOU_ROLLING_COLUMN_A_OVER_B,
        ),
        (
            (f64::INFINITY, 8e10, 0.28),
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_A_OVER_B,
        ),
    ];
    for ((r, g, nu), status, column) in cases {
        let s =
            unsafe { contensou_rolling_new_f64(&mut *c, r, g, nu, CONTENSOU_LAW_TABLE, &mut col) };
        assert_eq!((s, col), (status, column), "a/b = {r}, G = {g}, nu = {nu}");
        assert!(c.opaque.iter().all(|&w| w == 0), "storage written on error");
    }
    // f32 too, and the ends of the domains are valid.
    let mut c32 = storage32();
    let s = unsafe {
        contensou_rolling_new_f32(&mut *c32, 1.0, 8e10, 0.7, CONTENSOU_LAW_TABLE, &mut col)
    };
    assert_eq!(
        (s, col),
        (
            S::RollingPoissonRatioOutOfRange,
            CONTENSOU_ROLLING_COLUMN_NU
        )
    );
    for (r, nu) in [(0.01, 0.0), (100.0, 0.5)] {
        let s = unsafe {
            contensou_rolling_new_f64(&mut *c, r, 1.0, nu, CONTENSOU_LAW_TABLE, &mut col)
        };
        assert_eq!((s, col), (S::Ok, CONTENSOU_ROLLING_COLUMN_NONE));
    }
}

#[test]
fn state_errors_name_their_column_and_write_nothing() {
    let mut c = storage64();
    let mut col = 99;
    let s = unsafe {
        contensou_rolling_new_f64(&mut *c, 1.5, 8e10, 0.28, CONTENSOU_LAW_TABLE, null_mut())
    };
    assert_eq!(s, S::Ok);
    let cases = [
        (
            contensou_rolling_state { a: 0.0, ..STATE },
            S::LengthNotPositive,
            CONTENSOU_ROLLING_COLUMN_A,
        ),
        (
            contensou_rolling_state { b: -1e-3, ..STATE },
            S::LengthNotPositive,
            CONTENSOU_ROLLING_COLUMN_B,
        ),
        (
            contensou_rolling_state {
                a: f64::NAN,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_A,
        ),
        (
            contensou_rolling_state { f: -0.1, ..STATE },
            S::FrictionCoefficientNegative,
            CONTENSOU_ROLLING_COLUMN_F,
        ),
        (
            contensou_rolling_state {
                f: f64::INFINITY,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_F,
        ),
        (
            contensou_rolling_state {
                n: f64::NEG_INFINITY,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_N,
        ),
        (
            contensou_rolling_state {
                v: f64::NAN,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_V,
        ),
        (
            contensou_rolling_state {
                xi: f64::INFINITY,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_XI,
        ),
        (
            contensou_rolling_state {
                eta: f64::NAN,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_ETA,
        ),
        (
            contensou_rolling_state {
                phi: -f64::INFINITY,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_PHI,
        ),
        // finite creepages whose slip ξV overflows
        (
            contensou_rolling_state {
                xi: 1e300,
                v: 1e300,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_XI,
        ),
        (
            contensou_rolling_state {
                phi: 1e300,
                v: 1e300,
                ..STATE
            },
            S::NonFinite,
            CONTENSOU_ROLLING_COLUMN_PHI,
        ),
    ];
    for (state, status, column) in cases {
        let mut out = contensou_rolling_output::<f64>::default();
        let s = unsafe { contensou_rolling_wrench_f64(&*c, &state, &mut out, &mut col) };
        assert_eq!((s, col), (status, column), "{state:?}");
        assert_eq!(out, contensou_rolling_output::default(), "written on error");
    }
}

#[test]
fn bad_pointers_and_laws_are_codes() {
    let mut c = storage64();
    let mut out = contensou_rolling_output::<f64>::default();
    let mut col = 99;
    unsafe {
        assert_eq!(
            contensou_rolling_new_f64(null_mut(), 1.5, 8e10, 0.28, CONTENSOU_LAW_TABLE, &mut col),
            S::NullPointer
        );
        assert_eq!(col, CONTENSOU_ROLLING_COLUMN_NONE);
        for law in [CONTENSOU_LAW_BEST, CONTENSOU_LAW_COULOMB, 11, u32::MAX] {
            assert_eq!(
                contensou_rolling_new_f64(&mut *c, 1.5, 8e10, 0.28, law, null_mut()),
                S::InvalidLaw
            );
        }
        // Zeroed storage (as static memory is) was not initialised.
        assert_eq!(
            contensou_rolling_wrench_f64(&*c, &STATE, &mut out, null_mut()),
            S::NotInitialized
        );
        assert_eq!(
            contensou_rolling_new_f64(&mut *c, 1.5, 8e10, 0.28, CONTENSOU_LAW_BLEND, null_mut()),
            S::Ok
        );
        col = 77;
        let column: *mut u32 = &mut col;
        let wrench = |c, s, o| contensou_rolling_wrench_f64(c, s, o, column);
        assert_eq!(each_null(&*c, &STATE, wrench), [S::NullPointer; 3]);
        assert_eq!(col, CONTENSOU_ROLLING_COLUMN_NONE);
        let off = misaligned::<contensou_rolling_f64, _>(c.opaque.as_mut_ptr());
        assert_eq!(
            contensou_rolling_new_f64(off, 1.5, 8e10, 0.28, CONTENSOU_LAW_TABLE, null_mut()),
            S::Misaligned
        );
        assert_eq!(
            contensou_rolling_wrench_f64(off, &STATE, &mut out, null_mut()),
            S::Misaligned
        );
        assert_eq!(out, contensou_rolling_output::default());
        // Neither a f32 rolling contact nor a wrench contact is an f64 rolling contact.
        let mut c32 = storage32();
        assert_eq!(
            contensou_rolling_new_f32(&mut *c32, 1.5, 8e10, 0.28, CONTENSOU_LAW_TABLE, null_mut()),
            S::Ok
        );
        let big = copied::<_, contensou_rolling_f64>(&*c32);
        assert_eq!(
            contensou_rolling_wrench_f64(&*big, &STATE, &mut out, null_mut()),
            S::NotInitialized
        );
        let mut wrench_contact = Box::new(contensou_contact_f64 {
            opaque: [0; CONTENSOU_CONTACT_F64_SIZE / 8],
        });
        let spec = contensou_spec {
            p: 10.0,
            q: 50.0,
            estar: 1.15e11,
            cd: 0.0,
            f: 0.1,
            delta: 1e-4,
        };
        assert_eq!(
            contensou_contact_new_f64(&mut *wrench_contact, &spec, 0, 0, null_mut()),
            S::Ok
        );
        let big = copied::<_, contensou_rolling_f64>(&*wrench_contact); // the tag and the rest
        assert_eq!(
            contensou_rolling_wrench_f64(&*big, &STATE, &mut out, null_mut()),
            S::NotInitialized
        );
    }
}

/// The wrench of `contact_eval rolling`'s body for one row.
fn rust<T: Real, L: RollingLaw>(row: [T; 10]) -> [T; 3] {
    let [a, b, g, nu, f, n, v, xi, eta, phi] = row;
    let contact = RollingContact::new(a / b, Elasticity::new(g, nu).unwrap()).unwrap();
    let patch = Patch::new(a, b, n, f).unwrap();
    let v = if v == T::ZERO { T::ONE } else { v };
    let w = contact.wrench::<L>(
        &patch,
        &RollingSlip::from_creepages(xi, eta, phi, v).unwrap(),
    );
    [w.fx, w.fy, w.mz]
}

macro_rules! c_rolling {
    ($name:ident: $T:ty, $storage:ident, $new:ident, $wrench:ident) => {
        fn $name(law: u32, row: [$T; 10]) -> [$T; 3] {
            let [a, b, g, nu, f, n, v, xi, eta, phi] = row;
            let mut c = $storage();
            let mut out = contensou_rolling_output::default();
            assert_eq!(
                unsafe { $new(&mut *c, a / b, g, nu, law, null_mut()) },
                S::Ok
            );
            let state = contensou_rolling_state {
                a,
                b,
                f,
                n,
                v,
                xi,
                eta,
                phi,
            };
            assert_eq!(unsafe { $wrench(&*c, &state, &mut out, null_mut()) }, S::Ok);
            [out.fx, out.fy, out.mz]
        }
    };
}
c_rolling!(c64: f64, storage64, contensou_rolling_new_f64, contensou_rolling_wrench_f64);
c_rolling!(c32: f32, storage32, contensou_rolling_new_f32, contensou_rolling_wrench_f32);

fn same<L: RollingLaw>(law: u32, row: [f64; 10]) {
    let [got, want] = [c64(law, row), rust::<f64, L>(row)].map(|w| w.map(f64::to_bits));
    assert_eq!(got, want, "{} f64 {row:?}", L::NAME);
    let row32 = row.map(|x| x as f32);
    let [got, want] = [c32(law, row32), rust::<f32, L>(row32)].map(|w| w.map(f32::to_bits));
    assert_eq!(got, want, "{} f32 {row:?}", L::NAME);
}

#[test]
fn the_numbers_are_the_rolling_laws_bit_for_bit() {
    let mut n = 0;
    for (a, b) in [(6e-3, 4e-3), (4e-3, 6e-3), (1e-3, 1e-3), (1e-2, 2e-4)] {
        for v in [30.0, 0.0, -2.0] {
            for (xi, eta, phi) in [
                (0.0, 0.0, 0.0),
                (1e-4, 0.0, 0.0),
                (1e-3, -2e-3, 3.0),
                (0.5, 0.1, -100.0),
            ] {
                for n_ in [8e4, 0.0] {
                    let row = [a, b, 8e10, 0.28, 0.3, n_, v, xi, eta, phi];
                    same::<Table>(CONTENSOU_LAW_TABLE, row);
                    same::<Blend>(CONTENSOU_LAW_BLEND, row);
                    same::<Fastsim>(CONTENSOU_LAW_FASTSIM, row);
                    same::<FastsimGrid<16, 16>>(CONTENSOU_LAW_FASTSIM_16, row);
                    same::<FullSlip>(CONTENSOU_LAW_FULL_SLIP, row);
                    same::<Linear>(CONTENSOU_LAW_LINEAR, row);
                    n += 1;
                }
            }
        }
    }
    assert_eq!(n, 4 * 3 * 4 * 2);
    // A rolling wheel: F_x opposes a small creepage, below fN; V = 0 is the limit V → 0⁺ at
    // the same creepages; a large creepage saturates to full slip, |F_x| = fN.
    let row = |v: f64, xi: f64| [6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, v, xi, 0.0, 0.0];
    let w = c64(CONTENSOU_LAW_TABLE, row(30.0, 1e-4));
    assert!(w[0] < 0.0 && w[0] > -0.3 * 8e4 * 0.5, "{w:?}");
    let w0 = c64(CONTENSOU_LAW_TABLE, row(0.0, 1e-4));
    assert!((w0[0] - w[0]).abs() <= 1e-12 * w[0].abs(), "{w0:?} {w:?}");
    let w = c64(CONTENSOU_LAW_TABLE, row(30.0, 10.0));
    assert!((w[0] + 0.3 * 8e4).abs() < 1e-3 * 0.3 * 8e4, "{w:?}");
}
