//! Contensou–Erismann dry friction over the Hertz ellipse: the sliding force and the drilling
//! torque, on body B from body A, in the contact frame (crate conventions).
//!
//! The dimensionless core maps the slip state to a [`Traction`]: force / (fN), torque / (fNa).
//! Every law is homogeneous of degree 0 in (v_Px, v_Py, aω): only the direction of that triple
//! matters (u = v/(aω), ψ = atan2(v_Py, v_Px)).

pub mod exact;

/// Dimensionless friction on body B from body A: `fx`, `fy` in units of fN, `tz` in units of
/// fNa (a = major semi-axis). Contact frame: x along the major axis.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Traction<T> {
    /// F_x/(fN)
    pub fx: T,
    /// F_y/(fN)
    pub fy: T,
    /// T_z/(fNa)
    pub tz: T,
}
