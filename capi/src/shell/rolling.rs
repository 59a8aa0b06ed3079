//! The generic bodies of the rolling evaluator's functions (`contensou_rolling_*`): the
//! columns of `contact_eval rolling` through [`RollingContact::wrench`], so a row gives that
//! command's bits. No formula here.

use core::ffi::CStr;

use contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
};
use contensou::{Error, Real};

use super::{check, read, write, Precision};
use crate::cstr::c_str;
use crate::status::contensou_status as S;
use crate::types::*;

/// A precision's rolling storage and tag.
pub(crate) trait RollingPrecision: Precision {
    /// `contensou_rolling_f32` or `contensou_rolling_f64`.
    type RollingStorage;
    /// Written by the constructor in front of the contact.
    const ROLLING_TAG: u32;
}

impl RollingPrecision for f32 {
    type RollingStorage = contensou_rolling_f32;
    const ROLLING_TAG: u32 = u32::from_le_bytes(*b"rf32");
}

impl RollingPrecision for f64 {
    type RollingStorage = contensou_rolling_f64;
    const ROLLING_TAG: u32 = u32::from_le_bytes(*b"rf64");
}

/// The rolling laws, by `contensou_law` value, with the names of `contact_eval rolling --law`.
pub(crate) const ROLLING_LAWS: [(contensou_law, &str); 6] = [
    (CONTENSOU_LAW_TABLE, Table::NAME),
    (CONTENSOU_LAW_BLEND, Blend::NAME),
    (CONTENSOU_LAW_FASTSIM, Fastsim::NAME),
    (CONTENSOU_LAW_FASTSIM_16, "fastsim-16"),
    (CONTENSOU_LAW_FULL_SLIP, FullSlip::NAME),
    (CONTENSOU_LAW_LINEAR, Linear::NAME),
];

/// The value of a rolling law's name.
pub(crate) fn rolling_law_of(name: &str) -> Option<contensou_law> {
    ROLLING_LAWS
        .iter()
        .find(|(_, n)| *n == name)
        .map(|(code, _)| *code)
}

/// NUL-terminated column names, in `contensou_rolling_column` order.
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

fn bare(s: S) -> Failure {
    (s, CONTENSOU_ROLLING_COLUMN_NONE)
}

/// The column a library error names (`Error::NonFinite("a")` → `a`), else `fallback`.
fn named(e: Error, fallback: contensou_rolling_column) -> Failure {
    let column = match e {
        Error::NonFinite(name) => COLUMN_NAMES
            .iter()
            .position(|c| c.to_bytes() == name.as_bytes())
            .map_or(fallback, |k| k as contensou_rolling_column),
        _ => fallback,
    };
    (e.into(), column)
}

/// Stores the column of an error (or `NONE`) if `column` is usable.
///
/// # Safety
/// `column` NULL or writable.
unsafe fn report(column: *mut contensou_rolling_column, r: Result<(), Failure>) -> S {
    let (s, c) = match r {
        Ok(()) => (S::Ok, CONTENSOU_ROLLING_COLUMN_NONE),
        Err(e) => e,
    };
    if check(column).is_ok() {
        // SAFETY: non-NULL and aligned; writable by the caller's contract.
        unsafe { column.write(c) };
    }
    s
}

