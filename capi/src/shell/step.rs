//! The generic bodies of the step-aware wrench's functions: `contensou_contact_step_*` is
//! [`contract::step_row`] (the row of `contact_eval step`: the same validation, the same column
//! named in an error, the same bits) on the caller's contact; `contensou_step_many_*` is
//! [`step_wrenches`] for K = 1 … 8 contacts sharing W, each linearised as the contract's
//! [`contract::Row`]. No formula here.

use contensou::dynamic::{DynContact, Invalid, RollingStep, Step};
use contensou::friction::rolling::RollingVelocity;
use contensou::friction::Slip;
use contensou::jacobian::{Linearize, State};
use contensou::step::contract::{self, Row};
use contensou::step::{step_wrenches, Free, InverseMass, TimeStep};
use contensou::Error;
use core::ffi::CStr;

use crate::cstr::{c_str, c_strs};

use super::{
    bare, check, column_of, optional, read, report, report_at, rolling_step, slot, write, Precision,
};
use crate::status::contensou_status as S;
use crate::types::*;

type Failure = (S, contensou_column);

/// The code of a column name: the step's own (`dt`, `w_*`, `W`, `u*_free`, `h_free`), else the
/// wrench contract's.
fn step_column(name: &str) -> contensou_column {
    match STEP_COLUMNS.iter().position(|c| *c == name) {
        Some(i) => CONTENSOU_COLUMN_DT + i as contensou_column,
        None => column_of(name),
    }
}

/// The library's error with its column.
fn invalid(e: Invalid) -> Failure {
    (e.error.into(), step_column(e.column))
}

/// The library's error `e` at the column `name`.
fn at(name: &'static str, e: Error) -> Failure {
    invalid(Invalid {
        column: name,
        error: e,
    })
}

/// NUL-terminated names of the step's columns by code from `CONTENSOU_COLUMN_DT`.
const STEP_COLUMN_NAMES: [&CStr; 17] = c_strs!(crate::types::STEP_COLUMNS; 17);

/// The name of a step column code (`CONTENSOU_COLUMN_DT` …; `""` for any other code).
pub(crate) fn step_column_name(column: contensou_column) -> &'static CStr {
    column
        .checked_sub(CONTENSOU_COLUMN_DT)
        .and_then(|i| STEP_COLUMN_NAMES.get(i as usize).copied())
        .unwrap_or(c_str!(""))
}

/// `contensou_contact_step_*`: one row of `contact_eval step` (`rolling` NULL: V = 0; `u_free`
/// NULL: every free column absent, i.e. the start velocity).
///
/// # Safety
/// Pointers NULL or valid for their types.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn contact_step<T: Precision>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    rolling: *const contensou_rolling_step<T>,
    dt: T,
    w: *const contensou_inverse_mass<T>,
    u_free: *const contensou_step_velocity<T>,
    out: *mut contensou_step_wrench<T>,
    column: *mut contensou_column,
) -> S {
    let r = (|| {
        // SAFETY: caller's contract (each pointer NULL or valid).
        let (slot, s, roll, w, u) = unsafe {
            (
                slot::<T>(storage).map_err(bare)?,
                read(step).map_err(bare)?,
                rolling_step(rolling)?,
                read(w).map_err(bare)?,
                optional(u_free).map_err(bare)?,
            )
        };
        check(out).map_err(bare)?;
        let u_free = match u {
            Some(u) => [Some(u.vn), Some(u.vx), Some(u.vy), Some(u.omega)],
            None => [None; 4],
        };
        let [n, fx, fy, tz] =
            contract::step_row(&slot.contact, &Step::from(s), &roll, dt, w.upper(), u_free)
                .map_err(invalid)?;
        // SAFETY: caller's contract.
        unsafe { write(out, contensou_step_wrench { n, fx, fy, tz }) }.map_err(bare)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// `count` values of `T` at `p` (`count` ≥ 1).
///
/// # Safety
/// `p` NULL or valid for `count` reads.
unsafe fn array<'a, T>(p: *const T, count: usize) -> Result<&'a [T], S> {
    check(p)?;
    // SAFETY: non-NULL and aligned (checked); `count` ≤ 1024 values readable by the caller's
    // contract.
    Ok(unsafe { core::slice::from_raw_parts(p, count) })
}

/// One validated contact of a `contensou_step_many_*` call.
#[derive(Clone, Copy)]
struct Taken<'a, T: Precision> {
    contact: &'a DynContact<T>,
    rolling: RollingStep<T>,
    state: State<T>,
}

/// The validated start of contact `i`: its storage, start step (validated as the wrench
/// validates it, as in the contract) and rolling velocity (rolling laws).
///
/// # Safety
/// Pointers NULL or valid for their types.
unsafe fn start<'a, T: Precision>(
    storage: *const T::Storage,
    step: &contensou_step<T>,
    rolling: Option<&contensou_rolling_step<T>>,
) -> Result<Taken<'a, T>, Failure> {
    // SAFETY: caller's contract.
    let contact = &unsafe { slot::<T>(storage) }.map_err(bare)?.contact;
    let roll = RollingStep::from(rolling.copied().unwrap_or_default());
    let step = Step::from(*step);
    contact.wrench_rolling(&step, &roll).map_err(invalid)?;
    let v = if contact.law().is_rolling() {
        roll.velocity().map_err(invalid)?
    } else {
        RollingVelocity::ZERO
    };
    let slip = Slip::new(step.vx, step.vy, step.omega).map_err(|e| at("vx", e))?;
    let state = State {
        h: step.h,
        hdot: step.hdot,
        slip,
        rolling: v,
    };
    Ok(Taken {
        contact,
        rolling: roll,
        state,
    })
}

