//! The generic bodies of the exported functions: pointer checks, type conversion, error
//! mapping. No formula: every number comes from `contensou`.

use core::ffi::{c_char, CStr};
use core::ptr::null;

use contensou::dynamic::{
    self, DynContact, Form, Invalid, Law, RollingSpec, RollingStep, Spec, Step,
};
use contensou::geometry::{Curvatures, Race};
use contensou::normal::{Material, Modulus};
use contensou::Real;

use crate::cstr::{c_str, c_strs};
use crate::status::contensou_status as S;
use crate::types::*;

mod many;
mod rolling;
mod step;
pub(crate) use many::{contact_wrench_many, contact_wrench_many_rolling};
pub(crate) use rolling::{rolling_column_name, rolling_law_of, rolling_new, rolling_wrench};
pub(crate) use step::{contact_step, step_many};

/// A precision of the C API: its storage types and the tags their constructors write.
pub(crate) trait Precision: Real {
    /// `contensou_contact_f32` or `contensou_contact_f64`.
    type Storage;
    /// `contensou_rolling_f32` or `contensou_rolling_f64`.
    type RollingStorage;
    /// Written by the constructor in front of the contact; checked by every other call. A
    /// Thumb-2 immediate (`0x00XY00XY`): the per-call test is one `cmp`, no constant load.
    const TAG: u32;
    /// Written by `contensou_rolling_new_*` in front of the rolling contact.
    const ROLLING_TAG: u32;
}

/// [`Precision`] for `$t`: its storage types and their tags' bytes.
macro_rules! precision {
    ($t:ty: $storage:ty, $tag:literal; $rolling:ty, $rolling_tag:literal) => {
        impl Precision for $t {
            type Storage = $storage;
            type RollingStorage = $rolling;
            const TAG: u32 = u32::from_le_bytes(*$tag);
            const ROLLING_TAG: u32 = u32::from_le_bytes(*$rolling_tag);
        }
    };
}
precision!(f32: contensou_contact_f32, b"f\0f\0"; contensou_rolling_f32, b"rf32");
precision!(f64: contensou_contact_f64, b"d\0d\0"; contensou_rolling_f64, b"rf64");

/// `Err(NullPointer)` or `Err(Misaligned)` unless `p` can be dereferenced as a `T`.
fn check<T>(p: *const T) -> Result<(), S> {
    if p.is_null() {
        Err(S::NullPointer)
    } else if !p.is_aligned() {
        Err(S::Misaligned)
    } else {
        Ok(())
    }
}

/// The address bits of `p` below `T`'s alignment: 0 iff `p` is aligned for a `T` (the test of
/// [`check`] as a value, to OR several pointers' into one branch).
fn low_bits<T>(p: *const T) -> usize {
    p.addr() & (core::mem::align_of::<T>() - 1)
}

/// Reads a `T` from a C pointer.
///
/// # Safety
/// `p` is NULL or points to memory readable as a `T` (C's side of the contract).
unsafe fn read<T: Copy>(p: *const T) -> Result<T, S> {
    check(p)?;
    // SAFETY: non-NULL and aligned (checked); readable by the caller's contract.
    Ok(unsafe { p.read() })
}

/// Writes a `T` through a C pointer.
///
/// # Safety
/// `p` is NULL or points to memory writable as a `T`.
unsafe fn write<T>(p: *mut T, value: T) -> Result<(), S> {
    check(p)?;
    // SAFETY: non-NULL and aligned (checked); writable by the caller's contract.
    unsafe { p.write(value) };
    Ok(())
}

/// The status of a result.
fn status(r: Result<(), S>) -> S {
    match r {
        Ok(()) => S::Ok,
        Err(s) => s,
    }
}

/// Stores the column of an error (or `CONTENSOU_COLUMN_NONE`) if `column` is usable.
///
/// # Safety
/// `column` is NULL or writable as a `u32`.
pub(crate) unsafe fn report(
    column: *mut contensou_column,
    r: Result<(), (S, contensou_column)>,
) -> S {
    let (s, c) = match r {
        Ok(()) => (S::Ok, CONTENSOU_COLUMN_NONE),
        Err(e) => e,
    };
    if check(column).is_ok() {
        // SAFETY: non-NULL and aligned; writable by the caller's contract.
        unsafe { column.write(c) };
    }
    s
}

