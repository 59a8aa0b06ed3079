//! The generic body of `contensou_contact_jacobian_*` and `…_jacobian_rolling_*`: the
//! contract's [`DynContact::jacobian_rolling`] (the same validation and errors as the wrench,
//! the same bits as `contact_eval jacobian`). No formula here.

use contensou::dynamic::{DynContact, RollingStep, Step};

use super::{bare, check, invalid, optional, read, report, slot, write, Precision};
use crate::status::contensou_status as S;
use crate::types::*;

/// `contensou_contact_jacobian_rolling_*` (`rolling` NULL: V = 0; the plain call passes NULL,
/// which is [`DynContact::jacobian`]). Checked in the order of the wrench: storage, step,
/// output, then the rolling columns.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn contact_jacobian_rolling<T: Precision>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    rolling: *const contensou_rolling_step<T>,
    out: *mut contensou_jacobian<T>,
    column: *mut contensou_column,
) -> S {
    let r = (|| {
        // SAFETY: caller's contract.
        let slot = unsafe { slot::<T>(storage) }.map_err(bare)?;
        // SAFETY: caller's contract.
        let s = unsafe { read(step) }.map_err(bare)?;
        check(out).map_err(bare)?;
        // SAFETY: caller's contract.
        let roll = unsafe { optional(rolling) }
            .map_err(bare)?
            .unwrap_or_default();
        let roll = RollingStep {
            vrx: roll.vrx,
            vry: roll.vry,
        };
        let contact: &DynContact<T> = &slot.contact;
        let j = contact
            .jacobian_rolling(&Step::from(s), &roll)
            .map_err(invalid)?;
        // SAFETY: caller's contract.
        unsafe { write(out, contensou_jacobian::from(j)) }.map_err(bare)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}
