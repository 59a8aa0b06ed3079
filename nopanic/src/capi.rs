//! Probes of every function the C API (`capi/`, crate `contensou-capi`) exports, in both
//! precisions: each is called on black-boxed values **and** black-boxed pointers (the proof
//! covers any pointer a C caller can pass: NULL, misaligned, storage never initialised).
//! Counted by tools/no-panic.sh: `probe_capi_*` once per precision, `probe_capi_any_*` once.

use core::ffi::c_char;
use core::hint::black_box;

use contensou_capi::*;

/// A pointer the optimiser knows nothing about.
#[inline(always)]
fn ptr<P>(p: P) -> P {
    black_box(p)
}

/// A step of black-boxed values.
#[inline(always)]
fn step<T>(v: fn(f64) -> T) -> contensou_step<T> {
    contensou_step {
        h: v(1e-6),
        hdot: v(0.0),
        vx: v(0.01),
        vy: v(0.0),
        omega: v(50.0),
    }
}

/// Step columns all reading `x`, output columns writing `o` (black-boxed pointers).
#[inline(always)]
fn columns<T>(
    x: &[T; 9],
    o: &mut [[T; 9]; 7],
) -> (contensou_step_columns<T>, contensou_wrench_columns<T>) {
    let steps = contensou_step_columns {
        h: ptr(x.as_ptr()),
        hdot: ptr(x.as_ptr()),
        vx: ptr(x.as_ptr()),
        vy: ptr(x.as_ptr()),
        omega: ptr(x.as_ptr()),
    };
    let [n, fx, fy, tz, a, b, e2] = o.each_mut().map(|c| ptr(c.as_mut_ptr()));
    let out = contensou_wrench_columns {
        n,
        fx,
        fy,
        tz,
        a,
        b,
        e2,
    };
    (steps, out)
}