/// [`report`] of an error, out of line (the refused step of a wrench call).
///
/// # Safety
/// `column` is NULL or writable as a `u32`.
#[cold]
#[inline(never)]
unsafe fn report_cold(column: *mut contensou_column, e: (S, contensou_column)) -> S {
    // SAFETY: caller's contract.
    unsafe { report(column, Err(e)) }
}

/// The code of a contract column name: its index in [`dynamic::INPUTS`], or
/// `CONTENSOU_COLUMN_G + k` for [`dynamic::ROLLING_INPUTS`]`[k]`.
fn column_of(name: &str) -> contensou_column {
    let rolling = || {
        dynamic::ROLLING_INPUTS
            .iter()
            .position(|c| *c == name)
            .map(|k| CONTENSOU_COLUMN_G + k as contensou_column)
    };
    match dynamic::INPUTS.iter().position(|c| *c == name) {
        Some(i) => i as contensou_column,
        None => rolling().unwrap_or(CONTENSOU_COLUMN_NONE),
    }
}

/// An optional value: NULL is `None` (the column's default).
///
/// # Safety
/// `p` NULL or readable.
unsafe fn optional<T: Copy>(p: *const T) -> Result<Option<T>, S> {
    if p.is_null() {
        Ok(None)
    } else {
        // SAFETY: caller's contract.
        unsafe { read(p) }.map(Some)
    }
}

/// The optional rolling velocity at `p` (NULL: V = 0).
///
/// # Safety
/// `p` NULL or readable.
unsafe fn rolling_step<T: Real>(
    p: *const contensou_rolling_step<T>,
) -> Result<RollingStep<T>, (S, contensou_column)> {
    // SAFETY: caller's contract.
    let roll = unsafe { optional(p) }.map_err(bare)?;
    Ok(roll.unwrap_or_default().into())
}

