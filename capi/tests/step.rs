//! The step-aware wrench through the C API: `contensou_step_many_*` with one contact is
//! `contensou_contact_step_*` bit for bit (whose rows compare.sh checks against `contact_eval
//! step`), with two contacts sharing a body it is the library's `step_wrenches::<2>` bit for
//! bit, every count 1 … 8 dispatches (decoupled contacts give each one's own wrench), and the
//! errors name the count, the column and the contact.
use core::ptr::{null, null_mut};

use contensou::dynamic::{DynContact, Form, Law, RollingSpec, RollingStep, Spec, Step};
use contensou::frame::{Frame, MajorAxis};
use contensou::friction::rolling::RollingVelocity;
use contensou::friction::Slip;
use contensou::jacobian::{Linearize, State};
use contensou::step::contract::Row;
use contensou::step::{step_wrenches, Body, ContactPoint, Free, InverseMass, TimeStep};
use contensou_capi::*;

mod common;
use common::{storage64 as storage, text};

type S = contensou_status;

/// A 20 mm ball on a plane: P = Q = 50 (1/m), steel.
const BALL: contensou_spec<f64> = contensou_spec {
    p: 50.0,
    q: 50.0,
    estar: 1.15e11,
    cd: 0.3,
    f: 0.1,
    delta: 1e-4,
};

/// W of the ball (m = 32.67 g, r = 10 mm) at its contact point, upper triangle.
const BALL_W: contensou_inverse_mass<f64> = contensou_inverse_mass {
    nn: 30.609,
    nx: 0.0,
    ny: 0.0,
    nw: 0.0,
    xx: 107.13,
    xy: 0.0,
    xw: 0.0,
    yy: 107.13,
    yw: 0.0,
    ww: 7.6522e5,
};

fn full(w: &contensou_inverse_mass<f64>) -> [f64; 16] {
    [
        w.nn, w.nx, w.ny, w.nw, w.nx, w.xx, w.xy, w.xw, w.ny, w.xy, w.yy, w.yw, w.nw, w.xw, w.yw,
        w.ww,
    ]
}

/// Start states: resting, sliding and spinning, landing, apart.
const STEPS: [contensou_step<f64>; 4] = [
    contensou_step {
        h: 7.6e-8,
        hdot: 0.0,
        vx: 0.5,
        vy: 0.0,
        omega: 0.0,
    },
    contensou_step {
        h: 2e-7,
        hdot: 1e-3,
        vx: 0.01,
        vy: -0.02,
        omega: 30.0,
    },
    contensou_step {
        h: 1e-9,
        hdot: 0.2,
        vx: 1e-5,
        vy: 2e-5,
        omega: 0.5,
    },
    contensou_step {
        h: -1e-7,
        hdot: 0.0,
        vx: 0.5,
        vy: 0.0,
        omega: 0.0,
    },
];

fn contact(law: u32) -> Box<contensou_contact_f64> {
    let mut st = storage();
    let s = unsafe {
        contensou_contact_new_f64(&mut *st, &BALL, law, CONTENSOU_FORM_FIXED, null_mut())
    };
    assert_eq!(s, S::Ok);
    st
}

fn bits(w: &contensou_step_wrench<f64>) -> [u64; 4] {
    [w.n, w.fx, w.fy, w.tz].map(f64::to_bits)
}

