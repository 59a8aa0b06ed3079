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

impl<T: Copy> Elasticity<T> {
    /// G and ν through `f` (the dual form of the Jacobian).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> Elasticity<U> {
        Elasticity {
            g: f(self.g),
            nu: f(self.nu),
        }
    }
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
    /// The normal–tangential coupling is neglected (see the [module docs](self)). Two valid
    /// bodies always combine (G finite, between G₁ and G₂).
    pub fn dissimilar(g1: T, nu1: T, g2: T, nu2: T) -> Result<Self, Error> {
        let b1 = Self::new(g1, nu1)?;
        let b2 = Self::new(g2, nu2)?;
        // In terms of q = G_lo/G_hi ∈ (0, 1]: G = 2G_lo/(1 + q), ν = (ν_lo + qν_hi)/(1 + q) —
        // the same formulas, free of the overflow of 1/G_i for subnormal G_i and of
        // 1/G₁ + 1/G₂ → G = ∞ for G_i near the float's maximum (a fuzz finding).
        let (lo, hi) = if b1.g <= b2.g { (b1, b2) } else { (b2, b1) };
        let q = lo.g / hi.g;
        let r = T::ONE / (T::ONE + q);
        // G ∈ [G_lo, G_hi]: the factor 2/(1 + q) ∈ [1, 2), min() keeps the rounding inside
        let g = (lo.g * (T::TWO * r)).min(hi.g);
        let nu = (lo.nu + q * hi.nu) * r;
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