/// Stores `value` at `at` (the row or contact an error is about) if `at` is usable, then
/// [`report`]s `r`.
///
/// # Safety
/// `at` NULL or writable as a `usize`; `column` NULL or writable as a `u32`.
pub(crate) unsafe fn report_at(
    at: *mut usize,
    value: usize,
    column: *mut contensou_column,
    r: Result<(), (S, contensou_column)>,
) -> S {
    if check(at).is_ok() {
        // SAFETY: non-NULL and aligned; writable by the caller's contract.
        unsafe { at.write(value) };
    }
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// A boundary status without a column.
fn bare(s: S) -> (S, contensou_column) {
    (s, CONTENSOU_COLUMN_NONE)
}

/// The library's error with its column.
fn invalid(e: Invalid) -> (S, contensou_column) {
    (e.error.into(), column_of(e.column))
}

pub(crate) fn law(law: contensou_law) -> Result<Law, S> {
    Ok(match law {
        CONTENSOU_LAW_BEST => Law::Best,
        CONTENSOU_LAW_SIMPLIFIED => Law::Simplified,
        CONTENSOU_LAW_PADE => Law::Pade,
        CONTENSOU_LAW_ELLIPSOID => Law::Ellipsoid,
        CONTENSOU_LAW_COULOMB => Law::Coulomb,
        CONTENSOU_LAW_TABLE => Law::Table,
        CONTENSOU_LAW_BLEND => Law::Blend,
        CONTENSOU_LAW_FASTSIM => Law::Fastsim,
        CONTENSOU_LAW_FASTSIM_16 => Law::Fastsim16,
        _ => return Err(S::InvalidLaw),
    })
}

pub(crate) fn form(form: contensou_form) -> Result<Form, S> {
    Ok(match form {
        CONTENSOU_FORM_FIXED => Form::Fixed,
        CONTENSOU_FORM_VARYING => Form::Varying,
        _ => return Err(S::InvalidForm),
    })
}

/// The contact in a storage, if a constructor of this precision initialised it.
///
/// # Safety
/// `storage` is NULL or points to a readable `T::Storage`.
unsafe fn slot<'a, T: Precision>(storage: *const T::Storage) -> Result<&'a Slot<T>, S> {
    // SAFETY: caller's contract; `Slot` is `repr(C)` with its tag first, aligned for the
    // storage (8 bytes) and fits in it (asserted in types.rs); only `contact_new` writes the tag,
    // together with a valid contact.
    unsafe { tagged(storage, T::TAG) }
}

/// The `V` in a storage of type `St` whose constructor wrote `tag` in front of it:
/// `Err(NullPointer | Misaligned | NotInitialized)` otherwise.
///
/// # Safety
/// `storage` is NULL or points to a readable `St`; `V` is `repr(C)` with a `u32` tag first,
/// fits in an `St` and needs no more alignment; a `V` behind the tag `tag` is valid.
pub(crate) unsafe fn tagged<'a, St, V>(storage: *const St, tag: u32) -> Result<&'a V, S> {
    check(storage)?;
    // SAFETY: non-NULL and aligned (checked); the tag is a plain u32, valid for any bits.
    if unsafe { storage.cast::<u32>().read() } != tag {
        return Err(S::NotInitialized);
    }
    // SAFETY: the caller's contract on `V` and `tag`.
    Ok(unsafe { &*storage.cast::<V>() })
}

/// Writes `contact` behind `tag` into `storage`: what [`tagged`] reads back.
///
/// # Safety
/// `storage` non-NULL, aligned and writable; a [`Tagged`]`<C>` fits in an `St` and needs no
/// more alignment (asserted in types.rs for each storage).
pub(crate) unsafe fn store<St, C>(storage: *mut St, tag: u32, contact: C) {
    // SAFETY: caller's contract.
    unsafe { storage.cast::<Tagged<C>>().write(Tagged { tag, contact }) }
}

/// `contensou_contact_new_*`.
///
/// # Safety
/// Pointers NULL or valid for their types (`column` may be NULL).
pub(crate) unsafe fn contact_new<T: Precision>(
    storage: *mut T::Storage,
    spec: *const contensou_spec<T>,
    law_value: contensou_law,
    form_value: contensou_form,
    column: *mut contensou_column,
) -> S {
    // SAFETY: caller's contract.
    unsafe { contact_new_rolling(storage, spec, null(), null(), law_value, form_value, column) }
}

/// `contensou_contact_new_rolling_*` (`g`, `nu` NULL: the column's default).
///
/// # Safety
/// Pointers NULL or valid for their types (`column` may be NULL).
pub(crate) unsafe fn contact_new_rolling<T: Precision>(
    storage: *mut T::Storage,
    spec: *const contensou_spec<T>,
    g: *const T,
    nu: *const T,
    law_value: contensou_law,
    form_value: contensou_form,
    column: *mut contensou_column,
) -> S {
    let r = (|| {
        check(storage).map_err(bare)?;
        // SAFETY: caller's contract.
        let s = unsafe { read(spec) }.map_err(bare)?;
        // SAFETY: caller's contract.
        let rolling = unsafe {
            RollingSpec {
                g: optional(g).map_err(bare)?,
                nu: optional(nu).map_err(bare)?,
            }
        };
        let law = law(law_value).map_err(bare)?;
        let form = form(form_value).map_err(bare)?;
        let spec = Spec::from(s);
        let contact = DynContact::new_rolling(&spec, &rolling, law, form).map_err(invalid)?;
        // SAFETY: checked non-NULL and aligned; the slot fits (types.rs).
        unsafe { store(storage, T::TAG, contact) };
        Ok(())
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// `contensou_contact_set_curvatures_*`.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn contact_set_curvatures<T: Precision>(
    storage: *mut T::Storage,
    p: T,
    q: T,
    column: *mut contensou_column,
) -> S {
    let r = (|| {
        // SAFETY: caller's contract.
        unsafe { slot::<T>(storage) }.map_err(bare)?;
        // SAFETY: checked by `slot` (non-NULL, aligned, initialised); the storage is mutable.
        let slot = unsafe { &mut *storage.cast::<Slot<T>>() };
        slot.contact.set_curvatures(p, q).map_err(invalid)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r) }
}

/// `contensou_contact_wrench_*`.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn contact_wrench<T: Precision>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    out: *mut contensou_wrench<T>,
    column: *mut contensou_column,
) -> S {
    // SAFETY: caller's contract.
    unsafe {
        wrench_with(storage, step, out, column, |c, s| {
            c.wrench(s).map_err(invalid)
        })
    }
}

/// `contensou_contact_wrench_rolling_*` and `…_jacobian_*`, `…_jacobian_rolling_*`: `eval`
/// ([`DynContact::wrench_rolling`] or [`DynContact::jacobian_rolling`]) on the contact, the
/// step and the rolling velocity `rolling` (NULL: V = 0; the plain Jacobian passes NULL, which
/// is [`DynContact::jacobian`]), through [`wrench_with`]: checked in the order storage, step,
/// output, then the rolling columns.
///
/// # Safety
/// Pointers NULL or valid for their types.
pub(crate) unsafe fn rolling_with<T: Precision, W, O: From<W>>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    rolling: *const contensou_rolling_step<T>,
    out: *mut O,
    column: *mut contensou_column,
    eval: impl FnOnce(&DynContact<T>, &Step<T>, &RollingStep<T>) -> Result<W, Invalid>,
) -> S {
    let eval = |c: &DynContact<T>, s: &Step<T>| {
        // SAFETY: caller's contract.
        let roll = unsafe { rolling_step(rolling) }?;
        eval(c, s, &roll).map_err(invalid)
    };
    // SAFETY: caller's contract.
    unsafe { wrench_with(storage, step, out, column, eval) }
}

/// The body of `contensou_contact_wrench_*` and [`rolling_with`]'s: `eval` on the
/// validated contact and step, its result written to `*out` as an `O`, checked in the order
/// storage, step, output, then what `eval` reads (the sliding call keeps its own
/// `DynContact::wrench`, without the rolling columns' handling: the `c-fixed-best` M4F row).
///
/// The per-call path tests the pointers as plain conditions (one OR of their low address bits,
/// three NULL tests, the tag); a refused call goes to [`wrench_refused`] (out of line), which
/// finds the status in the documented order. `*column` gets `CONTENSOU_COLUMN_NONE` once the
/// pointers are accepted and the step is read, before the evaluation (a refused step then
/// overwrites it with its column: the same final values as writing it last), so that only
/// `out` stays live across the law's call. No status code is held in a register on the way and
/// `*out` is written from the law's result. M4F `c-fixed-best`: 249 instructions, 516 cycles
/// (mid estimate), against 267 / 553 with `Result`-chained checks — the same statuses.
///
/// # Safety
/// Pointers NULL or valid for their types.
#[inline(always)]
unsafe fn wrench_with<T: Precision, W, O: From<W>>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    out: *mut O,
    column: *mut contensou_column,
    eval: impl FnOnce(&DynContact<T>, &Step<T>) -> Result<W, (S, contensou_column)>,
) -> S {
    let misaligned = low_bits(storage) | low_bits(step) | low_bits(out);
    if misaligned == 0 && !storage.is_null() && !step.is_null() && !out.is_null() {
        let slot = storage.cast::<Slot<T>>();
        // SAFETY: as in `slot`: non-NULL and aligned (checked), the slot fits in the storage,
        // the tag is a plain u32.
        if unsafe { core::ptr::addr_of!((*slot).tag).read() } == T::TAG {
            // SAFETY: the tag is written only together with a valid contact (`contact_new`);
            // `step` is non-NULL, aligned and readable by the caller's contract.
            let (contact, s) = unsafe { (&(*slot).contact, step.read()) };
            if check(column).is_ok() {
                // SAFETY: non-NULL and aligned; writable by the caller's contract.
                unsafe { column.write(CONTENSOU_COLUMN_NONE) };
            }
            return match eval(contact, &Step::from(s)) {
                Ok(w) => {
                    // SAFETY: non-NULL and aligned (checked); writable by the caller's contract.
                    unsafe { out.write(O::from(w)) };
                    S::Ok
                }
                // SAFETY: caller's contract.
                Err(e) => unsafe { report_cold(column, e) },
            };
        }
    }
    // SAFETY: caller's contract.
    unsafe { wrench_refused::<T, O>(storage, step, out, column) }
}