#[test]
fn one_contact_of_many_is_the_single_call_bit_for_bit() {
    let dt = 1e-3;
    for law in [
        CONTENSOU_LAW_BEST,
        CONTENSOU_LAW_COULOMB,
        CONTENSOU_LAW_TABLE,
    ] {
        let c = contact(law);
        for s in &STEPS {
            let roll = contensou_rolling_step {
                vrx: 0.3,
                vry: -0.1,
            };
            let u = contensou_step_velocity {
                vn: -s.hdot - 9.81 * dt,
                vx: s.vx + 1e-3,
                vy: s.vy,
                omega: s.omega,
            };
            for with_free in [false, true] {
                let mut single = contensou_step_wrench::default();
                let up = if with_free { &u as *const _ } else { null() };
                let r = unsafe {
                    contensou_contact_step_f64(
                        &*c,
                        s,
                        &roll,
                        dt,
                        &BALL_W,
                        up,
                        &mut single,
                        null_mut(),
                    )
                };
                assert_eq!(r, S::Ok);
                let uf = if with_free {
                    u
                } else {
                    contensou_step_velocity {
                        vn: -s.hdot,
                        vx: s.vx,
                        vy: s.vy,
                        omega: s.omega,
                    }
                };
                let free = contensou_step_free {
                    u: uf,
                    h: s.h - dt * uf.vn,
                };
                let w = full(&BALL_W);
                let ptrs = [&*c as *const contensou_contact_f64];
                let mut many = [contensou_step_wrench::default()];
                let free: &[_] = if with_free { &[free] } else { &[] };
                let steps = core::slice::from_ref(s);
                let got = step_many(&ptrs, 1, steps, &[roll], dt, &w, free, &mut many);
                assert_eq!(got, (S::Ok, 1, CONTENSOU_COLUMN_NONE));
                assert_eq!(
                    bits(&many[0]),
                    bits(&single),
                    "law {law}, {s:?}, free {with_free}"
                );
            }
        }
    }
}

/// A body resting on two contacts (the tippe top's two spheres, a capsule's ends): W with
/// its cross blocks from the library's `InverseMass::from_bodies`.
fn two_contacts_w() -> InverseMass<f64, 2> {
    let m = 0.02;
    let i = [8e-7, 8e-7, 6e-7];
    let rot = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let body = Body::principal(m, i, rot, [0.0, 0.0, 0.012]).unwrap();
    let frame = Frame::new(
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
        MajorAxis::from_cos_sin(1.0, 0.0),
    );
    let points = [
        ContactPoint {
            a: None,
            b: Some(0),
            point: [0.01, 0.0, 0.0],
            frame,
        },
        ContactPoint {
            a: None,
            b: Some(0),
            point: [-0.01, 0.002, 0.0],
            frame,
        },
    ];
    InverseMass::from_bodies(&[body], &points).unwrap()
}

#[test]
fn two_contacts_sharing_a_body_are_the_librarys_step_wrenches() {
    let w = two_contacts_w();
    let mut flat = [0.0; 64];
    for r in 0..8 {
        for c in 0..8 {
            flat[8 * r + c] = w.get(r, c);
        }
    }
    let dt = 2e-3;
    for law in [CONTENSOU_LAW_BEST, CONTENSOU_LAW_TABLE] {
        let (ca, cb) = (contact(law), contact(law));
        let steps = [STEPS[0], STEPS[1]];
        let rolls = [
            contensou_rolling_step { vrx: 0.2, vry: 0.0 },
            contensou_rolling_step {
                vrx: -0.1,
                vry: 0.05,
            },
        ];
        let frees = [
            contensou_step_free {
                u: contensou_step_velocity {
                    vn: -9.81 * dt,
                    vx: 0.5,
                    vy: 0.0,
                    omega: 0.0,
                },
                h: 7.6e-8 + 9.81 * dt * dt,
            },
            contensou_step_free {
                u: contensou_step_velocity {
                    vn: -1e-3 - 9.81 * dt,
                    vx: 0.01,
                    vy: -0.02,
                    omega: 30.0,
                },
                h: 2e-7 + 1e-6,
            },
        ];
        let ptrs = [&*ca as *const _, &*cb as *const _];
        let mut out = [contensou_step_wrench::default(); 2];
        let (r, ..) = step_many(&ptrs, 2, &steps, &rolls, dt, &flat, &frees, &mut out);
        assert_eq!(r, S::Ok);
        // The library directly.
        let spec = Spec::from(BALL);
        let law_ = [Law::Best, Law::Table][(law == CONTENSOU_LAW_TABLE) as usize];
        let c = DynContact::new_rolling(&spec, &RollingSpec::default(), law_, Form::Fixed).unwrap();
        let rs = rolls.map(|r| RollingStep {
            vrx: r.vrx,
            vry: r.vry,
        });
        let rows = [Row::new(&c, rs[0]), Row::new(&c, rs[1])];
        let states: [State<f64>; 2] = core::array::from_fn(|i| {
            let s = Step::from(steps[i]);
            State {
                h: s.h,
                hdot: s.hdot,
                slip: Slip::new(s.vx, s.vy, s.omega).unwrap(),
                rolling: if law_.is_rolling() {
                    rs[i].velocity().unwrap()
                } else {
                    RollingVelocity::ZERO
                },
            }
        });
        let fr = frees.map(|f| Free::new([f.u.vn, f.u.vx, f.u.vy, f.u.omega], f.h).unwrap());
        let refs: [&dyn Linearize<f64>; 2] = [&rows[0], &rows[1]];
        let o = step_wrenches(refs, TimeStep::new(dt).unwrap(), &w, &states, &fr);
        for i in 0..2 {
            assert_eq!(
                bits(&out[i]),
                o[i].wrench.map(f64::to_bits),
                "law {law}, contact {i}"
            );
        }
        // They share the load: both push, and the cross blocks matter (solved apart they differ).
        assert!(out[0].n > 0.0 && out[1].n > 0.0);
    }
}

