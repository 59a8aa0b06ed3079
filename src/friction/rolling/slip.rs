//! The rolling slip state: the rigid slip (v_x, v_y) of body B relative to body A at the patch
//! centre, the relative spin ω about the normal, and the rolling velocity V; the creepages.
//!
//! # Formula
//!
//! Kalker's creepages (frame of [`super`]: x along the rolling direction):
//! ξ = v_x/V, η = v_y/V (dimensionless), φ = ω/V (1/m).
//!
//! # Domain and special cases
//!
//! Every finite (v_x, v_y, ω, V). The creepages are not formed by the laws (they are infinite
//! at V = 0): the laws use the homogeneous form ([`RollingSlip::scaled`]), so V → 0 is the
//! full-slip limit without a division by zero, and V = 0 is pure sliding/pivoting (the
//! Contensou–Erismann integrals). A negative V (rolling towards −x, the leading edge at −a) is
//! the mirror image x → −x of rolling towards +x: the laws evaluate (−v_x, v_y, −ω, |V|) and
//! negate F_x and M_z. Non-finite inputs: [`Error::NonFinite`] (`"v_x"`, `"v_y"`, `"omega"`,
//! `"V"`).

use crate::error::finite;
use crate::{Error, Real};

/// A validated rolling slip state (m/s, m/s, rad/s, m/s): see the [module docs](self).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollingSlip<T> {
    pub(crate) vx: T,
    pub(crate) vy: T,
    pub(crate) omega: T,
    pub(crate) v: T,
}

/// The homogeneous form of a [`RollingSlip`] for a patch of length scale c: every component
/// divided by S = max(|V|, |v_x| + |v_y| + c|ω|), so (vx, vy, c·omega) ∈ [−1, 1]³ and
/// v = |V|/S ∈ [0, 1], with the mirror for V < 0 applied (`mirrored`). All zero at rest.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Scaled<T> {
    /// v_x/S (mirrored: −v_x/S)
    pub vx: T,
    /// v_y/S
    pub vy: T,
    /// ω/S (1/m; mirrored: −ω/S)
    pub omega: T,
    /// |V|/S ∈ [0, 1]: 0 or at least the smallest normal float (a subnormal ratio is 0)
    pub v: T,
    /// V < 0: the caller negates F_x and M_z.
    pub mirrored: bool,
}

impl<T: Real> RollingSlip<T> {
    /// From the slip (v_x, v_y) (m/s), the spin ω (rad/s) and the rolling velocity V (m/s)
    /// along x; all finite.
    pub fn new(vx: T, vy: T, omega: T, v: T) -> Result<Self, Error> {
        Ok(Self {
            vx: finite(vx, "v_x")?,
            vy: finite(vy, "v_y")?,
            omega: finite(omega, "omega")?,
            v: finite(v, "V")?,
        })
    }

    /// From Kalker's creepages ξ, η (dimensionless), φ (1/m) at a rolling speed V (m/s):
    /// v_x = ξV, v_y = ηV, ω = φV. Errors as [`Self::new`] (also for products overflowing).
    pub fn from_creepages(xi: T, eta: T, phi: T, v: T) -> Result<Self, Error> {
        Self::new(xi * v, eta * v, phi * v, v)
    }

    /// v_x (m/s)
    pub fn vx(&self) -> T {
        self.vx
    }
    /// v_y (m/s)
    pub fn vy(&self) -> T {
        self.vy
    }
    /// ω (rad/s)
    pub fn omega(&self) -> T {
        self.omega
    }
    /// V (m/s)
    pub fn v(&self) -> T {
        self.v
    }

    /// Kalker's creepages (ξ, η, φ) = (v_x, v_y, ω)/V; `None` for V = 0 (full slip). Never
    /// NaN: a component is ±∞ only if the quotient overflows (|V| tiny), 0 if its numerator is.
    pub fn creepages(&self) -> Option<(T, T, T)> {
        if self.v == T::ZERO {
            None
        } else {
            // three divisions, not 1/V times each: 1/V overflows for subnormal V and
            // 0 · ∞ would be NaN (a fuzz finding)
            Some((self.vx / self.v, self.vy / self.v, self.omega / self.v))
        }
    }

    /// The homogeneous form for the length scale `c` > 0 (see [`Scaled`]). Total.
    #[inline]
    pub fn scaled(&self, c: T) -> Scaled<T> {
        let mirrored = self.v < T::ZERO;
        let (vx, om) = if mirrored {
            (-self.vx, -self.omega)
        } else {
            (self.vx, self.omega)
        };
        let v = self.v.abs();
        let l1 = vx.abs() + self.vy.abs() + (c * om).abs();
        let s = if l1 > v { l1 } else { v };
        let r = T::ONE / s;
        // rest (1/0), an overflowing sum, or a subnormal S whose reciprocal overflows
        let mut out = if s.is_finite() && r.is_finite() {
            Self::times(vx, self.vy, om, v, r, mirrored)
        } else {
            self.unusual(c, mirrored, vx, om, v)
        };
        // a subnormal |V|/S (a creepage beyond 1/MIN_POSITIVE) is full slip: 0, so that the
        // laws' 1/v stays finite (a fuzz finding: ∞·0 in `blend` at V = 1e-310 m/s)
        if out.v < T::MIN_POSITIVE {
            out.v = T::ZERO;
        }
        out
    }

    #[inline(always)]
    fn times(vx: T, vy: T, om: T, v: T, r: T, mirrored: bool) -> Scaled<T> {
        Scaled {
            vx: vx * r,
            vy: vy * r,
            omega: om * r,
            v: v * r,
            mirrored,
        }
    }

    /// Rest, an overflowing sum, or a subnormal one: divide by the largest magnitude (c|ω|
    /// overflowing: pure spin; an infinite component, from a caller's arithmetic: its sign), by four divisions (1/m may overflow for a subnormal m: ∞·0 =
    /// NaN, a fuzz finding).
    #[cold]
    fn unusual(&self, c: T, mirrored: bool, vx: T, om: T, v: T) -> Scaled<T> {
        let cw = c * om;
        if !cw.is_finite() {
            return Scaled {
                vx: T::ZERO,
                vy: T::ZERO,
                omega: T::ONE.copysign(om) / c,
                v: T::ZERO,
                mirrored,
            };
        }
        let m = vx.abs().max(self.vy.abs()).max(cw.abs()).max(v);
        if !m.is_finite() {
            // a component itself overflowed (a caller's rotation of an extreme slip, or |V|
            // from its components): the limit direction, ±1 for the infinite ones (fuzz
            // finding: ∞/∞ = NaN in contact::Rolling at f32 |v| ≈ 3.8e38)
            let unit = |x: T| {
                if !x.is_finite() {
                    T::ONE.copysign(x)
                } else {
                    T::ZERO
                }
            };
            return Scaled {
                vx: unit(vx),
                vy: unit(self.vy),
                omega: T::ZERO,
                v: unit(v),
                mirrored,
            };
        }
        if m > T::ZERO {
            Scaled {
                vx: vx / m,
                vy: self.vy / m,
                omega: om / m,
                v: v / m,
                mirrored,
            }
        } else {
            Scaled {
                mirrored,
                ..Scaled::default()
            }
        }
    }
}
