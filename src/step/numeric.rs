//! A reference [`Linearize`] by central differences of a wrench function: for a contact whose
//! analytic Jacobian is not at hand, and the check the analytic ones are measured against.
//!
//! # Formula
//!
//! ∂w/∂qⱼ ≈ (w(q + εⱼeⱼ) − w(q − εⱼeⱼ))/(2εⱼ), q = (h, ḣ, v_x, v_y, ω), with the caller's
//! absolute steps εⱼ (> 0, finite; an invalid step gives that column 0). Error O(εⱼ²·w‴)
//! where the wrench is smooth over [qⱼ − εⱼ, qⱼ + εⱼ], plus rounding ≈ ε_machine·|w|/εⱼ;
//! across a kink (h = 0, the friction ramp's edge at δ, a law's branch switch) it is the mean
//! of the one-sided slopes. Pick εⱼ well inside the smooth regions: e.g. ε_h ≈ 1e-3·h,
//! ε_v ≤ δ/10 near rest. Cost: 11 wrench calls per [`Linearize::linearize`] (host use).

use crate::Real;
use crate::friction::Slip;
use crate::jacobian::{Jacobian, Linearize, State};

/// Central differences of the wrench function `F` with absolute steps (h, ḣ, v_x, v_y, ω)
/// (see the [module docs](self)).
#[derive(Clone, Copy, Debug)]
pub struct Numeric<F, T> {
    wrench: F,
    steps: [T; 5],
}

impl<T: Real, F: Fn(&State<T>) -> [T; 4]> Numeric<F, T> {
    /// From the wrench function and the absolute steps for (h, ḣ, v_x, v_y, ω).
    pub fn new(wrench: F, steps: [T; 5]) -> Self {
        Numeric { wrench, steps }
    }
}

/// The state with input j (h, ḣ, v_x, v_y, ω) shifted by `by`.
pub(crate) fn shifted<T: Real>(s: &State<T>, j: usize, by: T) -> State<T> {
    let mut t = *s;
    let (vx, vy, om) = (s.slip.vx(), s.slip.vy(), s.slip.omega());
    match j {
        0 => t.h = s.h + by,
        1 => t.hdot = s.hdot + by,
        2 => t.slip = Slip::or_rest(vx + by, vy, om),
        3 => t.slip = Slip::or_rest(vx, vy + by, om),
        _ => t.slip = Slip::or_rest(vx, vy, om + by),
    }
    t
}

impl<T: Real, F: Fn(&State<T>) -> [T; 4]> Linearize<T> for Numeric<F, T> {
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        (self.wrench)(s)
    }

    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let mut j = Jacobian {
            value: (self.wrench)(s),
            d: [[T::ZERO; 5]; 4],
        };
        for (c, &e) in self.steps.iter().enumerate() {
            if !(e > T::ZERO) || !e.is_finite() {
                continue;
            }
            let hi = (self.wrench)(&shifted(s, c, e));
            let lo = (self.wrench)(&shifted(s, c, -e));
            for r in 0..4 {
                let d = (hi[r] - lo[r]) / (e + e);
                j.d[r][c] = if d.is_finite() { d } else { T::ZERO };
            }
        }
        j
    }
}
