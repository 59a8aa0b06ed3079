//! The rolling evaluator: Kalker's rolling contact with the columns of
//! `contact_eval rolling` (`a,b,G,nu,f,N,V,xi,eta,phi` → `Fx,Fy,Mz`), bit for bit.

use core::ffi::c_char;

#[cfg(doc)]
use super::{
    contensou_contact_new_f32, contensou_contact_wrench_f32, contensou_contact_wrench_many_f32,
};
use contensou::dynamic::DynContact;

use crate::shell;
use crate::status::contensou_status;
use crate::types::*;

/// The name of a rolling column (`"a"`, …, `"phi"`, `"a/b"`): a static NUL-terminated
/// string, `""` for `CONTENSOU_ROLLING_COLUMN_NONE` and unknown values.
#[no_mangle]
pub extern "C" fn contensou_rolling_column_name(column: contensou_rolling_column) -> *const c_char {
    shell::rolling_column_name(column)
}

twins! {
    /// Validates the elasticity (G (Pa) > 0, ν ∈ [0, 0.5]) and the shape a/b ∈ [0.01, 100] (a
    /// along the rolling direction) and builds a rolling contact of the rolling law `law`
    /// (`CONTENSOU_LAW_TABLE` … `CONTENSOU_LAW_LINEAR`; others: `INVALID_LAW`) into `storage`
    /// (left unchanged on error). The column of a rejected input goes to `*column` (`column` may
    /// be NULL). Cost: Kalker's coefficients and `best`'s full-slip tables (≈ 16,000 M4F f32
    /// instructions), once.
    ///
    /// # Safety
    /// `storage` is NULL or writable; `column` NULL or writable.
    fn contensou_rolling_new_f32, contensou_rolling_new_f64(
        storage: *mut contensou_rolling_f32 | *mut contensou_rolling_f64,
        a_over_b: f32 | f64,
        shear_modulus: f32 | f64,
        poisson: f32 | f64,
        law: contensou_law | contensou_law,
        column: *mut contensou_rolling_column | *mut contensou_rolling_column,
    ) -> contensou_status {
        unsafe { shell::rolling_new(storage, a_over_b, shear_modulus, poisson, law, column) }
    }
}

twins! {
    /// One evaluation: validates `state` (a, b > 0, f ≥ 0, all finite; the column of a rejected
    /// value goes to `*column`) and writes F_x, F_y, M_z on body B into `*out`: bit for bit
    /// `contact_eval rolling` on the row `a,b,G,nu,f,N,V,xi,eta,phi` for a contact built with
    /// a/b = `a / b` (computed in this precision). Fixed cost per law.
    ///
    /// # Safety
    /// `storage` is NULL or readable; `state` NULL or readable; `out`, `column` NULL or writable.
    fn contensou_rolling_wrench_f32, contensou_rolling_wrench_f64(
        storage: *const contensou_rolling_f32 | *const contensou_rolling_f64,
        state: *const contensou_rolling_state<f32> | *const contensou_rolling_state<f64>,
        out: *mut contensou_rolling_output<f32> | *mut contensou_rolling_output<f64>,
        column: *mut contensou_rolling_column | *mut contensou_rolling_column,
    ) -> contensou_status {
        unsafe { shell::rolling_wrench(storage, state, out, column) }
    }
}

// The rolling laws in the wrench contract (`contensou_contact_*`): the optional columns
// `G, nu` (contact) and `vrx, vry` (step) of `contensou::dynamic` and `contact_eval wrench`.

twins! {
    /// [`contensou_contact_new_f32`] with the optional rolling columns: `shear_modulus` (G > 0,
    /// Pa) and `poisson` (ν ∈ [0, 0.5]), each NULL for its default (G = E*·(1 − ν), ν = 0.3).
    /// Read and validated by the rolling laws (`CONTENSOU_LAW_TABLE`, `_BLEND`, `_FASTSIM`,
    /// `_FASTSIM_16`) only; errors name `CONTENSOU_COLUMN_G` / `_NU`. With both NULL this is
    /// [`contensou_contact_new_f32`].
    ///
    /// # Safety
    /// As [`contensou_contact_new_f32`]; `shear_modulus`, `poisson` NULL or readable.
    fn contensou_contact_new_rolling_f32, contensou_contact_new_rolling_f64(
        storage: *mut contensou_contact_f32 | *mut contensou_contact_f64,
        spec: *const contensou_spec<f32> | *const contensou_spec<f64>,
        shear_modulus: *const f32 | *const f64,
        poisson: *const f32 | *const f64,
        law: contensou_law | contensou_law,
        form: contensou_form | contensou_form,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_new_rolling(storage, spec, shear_modulus, poisson, law, form, column) }
    }
}

twins! {
    /// [`contensou_contact_wrench_f32`] with the rolling velocity `rolling` (`vrx, vry`: m/s in
    /// the contact frame; NULL: 0, i.e. full slip), validated after the step (finite; errors
    /// name `CONTENSOU_COLUMN_VRX` / `_VRY`) by the rolling laws only: the sliding laws give
    /// [`contensou_contact_wrench_f32`]'s bits whatever `rolling` holds. Bit for bit
    /// `contact_eval wrench` with the columns `vrx, vry`.
    ///
    /// # Safety
    /// As [`contensou_contact_wrench_f32`]; `rolling` NULL or readable.
    fn contensou_contact_wrench_rolling_f32, contensou_contact_wrench_rolling_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        step: *const contensou_step<f32> | *const contensou_step<f64>,
        rolling: *const contensou_rolling_step<f32> | *const contensou_rolling_step<f64>,
        out: *mut contensou_wrench<f32> | *mut contensou_wrench<f64>,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::rolling_with(storage, step, rolling, out, column, DynContact::wrench_rolling) }
    }
}

twins! {
    /// [`contensou_contact_wrench_many_f32`] with the rolling velocity columns `rolling` (two
    /// arrays of `rows` values; NULL: V = 0 on every row, exactly
    /// [`contensou_contact_wrench_many_f32`]): row i is bit for bit
    /// [`contensou_contact_wrench_rolling_f32`] on row i (a scalar loop when `rolling` is given).
    /// Errors as [`contensou_contact_wrench_many_f32`], `CONTENSOU_COLUMN_VRX` / `_VRY` too.
    ///
    /// # Safety
    /// As [`contensou_contact_wrench_many_f32`]; `rolling` NULL or readable, its arrays NULL or
    /// holding `rows` values.
    fn contensou_contact_wrench_many_rolling_f32, contensou_contact_wrench_many_rolling_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        rows: usize | usize,
        steps: *const contensou_step_columns<f32> | *const contensou_step_columns<f64>,
        rolling: *const contensou_rolling_step_columns<f32> | *const contensou_rolling_step_columns<f64>,
        out: *const contensou_wrench_columns<f32> | *const contensou_wrench_columns<f64>,
        row: *mut usize | *mut usize,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::contact_wrench_many_rolling(storage, rows, steps, rolling, out, row, column) }
    }
}
