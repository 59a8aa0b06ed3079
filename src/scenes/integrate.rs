//! Time integration of y' = f(t, y) for a state of N scalars held in a fixed array.
//!
//! - [`rk4_step`] / [`rk4`]: the classic fixed-step fourth-order Runge–Kutta method, 4 right-hand
//!   sides per step, no branches: the MCU integrator. Stability needs h·ω_max ≲ 2.8 for the
//!   stiffest oscillation; accuracy wants h·ω_max ≲ 0.3.
//! - [`dopri45`]: Dormand–Prince 5(4) with first-same-as-last (6 new right-hand sides per
//!   attempted step), error control in the max norm, step factor 0.9·err^(−1/5) clamped to
//!   [0.2, 5], at most `max_steps` attempted steps: the host reference integrator. Its step
//!   control uses `ln`/`exp` (host path).
//!
//! After each accepted step [`Ode::project`] may map the state back onto its manifold (e.g.
//! renormalise a quaternion).

use crate::Real;

/// A system of N first-order ODEs.
pub trait Ode<T: Real, const N: usize> {
    /// The right-hand side f(t, y). Must be total: finite for finite y.
    fn rhs(&self, t: T, y: &[T; N]) -> [T; N];

    /// Project an accepted state back onto its manifold. Default: nothing.
    #[inline(always)]
    fn project(&self, _y: &mut [T; N]) {}
}

/// y + h·Σ cᵢkᵢ for up to six stages (unused stages have c = 0 and are skipped by the caller).
#[inline(always)]
fn combine<T: Real, const N: usize>(y: &[T; N], h: T, terms: &[(T, &[T; N])]) -> [T; N] {
    let mut out = *y;
    for &(c, k) in terms {
        let hc = h * c;
        for (o, ki) in out.iter_mut().zip(k.iter()) {
            *o += hc * *ki;
        }
    }
    out
}

/// One classic RK4 step of size h from (t, y); the state is projected afterwards.
#[inline]
pub fn rk4_step<T: Real, S: Ode<T, N>, const N: usize>(sys: &S, t: T, y: &[T; N], h: T) -> [T; N] {
    let half = h * T::HALF;
    let k1 = sys.rhs(t, y);
    let k2 = sys.rhs(t + half, &combine(y, half, &[(T::ONE, &k1)]));
    let k3 = sys.rhs(t + half, &combine(y, half, &[(T::ONE, &k2)]));
    let k4 = sys.rhs(t + h, &combine(y, h, &[(T::ONE, &k3)]));
    let sixth = T::ONE / T::from_f64(6.0);
    let third = T::ONE / T::from_f64(3.0);
    let mut out = combine(
        y,
        h,
        &[(sixth, &k1), (third, &k2), (third, &k3), (sixth, &k4)],
    );
    sys.project(&mut out);
    out
}

/// `steps` RK4 steps of size h from (t0, y0); `observe(step index, t, y)` after each. Returns
/// the final state.
pub fn rk4<T: Real, S: Ode<T, N>, const N: usize>(
    sys: &S,
    t0: T,
    y0: [T; N],
    h: T,
    steps: usize,
    mut observe: impl FnMut(usize, T, &[T; N]),
) -> [T; N] {
    let mut y = y0;
    for i in 0..steps {
        let t = t0 + h * T::from_usize(i);
        y = rk4_step(sys, t, &y, h);
        observe(i + 1, t + h, &y);
    }
    y
}

/// Error tolerances of [`dopri45`]: a step is accepted when, for every component,
/// |error estimate| ≤ atol_i + rtol·max(|y_i|, |y_i,new|).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance<T, const N: usize> {
    /// Relative tolerance.
    pub rtol: T,
    /// Absolute tolerance per component (the component's unit).
    pub atol: [T; N],
}

/// Counters of an adaptive run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Whether t_end was reached within the step budget.
    pub finished: bool,
}

// Dormand–Prince 5(4) tableau: row s of `A` gives stage s + 2 from stages 1..=s + 1, at
// t + C[s]·h; `B` the 5th-order weights, `E` the 5th- minus embedded 4th-order weights (the
// zero weights B2, E2 are skipped, not multiplied: a zero times a non-finite stage is NaN).
const A: [&[f64]; 5] = [
    &[1.0 / 5.0],
    &[3.0 / 40.0, 9.0 / 40.0],
    &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
    &[
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
    ],
    &[
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ],
];
const B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
const C: [f64; 5] = [0.2, 0.3, 0.8, 8.0 / 9.0, 1.0];

