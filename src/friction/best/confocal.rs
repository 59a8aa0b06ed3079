//! The outside branch's geometry shared by every form of `best`: the confocal coordinates of
//! the instantaneous centre, the assembly of the traction from the seven coefficients (signs
//! and the torque's passive clamp), and the |F| ≤ 1 guard.

use crate::Real;
use crate::friction::{Traction, larger};

/// Confocal coordinates of the IC for x, y, w (IC outside or pure translation):
/// (cos ν, sin ν, τ, 1 − |τ|), with the signs of x and y on cos ν and sin ν and that of w on τ.
#[inline(always)]
pub(super) fn confocal<T: Real>(m: T, g1: T, x: T, y: T, w: T) -> (T, T, T, T) {
    let p = x * x + y * y;
    let w2 = w * w;
    let mw2 = m * w2;
    let dlt = p - mw2;
    let mx2w2 = mw2 * x * x;
    let r = (dlt * dlt + T::from_f64(4.0) * mx2w2).sqrt();
    // (a_c w)², (b_c w)² without cancellation
    let a2 = T::HALF * (p + mw2 + r);
    let b2 = if dlt >= T::ZERO {
        T::HALF * (dlt + r)
    } else {
        T::TWO * mx2w2 / (r - dlt)
    };
    let (ac, bc) = (a2.sqrt(), larger(b2.sqrt(), T::MIN_POSITIVE));
    let tau = g1 * w / (ac + bc);
    (x / bc, y / ac, tau, T::ONE - tau.abs())
}

/// Puts the signs back and clamps the coefficients to their passive signs.
#[inline(always)]
pub(super) fn assemble<T: Real>(c: T, sn: T, tau: T, k: &[T; 7]) -> Traction<T> {
    let q = sn * sn;
    // a + b·q ≥ 0.3 over the fitted domain (tested): no clamp needed for the forces, whose
    // signs come from c = cos ν and sn = sin ν (computed from the signed x and y).
    // τ carries the sign of w; the polynomial is clamped to its passive sign (≤ 0).
    let t = k[4] + q * (k[5] + k[6] * q);
    Traction {
        fx: -c * (k[0] + k[1] * q),
        fy: -sn * (k[2] + k[3] * q),
        tz: tau * if t < T::ZERO { t } else { T::ZERO },
    }
}

/// |F| ≤ 1: the fit can overshoot it by rounding (and by up to 4e-4 below the contract's end,
/// m₁ < 1e-5, where the fits are held at their last node); scale back onto the unit disk (a positive factor: passivity
/// and continuity are kept). One compare on the common path.
#[inline(always)]
pub(super) fn bounded<T: Real>(t: Traction<T>) -> Traction<T> {
    let f2 = t.fx * t.fx + t.fy * t.fy;
    if f2 > T::ONE { rescale(t, f2) } else { t }
}

#[cold]
#[inline(never)]
fn rescale<T: Real>(t: Traction<T>, f2: T) -> Traction<T> {
    let r = T::ONE / f2.sqrt();
    Traction {
        fx: t.fx * r,
        fy: t.fy * r,
        tz: t.tz,
    }
}