/// The 4k × 4k inverse mass of k balls each on its own plane: `BALL_W` block-diagonal.
fn ball_blocks(k: usize) -> Vec<f64> {
    let mut w = vec![0.0; 16 * k * k];
    let b = full(&BALL_W);
    for i in 0..k {
        for r in 0..4 {
            for col in 0..4 {
                w[(4 * i + r) * 4 * k + 4 * i + col] = b[4 * r + col];
            }
        }
    }
    w
}

#[test]
fn every_count_dispatches_and_decoupled_contacts_are_each_ones_own() {
    let dt = 1e-3;
    let c = contact(CONTENSOU_LAW_BEST);
    for k in 1..=CONTENSOU_STEP_MAX_CONTACTS {
        // k balls, each on its own plane: W block-diagonal.
        let w = ball_blocks(k);
        let steps: Vec<_> = (0..k).map(|i| STEPS[i % 3]).collect();
        let ptrs: Vec<*const contensou_contact_f64> = (0..k).map(|_| &*c as *const _).collect();
        let mut out = vec![contensou_step_wrench::default(); k];
        let (r, index, _) = step_many(&ptrs, k, &steps, &[], dt, &w, &[], &mut out);
        assert_eq!((r, index), (S::Ok, k));
        for i in 0..k {
            let mut one = contensou_step_wrench::default();
            let r = unsafe {
                contensou_contact_step_f64(
                    &*c,
                    &steps[i],
                    null(),
                    dt,
                    &BALL_W,
                    null(),
                    &mut one,
                    null_mut(),
                )
            };
            assert_eq!(r, S::Ok);
            for (x, y) in [out[i].n, out[i].fx, out[i].fy, out[i].tz]
                .into_iter()
                .zip([one.n, one.fx, one.fy, one.tz])
            {
                assert!(
                    (x - y).abs() <= 1e-12 * y.abs().max(1e-9),
                    "k {k}, contact {i}: {x} vs {y}"
                );
            }
        }
    }
}

/// The slice's pointer, NULL when it is empty.
fn or_null<T>(s: &[T]) -> *const T {
    if s.is_empty() {
        null()
    } else {
        s.as_ptr()
    }
}

/// `contensou_step_many_f64` over `k` contacts of `ptrs` (the count as given, for the tests
/// of a wrong one), an empty `rolls` or `free` passed as NULL: the status, `*index`, `*column`.
#[allow(clippy::too_many_arguments)]
fn step_many(
    ptrs: &[*const contensou_contact_f64],
    k: usize,
    steps: &[contensou_step<f64>],
    rolls: &[contensou_rolling_step<f64>],
    dt: f64,
    w: &[f64],
    free: &[contensou_step_free<f64>],
    out: &mut [contensou_step_wrench<f64>],
) -> (S, usize, u32) {
    let (mut index, mut column) = (99, 99);
    let r = unsafe {
        contensou_step_many_f64(
            ptrs.as_ptr(),
            k,
            steps.as_ptr(),
            or_null(rolls),
            dt,
            w.as_ptr(),
            or_null(free),
            out.as_mut_ptr(),
            &mut index,
            &mut column,
        )
    };
    (r, index, column)
}