/// One module of probes per precision (`$m32` in `f32`, `$m64` in `f64`): every exported
/// function, each given as its `[_f32, _f64]` pair.
macro_rules! precision_probes {
    (
        $m32:ident, $m64:ident;
        storage = [$s32:ident, $s64:ident], words = [$w32:expr, $w64:expr],
        rolling = [$r32:ident, $r64:ident], rolling_words = [$rw32:expr, $rw64:expr],
        $($key:ident = [$f32:ident, $f64:ident]),* $(,)?
    ) => {
        precision_probes!(@module $m32: f32, $s32, $w32, $r32, $rw32; $($key = $f32),*);
        precision_probes!(@module $m64: f64, $s64, $w64, $r64, $rw64; $($key = $f64),*);
    };
    (@module $m:ident: $T:ty, $storage:ident, $words:expr, $rolling:ident, $rwords:expr;
     new = $new:ident, set = $set:ident, wrench = $wrench:ident, many = $many:ident,
     curvatures_new = $curv_new:ident, sphere_plane = $sphere_plane:ident,
     sphere_sphere = $sphere_sphere:ident, ball_race = $ball_race:ident,
     modulus = $modulus:ident,
     new_rolling = $new_rolling:ident, wrench_rolling = $wrench_rolling:ident,
     many_rolling = $many_rolling:ident, rolling_new = $rnew:ident, rolling_wrench = $rwrench:ident,
     jacobian = $jacobian:ident, jacobian_rolling = $jacobian_rolling:ident,
     step = $single:ident, step_many = $step_many:ident) => {
        pub(crate) mod $m {
            use super::*;

            fn v(x: f64) -> $T {
                black_box(x as $T)
            }

            /// A contact storage of black-boxed (zero) words: never initialised, as far as
            /// the optimiser knows.
            fn storage() -> $storage {
                $storage {
                    opaque: black_box([0; $words]),
                }
            }

            /// A rolling storage, as [`storage`].
            fn rolling_storage() -> $rolling {
                $rolling {
                    opaque: black_box([0; $rwords]),
                }
            }

            fn spec() -> contensou_spec<$T> {
                contensou_spec {
                    p: v(1.0),
                    q: v(2.0),
                    estar: v(3.0),
                    cd: v(0.0),
                    f: v(0.1),
                    delta: v(1e-4),
                }
            }

            fn roll() -> contensou_rolling_step<$T> {
                contensou_rolling_step {
                    vrx: v(1.0),
                    vry: v(0.1),
                }
            }

            fn velocity() -> contensou_step_velocity<$T> {
                contensou_step_velocity {
                    vn: v(-1e-2),
                    vx: v(0.01),
                    vy: v(0.0),
                    omega: v(50.0),
                }
            }

            #[inline(never)]
            fn probe_capi_contact_new() {
                let mut s = storage();
                let mut col = black_box(0);
                let r = unsafe {
                    $new(
                        ptr(&mut s),
                        ptr(&spec()),
                        black_box(0),
                        black_box(1),
                        ptr(&mut col),
                    )
                };
                black_box((r, &s, col));
            }

            #[inline(never)]
            fn probe_capi_contact_set_curvatures() {
                let mut s = storage();
                let mut col = black_box(0);
                let r = unsafe { $set(ptr(&mut s), v(1.0), v(2.0), ptr(&mut col)) };
                black_box((r, &s, col));
            }

            #[inline(never)]
            fn probe_capi_contact_wrench() {
                let s = storage();
                let step = step::<$T>(v);
                let mut w = contensou_wrench::<$T>::default();
                let mut col = black_box(0);
                let r = unsafe { $wrench(ptr(&s), ptr(&step), ptr(&mut w), ptr(&mut col)) };
                black_box((r, w, col));
            }

            #[inline(never)]
            fn probe_capi_contact_wrench_many() {
                let s = storage();
                let x = [v(1e-6); 9];
                let mut o: [[$T; 9]; 7] = [[v(0.0); 9]; 7];
                let (steps, out) = columns(&x, &mut o);
                let (mut row, mut col) = (black_box(0), black_box(0));
                let r = unsafe {
                    $many(
                        ptr(&s),
                        black_box(9),
                        ptr(&steps),
                        ptr(&out),
                        ptr(&mut row),
                        ptr(&mut col),
                    )
                };
                black_box((r, o, row, col));
            }

            #[inline(never)]
            fn probe_capi_curvatures() {
                let mut c = contensou_curvatures::<$T>::default();
                let r = unsafe {
                    (
                        $curv_new(v(1.0), v(2.0), ptr(&mut c)),
                        $sphere_plane(v(1.0), ptr(&mut c)),
                        $sphere_sphere(v(1.0), v(-2.0), ptr(&mut c)),
                        $ball_race(v(1.0), v(0.52), v(5.0), v(0.1), black_box(1), ptr(&mut c)),
                    )
                };
                black_box((r, c));
            }

            #[inline(never)]
            fn probe_capi_modulus_of() {
                let mut e = v(0.0);
                let r = unsafe { $modulus(v(2e11), v(0.3), v(7e10), v(0.33), ptr(&mut e)) };
                black_box((r, e));
            }

            #[inline(never)]
            fn probe_capi_contact_new_rolling() {
                let mut s = storage();
                let (g, nu) = (v(1e9), v(0.3));
                let mut col = black_box(0);
                let r = unsafe {
                    $new_rolling(
                        ptr(&mut s),
                        ptr(&spec()),
                        ptr(&g),
                        ptr(&nu),
                        black_box(5),
                        black_box(1),
                        ptr(&mut col),
                    )
                };
                black_box((r, &s, col));
            }

            #[inline(never)]
            fn probe_capi_contact_wrench_rolling() {
                let s = storage();
                let step = step::<$T>(v);
                let mut w = contensou_wrench::<$T>::default();
                let mut col = black_box(0);
                let r = unsafe {
                    $wrench_rolling(
                        ptr(&s),
                        ptr(&step),
                        ptr(&roll()),
                        ptr(&mut w),
                        ptr(&mut col),
                    )
                };
                black_box((r, w, col));
            }

            #[inline(never)]
            fn probe_capi_contact_wrench_many_rolling() {
                let s = storage();
                let x = [v(1e-6); 9];
                let mut o: [[$T; 9]; 7] = [[v(0.0); 9]; 7];
                let (steps, out) = columns(&x, &mut o);
                let roll = contensou_rolling_step_columns::<$T> {
                    vrx: ptr(x.as_ptr()),
                    vry: ptr(x.as_ptr()),
                };
                let (mut row, mut col) = (black_box(0), black_box(0));
                let r = unsafe {
                    $many_rolling(
                        ptr(&s),
                        black_box(9),
                        ptr(&steps),
                        ptr(&roll),
                        ptr(&out),
                        ptr(&mut row),
                        ptr(&mut col),
                    )
                };
                black_box((r, o, row, col));
            }

            #[inline(never)]
            fn probe_capi_rolling_new() {
                let mut s = rolling_storage();
                let mut col = black_box(0);
                let r = unsafe {
                    $rnew(
                        ptr(&mut s),
                        v(1.5),
                        v(8e10),
                        v(0.28),
                        black_box(5),
                        ptr(&mut col),
                    )
                };
                black_box((r, &s, col));
            }

            #[inline(never)]
            fn probe_capi_rolling_wrench() {
                let s = rolling_storage();
                let state = contensou_rolling_state::<$T> {
                    a: v(6e-3),
                    b: v(4e-3),
                    f: v(0.3),
                    n: v(8e4),
                    v: v(30.0),
                    xi: v(1e-3),
                    eta: v(0.0),
                    phi: v(1.0),
                };
                let mut out = contensou_rolling_output::<$T>::default();
                let mut col = black_box(0);
                let r = unsafe { $rwrench(ptr(&s), ptr(&state), ptr(&mut out), ptr(&mut col)) };
                black_box((r, out, col));
            }

            #[inline(never)]
            fn probe_capi_contact_jacobian() {
                let s = storage();
                let step = step::<$T>(v);
                let mut j = contensou_jacobian::<$T>::default();
                let mut col = black_box(0);
                let r = unsafe {
                    (
                        $jacobian(ptr(&s), ptr(&step), ptr(&mut j), ptr(&mut col)),
                        $jacobian_rolling(
                            ptr(&s),
                            ptr(&step),
                            ptr(&roll()),
                            ptr(&mut j),
                            ptr(&mut col),
                        ),
                    )
                };
                black_box((r, j, col));
            }

            #[inline(never)]
            fn probe_capi_contact_step() {
                let s = storage();
                let w = contensou_inverse_mass {
                    nn: v(30.0),
                    nx: v(0.0),
                    ny: v(0.0),
                    nw: v(0.0),
                    xx: v(100.0),
                    xy: v(0.0),
                    xw: v(0.0),
                    yy: v(100.0),
                    yw: v(0.0),
                    ww: v(7e5),
                };
                let (st, mut out, mut col) =
                    (step(v), contensou_step_wrench::default(), black_box(0));
                let r = unsafe {
                    $single(
                        ptr(&s),
                        ptr(&st),
                        ptr(&roll()),
                        v(1e-3),
                        ptr(&w),
                        ptr(&velocity()),
                        ptr(&mut out),
                        ptr(&mut col),
                    )
                };
                black_box((r, out, col));
            }

            #[inline(never)]
            fn probe_capi_step_many() {
                const M: usize = CONTENSOU_STEP_MAX_CONTACTS;
                let s = storage();
                let contacts: [*const $storage; M] = [ptr(&s as *const $storage); M];
                let steps = [step(v); M];
                let roll = [roll(); M];
                let w = [v(0.0); 16 * M * M];
                let free = [contensou_step_free {
                    u: velocity(),
                    h: v(1e-6),
                }; M];
                let mut out = [contensou_step_wrench::default(); M];
                let (mut index, mut col) = (black_box(0), black_box(0));
                let r = unsafe {
                    $step_many(
                        ptr(contacts.as_ptr()),
                        black_box(3),
                        ptr(steps.as_ptr()),
                        ptr(roll.as_ptr()),
                        v(1e-3),
                        ptr(w.as_ptr()),
                        ptr(free.as_ptr()),
                        ptr(out.as_mut_ptr()),
                        ptr(&mut index),
                        ptr(&mut col),
                    )
                };
                black_box((r, out, index, col));
            }

            pub(crate) fn run() {
                probe_capi_contact_new();
                probe_capi_contact_set_curvatures();
                probe_capi_contact_wrench();
                probe_capi_contact_wrench_many();
                probe_capi_curvatures();
                probe_capi_modulus_of();
                probe_capi_contact_new_rolling();
                probe_capi_contact_wrench_rolling();
                probe_capi_contact_wrench_many_rolling();
                probe_capi_rolling_new();
                probe_capi_rolling_wrench();
                probe_capi_contact_jacobian();
                probe_capi_contact_step();
                probe_capi_step_many();
            }
        }
    };
}

