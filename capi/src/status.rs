//! The one status code of every fallible function, and its message.
//!
//! Codes 1–21 map one to one to the variants of [`contensou::Error`] (their messages are
//! [`contensou::Error::as_str`]); codes from 100 are the C boundary's own.

use core::ffi::{c_char, CStr};

use contensou::Error;

use crate::cstr::{c_str, c_strs};

/// What a call did: [`contensou_status::Ok`] or why it refused (nothing was written then,
/// except the `column` out-parameter).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum contensou_status {
    /// Success.
    Ok = 0,
    /// [`Error::NonFinite`]: an input that must be finite was NaN or ±∞.
    NonFinite = 1,
    /// [`Error::EllipticParameterOutOfDomain`].
    EllipticParameterOutOfDomain = 2,
    /// [`Error::CurvatureNotPositive`]: P ≤ 0, or two bodies not convex towards each other.
    CurvatureNotPositive = 3,
    /// [`Error::CurvaturesNotOrdered`]: P > Q where the contract requires P ≤ Q.
    CurvaturesNotOrdered = 4,
    /// [`Error::CurvatureRatioOutOfRange`]: P/Q below 1e-4.
    CurvatureRatioOutOfRange = 5,
    /// [`Error::ModulusNotPositive`].
    ModulusNotPositive = 6,
    /// [`Error::PoissonRatioOutOfRange`]: ν outside (−1, 0.5].
    PoissonRatioOutOfRange = 7,
    /// [`Error::FrictionCoefficientNegative`].
    FrictionCoefficientNegative = 8,
    /// [`Error::LengthNotPositive`]: a radius or diameter ≤ 0.
    LengthNotPositive = 9,
    /// [`Error::RegularizationSpeedNegative`]: δ < 0.
    RegularizationSpeedNegative = 10,
    /// [`Error::DampingNegative`]: c_d < 0.
    DampingNegative = 11,
    /// [`Error::ShearModulusNotPositive`]: G ≤ 0 (rolling contacts).
    ShearModulusNotPositive = 12,
    /// [`Error::RollingPoissonRatioOutOfRange`]: ν outside [0, 0.5] (rolling contacts).
    RollingPoissonRatioOutOfRange = 13,
    /// [`Error::RollingAspectOutOfRange`]: a/b outside [0.01, 100] (rolling contacts).
    RollingAspectOutOfRange = 14,
    /// [`Error::ColumnLengthMismatch`] (batch columns; not returned by this API's calls,
    /// whose columns share one `rows`).
    ColumnLengthMismatch = 15,
    /// [`Error::StepNotPositive`]: a time step Δt ≤ 0 (step-aware calls).
    StepNotPositive = 16,
    /// [`Error::InverseMassNotSymmetric`]: the inverse-mass matrix W is not symmetric within
    /// the library's stated tolerance (step-aware calls).
    InverseMassNotSymmetric = 17,
    /// [`Error::InverseMassNotPositiveSemidefinite`]: W is not positive semidefinite within
    /// the library's stated tolerance (step-aware calls).
    InverseMassNotPositiveSemidefinite = 18,
    /// [`Error::MassNotPositive`]: a body's mass ≤ 0 (building W from bodies).
    MassNotPositive = 19,
    /// [`Error::InertiaNotPositiveDefinite`]: a body's inertia tensor is not symmetric
    /// positive definite (building W from bodies).
    InertiaNotPositiveDefinite = 20,
    /// [`Error::BodyIndexInvalid`]: a contact names a body index out of range, or the same
    /// body as A and B (building W from bodies).
    BodyIndexInvalid = 21,
    /// A pointer parameter that must not be NULL was NULL.
    NullPointer = 100,
    /// A pointer parameter is not aligned for its type (storage: 8 bytes).
    Misaligned = 101,
    /// The contact storage was not initialised by `contensou_contact_new_*` (or
    /// `contensou_rolling_new_*`) of this precision.
    NotInitialized = 102,
    /// A `contensou_law` value outside the `CONTENSOU_LAW_*` constants, or one the call does
    /// not take (a sliding law for a rolling contact, `full-slip`/`linear` for a wrench
    /// contact).
    InvalidLaw = 103,
    /// A `contensou_form` value outside the `CONTENSOU_FORM_*` constants.
    InvalidForm = 104,
    /// A `contensou_race` value outside the `CONTENSOU_RACE_*` constants.
    InvalidRace = 105,
    /// A name that is no law or form (`contensou_law_from_name`, `contensou_form_from_name`).
    UnknownName = 106,
    /// Reserved for a panic caught at the boundary. Never returned: no exported function can
    /// panic (the link-time proof tools/no-panic.sh), and the library is built with
    /// `panic = "abort"`.
    Panic = 107,
    /// A `contensou::Error` variant newer than this C API (the enum is non-exhaustive). Never
    /// returned by this build: every variant of its `contensou` is mapped.
    UnknownError = 108,
    /// A contact count outside 1 … `CONTENSOU_STEP_MAX_CONTACTS` (8) for
    /// `contensou_step_many_*`.
    ContactCountOutOfRange = 109,
}

