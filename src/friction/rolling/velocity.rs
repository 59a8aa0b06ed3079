//! The rolling velocity of a contact in the contact frame, for the per-step wrench
//! ([`crate::contact::Rolling`]).
//!
//! # Meaning
//!
//! V = v_P − ½(u_A + u_B): the velocity at which the (geometric) contact point P moves over
//! the two surfaces, relative to their material, averaged over both (v_P the velocity of P,
//! u_A, u_B the material velocities of bodies A and B at P), tangential components in the
//! contact frame (x the major axis, y the minor axis, z from A into B), m/s. A wheel rolling
//! forward along +x: V along +x; material flows through the patch towards −x and the leading
//! edge is at +a. The slip (B relative to A: u_B − u_A) and V together are the kinematics of
//! a rolling contact; V = 0 is a patch that does not move over the surfaces (pure sliding and
//! pivoting: the full-slip law).
//!
//! # Domain
//!
//! Every finite (V_x, V_y) ([`Error::NonFinite`] `"V_x"`, `"V_y"` otherwise).

use crate::error::finite;
use crate::{Error, Real};

/// A validated rolling velocity (V_x, V_y) in the contact frame (m/s): see the
/// [module docs](self).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollingVelocity<T> {
    pub(crate) vx: T,
    pub(crate) vy: T,
}

impl<T: Real> RollingVelocity<T> {
    /// No rolling: the patch stands still on both surfaces (full slip).
    pub const ZERO: Self = Self {
        vx: T::ZERO,
        vy: T::ZERO,
    };

    /// From V_x, V_y (m/s) in the contact frame; both finite ([`Error::NonFinite`] `"V_x"`,
    /// `"V_y"`).
    pub fn new(vx: T, vy: T) -> Result<Self, Error> {
        Ok(Self {
            vx: finite(vx, "V_x")?,
            vy: finite(vy, "V_y")?,
        })
    }

    /// V_x (m/s), along the major axis.
    pub fn vx(&self) -> T {
        self.vx
    }

    /// V_y (m/s), along the minor axis.
    pub fn vy(&self) -> T {
        self.vy
    }
}
