//! The rolling evaluator (issue 20): Kalker's rolling contact with the columns of
//! `contact_eval rolling` (`a,b,G,nu,f,N,V,xi,eta,phi` → `Fx,Fy,Mz`), bit for bit.

use core::ffi::c_char;

use crate::shell;
use crate::status::contensou_status;
use crate::types::*;

/// The name of a rolling column (`"a"`, …, `"phi"`, `"a/b"`): a static NUL-terminated
/// string, `""` for `CONTENSOU_ROLLING_COLUMN_NONE` and unknown values.
#[no_mangle]
pub extern "C" fn contensou_rolling_column_name(column: contensou_rolling_column) -> *const c_char {
    shell::rolling_column_name(column)
}

/// Validates the elasticity (G (Pa) > 0, ν ∈ [0, 0.5]) and the shape a/b ∈ [0.01, 100] (a
/// along the rolling direction) and builds a rolling contact of the rolling law `law`
/// (`CONTENSOU_LAW_TABLE` … `CONTENSOU_LAW_LINEAR`; others: `INVALID_LAW`) into `storage`
/// (left unchanged on error). The column of a rejected input goes to `*column` (`column` may
/// be NULL). Cost: Kalker's coefficients and `best`'s full-slip tables (≈ 16,000 M4F f32
/// instructions), once.
///
/// # Safety
/// `storage` is NULL or writable; `column` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn contensou_rolling_new_f32(
    storage: *mut contensou_rolling_f32,
    a_over_b: f32,
    shear_modulus: f32,
    poisson: f32,
    law: contensou_law,
    column: *mut contensou_rolling_column,
) -> contensou_status {
    unsafe { shell::rolling_new(storage, a_over_b, shear_modulus, poisson, law, column) }
}

/// [`contensou_rolling_new_f32`] in `double`.
///
/// # Safety
/// As [`contensou_rolling_new_f32`].
#[no_mangle]
pub unsafe extern "C" fn contensou_rolling_new_f64(
    storage: *mut contensou_rolling_f64,
    a_over_b: f64,
    shear_modulus: f64,
    poisson: f64,
    law: contensou_law,
    column: *mut contensou_rolling_column,
) -> contensou_status {
    unsafe { shell::rolling_new(storage, a_over_b, shear_modulus, poisson, law, column) }
}

/// One evaluation: validates `state` (a, b > 0, f ≥ 0, all finite; the column of a rejected
/// value goes to `*column`) and writes F_x, F_y, M_z on body B into `*out`: bit for bit
/// `contact_eval rolling` on the row `a,b,G,nu,f,N,V,xi,eta,phi` for a contact built with
/// a/b = `a / b` (computed in this precision). Fixed cost per law.
///
/// # Safety
/// `storage` is NULL or readable; `state` NULL or readable; `out`, `column` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn contensou_rolling_wrench_f32(
    storage: *const contensou_rolling_f32,
    state: *const contensou_rolling_state<f32>,
    out: *mut contensou_rolling_output<f32>,
    column: *mut contensou_rolling_column,
) -> contensou_status {
    unsafe { shell::rolling_wrench(storage, state, out, column) }
}

/// [`contensou_rolling_wrench_f32`] in `double`.
///
/// # Safety
/// As [`contensou_rolling_wrench_f32`].
#[no_mangle]
pub unsafe extern "C" fn contensou_rolling_wrench_f64(
    storage: *const contensou_rolling_f64,
    state: *const contensou_rolling_state<f64>,
    out: *mut contensou_rolling_output<f64>,
    column: *mut contensou_rolling_column,
) -> contensou_status {
    unsafe { shell::rolling_wrench(storage, state, out, column) }
}