/// A contact's free motion (`None`: coasting, the contract's default).
fn free_motion<T: Precision>(
    dt: TimeStep<T>,
    state: &State<T>,
    free: Option<&contensou_step_free<T>>,
) -> Result<Free<T>, Failure> {
    let Some(f) = free else {
        let u = [
            -state.hdot,
            state.slip.vx(),
            state.slip.vy(),
            state.slip.omega(),
        ];
        return Free::predicted(dt, state, u).map_err(|e| at("un_free", e));
    };
    let u = [f.u.vn, f.u.vx, f.u.vy, f.u.omega];
    for (x, name) in u.iter().zip(contract::FREE_INPUTS) {
        if !x.is_finite() {
            return Err(at(name, Error::NonFinite(name)));
        }
    }
    Free::new(u, f.h).map_err(|e| at("h_free", e))
}

/// `contensou_step_many_*`: the wrenches of `k` ∈ 1 … 8 contacts sharing W.
///
/// # Safety
/// Pointers NULL or valid for their types; the arrays hold `k` values (`w`: (4k)²).
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn step_many<T: Precision>(
    contacts: *const *const T::Storage,
    k: usize,
    steps: *const contensou_step<T>,
    rolling: *const contensou_rolling_step<T>,
    dt: T,
    w: *const T,
    free: *const contensou_step_free<T>,
    out: *mut contensou_step_wrench<T>,
    index: *mut usize,
    column: *mut contensou_column,
) -> S {
    // The contact an error is about (k: none).
    let mut which = k;
    let r = (|| {
        if k == 0 || k > CONTENSOU_STEP_MAX_CONTACTS {
            return Err(bare(S::ContactCountOutOfRange));
        }
        // SAFETY: caller's contract: each array NULL or holding its count of values.
        let (ptrs, steps, w, rolling, free) = unsafe {
            (
                array(contacts, k).map_err(bare)?,
                array(steps, k).map_err(bare)?,
                array(w, 16 * k * k).map_err(bare)?,
                match rolling.is_null() {
                    true => None,
                    false => Some(array(rolling, k).map_err(bare)?),
                },
                match free.is_null() {
                    true => None,
                    false => Some(array(free, k).map_err(bare)?),
                },
            )
        };
        check(out).map_err(bare)?;
        // The contacts' starts, then Δt, W, the free motions: the contract's order.
        let mut taken: [Option<Taken<'_, T>>; CONTENSOU_STEP_MAX_CONTACTS] =
            [None; CONTENSOU_STEP_MAX_CONTACTS];
        for (i, (slot, (&p, s))) in taken.iter_mut().zip(ptrs.iter().zip(steps)).enumerate() {
            which = i;
            let r = rolling.and_then(|r| r.get(i));
            // SAFETY: caller's contract.
            *slot = Some(unsafe { start::<T>(p, s, r) }?);
        }
        which = k;
        let dt = TimeStep::new(dt).map_err(|e| at("dt", e))?;
        if let Some(i) = w.iter().position(|x| !x.is_finite()) {
            // Its row / 4 (k ≥ 1 here; no division that could panic).
            which = i.checked_div(16 * k).unwrap_or(k);
            return Err(at("W", Error::NonFinite("W")));
        }
        let mut frees: [Option<Free<T>>; CONTENSOU_STEP_MAX_CONTACTS] =
            [None; CONTENSOU_STEP_MAX_CONTACTS];
        for (i, (f, t)) in frees.iter_mut().zip(&taken).enumerate().take(k) {
            which = i;
            if let Some(t) = t {
                *f = Some(free_motion(dt, &t.state, free.and_then(|f| f.get(i)))?);
            }
        }
        which = k;
        let wrenches = match k {
            1 => solve::<T, 1>(&taken, &frees, dt, w),
            2 => solve::<T, 2>(&taken, &frees, dt, w),
            3 => solve::<T, 3>(&taken, &frees, dt, w),
            4 => solve::<T, 4>(&taken, &frees, dt, w),
            5 => solve::<T, 5>(&taken, &frees, dt, w),
            6 => solve::<T, 6>(&taken, &frees, dt, w),
            7 => solve::<T, 7>(&taken, &frees, dt, w),
            _ => solve::<T, 8>(&taken, &frees, dt, w),
        }?;
        // SAFETY: non-NULL and aligned (checked); `k` writable values by the caller's contract,
        // not overlapping the inputs.
        let out = unsafe { core::slice::from_raw_parts_mut(out, k) };
        for (o, x) in out.iter_mut().zip(wrenches) {
            *o = x;
        }
        Ok(())
    })();
    if r.is_ok() {
        which = k;
    }
    // SAFETY: caller's contract.
    unsafe { report_at(index, which, column, r) }
}

/// [`step_wrenches`] over the first K taken contacts and their free motions (all `Some`), W
/// the (4K)² row-major values `w`.
fn solve<T: Precision, const K: usize>(
    taken: &[Option<Taken<'_, T>>; CONTENSOU_STEP_MAX_CONTACTS],
    frees: &[Option<Free<T>>; CONTENSOU_STEP_MAX_CONTACTS],
    dt: TimeStep<T>,
    w: &[T],
) -> Result<[contensou_step_wrench<T>; CONTENSOU_STEP_MAX_CONTACTS], Failure> {
    let mut blocks = [[[[T::ZERO; 4]; 4]; K]; K];
    for (i, row) in blocks.iter_mut().enumerate() {
        for (j, block) in row.iter_mut().enumerate() {
            for (r, line) in block.iter_mut().enumerate() {
                for (c, x) in line.iter_mut().enumerate() {
                    *x = w
                        .get((4 * i + r) * 4 * K + 4 * j + c)
                        .copied()
                        .unwrap_or(T::ZERO);
                }
            }
        }
    }
    let w = InverseMass::new(blocks).map_err(|e| at("W", e))?;
    let (Some(Some(first)), Some(Some(first_free))) = (taken.first(), frees.first()) else {
        return Err(bare(S::ContactCountOutOfRange));
    };
    let t: [Taken<'_, T>; K] =
        core::array::from_fn(|i| taken.get(i).copied().flatten().unwrap_or(*first));
    let frees: [Free<T>; K] =
        core::array::from_fn(|i| frees.get(i).copied().flatten().unwrap_or(*first_free));
    let rows: [Row<'_, T>; K] = t.map(|t| Row::new(t.contact, t.rolling));
    let refs: [&dyn Linearize<T>; K] = rows.each_ref().map(|r| r as &dyn Linearize<T>);
    let states = t.map(|t| t.state);
    let o = step_wrenches(refs, dt, &w, &states, &frees);
    let mut out = [contensou_step_wrench::default(); CONTENSOU_STEP_MAX_CONTACTS];
    for (x, o) in out.iter_mut().zip(o) {
        let [n, fx, fy, tz] = o.wrench;
        *x = contensou_step_wrench { n, fx, fy, tz };
    }
    Ok(out)
}
