//! How the caller's integrator moves the bodies over the step, as the step-aware wrench needs
//! to know it: where the friction is evaluated within the step (θ) and how much of the step
//! the pose moves with the new velocities (γ).
//!
//! # The two schemes
//!
//! - [`Scheme::backward_euler`] (θ = 1, γ = 1; the default of [`super::step_wrench`]):
//!   semi-implicit Euler — velocities first with every force of the step, then the pose with
//!   the end velocities over the whole step. The wrench is the law's at the end of the step:
//!   first order, L-stable (a stiff friction or creep mode is damped at any Δt).
//! - [`Scheme::strang`] (θ = ½, γ = ½): a Strang splitting — the pose drifts with the start
//!   velocities over Δt/2 (G with Ġ, the attitude torque-free at constant angular momentum),
//!   the impulse acts at that mid-step pose (W and u_free are read there), then the pose
//!   drifts Δt/2 with the end velocities. The friction is evaluated by the trapezoidal rule,
//!   u_θ = u_free + ½·Δt·W·w̄ (second order while the slip keeps its direction; a contact whose
//!   slip or spin would reverse within the step is evaluated at θ = 1 for that step, see the
//!   [module docs](super)). The normal row stays backward Euler (the end approach and the end
//!   normal velocity), with the end approach h⁺ = h_free − γ·Δt²·(W·w̄)_n: the pose moves with
//!   the new velocities over the second half only.
//!
//! # The slip's own change within the step
//!
//! A contact point that runs over a curved body (a rolling rattleback, a top) sees its slip
//! change within the step without any force: the same body velocities read at the end pose
//! differ from those read at the impulse's pose. [`super::Free::with_drift`] takes that change
//! (the free velocity at the end pose minus u_free); the velocity the law sees at θ is then
//! u_free + θ·Δt·W·w̄ + s(θ)·drift with s(θ) = (θ + γ − 1)/γ (the fraction of the drift from
//! the impulse's pose, at 1 − γ of the step, to the evaluation time θ): 0 for the trapezoidal
//! friction of the Strang scheme, 1 at the end of the step. Measured on the rattleback
//! (`coulomb`, reversal time against fine-step RK4): without it −9 % at 0.5 ms and −14 % at
//! 1 ms; with it −0.05 % at 1 ms.

use crate::Real;

/// θ (where the friction is evaluated) and γ (the share of the step the pose moves with the
/// new velocities) of the caller's integrator (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scheme<T> {
    theta: T,
    gap: T,
}

impl<T: Real> Scheme<T> {
    /// Semi-implicit Euler: θ = 1, γ = 1.
    pub fn backward_euler() -> Self {
        Scheme {
            theta: T::ONE,
            gap: T::ONE,
        }
    }

    /// A Strang splitting of the pose around the impulse: θ = ½, γ = ½.
    pub fn strang() -> Self {
        Scheme {
            theta: T::HALF,
            gap: T::HALF,
        }
    }

    /// θ: the friction is evaluated at u_free + θ·Δt·W·w̄ (+ the drift's share).
    #[inline(always)]
    pub fn theta(&self) -> T {
        self.theta
    }

    /// γ: the end approach is h_free − γ·Δt²·(W·w̄)_n.
    #[inline(always)]
    pub fn gap(&self) -> T {
        self.gap
    }

    /// The drift's share at the evaluation fraction `theta`: (θ + γ − 1)/γ.
    #[inline(always)]
    pub(crate) fn drift_share(&self, theta: T) -> T {
        (theta + self.gap - T::ONE) / self.gap
    }
}

impl<T: Real> Default for Scheme<T> {
    fn default() -> Self {
        Self::backward_euler()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jacobian::State;
    use crate::step::{Free, InverseMass, Numeric, TimeStep, step_wrenches_with};

    /// A linear spring-damper normal and a linear friction damper (N = k·h + c·ḣ,
    /// F_x = −b·v_x) on a diagonal W: the θ/γ step in closed form.
    #[test]
    fn linear_contact_follows_theta_and_gamma() {
        let (k, c, b) = (1e6, 10.0, 20.0);
        let lin = Numeric::new(
            |s: &State<f64>| {
                if s.h <= 0.0 {
                    return [0.0; 4];
                }
                [k * s.h + c * s.hdot, -b * s.slip.vx(), 0.0, 0.0]
            },
            [1e-9, 1e-6, 1e-6, 1e-6, 1e-6],
        );
        let (wn, wx) = (1.0, 2.0);
        let w = InverseMass::single([
            [wn, 0.0, 0.0, 0.0],
            [0.0, wx, 0.0, 0.0],
            [0.0, 0.0, wx, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ])
        .unwrap();
        let dt = 2e-3;
        let (h_f, un, ux, drift) = (1e-5, -0.01, 0.3, 0.05);
        let free = Free::new([un, ux, 0.0, 0.0], h_f)
            .unwrap()
            .with_drift([0.0, drift, 0.0, 0.0])
            .unwrap();
        let s = State::default();
        for (scheme, theta, gamma) in [
            (Scheme::backward_euler(), 1.0, 1.0),
            (Scheme::strang(), 0.5, 0.5),
        ] {
            let o = step_wrenches_with(
                [&lin as &dyn crate::jacobian::Linearize<f64>],
                TimeStep::new(dt).unwrap(),
                &w,
                &[s],
                &[free],
                &scheme,
            )[0];
            // N = k·h⁺ − c·u⁺_n, h⁺ = h_f − γΔt²·W_nn·N, u⁺_n = u_n + Δt·W_nn·N.
            let n = (k * h_f - c * un) / (1.0 + k * gamma * dt * dt * wn + c * dt * wn);
            // F = −b·(u_x + θΔt·W_xx·F + s·drift), s = (θ + γ − 1)/γ.
            let share = (theta + gamma - 1.0) / gamma;
            let f = -b * (ux + share * drift) / (1.0 + b * theta * dt * wx);
            assert!(
                (o.wrench[0] / n - 1.0).abs() < 1e-9,
                "{theta}: N {} vs {n}",
                o.wrench[0]
            );
            assert!(
                (o.wrench[1] / f - 1.0).abs() < 1e-6,
                "{theta}: F {} vs {f}",
                o.wrench[1]
            );
            // The end velocity carries the whole drift; the end approach γ of the impulse.
            let u_end = ux + dt * wx * o.wrench[1] + drift;
            assert!((o.u_end[1] - u_end).abs() < 1e-12);
            let h_end = h_f - gamma * dt * dt * wn * o.wrench[0];
            assert!((o.h_end - h_end).abs() < 1e-15);
        }
    }
}
