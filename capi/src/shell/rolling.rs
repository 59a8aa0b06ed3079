//! The generic bodies of the rolling evaluator's functions (`contensou_rolling_*`): the
//! columns of `contact_eval rolling` through the library's row evaluator
//! ([`contensou::friction::rolling::row`]: the same validation, the same column named in an
//! error, the same bits). No formula here.

use core::ffi::CStr;

use contensou::friction::rolling::row::{Rejected, RowContact, RowLaw, RowState};

use super::{bare, check, read, report, store, tagged, write, Precision};
use crate::cstr::c_str;
use crate::status::contensou_status as S;
use crate::types::*;

/// The rolling laws, by `contensou_law` value.
const ROLLING_LAWS: [(contensou_law, RowLaw); 6] = [
    (CONTENSOU_LAW_TABLE, RowLaw::Table),
    (CONTENSOU_LAW_BLEND, RowLaw::Blend),
    (CONTENSOU_LAW_FASTSIM, RowLaw::Fastsim),
    (CONTENSOU_LAW_FASTSIM_16, RowLaw::Fastsim16),
    (CONTENSOU_LAW_FULL_SLIP, RowLaw::FullSlip),
    (CONTENSOU_LAW_LINEAR, RowLaw::Linear),
];

/// The value of a rolling law's name (`contact_eval rolling --law`).
pub(crate) fn rolling_law_of(name: &str) -> Option<contensou_law> {
    let law = RowLaw::from_name(name)?;
    ROLLING_LAWS
        .iter()
        .find(|(_, l)| *l == law)
        .map(|(code, _)| *code)
}

/// NUL-terminated column names, in `contensou_rolling_column` order (the values of `contensou::friction::rolling::row::Column`).
const COLUMN_NAMES: [&CStr; 11] = [
    c_str!("a"),
    c_str!("b"),
    c_str!("G"),
    c_str!("nu"),
    c_str!("f"),
    c_str!("N"),
    c_str!("V"),
    c_str!("xi"),
    c_str!("eta"),
    c_str!("phi"),
    c_str!("a/b"),
];

/// The name of a rolling column code (`""` for `CONTENSOU_ROLLING_COLUMN_NONE` and unknown).
pub(crate) fn rolling_column_name(column: contensou_rolling_column) -> *const core::ffi::c_char {
    match COLUMN_NAMES.get(column as usize) {
        Some(c) => c.as_ptr(),
        None => c_str!("").as_ptr(),
    }
}

type Failure = (S, contensou_rolling_column);

/// The status and column of a refused input.
fn rejected<T>(r: Rejected<T>) -> Failure {
    (r.error.into(), r.column as contensou_rolling_column)
}

// One `report` and one `bare` for both column kinds: their "no column" values are the same
// number.
const _: () = assert!(CONTENSOU_ROLLING_COLUMN_NONE == CONTENSOU_COLUMN_NONE);

/// `contensou_rolling_new_*`: the contact of shape `a_over_b` and elasticity (G, ν), law `law`.
///
/// # Safety
/// `storage` NULL or writable; `column` NULL or writable.
pub(crate) unsafe fn rolling_new<T: Precision>(
    storage: *mut T::RollingStorage,
    a_over_b: T,
    g: T,
    nu: T,
    law: contensou_law,
    column: *mut contensou_rolling_column,
) -> S {
    let r = (|| {
        check(storage).map_err(bare)?;
        let (_, law) = ROLLING_LAWS
            .iter()
            .find(|(code, _)| *code == law)
            .ok_or(bare(S::InvalidLaw))?;
        let contact = RowContact::new(a_over_b, g, nu, *law).map_err(rejected)?;
        // SAFETY: checked non-NULL and aligned; the slot fits (types/rolling.rs).
        unsafe { store(storage, T::ROLLING_TAG, contact) };
        Ok(())
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// The rolling contact in a storage, if `contensou_rolling_new_*` of this precision wrote it.
///
/// # Safety
/// `storage` NULL or readable.
unsafe fn rolling_slot<'a, T: Precision>(
    storage: *const T::RollingStorage,
) -> Result<&'a RollingSlot<T>, S> {
    // SAFETY: caller's contract; `RollingSlot` is `repr(C)` with its tag first, aligned for the
    // storage (8) and fits in it (asserted in types/rolling.rs); only `rolling_new` writes the
    // tag, together with a valid contact.
    unsafe { tagged(storage, T::ROLLING_TAG) }
}

/// `contensou_rolling_wrench_*`.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn rolling_wrench<T: Precision>(
    storage: *const T::RollingStorage,
    state: *const contensou_rolling_state<T>,
    out: *mut contensou_rolling_output<T>,
    column: *mut contensou_rolling_column,
) -> S {
    let r = (|| {
        // SAFETY: caller's contract.
        let slot = unsafe { rolling_slot::<T>(storage) }.map_err(bare)?;
        // SAFETY: caller's contract.
        let s = unsafe { read(state) }.map_err(bare)?;
        check(out).map_err(bare)?;
        let w = slot.contact.wrench(&RowState::from(s)).map_err(rejected)?;
        let w = contensou_rolling_output::from(w);
        // SAFETY: caller's contract.
        unsafe { write(out, w) }.map_err(bare)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}
