//! The wrench's Jacobian: N, F_x, F_y, T_z and their 20 derivatives with respect to
//! (h, ḣ, v_x, v_y, ω) — the columns of `contact_eval jacobian`, bit for bit.

#[cfg(doc)]
use super::{contensou_contact_new_f32, contensou_contact_wrench_f32};
use contensou::dynamic::DynContact;

use crate::shell;
use crate::status::contensou_status;
use crate::types::*;

twins! {
    /// The wrench of one step and its Jacobian ([`contensou_jacobian`]): `step` validated as
    /// by [`contensou_contact_wrench_f32`] (the same errors and columns), N, F_x, F_y, T_z bit
    /// for bit its values, the derivatives by forward-mode dual numbers through the library's
    /// own code (`contensou::jacobian`: at a law's kink the derivative of the branch the value
    /// takes; h ≤ 0 gives zeros). A rolling law takes V = 0
    /// ([`contensou_contact_jacobian_rolling_f32`]). Bit for bit `contact_eval jacobian`.
    /// Fixed cost: ≈ 8× the wrench's (≈ 1,540 M4F `float` instructions for fixed `best`; the wrench 184).
    ///
    /// # Safety
    /// `storage` is NULL or readable; `step` NULL or readable; `out`, `column` NULL or writable.
    fn contensou_contact_jacobian_f32, contensou_contact_jacobian_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        step: *const contensou_step<f32> | *const contensou_step<f64>,
        out: *mut contensou_jacobian<f32> | *mut contensou_jacobian<f64>,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        let rolling = core::ptr::null();
        unsafe { shell::rolling_with(storage, step, rolling, out, column, DynContact::jacobian_rolling) }
    }
}

twins! {
    /// [`contensou_contact_jacobian_f32`] with the rolling velocity `rolling` (`vrx, vry`, m/s
    /// in the contact frame; NULL: 0), read and validated after the step by the rolling laws
    /// only (errors name `CONTENSOU_COLUMN_VRX` / `_VRY`); V is held fixed (no derivative with
    /// respect to it). Bit for bit `contact_eval jacobian` with the columns `vrx, vry`.
    ///
    /// # Safety
    /// As [`contensou_contact_jacobian_f32`]; `rolling` NULL or readable.
    fn contensou_contact_jacobian_rolling_f32, contensou_contact_jacobian_rolling_f64(
        storage: *const contensou_contact_f32 | *const contensou_contact_f64,
        step: *const contensou_step<f32> | *const contensou_step<f64>,
        rolling: *const contensou_rolling_step<f32> | *const contensou_rolling_step<f64>,
        out: *mut contensou_jacobian<f32> | *mut contensou_jacobian<f64>,
        column: *mut contensou_column | *mut contensou_column,
    ) -> contensou_status {
        unsafe { shell::rolling_with(storage, step, rolling, out, column, DynContact::jacobian_rolling) }
    }
}
