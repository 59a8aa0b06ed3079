//! Derivatives of the wrench: the linearisation a large-step (implicit) integrator needs.
//!
//! The per-step inputs are, in the contact frame of the crate conventions (see the crate docs),
//!
//! ```text
//! q = (h, ḣ, v_Px, v_Py, ω)        (m, m/s, m/s, m/s, rad/s)
//! ```
//!
//! with h the approach (h > 0 in contact; the gap is g = −h) and ḣ its rate. The wrench on B
//! from A is w = (N, F_x, F_y, T_z) (N, N, N, N·m). [`Jacobian`] carries w(q) and ∂w/∂q.
//!
//! A rolling contact also takes the rolling velocity V; it is an input of the step, held
//! fixed here (no derivative with respect to V).

use crate::Real;
use crate::friction::Slip;
use crate::friction::rolling::RollingVelocity;

/// Column indices of [`Jacobian::d`]: the per-step inputs q = (h, ḣ, v_Px, v_Py, ω).
pub mod input {
    /// The approach h (m).
    pub const H: usize = 0;
    /// Its rate ḣ (m/s).
    pub const HDOT: usize = 1;
    /// The slip v_Px (m/s).
    pub const VX: usize = 2;
    /// The slip v_Py (m/s).
    pub const VY: usize = 3;
    /// The relative spin ω about the normal (rad/s).
    pub const OMEGA: usize = 4;
}

/// Row indices of [`Jacobian::value`] and [`Jacobian::d`]: the wrench w = (N, F_x, F_y, T_z).
pub mod output {
    /// The normal force N (N).
    pub const N: usize = 0;
    /// The friction force F_x (N).
    pub const FX: usize = 1;
    /// The friction force F_y (N).
    pub const FY: usize = 2;
    /// The drilling torque T_z (N·m).
    pub const TZ: usize = 3;
}

/// The wrench w = (N, F_x, F_y, T_z) at a per-step input q = (h, ḣ, v_Px, v_Py, ω) and its
/// Jacobian `d[i][j]` = ∂wᵢ/∂qⱼ (rows [`output`], columns [`input`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Jacobian<T> {
    /// (N, F_x, F_y, T_z) on B from A in the contact frame.
    pub value: [T; 4],
    /// ∂wᵢ/∂qⱼ: rows (N, F_x, F_y, T_z), columns (h, ḣ, v_Px, v_Py, ω).
    pub d: [[T; 5]; 4],
}

/// One contact's per-step input: the approach, its rate, the slip and (for a rolling law) the
/// rolling velocity (zero: full slip, and ignored by the sliding laws).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State<T> {
    /// The approach h (m); h ≤ 0 is out of contact.
    pub h: T,
    /// Its rate ḣ (m/s).
    pub hdot: T,
    /// The slip (v_Px, v_Py, ω) of B relative to A.
    pub slip: Slip<T>,
    /// The rolling velocity V in the contact frame (rolling laws only).
    pub rolling: RollingVelocity<T>,
}

/// A contact that can give its wrench and the wrench's Jacobian at a per-step state.
pub trait Linearize<T: Real> {
    /// The wrench (N, F_x, F_y, T_z) alone.
    fn wrench4(&self, s: &State<T>) -> [T; 4];
    /// The wrench and its Jacobian with respect to (h, ḣ, v_Px, v_Py, ω).
    fn linearize(&self, s: &State<T>) -> Jacobian<T>;
}
