//! The stable explicit step for the spin about the contact normal: the drilling torque's
//! regularization ramp has its own stiffness −∂T_z/∂ω ∝ fN·a²/δ, next to the translational
//! one of [`Friction::stable_step`].

use super::best::spin_stiffness;
use super::law::ramp_step;
use super::{Constants, Explicit, Friction};
use crate::Real;

/// limit·Iδ/(κ_T·fN·a²) with the edge cases of [`ramp_step`]; `a` ≤ 0 or NaN (point contact,
/// no torque) → `T::MAX` unless the inertia is invalid. Total.
fn spin_ramp_step<T: Real>(f_kappa: T, a: T, delta: T, inertia: T, n: T, scheme: Explicit) -> T {
    // `x > 0` is false for NaN; a² may overflow to +∞: then fN·∞ = ∞ (step 0) or NaN for
    // f = 0 or n = 0 (read as "no friction" by `ramp_step`: T::MAX).
    let a2 = if a > T::ZERO { a * a } else { T::ZERO };
    ramp_step(f_kappa * a2, delta, inertia, n, scheme)
}

macro_rules! simplified_spin_step_for {
    ($law:ty) => {
        impl<T: Real> Friction<T, $law> {
            /// The largest stable step of an explicit `scheme` for the spin ω about the contact
            /// normal of a body of moment of inertia `inertia` (kg·m², about that normal)
            /// under the `simplified` law, at major semi-axis `a` (m) and normal force `n` (N),
            /// with v_P held fixed (any value): h* = limit·5Iδ/(2fN·a²) (limit 2 for Euler,
            /// 2.785 for RK4; see [`Explicit::limit`]). Independent of e².
            ///
            /// # Why
            ///
            /// The torque is scaled by a|ω|/(5Cδ) while a|ω| < 5Cδ. In pure spin that is the
            /// plateau −C·fNa·sgn ω ramped: T_z = −fN·a²·ω/(5δ), stiffness fN·a²/(5δ). With a
            /// translation v = |v_P| the hyperbola T₁/u applies for a|ω| < 5Cv³/q
            /// (q = v_Px² + m₁v_Py² ≤ v²); ramped, T_z = −fN·a·(aω)|aω|·q/(25Cv³δ),
            /// quadratic in ω, with slope 2|aω|q/(25Cv³δ)·fN·a² < 2fN·a²/(5δ), approached
            /// just below the switch to the plateau (a|ω| → 5Cv³/q, reachable inside the
            /// ramp when v·v²/q ≤ δ, e.g. v_P along the major axis with v ≤ δ). Past the ramp
            /// the plateau is flat and the hyperbola's slope q/(5v³)·fN·a² is below
            /// fN·a²/(5δ). So the stiffness is at most 2fN·a²/(5δ) for every slip, and the
            /// step h* keeps h·stiffness/I under the scheme's limit. It is conservative by 2×
            /// in pure spin (h = limit·5Iδ/(fN·a²) there). Not covered: the coupling with the
            /// translational degrees of freedom (F depends on ω, T_z on v_P): when v_P and ω
            /// both move, the smaller of this and [`Friction::stable_step`] is a guide, not a
            /// bound (the joint limit can be shorter than both).
            ///
            /// # Edge cases and accuracy
            ///
            /// δ = 0 → 0 (no stable explicit step); `inertia` ≤ 0 or NaN → 0; fN ≤ 0 or NaN,
            /// f = 0, or `a` ≤ 0 or NaN (point contact: no torque) → `T::MAX`; an overflowing
            /// quotient → `T::MAX`; an overflowing fN·a² → 0. Measured by integrating the spin
            /// alone (v_P held, ω held at a probe by a constant drive torque) and bisecting
            /// the step at which a perturbation stops decaying (`host-tests/stability.rs`;
            /// `examples/stability.rs` → `docs/report/stability/spin_step.csv`): for
            /// e² ∈ {0, 0.5, 0.9, 0.99}, both schemes, the measured step is ≥ h*, 1.001·h* at
            /// the stiffest probe (a|ω| 0.1 % below the switch, v_P = (δ/2, 0)), 2·h* in pure
            /// spin, 1.77–2.20·h* at a generic slip. Cost: a division and
            /// three multiplications (construction/host use).
            pub fn stable_spin_step(&self, a: T, inertia: T, n: T, scheme: Explicit) -> T {
                let f_kappa = self.coefficient() * T::from_f64(0.4);
                spin_ramp_step(f_kappa, a, self.delta(), inertia, n, scheme)
            }
        }
    };
}