/// The status of a wrench call whose pointers or storage [`wrench_with`] refused: the first
/// failing check in the order storage (NULL, alignment, tag), step, output.
///
/// # Safety
/// Pointers NULL or valid for their types.
#[cold]
#[inline(never)]
unsafe fn wrench_refused<T: Precision, O>(
    storage: *const T::Storage,
    step: *const contensou_step<T>,
    out: *mut O,
    column: *mut contensou_column,
) -> S {
    let r = (|| {
        // SAFETY: caller's contract.
        unsafe { slot::<T>(storage) }?;
        check(step)?;
        check(out)
    })();
    // SAFETY: caller's contract.
    unsafe { report(column, r.map_err(bare)) }
}

/// Checks `out`, then makes the value and writes it: the status.
///
/// # Safety
/// `out` NULL or writable.
unsafe fn produce<V>(out: *mut V, make: impl FnOnce() -> Result<V, S>) -> S {
    status((|| {
        check(out)?;
        let v = make()?;
        // SAFETY: caller's contract.
        unsafe { write(out, v) }
    })())
}

/// Checks `out`, then builds the curvatures and writes them.
///
/// # Safety
/// `out` NULL or writable.
pub(crate) unsafe fn curvatures<T: Precision>(
    out: *mut contensou_curvatures<T>,
    make: impl FnOnce() -> Result<Curvatures<T>, S>,
) -> S {
    let make = || {
        let c = make()?;
        Ok(contensou_curvatures {
            p: c.p(),
            q: c.q(),
            major_angle: c.major_angle(),
        })
    };
    // SAFETY: caller's contract.
    unsafe { produce(out, make) }
}

