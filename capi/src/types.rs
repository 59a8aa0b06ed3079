//! The C types: plain `repr(C)` value structs (generic here, one C struct per precision in the
//! header: `contensou_spec_f32`, `contensou_spec_f64`, …), the opaque caller-owned contact
//! storage, and the `uint32_t` enumerations (plain integers, so that any value a C caller
//! passes is defined behaviour and an unknown one is a status code).

use contensou::dynamic::DynContact;

mod jacobian;
mod rolling;
mod step;
pub use jacobian::*;
pub use rolling::*;
pub use step::*;

/// The contact columns `P,Q,estar,cd,f,delta` of the contract ([`contensou::dynamic::Spec`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_spec<T> {
    /// P (1/m), 0 < P ≤ Q: x is the major axis (the helpers give P, Q in this order).
    pub p: T,
    /// Q (1/m), P/Q ≥ 1e-4.
    pub q: T,
    /// Effective modulus E* (Pa) > 0 (`contensou_modulus_of_*` from two materials).
    pub estar: T,
    /// Hunt–Crossley damping c_d (s/m) ≥ 0; 0 = undamped.
    pub cd: T,
    /// Friction coefficient f ≥ 0.
    pub f: T,
    /// Regularization speed δ (m/s) ≥ 0.
    pub delta: T,
}

/// The step columns `h,hdot,vx,vy,omega` ([`contensou::dynamic::Step`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_step<T> {
    /// Approach h (m); ≤ 0 is contact loss.
    pub h: T,
    /// Approach rate ḣ (m/s); > 0 compression.
    pub hdot: T,
    /// Slip of B relative to A along the major axis x (m/s).
    pub vx: T,
    /// Slip along y (m/s).
    pub vy: T,
    /// Spin ω about the normal z (rad/s).
    pub omega: T,
}

/// The wrench on body B from body A and the patch ([`contensou::dynamic::Output`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_wrench<T> {
    /// Normal force N (N).
    pub n: T,
    /// Friction force F_x (N).
    pub fx: T,
    /// Friction force F_y (N).
    pub fy: T,
    /// Drilling torque T_z (N·m).
    pub tz: T,
    /// Major semi-axis a (m); 0 without contact.
    pub a: T,
    /// Minor semi-axis b (m).
    pub b: T,
    /// e² of the patch.
    pub e2: T,
}

/// Curvatures from a geometry helper, in contract order: 0 < P ≤ Q, and the angle (rad) from
/// the helper's reference direction to the major axis x of the contact frame
/// ([`contensou::geometry::Curvatures::major_angle`]).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_curvatures<T> {
    /// P (1/m), the smaller coefficient.
    pub p: T,
    /// Q (1/m).
    pub q: T,
    /// Angle (rad, in (−π/2, π/2]) to the major axis: for ball–race, from the rolling
    /// direction (π/2 for a conforming groove); for `contensou_curvatures_new_*`, 0 or π/2.
    pub major_angle: T,
}

/// Bytes of [`contensou_contact_f32`].
pub const CONTENSOU_CONTACT_F32_SIZE: usize = 2960;
/// Bytes of [`contensou_contact_f64`].
pub const CONTENSOU_CONTACT_F64_SIZE: usize = 5824;
/// Alignment (bytes) of both contact storage types.
pub const CONTENSOU_CONTACT_ALIGN: usize = 8;

/// Codes of a C enumeration (`$ty` constants), each documented by its column's name: a row
/// `NAME = value, "name";` is ``/// `name`.`` and `pub const NAME: $ty = value;`.
macro_rules! codes {
    ($ty:ty: $($name:ident = $value:literal, $column:literal;)*) => {$(
        #[doc = concat!(" `", $column, "`.")]
        pub const $name: $ty = $value;
    )*};
}

