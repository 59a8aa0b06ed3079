//! `contensou_contact_wrench_many_*`: the batch path (`contensou::batch`, through
//! `DynContact::wrench_many`) over caller arrays. The pointer checks are paid once per array,
//! the dispatch once per call; every row is bit for bit `contensou_contact_wrench_*`'s.

use contensou::batch::{BatchReal, Steps, Wrenches};
use contensou::dynamic::RollingSteps;

use super::{bare, check, column_of, read, report_at, slot, Precision};
use crate::status::contensou_status as S;
use crate::types::*;

/// `rows` values of `T` from `p` (no pointer is read for 0 rows).
///
/// # Safety
/// `p` NULL or valid for `rows` reads (C's contract).
unsafe fn input<'a, T>(p: *const T, rows: usize) -> Result<&'a [T], S> {
    if rows == 0 {
        return Ok(&[]);
    }
    check(p)?;
    // SAFETY: non-NULL, aligned (checked), `rows` readable values by the caller's contract;
    // `rows` ≤ isize::MAX / size_of::<T>() (checked by the caller of `input`).
    Ok(unsafe { core::slice::from_raw_parts(p, rows) })
}

/// `rows` writable values of `T` at `p`.
///
/// # Safety
/// `p` NULL or valid for `rows` writes, not overlapping any other column (C's contract).
unsafe fn output<'a, T>(p: *mut T, rows: usize) -> Result<&'a mut [T], S> {
    if rows == 0 {
        return Ok(&mut []);
    }
    check(p)?;
    // SAFETY: as `input`, writable and not aliased by the caller's contract.
    Ok(unsafe { core::slice::from_raw_parts_mut(p, rows) })
}

/// `contensou_contact_wrench_many_*`.
///
/// # Safety
/// Pointers NULL or valid for their types; the arrays hold `rows` values, the output arrays
/// distinct and not overlapping the inputs.
pub(crate) unsafe fn contact_wrench_many<T: Precision + BatchReal>(
    storage: *const T::Storage,
    rows: usize,
    steps: *const contensou_step_columns<T>,
    out: *const contensou_wrench_columns<T>,
    row: *mut usize,
    column: *mut contensou_column,
) -> S {
    // SAFETY: caller's contract.
    unsafe {
        contact_wrench_many_rolling(storage, rows, steps, core::ptr::null(), out, row, column)
    }
}

/// `contensou_contact_wrench_many_rolling_*` (`rolling` NULL: V = 0 on every row, the batch
/// path of `contensou_contact_wrench_many_*`; otherwise a scalar loop).
///
/// # Safety
/// As [`contact_wrench_many`]; `rolling` NULL or readable, its arrays holding `rows` values.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn contact_wrench_many_rolling<T: Precision + BatchReal>(
    storage: *const T::Storage,
    rows: usize,
    steps: *const contensou_step_columns<T>,
    rolling: *const contensou_rolling_step_columns<T>,
    out: *const contensou_wrench_columns<T>,
    row: *mut usize,
    column: *mut contensou_column,
) -> S {
    let mut first_bad = rows;
    let r = (|| {
        // SAFETY (this block's calls): caller's contract.
        let slot = unsafe { slot::<T>(storage) }.map_err(bare)?;
        let s = unsafe { read(steps) }.map_err(bare)?;
        let o = unsafe { read(out) }.map_err(bare)?;
        // No array of more values than this exists (the slice length limit).
        if rows > isize::MAX as usize / core::mem::size_of::<T>() {
            return Err(bare(S::NullPointer));
        }
        let i = |p| unsafe { input(p, rows) };
        let (h, hdot, vx, vy, omega) = (i(s.h), i(s.hdot), i(s.vx), i(s.vy), i(s.omega));
        let steps = Steps {
            h: h.map_err(bare)?,
            hdot: hdot.map_err(bare)?,
            vx: vx.map_err(bare)?,
            vy: vy.map_err(bare)?,
            omega: omega.map_err(bare)?,
        };
        let o_ = |p| unsafe { output(p, rows) };
        let mut wrenches = Wrenches {
            n: o_(o.n).map_err(bare)?,
            fx: o_(o.fx).map_err(bare)?,
            fy: o_(o.fy).map_err(bare)?,
            tz: o_(o.tz).map_err(bare)?,
            a: o_(o.a).map_err(bare)?,
            b: o_(o.b).map_err(bare)?,
            e2: o_(o.e2).map_err(bare)?,
        };
        let r = if rolling.is_null() {
            None
        } else {
            // SAFETY: caller's contract.
            Some(unsafe { read(rolling) }.map_err(bare)?)
        };
        let done = match r {
            None => slot.contact.wrench_many(&steps, &mut wrenches),
            Some(r) => {
                let rolling = RollingSteps {
                    vrx: i(r.vrx).map_err(bare)?,
                    vry: i(r.vry).map_err(bare)?,
                };
                slot.contact
                    .wrench_many_rolling(&steps, &rolling, &mut wrenches)
            }
        };
        done.map_err(|e| {
            first_bad = e.row;
            (S::from(e.error), column_of(e.column))
        })
    })();
    // SAFETY: caller's contract.
    unsafe { report_at(row, first_bad, column, r) }
}