/// y + h·Σ wᵢkᵢ over the nonzero weights, in order (as [`combine`]).
#[inline(always)]
fn weighted<T: Real, const N: usize>(y: &[T; N], h: T, w: &[f64], k: &[[T; N]]) -> [T; N] {
    let mut out = *y;
    for (&wi, ki) in w.iter().zip(k) {
        if wi != 0.0 {
            let hc = h * T::from_f64(wi);
            for (o, kij) in out.iter_mut().zip(ki.iter()) {
                *o += hc * *kij;
            }
        }
    }
    out
}

/// Adaptive Dormand–Prince 5(4) from (t0, y0) to t_end, first trial step `h0`, steps capped at
/// `h_max`, at most `max_steps` attempts. `observe(t, y)` is called after each accepted step.
/// Returns the last accepted (t, y) and the counters (`finished` false if the budget ran out
/// first). Host reference integrator: the step control uses `ln` and `exp`.
#[allow(clippy::too_many_arguments)]
pub fn dopri45<T: Real, S: Ode<T, N>, const N: usize>(
    sys: &S,
    t0: T,
    y0: [T; N],
    t_end: T,
    h0: T,
    h_max: T,
    tol: &Tolerance<T, N>,
    max_steps: usize,
    mut observe: impl FnMut(T, &[T; N]),
) -> (T, [T; N], Stats) {
    let c = |x: f64| T::from_f64(x);
    let mut stats = Stats::default();
    let (mut t, mut y) = (t0, y0);
    let mut h = h0.min(h_max);
    let mut k1 = sys.rhs(t, &y);
    stats.rhs_evals += 1;
    for _ in 0..max_steps {
        if t >= t_end {
            stats.finished = true;
            break;
        }
        let h_step = h.min(t_end - t);
        // k[0] = k1 (first same as last), k[1..6] the stages, k[6] at the trial end.
        let mut k = [k1; 7];
        for (s, (row, cs)) in A.iter().zip(C).enumerate() {
            k[s + 1] = sys.rhs(t + c(cs) * h_step, &weighted(&y, h_step, row, &k));
        }
        let y_new = weighted(&y, h_step, &B, &k);
        k[6] = sys.rhs(t + h_step, &y_new);
        stats.rhs_evals += 6;
        let e = weighted(&[T::ZERO; N], h_step, &E, &k);
        let mut err = T::ZERO;
        for (((ei, yi), yn), at) in e
            .iter()
            .zip(y.iter())
            .zip(y_new.iter())
            .zip(tol.atol.iter())
        {
            let sc = *at + tol.rtol * yi.abs().max(yn.abs());
            err = err.max(ei.abs() / sc);
        }
        // A NaN or ∞ error (a non-finite trial state) fails the step and shrinks h fivefold.
        let ok = err <= T::ONE;
        let fac = if !err.is_finite() {
            c(0.2)
        } else if err > T::ZERO {
            (c(0.9) * (c(-0.2) * err.ln()).exp()).clamp_to(c(0.2), c(5.0))
        } else {
            c(5.0)
        };
        if ok {
            t += h_step;
            y = y_new;
            sys.project(&mut y);
            // First same as last (the projection moves y by round-off only).
            k1 = k[6];
            stats.accepted += 1;
            observe(t, &y);
            h = (h_step * fac).min(h_max);
        } else {
            stats.rejected += 1;
            h = h_step * fac.min(T::ONE);
        }
    }
    if t >= t_end {
        stats.finished = true;
    }
    (t, y, stats)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Harmonic oscillator y'' = −y (also the event tests' system).
    pub(in crate::scenes) struct Osc;
    impl<T: Real> Ode<T, 2> for Osc {
        fn rhs(&self, _t: T, y: &[T; 2]) -> [T; 2] {
            [y[1], -y[0]]
        }
    }

    #[test]
    fn rk4_is_fourth_order() {
        let err = |n: usize| {
            let y = rk4(&Osc, 0.0, [1.0, 0.0], 1.0 / n as f64, n, |_, _, _| {});
            (y[0] - 1f64.cos()).abs()
        };
        let ratio = err(20) / err(40);
        assert!((14.0..18.0).contains(&ratio), "{ratio}");
    }

    #[test]
    fn dopri_meets_tolerance() {
        let tol = Tolerance {
            rtol: 1e-9,
            atol: [1e-9; 2],
        };
        let (t, y, s) = dopri45(
            &Osc,
            0.0,
            [1.0, 0.0],
            10.0,
            0.1,
            1.0,
            &tol,
            10_000,
            |_, _| {},
        );
        assert!(s.finished && t == 10.0);
        assert!((y[0] - 10f64.cos()).abs() < 1e-7, "{}", y[0] - 10f64.cos());
        assert_eq!(s.rhs_evals, 1 + 6 * (s.accepted + s.rejected));
    }
}