/// Opaque caller-owned storage structs, `[u64; words]` each (8-byte aligned), with their docs.
macro_rules! storage {
    ($($(#[doc = $doc:literal])* $name:ident: $words:literal;)*) => {$(
        $(#[doc = $doc])*
        #[repr(C)]
        #[derive(Debug)]
        pub struct $name {
            /// Opaque.
            pub opaque: [u64; $words],
        }
    )*};
}
pub(crate) use storage;

storage! {
    /// Caller-owned storage of one `float` contact: opaque, [`CONTENSOU_CONTACT_F32_SIZE`] bytes,
    /// 8-byte aligned. Initialised by `contensou_contact_new_f32`: other calls on storage it did
    /// not initialise (zeroed, as static memory is) return `CONTENSOU_STATUS_NOT_INITIALIZED`.
    /// Plain data (may be copied with `memcpy` or assignment); no destructor. No global state:
    /// `contensou_contact_wrench_f32` only reads the contact, so threads may share one.
    contensou_contact_f32: 370;
    /// Caller-owned storage of one `double` contact: opaque, [`CONTENSOU_CONTACT_F64_SIZE`]
    /// bytes, 8-byte aligned. As [`contensou_contact_f32`].
    contensou_contact_f64: 728;
}

/// What a storage holds: a tag that only its constructor writes, then the contact.
#[repr(C)]
pub(crate) struct Tagged<C> {
    pub(crate) tag: u32,
    pub(crate) contact: C,
}

/// What a contact storage holds.
pub(crate) type Slot<T> = Tagged<DynContact<T>>;

// The header's sizes are exact on 64-bit targets: the slot rounded up to the storage
// alignment. On 32-bit targets (thumbv7em-none-eabihf) the slot is smaller — the rolling
// laws' curves hold references into flash — and fits: one header for every target.
const _: () = {
    use core::mem::{align_of, size_of};
    assert!(size_of::<contensou_contact_f32>() == CONTENSOU_CONTACT_F32_SIZE);
    assert!(size_of::<contensou_contact_f64>() == CONTENSOU_CONTACT_F64_SIZE);
    let (f32_slot, f64_slot) = (
        size_of::<Slot<f32>>().next_multiple_of(8),
        size_of::<Slot<f64>>().next_multiple_of(8),
    );
    if cfg!(target_pointer_width = "64") {
        assert!(f32_slot == CONTENSOU_CONTACT_F32_SIZE);
        assert!(f64_slot == CONTENSOU_CONTACT_F64_SIZE);
    } else {
        assert!(f32_slot <= CONTENSOU_CONTACT_F32_SIZE);
        assert!(f64_slot <= CONTENSOU_CONTACT_F64_SIZE);
    }
    assert!(align_of::<contensou_contact_f32>() == CONTENSOU_CONTACT_ALIGN);
    assert!(align_of::<contensou_contact_f64>() == CONTENSOU_CONTACT_ALIGN);
    assert!(align_of::<Slot<f32>>() <= CONTENSOU_CONTACT_ALIGN);
    assert!(align_of::<Slot<f64>>() <= CONTENSOU_CONTACT_ALIGN);
};

/// A friction law: one of the `CONTENSOU_LAW_*` values ([`contensou::dynamic::Law`]).
pub type contensou_law = u32;
/// `best`, the exact-grade default.
pub const CONTENSOU_LAW_BEST: contensou_law = 0;
/// `simplified`, the paper's model.
pub const CONTENSOU_LAW_SIMPLIFIED: contensou_law = 1;
/// `pade`.
pub const CONTENSOU_LAW_PADE: contensou_law = 2;
/// `ellipsoid`.
pub const CONTENSOU_LAW_ELLIPSOID: contensou_law = 3;
/// `coulomb` (point contact: no drilling torque).
pub const CONTENSOU_LAW_COULOMB: contensou_law = 4;
/// `table`: the default rolling law (Kalker's theory, `contensou::friction::rolling::Table`).
/// Rolling laws (`TABLE` … `LINEAR`) build `contensou_rolling_*` contacts.
pub const CONTENSOU_LAW_TABLE: contensou_law = 5;
/// `blend`: Kalker's linear theory and the exact full slip joined by a saturation shape.
pub const CONTENSOU_LAW_BLEND: contensou_law = 6;
/// `fastsim`: FASTSIM (Kalker 1982), elliptic traction bound, 32 × 32 grid.
pub const CONTENSOU_LAW_FASTSIM: contensou_law = 7;
/// `fastsim-16`: FASTSIM on a 16 × 16 grid.
pub const CONTENSOU_LAW_FASTSIM_16: contensou_law = 8;
/// `full-slip`: the full-slip law (`best`) whatever the creepage (rolling contacts only).
pub const CONTENSOU_LAW_FULL_SLIP: contensou_law = 9;
/// `linear`: Kalker's linear theory, unsaturated (a reference; rolling contacts only).
pub const CONTENSOU_LAW_LINEAR: contensou_law = 10;

/// A contact form: one of the `CONTENSOU_FORM_*` values ([`contensou::dynamic::Form`]).
pub type contensou_form = u32;
/// Exact eccentricity solved once at construction.
pub const CONTENSOU_FORM_FIXED: contensou_form = 0;
/// Eccentricity and shape constants by table at every step; curvatures updated per step by
/// `contensou_contact_set_curvatures_*`.
pub const CONTENSOU_FORM_VARYING: contensou_form = 1;

/// A bearing raceway: one of the `CONTENSOU_RACE_*` values ([`contensou::geometry::Race`]).
pub type contensou_race = u32;
/// The inner ring's raceway.
pub const CONTENSOU_RACE_INNER: contensou_race = 0;
/// The outer ring's raceway.
pub const CONTENSOU_RACE_OUTER: contensou_race = 1;

/// An input column of the contract (the order of [`contensou::dynamic::INPUTS`], then the
/// optional rolling columns from [`CONTENSOU_COLUMN_G`]), or [`CONTENSOU_COLUMN_NONE`]: which
/// input an error came from.
pub type contensou_column = u32;
codes! {
    contensou_column:
    CONTENSOU_COLUMN_P = 0, "P";
    CONTENSOU_COLUMN_Q = 1, "Q";
    CONTENSOU_COLUMN_ESTAR = 2, "estar";
    CONTENSOU_COLUMN_CD = 3, "cd";
    CONTENSOU_COLUMN_F = 4, "f";
    CONTENSOU_COLUMN_DELTA = 5, "delta";
    CONTENSOU_COLUMN_H = 6, "h";
    CONTENSOU_COLUMN_HDOT = 7, "hdot";
    CONTENSOU_COLUMN_VX = 8, "vx";
    CONTENSOU_COLUMN_VY = 9, "vy";
    CONTENSOU_COLUMN_OMEGA = 10, "omega";
}

/// No column: success, or an error not tied to a contract column (a NULL pointer, …).
pub const CONTENSOU_COLUMN_NONE: contensou_column = 11;
/// `G` (optional rolling column; after `NONE`, which keeps its value).
pub const CONTENSOU_COLUMN_G: contensou_column = 12;
/// `nu` (optional rolling column).
pub const CONTENSOU_COLUMN_NU: contensou_column = 13;
/// `vrx` (optional rolling step column).
pub const CONTENSOU_COLUMN_VRX: contensou_column = 14;
/// `vry` (optional rolling step column).
pub const CONTENSOU_COLUMN_VRY: contensou_column = 15;

/// The optional step columns `vrx, vry` of the rolling laws
/// ([`contensou::dynamic::RollingStep`]): the contact's rolling velocity in the contact frame
/// (x the major axis), m/s. The sliding laws ignore it.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_rolling_step<T> {
    /// V_x (m/s), along the major axis.
    pub vrx: T,
    /// V_y (m/s).
    pub vry: T,
}

/// The rolling step columns of `contensou_contact_wrench_many_rolling_*`: two caller arrays
/// of `rows` values each (`vrx, vry`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct contensou_rolling_step_columns<T> {
    /// V_x (m/s) per row.
    pub vrx: *const T,
    /// V_y (m/s) per row.
    pub vry: *const T,
}