/// `contensou_rolling_new_*`: the contact of shape `a_over_b` and elasticity (G, ν), law `law`.
///
/// # Safety
/// `storage` NULL or writable; `column` NULL or writable.
pub(crate) unsafe fn rolling_new<T: RollingPrecision>(
    storage: *mut T::RollingStorage,
    a_over_b: T,
    g: T,
    nu: T,
    law: contensou_law,
    column: *mut contensou_rolling_column,
) -> S {
    let r = (|| {
        check(storage).map_err(bare)?;
        if !ROLLING_LAWS.iter().any(|(code, _)| *code == law) {
            return Err(bare(S::InvalidLaw));
        }
        let el = Elasticity::new(g, nu).map_err(|e| {
            let culprit = if g > T::ZERO {
                CONTENSOU_ROLLING_COLUMN_NU
            } else {
                CONTENSOU_ROLLING_COLUMN_G
            };
            named(e, culprit)
        })?;
        let contact = RollingContact::new(a_over_b, el)
            .map_err(|e| (e.into(), CONTENSOU_ROLLING_COLUMN_A_OVER_B))?;
        // SAFETY: checked non-NULL and aligned; the slot fits (types/rolling.rs).
        unsafe {
            storage.cast::<RollingSlot<T>>().write(RollingSlot {
                tag: T::ROLLING_TAG,
                law,
                contact,
            })
        };
        Ok(())
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// The rolling contact in a storage, if `contensou_rolling_new_*` of this precision wrote it.
///
/// # Safety
/// `storage` NULL or readable.
unsafe fn rolling_slot<'a, T: RollingPrecision>(
    storage: *const T::RollingStorage,
) -> Result<&'a RollingSlot<T>, S> {
    check(storage)?;
    let slot = storage.cast::<RollingSlot<T>>();
    // SAFETY: aligned for the storage (8) hence for the slot (asserted), which fits in it;
    // the tag is a plain u32.
    let tag = unsafe { core::ptr::addr_of!((*slot).tag).read() };
    if tag != T::ROLLING_TAG {
        return Err(S::NotInitialized);
    }
    // SAFETY: the tag is written only together with a valid contact (`rolling_new`).
    Ok(unsafe { &*slot })
}

/// The first of a, b (≤ 0) or f (< 0) that `Patch::new` refuses (as `contact_eval rolling`).
fn patch_culprit<T: Real>(s: &contensou_rolling_state<T>) -> contensou_rolling_column {
    if s.a <= T::ZERO {
        CONTENSOU_ROLLING_COLUMN_A
    } else if s.b <= T::ZERO {
        CONTENSOU_ROLLING_COLUMN_B
    } else {
        CONTENSOU_ROLLING_COLUMN_F
    }
}

/// The slip of `contact_eval rolling`: the creepages at V, V = 0 read as the limit V → 0⁺
/// (the wrench depends on V only through its sign).
fn slip<T: Real>(s: &contensou_rolling_state<T>) -> Result<RollingSlip<T>, Failure> {
    let columns = [
        (s.v, CONTENSOU_ROLLING_COLUMN_V),
        (s.xi, CONTENSOU_ROLLING_COLUMN_XI),
        (s.eta, CONTENSOU_ROLLING_COLUMN_ETA),
        (s.phi, CONTENSOU_ROLLING_COLUMN_PHI),
    ];
    for (x, column) in columns {
        if !x.is_finite() {
            return Err((S::NonFinite, column));
        }
    }
    let v = if s.v == T::ZERO { T::ONE } else { s.v };
    RollingSlip::from_creepages(s.xi, s.eta, s.phi, v).map_err(|e| {
        // finite creepages whose product with V overflows
        let column = match e {
            Error::NonFinite("v_y") => CONTENSOU_ROLLING_COLUMN_ETA,
            Error::NonFinite("omega") => CONTENSOU_ROLLING_COLUMN_PHI,
            _ => CONTENSOU_ROLLING_COLUMN_XI,
        };
        (e.into(), column)
    })
}

/// The wrench of `contact` by the law `code` (one of [`ROLLING_LAWS`], checked at
/// construction).
fn wrench_by<T: Real>(
    contact: &RollingContact<T>,
    code: contensou_law,
    patch: &Patch<T>,
    slip: &RollingSlip<T>,
) -> contensou_rolling_output<T> {
    fn by<T: Real, L: RollingLaw>(
        c: &RollingContact<T>,
        p: &Patch<T>,
        s: &RollingSlip<T>,
    ) -> contensou_rolling_output<T> {
        let w = c.wrench::<L>(p, s);
        contensou_rolling_output {
            fx: w.fx,
            fy: w.fy,
            mz: w.mz,
        }
    }
    match code {
        CONTENSOU_LAW_BLEND => by::<T, Blend>(contact, patch, slip),
        CONTENSOU_LAW_FASTSIM => by::<T, Fastsim>(contact, patch, slip),
        CONTENSOU_LAW_FASTSIM_16 => by::<T, FastsimGrid<16, 16>>(contact, patch, slip),
        CONTENSOU_LAW_FULL_SLIP => by::<T, FullSlip>(contact, patch, slip),
        CONTENSOU_LAW_LINEAR => by::<T, Linear>(contact, patch, slip),
        _ => by::<T, Table>(contact, patch, slip),
    }
}

/// `contensou_rolling_wrench_*`.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn rolling_wrench<T: RollingPrecision>(
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
        let patch = Patch::new(s.a, s.b, s.n, s.f).map_err(|e| named(e, patch_culprit(&s)))?;
        let slip = slip(&s)?;
        let w = wrench_by(&slot.contact, slot.law, &patch, &slip);
        // SAFETY: caller's contract.
        unsafe { write(out, w) }.map_err(bare)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}