/// The `contensou_race` value as a [`Race`].
pub(crate) fn race(race: contensou_race) -> Result<Race, S> {
    Ok(match race {
        CONTENSOU_RACE_INNER => Race::Inner,
        CONTENSOU_RACE_OUTER => Race::Outer,
        _ => return Err(S::InvalidRace),
    })
}

/// `contensou_modulus_of_*`.
///
/// # Safety
/// `estar` NULL or writable.
pub(crate) unsafe fn modulus_of<T: Precision>(
    young_a: T,
    poisson_a: T,
    young_b: T,
    poisson_b: T,
    estar: *mut T,
) -> S {
    let make = || {
        let a = Material::new(young_a, poisson_a)?;
        let b = Material::new(young_b, poisson_b)?;
        Ok(Modulus::of(a, b)?.get())
    };
    // SAFETY: caller's contract.
    unsafe { produce(estar, make) }
}

/// Parses a NUL-terminated name with `parse` and writes the value.
///
/// # Safety
/// `name` NULL or a NUL-terminated string; `out` NULL or writable.
pub(crate) unsafe fn from_name<V>(
    name: *const c_char,
    out: *mut u32,
    parse: impl Fn(&str) -> Option<V>,
    code: impl Fn(V) -> u32,
) -> S {
    status((|| {
        if name.is_null() {
            return Err(S::NullPointer);
        }
        check(out)?;
        // SAFETY: non-NULL, NUL-terminated by the caller's contract.
        let name = unsafe { CStr::from_ptr(name) };
        let v = name.to_str().ok().and_then(parse).ok_or(S::UnknownName)?;
        // SAFETY: caller's contract.
        unsafe { write(out, code(v)) }
    })())
}

pub(crate) fn law_code(law: Law) -> contensou_law {
    match law {
        Law::Best => CONTENSOU_LAW_BEST,
        Law::Simplified => CONTENSOU_LAW_SIMPLIFIED,
        Law::Pade => CONTENSOU_LAW_PADE,
        Law::Ellipsoid => CONTENSOU_LAW_ELLIPSOID,
        Law::Coulomb => CONTENSOU_LAW_COULOMB,
        Law::Table => CONTENSOU_LAW_TABLE,
        Law::Blend => CONTENSOU_LAW_BLEND,
        Law::Fastsim => CONTENSOU_LAW_FASTSIM,
        Law::Fastsim16 => CONTENSOU_LAW_FASTSIM_16,
    }
}

pub(crate) fn form_code(form: Form) -> contensou_form {
    match form {
        Form::Fixed => CONTENSOU_FORM_FIXED,
        Form::Varying => CONTENSOU_FORM_VARYING,
    }
}

/// NUL-terminated column names by code: [`dynamic::INPUTS`], `""` (NONE), then
/// [`dynamic::ROLLING_INPUTS`].
const COLUMN_NAMES: [&CStr; 16] = {
    let [p, q, estar, cd, f, delta, h, hdot, vx, vy, omega] = c_strs!(dynamic::INPUTS; 11);
    let [g, nu, vrx, vry] = c_strs!(dynamic::ROLLING_INPUTS; 4);
    let none = c_str!("");
    [
        p, q, estar, cd, f, delta, h, hdot, vx, vy, omega, none, g, nu, vrx, vry,
    ]
};

/// The name of a column code (`""` for `CONTENSOU_COLUMN_NONE` and unknown codes; the step's
/// columns from `CONTENSOU_COLUMN_DT`).
pub(crate) fn column_name(column: contensou_column) -> *const c_char {
    match COLUMN_NAMES.get(column as usize) {
        Some(c) => c.as_ptr(),
        None => step::step_column_name(column).as_ptr(),
    }
}
