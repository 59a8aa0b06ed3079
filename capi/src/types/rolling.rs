//! The C types of the rolling evaluator (`contensou_rolling_*`): Kalker's rolling
//! contact ([`contensou::friction::rolling`]) with the columns of `contact_eval rolling`.

use contensou::friction::rolling::row::{Column, RowContact};

/// The per-call inputs of a rolling contact: the columns `a,b,f,N,V,xi,eta,phi` of
/// `contact_eval rolling` (its `G, nu` and the shape a/b are the contact's).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_rolling_state<T> {
    /// Semi-axis a (m) along the rolling direction +x, > 0.
    pub a: T,
    /// Semi-axis b (m) across, > 0. The patch size c = √(ab) comes from a and b; its shape
    /// is the contact's a/b (`contensou_rolling_new_*`).
    pub b: T,
    /// Friction coefficient f ≥ 0.
    pub f: T,
    /// Normal force N (N); ≤ 0 is no contact (zero wrench).
    pub n: T,
    /// Rolling velocity V (m/s) along x: only its sign matters at given creepages (V < 0 is
    /// the mirror image, V = 0 the limit V → 0⁺).
    pub v: T,
    /// Longitudinal creepage ξ of body B relative to A (dimensionless).
    pub xi: T,
    /// Lateral creepage η (dimensionless).
    pub eta: T,
    /// Spin creepage φ (1/m).
    pub phi: T,
}

/// The rolling wrench on body B from body A in the rolling frame (x along the rolling
/// direction): the outputs `Fx,Fy,Mz` of `contact_eval rolling`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct contensou_rolling_output<T> {
    /// F_x (N).
    pub fx: T,
    /// F_y (N).
    pub fy: T,
    /// M_z (N·m), about the patch centre.
    pub mz: T,
}

/// Bytes of [`contensou_rolling_f32`]: the contact (1,936 bytes in this version on 64-bit hosts) and room
/// for the laws' per-contact tables to grow without an ABI change.
pub const CONTENSOU_ROLLING_F32_SIZE: usize = 4096;
/// Bytes of [`contensou_rolling_f64`] (3,568 bytes used in this version on 64-bit hosts).
pub const CONTENSOU_ROLLING_F64_SIZE: usize = 8192;

super::storage! {
    /// Caller-owned storage of one `float` rolling contact: opaque,
    /// [`CONTENSOU_ROLLING_F32_SIZE`] bytes, 8-byte aligned (`CONTENSOU_CONTACT_ALIGN`).
    /// Initialised by `contensou_rolling_new_f32`; other calls on storage it did not initialise
    /// return `CONTENSOU_STATUS_NOT_INITIALIZED`. Plain data (may be copied), no destructor;
    /// `contensou_rolling_wrench_f32` only reads it, so threads may share one.
    contensou_rolling_f32: 512;
    /// Caller-owned storage of one `double` rolling contact: opaque,
    /// [`CONTENSOU_ROLLING_F64_SIZE`] bytes, 8-byte aligned. As [`contensou_rolling_f32`].
    contensou_rolling_f64: 1024;
}

/// What a rolling storage holds: a tag only the constructor writes, the contact and its law.
pub(crate) type RollingSlot<T> = super::Tagged<RowContact<T>>;

// The slot fits in the storage, on every target this crate is built for.
const _: () = {
    use core::mem::{align_of, size_of};
    assert!(size_of::<contensou_rolling_f32>() == CONTENSOU_ROLLING_F32_SIZE);
    assert!(size_of::<contensou_rolling_f64>() == CONTENSOU_ROLLING_F64_SIZE);
    assert!(size_of::<RollingSlot<f32>>() <= CONTENSOU_ROLLING_F32_SIZE);
    assert!(size_of::<RollingSlot<f64>>() <= CONTENSOU_ROLLING_F64_SIZE);
    assert!(align_of::<contensou_rolling_f32>() == super::CONTENSOU_CONTACT_ALIGN);
    assert!(align_of::<contensou_rolling_f64>() == super::CONTENSOU_CONTACT_ALIGN);
    assert!(align_of::<RollingSlot<f64>>() <= super::CONTENSOU_CONTACT_ALIGN);
};

// The column codes are the library's `Column` values.
const _: () = {
    assert!(CONTENSOU_ROLLING_COLUMN_A == Column::A as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_B == Column::B as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_G == Column::G as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_NU == Column::Nu as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_F == Column::F as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_N == Column::N as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_V == Column::V as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_XI == Column::Xi as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_ETA == Column::Eta as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_PHI == Column::Phi as u32);
    assert!(CONTENSOU_ROLLING_COLUMN_A_OVER_B == Column::AOverB as u32);
};

/// A column of `contact_eval rolling` (`a,b,G,nu,f,N,V,xi,eta,phi`), the shape a/b, or
/// [`CONTENSOU_ROLLING_COLUMN_NONE`]: which input a rolling call's error came from.
pub type contensou_rolling_column = u32;
/// `a`.
pub const CONTENSOU_ROLLING_COLUMN_A: contensou_rolling_column = 0;
/// `b`.
pub const CONTENSOU_ROLLING_COLUMN_B: contensou_rolling_column = 1;
/// `G`.
pub const CONTENSOU_ROLLING_COLUMN_G: contensou_rolling_column = 2;
/// `nu`.
pub const CONTENSOU_ROLLING_COLUMN_NU: contensou_rolling_column = 3;
/// `f`.
pub const CONTENSOU_ROLLING_COLUMN_F: contensou_rolling_column = 4;
/// `N`.
pub const CONTENSOU_ROLLING_COLUMN_N: contensou_rolling_column = 5;
/// `V`.
pub const CONTENSOU_ROLLING_COLUMN_V: contensou_rolling_column = 6;
/// `xi`.
pub const CONTENSOU_ROLLING_COLUMN_XI: contensou_rolling_column = 7;
/// `eta`.
pub const CONTENSOU_ROLLING_COLUMN_ETA: contensou_rolling_column = 8;
/// `phi`.
pub const CONTENSOU_ROLLING_COLUMN_PHI: contensou_rolling_column = 9;
/// `a/b`: the shape given to `contensou_rolling_new_*`.
pub const CONTENSOU_ROLLING_COLUMN_A_OVER_B: contensou_rolling_column = 10;
/// No column: success, or an error not tied to an input (a NULL pointer, …).
pub const CONTENSOU_ROLLING_COLUMN_NONE: contensou_rolling_column = 11;

impl<T> From<contensou_rolling_state<T>> for contensou::friction::rolling::row::RowState<T> {
    fn from(s: contensou_rolling_state<T>) -> Self {
        Self {
            a: s.a,
            b: s.b,
            f: s.f,
            n: s.n,
            v: s.v,
            xi: s.xi,
            eta: s.eta,
            phi: s.phi,
        }
    }
}

impl<T> From<contensou::friction::rolling::Wrench<T>> for contensou_rolling_output<T> {
    fn from(w: contensou::friction::rolling::Wrench<T>) -> Self {
        Self {
            fx: w.fx,
            fy: w.fy,
            mz: w.mz,
        }
    }
}
