//! The crate's one error type.
//!
//! Errors happen only at construction (validating inputs into the types the hot path takes).
//! The per-step calls are total: they take validated types and return plain values.

use core::fmt;

/// Why an input was rejected. Every variant names the input that triggers it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// An input that must be a finite number was NaN or ±∞. Carries the input's name.
    NonFinite(&'static str),
    /// Elliptic parameter m outside the supported domain `[0, 1 − m₁_min]`
    /// (`m₁_min` = 1e-12 for `f64`, 2⁻²⁴ for `f32`), or m₁ = 1 − m outside `[m₁_min, 1]`.
    EllipticParameterOutOfDomain,
    /// A curvature that must be positive is ≤ 0 — P or Q itself (`Curvatures::new`), or a sum
    /// of two bodies' curvatures (`sphere_sphere`, `ball_race`, `from_bodies`): the bodies are
    /// not locally convex towards each other (no Hertz contact).
    CurvatureNotPositive,
    /// Curvatures given in a fixed frame with P > Q where that frame requires P ≤ Q (x must be
    /// the major axis: `Curvatures::ordered`, the wrench contract of [`crate::dynamic`]).
    /// [`crate::geometry::Curvatures::new`] instead swaps them and reports the major-axis angle.
    CurvaturesNotOrdered,
    /// Curvature ratio g = P/Q outside the supported range of the eccentricity solver
    /// (below `shape::Ratio::MIN` = 1e-4), or, for `normal::Volumetric::checked`, below that
    /// law's stated domain g ≥ 0.5.
    CurvatureRatioOutOfRange,
    /// A Young's modulus or effective modulus that must be positive is ≤ 0.
    ModulusNotPositive,
    /// Poisson's ratio ν outside (−1, 0.5].
    PoissonRatioOutOfRange,
    /// Friction coefficient f < 0.
    FrictionCoefficientNegative,
    /// A length (radius, diameter, pitch diameter, groove radius) that must be positive is ≤ 0.
    LengthNotPositive,
    /// The friction regularization speed δ (m/s) is negative (δ = 0 is allowed: no
    /// regularization).
    RegularizationSpeedNegative,
    /// A damping coefficient is negative.
    DampingNegative,
    /// The combined shear modulus G of a rolling contact ([`crate::friction::rolling`]) is ≤ 0
    /// or its combination from two bodies under- or overflows.
    ShearModulusNotPositive,
    /// Poisson's ratio ν of a rolling contact outside [0, 0.5] (the domain of Kalker's
    /// coefficient table).
    RollingPoissonRatioOutOfRange,
    /// The semi-axis ratio a/b of a rolling contact (a along the rolling direction) outside
    /// [0.01, 100].
    RollingAspectOutOfRange,
    /// The columns of a batch call ([`crate::batch`]) have different lengths: the error names
    /// the first column whose length differs from `h`'s.
    ColumnLengthMismatch,
    /// A time step Δt ([`crate::step::TimeStep`]) is ≤ 0 (NaN or ±∞ is
    /// [`Error::NonFinite`] `"dt"`).
    StepNotPositive,
    /// An inverse-mass matrix W ([`crate::step::InverseMass`]) is not symmetric within the
    /// stated tolerance: |W_ij − W_ji| > [`crate::step::SYMMETRY_TOLERANCE`]·ε·√(W_ii·W_jj), or
    /// W_ij ≠ W_ji in the row of a zero diagonal entry.
    InverseMassNotSymmetric,
    /// An inverse-mass matrix W ([`crate::step::InverseMass`]) is not positive semidefinite
    /// within the stated tolerance (a negative diagonal entry, W_ij = W_ji ≠ 0 in the row of a
    /// zero diagonal entry, or an LDLᵀ pivot of the diagonally scaled matrix below
    /// −[`crate::step::PSD_TOLERANCE`]·ε).
    InverseMassNotPositiveSemidefinite,
    /// A body's mass ([`crate::step::Body`]) is ≤ 0.
    MassNotPositive,
    /// A body's inertia tensor ([`crate::step::Body`]) is not symmetric positive definite.
    InertiaNotPositiveDefinite,
    /// A contact of [`crate::step::InverseMass::from_bodies`] names a body index beyond the
    /// bodies given, or the same body as both A and B.
    BodyIndexInvalid,
}

