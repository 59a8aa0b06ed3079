//! The elastic constants of the tangential problem: combined shear modulus G and Poisson ratio ν.
//!
//! # Formula
//!
//! Quasi-identical bodies (the same G and ν, or elastically similar: (1 − 2ν₁)/G₁ =
//! (1 − 2ν₂)/G₂) decouple the normal and the tangential problems; Kalker's theory then needs
//! one G and one ν. For two dissimilar bodies Kalker combines them as
//!
//! 1/G = ½(1/G₁ + 1/G₂),   ν/G = ½(ν₁/G₁ + ν₂/G₂)
//!
//! (Kalker 1990, §1.3; CONTACT's user guide, "material parameters"), and the coupling between
//! the normal and the tangential problem through Kalker's difference constant
//! K = ¼[(1 − 2ν₁)/G₁ − (1 − 2ν₂)/G₂]·G is **neglected**: the normal pressure stays Hertz's and
//! the traction bound f·p is unchanged. For steel on steel K = 0 (exact); for very dissimilar
//! pairs (rubber on steel) the neglected coupling shifts the creep curve by a few percent
//! (Kalker 1990, ch. 5).
//!
//! # Domain
//!
//! G finite and > 0 ([`Error::ShearModulusNotPositive`]); ν ∈ [0, 0.5]
//! ([`Error::RollingPoissonRatioOutOfRange`]: the domain of Kalker's coefficient table;
//! auxetic materials, ν < 0, are outside it); non-finite inputs: [`Error::NonFinite`]
//! (`"G"`, `"nu"`).

use crate::error::finite;
use crate::{Error, Real};

/// Validated elastic constants of a rolling contact: combined shear modulus G (Pa) and Poisson
/// ratio ν (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elasticity<T> {
    g: T,
    nu: T,
}

impl<T: Real> Elasticity<T> {
    /// Quasi-identical bodies: G (Pa) > 0, ν ∈ [0, 0.5].
    pub fn new(g: T, nu: T) -> Result<Self, Error> {
        let g = finite(g, "G")?;
        let nu = finite(nu, "nu")?;
        if g <= T::ZERO {
            return Err(Error::ShearModulusNotPositive);
        }
        if !(nu >= T::ZERO && nu <= T::HALF) {
            return Err(Error::RollingPoissonRatioOutOfRange);
        }
        Ok(Self { g, nu })
    }

    /// Kalker's combination of two dissimilar bodies (G₁, ν₁) and (G₂, ν₂):
    /// 1/G = ½(1/G₁ + 1/G₂), ν = G·½(ν₁/G₁ + ν₂/G₂); each body validated as in [`Self::new`].
    /// The normal–tangential coupling is neglected (see the [module docs](self)).
    pub fn dissimilar(g1: T, nu1: T, g2: T, nu2: T) -> Result<Self, Error> {
        let b1 = Self::new(g1, nu1)?;
        let b2 = Self::new(g2, nu2)?;
        let inv = T::HALF * (T::ONE / b1.g + T::ONE / b2.g);
        let g = T::ONE / inv;
        if !(g.is_finite() && g > T::ZERO) {
            return Err(Error::ShearModulusNotPositive);
        }
        let nu = g * T::HALF * (b1.nu / b1.g + b2.nu / b2.g);
        // a weighted mean of ν₁, ν₂ ∈ [0, 0.5]: inside up to rounding
        Ok(Self {
            g,
            nu: nu.max(T::ZERO).min(T::HALF),
        })
    }

    /// Combined shear modulus G (Pa).
    #[inline]
    pub fn g(&self) -> T {
        self.g
    }

    /// Poisson ratio ν.
    #[inline]
    pub fn nu(&self) -> T {
        self.nu
    }
}
