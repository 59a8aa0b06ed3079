//! A rolling direction not along an axis of the contact ellipse.
//!
//! # Formula
//!
//! Kalker's coefficients, FASTSIM and the exact reference are for a rolling velocity along a
//! semi-axis. For a patch with semi-axes (a_M, b_m) along the library frame's x (major) and y,
//! and a rolling velocity at the angle θ from x (cos θ, sin θ), the rolling law is evaluated on
//! the ellipse aligned with the rolling direction whose semi-axis along it is the patch's
//! extent in that direction,
//!
//! a_r = a_M b_m / √(b_m² cos²θ + a_M² sin²θ),   b_r = a_M b_m / a_r
//!
//! (the same area and the same c = √(ab)). Exact along either axis (θ = 0: (a_M, b_m);
//! θ = π/2: (b_m, a_M)), continuous in θ, and symmetric under θ → −θ, θ → π − θ. The
//! approximation is the rest of the shape: the aligned ellipse is not the patch, so the
//! full-slip limit is the Contensou integral of the aligned ellipse, not of the patch, for
//! 0 < |θ| < π/2 (the per-step contract still takes its rolling velocity along x).
//!
//! # Domain
//!
//! a_M ≥ b_m > 0 (the library frame's ordering), (cos θ, sin θ) any direction (normalised
//! here; zero → θ = 0). Total: no error, no division by zero for positive semi-axes.
//!
//! # Cost
//!
//! Two square roots and two divisions.

use crate::Real;

/// The aligned ellipse (a_r along the rolling direction, b_r across) for a patch (a_M along x,
/// b_m along y) and a rolling direction (cx, sx) in the library frame (see the
/// [module docs](self)).
pub fn aligned_ellipse<T: Real>(a_major: T, b_minor: T, cx: T, sx: T) -> (T, T) {
    let n2 = cx * cx + sx * sx;
    let (c2, s2) = if n2 > T::ZERO {
        (cx * cx / n2, sx * sx / n2)
    } else {
        (T::ONE, T::ZERO)
    };
    let ab = a_major * b_minor;
    let ar = ab / (b_minor * b_minor * c2 + a_major * a_major * s2).sqrt();
    (ar, ab / ar)
}