/// `contensou_step_many_f64` on two ball contacts, with `edit` applied to its inputs first.
fn many_error(
    edit: impl FnOnce(
        &mut usize,
        &mut [contensou_step<f64>; 2],
        &mut f64,
        &mut [f64; 64],
        &mut [contensou_step_free<f64>; 2],
    ),
    second: Option<&contensou_contact_f64>,
) -> (S, usize, u32) {
    let c = contact(CONTENSOU_LAW_BEST);
    let mut k = 2;
    let mut steps = [STEPS[0], STEPS[1]];
    let mut dt = 1e-3;
    let mut w = [0.0; 64];
    w.copy_from_slice(&ball_blocks(2));
    let mut free = steps.map(|s| contensou_step_free {
        u: contensou_step_velocity {
            vn: -s.hdot,
            vx: s.vx,
            vy: s.vy,
            omega: s.omega,
        },
        h: s.h,
    });
    edit(&mut k, &mut steps, &mut dt, &mut w, &mut free);
    let ptrs = [
        &*c as *const _,
        second.map_or(&*c as *const _, |s| s as *const _),
    ];
    let mut out = [contensou_step_wrench::default(); 2];
    let got = step_many(&ptrs, k, &steps, &[], dt, &w, &free, &mut out);
    assert!(got.0 == S::Ok || out.iter().all(|o| *o == contensou_step_wrench::default()));
    got
}

#[test]
fn many_errors_name_the_count_the_column_and_the_contact() {
    let none = CONTENSOU_COLUMN_NONE;
    assert_eq!(many_error(|_, _, _, _, _| {}, None), (S::Ok, 2, none));
    assert_eq!(
        many_error(|k, _, _, _, _| *k = 0, None),
        (S::ContactCountOutOfRange, 0, none)
    );
    assert_eq!(
        many_error(|k, _, _, _, _| *k = 9, None),
        (S::ContactCountOutOfRange, 9, none)
    );
    let blank = storage();
    assert_eq!(
        many_error(|_, _, _, _, _| {}, Some(&blank)),
        (S::NotInitialized, 1, none)
    );
    assert_eq!(
        many_error(|_, s, _, _, _| s[1].h = f64::INFINITY, None),
        (S::NonFinite, 1, CONTENSOU_COLUMN_H)
    );
    assert_eq!(
        many_error(|_, _, dt, _, _| *dt = 0.0, None),
        (S::StepNotPositive, 2, CONTENSOU_COLUMN_DT)
    );
    assert_eq!(
        many_error(|_, _, _, w, _| w[8 * 5 + 5] = f64::NAN, None),
        (S::NonFinite, 1, CONTENSOU_COLUMN_W)
    );
    assert_eq!(
        many_error(|_, _, _, w, _| w[8 + 6] = 1.0, None),
        (S::InverseMassNotSymmetric, 2, CONTENSOU_COLUMN_W)
    );
    assert_eq!(
        many_error(|_, _, _, w, _| w[8 * 5 + 5] = -1.0, None),
        (S::InverseMassNotPositiveSemidefinite, 2, CONTENSOU_COLUMN_W)
    );
    assert_eq!(
        many_error(|_, _, _, _, f| f[0].u.vy = f64::NAN, None),
        (S::NonFinite, 0, CONTENSOU_COLUMN_UN_FREE + 2)
    );
    assert_eq!(
        many_error(|_, _, _, _, f| f[1].h = f64::NEG_INFINITY, None),
        (S::NonFinite, 1, CONTENSOU_COLUMN_H_FREE)
    );
    // NULL arrays.
    let r = unsafe {
        contensou_step_many_f64(
            null(),
            1,
            null(),
            null(),
            1e-3,
            null(),
            null(),
            null_mut(),
            null_mut(),
            null_mut(),
        )
    };
    assert_eq!(r, S::NullPointer);
}

