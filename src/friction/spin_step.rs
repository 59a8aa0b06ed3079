//! The stable explicit step for the spin about the contact normal: the drilling torque's
//! regularization ramp has its own stiffness −∂T_z/∂ω ∝ fN·a²/δ, next to the translational
//! one of [`Friction::stable_step`].

use super::law::{no_ramp_step, ramp_step};
use super::{Constants, Explicit, Friction, FrictionLaw};
use crate::Real;

/// limit·Iδ/(κ_T·fN·a²) with the edge cases of [`ramp_step`]; `a` ≤ 0 or NaN (point contact,
/// no torque) → `T::MAX` unless the inertia is invalid. Total.
fn spin_ramp_step<T: Real>(f_kappa: T, a: T, delta: T, inertia: T, n: T, scheme: Explicit) -> T {
    // `x > 0` is false for NaN; a² may overflow to +∞: then fN·∞ = ∞ (step 0) or NaN for
    // f = 0 or n = 0 (read as "no friction" by `ramp_step`: T::MAX).
    let a2 = if a > T::ZERO { a * a } else { T::ZERO };
    ramp_step(f_kappa * a2, delta, inertia, n, scheme)
}

impl<T: Real, L: FrictionLaw> Friction<T, L> {
    /// The largest stable step of an explicit `scheme` for the spin ω about the contact normal
    /// of a body of moment of inertia `inertia` (kg·m², about that normal) under this law, for
    /// the patch shape `k` at major semi-axis `a` (m) and normal force `n` (N), with v_P held
    /// fixed (any value): h* = limit·Iδ/(κ_T·fN·a²), κ_T = [`FrictionLaw::spin_ramp`] (limit
    /// 2 for Euler, 2.785 for RK4, see [`Explicit::limit`]). One signature for every law; from
    /// a built contact: [`Contact::stable_spin_step`](crate::contact::Contact::stable_spin_step).
    ///
    /// | law | κ_T |
    /// |---|---|
    /// | `Coulomb` | 0: no torque, no limit (`T::MAX`) |
    /// | `Simplified` | 2/5, independent of e² |
    /// | `Best` (default) | [`spin_stiffness`](super::best::spin_stiffness)`(k)`: 1.226 for a circle, 1.029 at e² = 0.5, 0.842 at 0.9, 0.775 at 0.99 |
    /// | `Pade`, `Ellipsoid`, `Exact` | none: no ramp → 0 |
    ///
    /// `inertia` is the effective one: 1/(1/I_A + 1/I_B) about the normal when both bodies
    /// spin freely (a ball on a fixed plane: its own I = (2/5)mR², the normal passing through
    /// its centre).
    ///
    /// # Why
    ///
    /// `simplified` scales its torque by a|ω|/(5Cδ) while a|ω| < 5Cδ: in pure spin the plateau
    /// −C·fNa·sgn ω ramped, T_z = −fN·a²·ω/(5δ); with a translation the ramped hyperbola's
    /// slope reaches 2fN·a²/(5δ) just below the switch to the plateau, and past the ramp it is
    /// smaller, so κ_T = 2/5 bounds every slip (conservative by 2× in pure spin). `best` ramps
    /// its core below its own dissipation p < 3δ/8 (p = C·a|ω| in pure spin): the torque's
    /// stiffness is fN·a²/δ times a function of the slip direction, (8/3)·C² in pure spin and
    /// largest (κ_T ≈ 1.3–2.03× that) with the instantaneous centre inside the patch at ≈
    /// 0.76–0.81 of the way to its edge (derivation in
    /// [`spin_stiffness`](super::best::spin_stiffness)); conservative by that ratio in pure
    /// spin.
    /// **When v_P and ω both move** (F depends on ω, T_z on v_P): `best`'s ramped stiffness is
    /// a symmetric positive semidefinite 3 × 3 matrix (the Hessian of a convex potential, see
    /// [`ramp_stiffness`](super::best::ramp_stiffness)), so in the mass metric its largest
    /// eigenvalue is at most the sum of its diagonal blocks' — the joint step is at least
    /// 1/(1/h*_v + 1/h*_ω) with h*_v from [`Friction::stable_step`] and h*_ω from this (a
    /// bound, ≥ half the smaller of the two); `simplified`'s ramp is not symmetric and has no
    /// such bound.
    ///
    /// # Edge cases and accuracy
    ///
    /// δ = 0 → 0 (no stable explicit step); `inertia` ≤ 0 or NaN → 0; fN ≤ 0 or NaN, f = 0,
    /// or `a` ≤ 0 or NaN (point contact: no torque) → `T::MAX`; an overflowing quotient →
    /// `T::MAX`; an overflowing fN·a² → 0; a law without a ramp → 0 where a torque acts.
    /// Measured by integrating the spin alone (v_P held, ω held at a probe by a constant drive
    /// torque) and bisecting the step at which a perturbation stops decaying
    /// (`host-tests/stability.rs`; `examples/stability.rs` →
    /// `docs/report/stability/spin_step.csv`): for e² ∈ {0, 0.5, 0.9, 0.99}, both schemes, the
    /// measured step is ≥ h*; `simplified` 1.001·h* at the stiffest probe, 2·h* in pure spin,
    /// 1.77–2.20·h* at a generic slip; `best` equal to h* within the bisection's resolution
    /// (1e-6) at the derivation's stiffest slip, 1.90–1.97·h* in pure spin, 1.04–1.60·h* at a
    /// generic slip. Cost: a division and three multiplications, plus
    /// [`spin_stiffness`](super::best::spin_stiffness) for `best` (≈ 9,000 quintic evaluations,
    /// host ≈ 26 µs; construction/host use).
    pub fn stable_spin_step(
        &self,
        k: &Constants<T>,
        a: T,
        inertia: T,
        n: T,
        scheme: Explicit,
    ) -> T {
        match L::spin_ramp(k) {
            Some(kappa) => spin_ramp_step(
                self.coefficient() * kappa,
                a,
                self.delta(),
                inertia,
                n,
                scheme,
            ),
            None => {
                // A point contact (a ≤ 0 or NaN) has no torque: no limit.
                let f = if a > T::ZERO {
                    self.coefficient()
                } else {
                    T::ZERO
                };
                no_ramp_step(f, inertia, n)
            }
        }
    }
}