simplified_spin_step_for!(super::Simplified);
#[cfg(feature = "micromath")]
simplified_spin_step_for!(super::SimplifiedMicromath);

macro_rules! coulomb_spin_step_for {
    ($law:ty) => {
        impl<T: Real> Friction<T, $law> {
            /// The regularized Coulomb law has no drilling torque: the spin sets no step limit.
            /// `T::MAX` for a valid `inertia` (> 0), 0 for `inertia` ≤ 0 or NaN (as every
            /// `stable_spin_step`). The other arguments are accepted for a uniform signature
            /// with `Simplified` and are not read. Total.
            pub fn stable_spin_step(&self, _a: T, inertia: T, _n: T, _scheme: Explicit) -> T {
                if inertia > T::ZERO { T::MAX } else { T::ZERO }
            }
        }
    };
}

coulomb_spin_step_for!(super::Coulomb);
#[cfg(feature = "micromath")]
coulomb_spin_step_for!(super::CoulombMicromath);

macro_rules! best_spin_step_for {
    ($law:ty) => {
        impl<T: Real> Friction<T, $law> {
            /// The largest stable step of an explicit `scheme` for the spin ω about the contact
            /// normal of a body of moment of inertia `inertia` (kg·m², about that normal)
            /// under the `best` law, for the patch shape `k` at major semi-axis `a` (m) and
            /// normal force `n` (N), with v_P held fixed (any value):
            /// h* = limit·Iδ/(κ_T·fN·a²), κ_T = [`spin_stiffness`]`(k)` (1.141 for a circle,
            /// 0.963 at e² = 0.5, 0.810 at 0.9, 0.752 at 0.99; limit 2 for Euler, 2.785 for
            /// RK4, see [`Explicit::limit`]).
            ///
            /// # Why
            ///
            /// Below the slip scale s = |v_Px| + |v_Py| + a|ω| < δ the wrapper ramps the core
            /// by s/δ, so the torque's stiffness −∂T_z/∂ω is fN·a²/δ times a function of the
            /// slip direction: C in pure spin, largest (κ_T ≈ 1.9–2·C) with the instantaneous
            /// centre inside the patch at ≈ 0.75–0.85 of the way to its edge (on it for
            /// m₁ ≲ 1e-5; derivation in [`spin_stiffness`]). Past the ramp it is smaller. So h*
            /// holds for every slip direction and speed with v_P fixed; it is conservative by
            /// κ_T/C ≈ 1.9–2 in pure spin. Not covered: the coupling with the translational degrees of freedom (the
            /// force depends on ω and the torque on v_P): when v_P and ω both move, the smaller
            /// of this and [`Friction::stable_step`] is a guide, not a bound — the joint limit
            /// can be shorter than both (by ≈ 16 % for a circle with m·a²/I ≈ 2.5, where the
            /// two limits are close, in an exploratory scan of the quartic's 3 × 3 Jacobian,
            /// `tools/explore_coupled_step.py`; ≤ 4 % elsewhere on that scan).
            ///
            /// # Edge cases and accuracy
            ///
            /// δ = 0 → 0 (no stable explicit step); `inertia` ≤ 0 or NaN → 0; fN ≤ 0 or NaN,
            /// f = 0, or `a` ≤ 0 or NaN (point contact: no torque) → `T::MAX`; an overflowing
            /// quotient → `T::MAX`; an overflowing fN·a² → 0. Measured by integrating the spin
            /// alone under this law (v_P held, ω held at a probe by a constant drive torque)
            /// and bisecting the step at which a perturbation stops decaying
            /// (`host-tests/stability.rs`; `examples/stability.rs` →
            /// `docs/report/stability/spin_step.csv`): for e² ∈ {0, 0.5, 0.9, 0.99}, both
            /// schemes, the measured step is ≥ h*, equal to it within the bisection's
            /// resolution (1e-6) at the derivation's stiffest slip, κ_T/C = 1.90–1.97·h* in pure
            /// spin, 1.04–1.60·h* at a generic slip.
            /// Cost: [`spin_stiffness`] (≈ 9,000 quintic evaluations, host ≈ 26 µs) and a division
            /// (construction/host use).
            pub fn stable_spin_step(
                &self,
                k: &Constants<T>,
                a: T,
                inertia: T,
                n: T,
                scheme: Explicit,
            ) -> T {
                let f_kappa = self.coefficient() * spin_stiffness(k);
                spin_ramp_step(f_kappa, a, self.delta(), inertia, n, scheme)
            }
        }
    };
}

best_spin_step_for!(super::Best);
#[cfg(feature = "micromath")]
best_spin_step_for!(super::BestMicromath);