/// The step columns of `contensou_contact_wrench_many_*`: five caller arrays of `rows`
/// values each (`h, hdot, vx, vy, omega`, as [`contensou_step`]).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct contensou_step_columns<T> {
    /// Approach h (m) per row.
    pub h: *const T,
    /// ḣ (m/s) per row.
    pub hdot: *const T,
    /// v_Px (m/s) per row.
    pub vx: *const T,
    /// v_Py (m/s) per row.
    pub vy: *const T,
    /// ω (rad/s) per row.
    pub omega: *const T,
}

/// The output columns of `contensou_contact_wrench_many_*`: seven caller arrays of `rows`
/// values each (`N, Fx, Fy, Tz, a, b, e2`, as [`contensou_wrench`]), distinct and not
/// overlapping the inputs.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct contensou_wrench_columns<T> {
    /// N (N) per row.
    pub n: *mut T,
    /// F_x (N) per row.
    pub fx: *mut T,
    /// F_y (N) per row.
    pub fy: *mut T,
    /// T_z (N·m) per row.
    pub tz: *mut T,
    /// a (m) per row.
    pub a: *mut T,
    /// b (m) per row.
    pub b: *mut T,
    /// e² per row.
    pub e2: *mut T,
}

// The library's types of the C structs, field for field (the header keeps its own structs:
// cbindgen reads this crate only).

impl<T> From<contensou_spec<T>> for contensou::dynamic::Spec<T> {
    fn from(s: contensou_spec<T>) -> Self {
        Self {
            p: s.p,
            q: s.q,
            estar: s.estar,
            cd: s.cd,
            f: s.f,
            delta: s.delta,
        }
    }
}

impl<T> From<contensou_step<T>> for contensou::dynamic::Step<T> {
    fn from(s: contensou_step<T>) -> Self {
        Self {
            h: s.h,
            hdot: s.hdot,
            vx: s.vx,
            vy: s.vy,
            omega: s.omega,
        }
    }
}

impl<T> From<contensou_rolling_step<T>> for contensou::dynamic::RollingStep<T> {
    fn from(s: contensou_rolling_step<T>) -> Self {
        Self {
            vrx: s.vrx,
            vry: s.vry,
        }
    }
}

impl<T> From<contensou::dynamic::Output<T>> for contensou_wrench<T> {
    fn from(w: contensou::dynamic::Output<T>) -> Self {
        Self {
            n: w.n,
            fx: w.fx,
            fy: w.fy,
            tz: w.tz,
            a: w.a,
            b: w.b,
            e2: w.e2,
        }
    }
}
