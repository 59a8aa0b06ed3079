//! Fixtures shared by the C API's Rust tests and `examples/overhead.rs`: zeroed storages, the
//! reference contact of the contract, conversions between the C and the library types.
#![allow(dead_code)]

use core::ffi::{c_char, CStr};
use core::ptr::{null, null_mut};

use contensou::dynamic::Spec;
use contensou_capi::*;

/// A static NUL-terminated string of the API as `&str`.
pub fn text(p: *const c_char) -> &'static str {
    unsafe { CStr::from_ptr(p) }.to_str().unwrap()
}

/// A zeroed storage (as static memory is: no constructor wrote it). The storages are arrays
/// of `u64`, for which all-zero bytes are a valid value.
fn zeroed<St>() -> Box<St> {
    let layout = std::alloc::Layout::new::<St>();
    let p = unsafe { std::alloc::alloc_zeroed(layout) }.cast::<St>();
    assert!(!p.is_null(), "allocation failed");
    unsafe { Box::from_raw(p) }
}

/// Storage of kind `B` holding the bytes of `from` (as many as fit; the rest zero): a contact
/// of another precision or kind, which `B`'s calls must refuse by its tag.
pub fn copied<A, B>(from: &A) -> Box<B> {
    let mut to = zeroed::<B>();
    let n = size_of::<A>().min(size_of::<B>());
    let (src, dst) = (
        (from as *const A).cast::<u8>(),
        (&mut *to as *mut B).cast::<u8>(),
    );
    unsafe { core::ptr::copy_nonoverlapping(src, dst, n) };
    to
}

/// `p` 4 bytes on, as a `T` pointer: misaligned for the `double` types (8-byte aligned).
pub fn misaligned<T, U>(p: *const U) -> *mut T {
    p.cast::<u8>().wrapping_add(4).cast_mut().cast()
}

/// Zeroed storage of one `float` contact.
pub fn storage32() -> Box<contensou_contact_f32> {
    zeroed()
}

/// Zeroed storage of one `double` contact.
pub fn storage64() -> Box<contensou_contact_f64> {
    zeroed()
}

/// Zeroed storage of one `float` rolling contact.
pub fn rolling32() -> Box<contensou_rolling_f32> {
    zeroed()
}

/// Zeroed storage of one `double` rolling contact.
pub fn rolling64() -> Box<contensou_rolling_f64> {
    zeroed()
}

/// The statuses of `call` (a per-step call on a contact: storage, step, output) with each
/// pointer NULL in turn — storage, step, output — the others valid; asserts that nothing was
/// written.
pub fn each_null<St, In, O: Default + PartialEq + core::fmt::Debug>(
    c: &St,
    step: &In,
    call: impl Fn(*const St, *const In, *mut O) -> contensou_status,
) -> [contensou_status; 3] {
    let mut out = O::default();
    let statuses = [
        call(null(), step, &mut out),
        call(c, null(), &mut out),
        call(c, step, null_mut()),
    ];
    assert_eq!(out, O::default(), "nothing written on error");
    statuses
}

/// The reference contact: P = 10, Q = 50 (1/m), E* = 1.15e11 Pa, c_d = 0.1, f = 0.1,
/// δ = 1e-4 m/s.
pub const SPEC: contensou_spec<f64> = contensou_spec {
    p: 10.0,
    q: 50.0,
    estar: 1.15e11,
    cd: 0.1,
    f: 0.1,
    delta: 1e-4,
};

/// A step of the reference contact: pressed in, compressing, sliding and spinning.
pub const STEP: contensou_step<f64> = contensou_step {
    h: 1e-6,
    hdot: 0.01,
    vx: 0.01,
    vy: -0.002,
    omega: 50.0,
};

/// [`SPEC`] in another precision, each value converted by `to`.
pub fn spec_in<T>(to: fn(f64) -> T) -> contensou_spec<T> {
    contensou_spec {
        p: to(SPEC.p),
        q: to(SPEC.q),
        estar: to(SPEC.estar),
        cd: to(SPEC.cd),
        f: to(SPEC.f),
        delta: to(SPEC.delta),
    }
}

/// The library's contact columns of a C spec.
pub fn spec_of<T: Copy>(s: &contensou_spec<T>) -> Spec<T> {
    Spec::from(*s)
}

/// Row `i` of the step columns `h, hdot, vx, vy, omega`.
pub fn step_at<T: Copy>(columns: [&[T]; 5], i: usize) -> contensou_step<T> {
    let [h, hdot, vx, vy, omega] = columns.map(|c| c[i]);
    contensou_step {
        h,
        hdot,
        vx,
        vy,
        omega,
    }
}

/// Step columns reading `h, hdot, vx, vy, omega`.
pub fn step_columns<T>(c: [&[T]; 5]) -> contensou_step_columns<T> {
    let [h, hdot, vx, vy, omega] = c.map(<[T]>::as_ptr);
    contensou_step_columns {
        h,
        hdot,
        vx,
        vy,
        omega,
    }
}

/// Output columns writing the seven vectors of `out`.
pub fn wrench_columns<T>(out: &mut [Vec<T>; 7]) -> contensou_wrench_columns<T> {
    let [n, fx, fy, tz, a, b, e2] = out.each_mut().map(|c| c.as_mut_ptr());
    contensou_wrench_columns {
        n,
        fx,
        fy,
        tz,
        a,
        b,
        e2,
    }
}