#[test]
fn step_columns_have_the_contracts_names() {
    let names = [
        (CONTENSOU_COLUMN_DT, "dt"),
        (CONTENSOU_COLUMN_W_NN, "w_nn"),
        (CONTENSOU_COLUMN_W_NN + 9, "w_ww"),
        (CONTENSOU_COLUMN_W, "W"),
        (CONTENSOU_COLUMN_UN_FREE, "un_free"),
        (CONTENSOU_COLUMN_UN_FREE + 3, "uw_free"),
        (CONTENSOU_COLUMN_H_FREE, "h_free"),
        (CONTENSOU_COLUMN_H_FREE + 1, ""),
        (CONTENSOU_COLUMN_VRY, "vry"),
    ];
    for (code, name) in names {
        assert_eq!(text(contensou_column_name(code)), name);
    }
    assert_eq!(
        text(contensou_status_message(S::ContactCountOutOfRange as u32)),
        "contact count outside 1 ... CONTENSOU_STEP_MAX_CONTACTS (8)"
    );
    // The single call names its columns too: a W entry, W as a whole, a free velocity.
    let c = contact(CONTENSOU_LAW_BEST);
    let single = |w: contensou_inverse_mass<f64>, u: Option<contensou_step_velocity<f64>>| {
        let mut out = contensou_step_wrench::default();
        let mut col = 99;
        let u = u.as_ref().map_or(null(), |u| u as *const _);
        let s = &STEPS[0];
        let r =
            unsafe { contensou_contact_step_f64(&*c, s, null(), 1e-3, &w, u, &mut out, &mut col) };
        (r, col)
    };
    let nan_spin = contensou_step_velocity {
        omega: f64::NAN,
        ..Default::default()
    };
    let cases = [
        (
            contensou_inverse_mass {
                yw: f64::INFINITY,
                ..BALL_W
            },
            None,
            (S::NonFinite, CONTENSOU_COLUMN_W_NN + 8),
        ),
        (
            contensou_inverse_mass {
                nx: 100.0,
                ..BALL_W
            },
            None,
            (S::InverseMassNotPositiveSemidefinite, CONTENSOU_COLUMN_W),
        ),
        (
            BALL_W,
            Some(nan_spin),
            (S::NonFinite, CONTENSOU_COLUMN_UN_FREE + 3),
        ),
    ];
    for (w, u, want) in cases {
        assert_eq!(single(w, u), want);
    }
}

#[test]
fn float_twins_agree_with_the_double_calls_in_sign_and_size() {
    let mut c32 = common::storage32();
    let spec = common::spec_in(|x| x as f32);
    let s = unsafe {
        contensou_contact_new_f32(
            &mut *c32,
            &spec,
            CONTENSOU_LAW_BEST,
            CONTENSOU_FORM_FIXED,
            null_mut(),
        )
    };
    assert_eq!(s, S::Ok);
    let step = contensou_step::<f32> {
        h: 7.6e-8,
        hdot: 0.0,
        vx: 0.5,
        vy: 0.0,
        omega: 0.0,
    };
    let w = contensou_inverse_mass::<f32> {
        nn: 30.609,
        xx: 107.13,
        yy: 107.13,
        ww: 7.6522e5,
        ..Default::default()
    };
    let mut one = contensou_step_wrench::default();
    let r = unsafe {
        contensou_contact_step_f32(&*c32, &step, null(), 1e-3, &w, null(), &mut one, null_mut())
    };
    assert_eq!(r, S::Ok);
    let flat: [f32; 16] = [
        30.609, 0., 0., 0., 0., 107.13, 0., 0., 0., 0., 107.13, 0., 0., 0., 0., 7.6522e5,
    ];
    let mut many = [contensou_step_wrench::default()];
    let free = contensou_step_free {
        u: contensou_step_velocity {
            vn: 0.0,
            vx: 0.5,
            vy: 0.0,
            omega: 0.0,
        },
        h: 7.6e-8,
    };
    let ptrs = [&*c32 as *const _];
    let r = unsafe {
        contensou_step_many_f32(
            ptrs.as_ptr(),
            1,
            &step,
            null(),
            1e-3,
            flat.as_ptr(),
            &free,
            many.as_mut_ptr(),
            null_mut(),
            null_mut(),
        )
    };
    assert_eq!(r, S::Ok);
    assert_eq!(
        [one.n, one.fx, one.fy, one.tz].map(f32::to_bits),
        [many[0].n, many[0].fx, many[0].fy, many[0].tz].map(f32::to_bits)
    );
    // Sliding at 0.5 m/s: friction opposes the slip, bounded by f·N.
    assert!(one.n > 0.0 && one.fx < 0.0 && -one.fx <= 0.1 * one.n * 1.0001);
}