precision_probes! {
    single, double;
    storage = [contensou_contact_f32, contensou_contact_f64],
    words = [CONTENSOU_CONTACT_F32_SIZE / 8, CONTENSOU_CONTACT_F64_SIZE / 8],
    rolling = [contensou_rolling_f32, contensou_rolling_f64],
    rolling_words = [CONTENSOU_ROLLING_F32_SIZE / 8, CONTENSOU_ROLLING_F64_SIZE / 8],
    new = [contensou_contact_new_f32, contensou_contact_new_f64],
    set = [contensou_contact_set_curvatures_f32, contensou_contact_set_curvatures_f64],
    wrench = [contensou_contact_wrench_f32, contensou_contact_wrench_f64],
    many = [contensou_contact_wrench_many_f32, contensou_contact_wrench_many_f64],
    curvatures_new = [contensou_curvatures_new_f32, contensou_curvatures_new_f64],
    sphere_plane = [contensou_curvatures_sphere_plane_f32, contensou_curvatures_sphere_plane_f64],
    sphere_sphere = [contensou_curvatures_sphere_sphere_f32, contensou_curvatures_sphere_sphere_f64],
    ball_race = [contensou_curvatures_ball_race_f32, contensou_curvatures_ball_race_f64],
    modulus = [contensou_modulus_of_f32, contensou_modulus_of_f64],
    new_rolling = [contensou_contact_new_rolling_f32, contensou_contact_new_rolling_f64],
    wrench_rolling = [contensou_contact_wrench_rolling_f32, contensou_contact_wrench_rolling_f64],
    many_rolling = [contensou_contact_wrench_many_rolling_f32, contensou_contact_wrench_many_rolling_f64],
    rolling_new = [contensou_rolling_new_f32, contensou_rolling_new_f64],
    rolling_wrench = [contensou_rolling_wrench_f32, contensou_rolling_wrench_f64],
    jacobian = [contensou_contact_jacobian_f32, contensou_contact_jacobian_f64],
    jacobian_rolling = [contensou_contact_jacobian_rolling_f32, contensou_contact_jacobian_rolling_f64],
    step = [contensou_contact_step_f32, contensou_contact_step_f64],
    step_many = [contensou_step_many_f32, contensou_step_many_f64],
}

#[inline(never)]
fn probe_capi_any_messages() {
    black_box((
        contensou_status_message(black_box(3)),
        contensou_column_name(black_box(4)),
        contensou_rolling_column_name(black_box(4)),
    ));
}

#[inline(never)]
fn probe_capi_any_names() {
    let name: *const c_char = ptr(b"pade\0".as_ptr().cast());
    let (mut law, mut form) = (black_box(0), black_box(0));
    let r = unsafe {
        (
            contensou_law_from_name(name, ptr(&mut law)),
            contensou_form_from_name(name, ptr(&mut form)),
        )
    };
    black_box((r, law, form));
}

pub(crate) fn run() {
    single::run();
    double::run();
    probe_capi_any_messages();
    probe_capi_any_names();
}