impl From<Error> for contensou_status {
    fn from(e: Error) -> Self {
        Self::of_error(e)
    }
}

/// The library errors' messages ([`Error::as_str`]), NUL-terminated at compile time, in
/// [`Error::ALL`] order: code k's is entry k − 1.
const ERROR_MESSAGES: [&CStr; Error::ALL.len()] = c_strs!(error_texts(); 21);

const fn error_texts() -> [&'static str; Error::ALL.len()] {
    let mut out = [""; Error::ALL.len()];
    let mut k = 0;
    while k < out.len() {
        out[k] = Error::ALL[k].as_str();
        k += 1;
    }
    out
}

// Codes 1 … 21 are the library's errors in `Error::ALL` order.
const _: () = {
    let mut k = 0;
    while k < Error::ALL.len() {
        assert!(contensou_status::of_error(Error::ALL[k]) as usize == k + 1);
        k += 1;
    }
};

impl contensou_status {
    /// The status of a library error (codes 1 … 21, in [`Error::ALL`] order).
    pub(crate) const fn of_error(e: Error) -> Self {
        match e {
            Error::NonFinite(_) => Self::NonFinite,
            Error::EllipticParameterOutOfDomain => Self::EllipticParameterOutOfDomain,
            Error::CurvatureNotPositive => Self::CurvatureNotPositive,
            Error::CurvaturesNotOrdered => Self::CurvaturesNotOrdered,
            Error::CurvatureRatioOutOfRange => Self::CurvatureRatioOutOfRange,
            Error::ModulusNotPositive => Self::ModulusNotPositive,
            Error::PoissonRatioOutOfRange => Self::PoissonRatioOutOfRange,
            Error::FrictionCoefficientNegative => Self::FrictionCoefficientNegative,
            Error::LengthNotPositive => Self::LengthNotPositive,
            Error::RegularizationSpeedNegative => Self::RegularizationSpeedNegative,
            Error::DampingNegative => Self::DampingNegative,
            Error::ShearModulusNotPositive => Self::ShearModulusNotPositive,
            Error::RollingPoissonRatioOutOfRange => Self::RollingPoissonRatioOutOfRange,
            Error::RollingAspectOutOfRange => Self::RollingAspectOutOfRange,
            Error::ColumnLengthMismatch => Self::ColumnLengthMismatch,
            Error::StepNotPositive => Self::StepNotPositive,
            Error::InverseMassNotSymmetric => Self::InverseMassNotSymmetric,
            Error::InverseMassNotPositiveSemidefinite => Self::InverseMassNotPositiveSemidefinite,
            Error::MassNotPositive => Self::MassNotPositive,
            Error::InertiaNotPositiveDefinite => Self::InertiaNotPositiveDefinite,
            Error::BodyIndexInvalid => Self::BodyIndexInvalid,
            _ => Self::UnknownError,
        }
    }

    /// The message of a raw code (any `u32`: unknown codes get a message too).
    pub fn message_of(code: u32) -> &'static CStr {
        use contensou_status as S;
        const OWN: [contensou_status; 11] = [
            S::Ok,
            S::NullPointer,
            S::Misaligned,
            S::NotInitialized,
            S::InvalidLaw,
            S::InvalidForm,
            S::InvalidRace,
            S::UnknownName,
            S::Panic,
            S::UnknownError,
            S::ContactCountOutOfRange,
        ];
        let k = (code as usize).wrapping_sub(1);
        if k < ERROR_MESSAGES.len() {
            return ERROR_MESSAGES[k];
        }
        match OWN.into_iter().find(|s| *s as u32 == code) {
            Some(s) => s.message(),
            None => c_str!("unknown contensou_status code"),
        }
    }

    /// The static message of this code (for the library's errors: [`Error::as_str`]).
    pub const fn message(self) -> &'static CStr {
        use contensou_status as S;
        match self {
            S::Ok => c_str!("ok"),
            S::NullPointer => c_str!("a pointer parameter is NULL"),
            S::Misaligned => c_str!("a pointer parameter is misaligned for its type"),
            S::NotInitialized => {
                c_str!(
                    "contact storage not initialised by contensou_contact_new_* of this precision"
                )
            }
            S::InvalidLaw => c_str!("invalid contensou_law value"),
            S::InvalidForm => c_str!("invalid contensou_form value"),
            S::InvalidRace => c_str!("invalid contensou_race value"),
            S::UnknownName => c_str!("unknown law or form name"),
            S::Panic => c_str!("panic caught at the C boundary (reserved: cannot happen)"),
            S::UnknownError => c_str!("contensou error unknown to this C API version"),
            S::ContactCountOutOfRange => {
                c_str!("contact count outside 1 ... CONTENSOU_STEP_MAX_CONTACTS (8)")
            }
            // codes 1 … 21: the library's errors
            _ => {
                let k = (self as usize).wrapping_sub(1);
                if k < ERROR_MESSAGES.len() {
                    ERROR_MESSAGES[k]
                } else {
                    c_str!("")
                }
            }
        }
    }

    /// [`contensou_status::message`] as a C pointer.
    pub(crate) fn message_ptr(code: u32) -> *const c_char {
        Self::message_of(code).as_ptr()
    }
}