impl Error {
    /// Every variant once, in declaration order (`NonFinite` with the placeholder name
    /// `"input"`): for the shells that give each its own code and the tests that walk them all.
    /// A new variant goes here too.
    pub const ALL: [Error; 21] = [
        Error::NonFinite("input"),
        Error::EllipticParameterOutOfDomain,
        Error::CurvatureNotPositive,
        Error::CurvaturesNotOrdered,
        Error::CurvatureRatioOutOfRange,
        Error::ModulusNotPositive,
        Error::PoissonRatioOutOfRange,
        Error::FrictionCoefficientNegative,
        Error::LengthNotPositive,
        Error::RegularizationSpeedNegative,
        Error::DampingNegative,
        Error::ShearModulusNotPositive,
        Error::RollingPoissonRatioOutOfRange,
        Error::RollingAspectOutOfRange,
        Error::ColumnLengthMismatch,
        Error::StepNotPositive,
        Error::InverseMassNotSymmetric,
        Error::InverseMassNotPositiveSemidefinite,
        Error::MassNotPositive,
        Error::InertiaNotPositiveDefinite,
        Error::BodyIndexInvalid,
    ];

    /// A short description of the error (for `NonFinite`, without the input's name).
    pub const fn as_str(&self) -> &'static str {
        match self {
            Error::NonFinite(_) => "input must be finite",
            Error::EllipticParameterOutOfDomain => {
                "elliptic parameter m outside [0, 1 - m1_min] (m1_min = 1e-12 in f64, 2^-24 in f32)"
            }
            Error::CurvatureNotPositive => {
                "curvature must be positive (P and Q, or the sum of the two bodies' curvatures)"
            }
            Error::CurvaturesNotOrdered => "curvatures must satisfy P <= Q (x is the major axis)",
            Error::CurvatureRatioOutOfRange => {
                "curvature ratio P/Q below the solver's range (g >= 1e-4; volumetric law: g >= 0.5)"
            }
            Error::ModulusNotPositive => "elastic modulus must be positive",
            Error::PoissonRatioOutOfRange => "Poisson's ratio outside (-1, 0.5]",
            Error::FrictionCoefficientNegative => "friction coefficient is negative",
            Error::LengthNotPositive => "length must be positive",
            Error::RegularizationSpeedNegative => {
                "regularization speed delta must be >= 0 (m/s; 0 = no regularization)"
            }
            Error::DampingNegative => "damping coefficient is negative",
            Error::ShearModulusNotPositive => "shear modulus G must be positive (Pa)",
            Error::RollingPoissonRatioOutOfRange => {
                "Poisson's ratio of a rolling contact outside [0, 0.5] (Kalker's table)"
            }
            Error::RollingAspectOutOfRange => {
                "semi-axis ratio a/b of a rolling contact outside [0.01, 100]"
            }
            Error::ColumnLengthMismatch => "batch columns have different lengths",
            Error::StepNotPositive => "time step dt must be > 0 (s)",
            Error::InverseMassNotSymmetric => {
                "inverse-mass matrix W is not symmetric within the stated tolerance"
            }
            Error::InverseMassNotPositiveSemidefinite => {
                "inverse-mass matrix W is not positive semidefinite within the stated tolerance"
            }
            Error::MassNotPositive => "body mass must be > 0 (kg)",
            Error::InertiaNotPositiveDefinite => {
                "inertia tensor must be symmetric positive definite (kg m^2)"
            }
            Error::BodyIndexInvalid => {
                "contact names a body index out of range, or the same body as A and B"
            }
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NonFinite(what) => write!(f, "{what} must be finite"),
            other => f.write_str(other.as_str()),
        }
    }
}

impl core::error::Error for Error {}

/// `Err(Error::NonFinite(name))` unless `x` is finite.
#[inline]
pub(crate) fn finite<T: crate::Real>(x: T, name: &'static str) -> Result<T, Error> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Error::NonFinite(name))
    }
}
