//! Events located between integration steps: the time at which a scalar event function
//! g(y) of the state crosses zero, found inside the step where its sign changes — not at the
//! step's end, and not at an output sample.
//!
//! # Method
//!
//! 1. **Detection** ([`Crossing::update`], once per accepted step): g at the step's end; a sign
//!    change from the previous step's value (in the [`Direction`] asked for) brackets a crossing
//!    in [t₀, t₁]. Cost per step: one g evaluation and a copy of the state.
//! 2. **Interpolation** (only on the bracketing step): the cubic Hermite interpolant of the
//!    state from both ends' values and derivatives, y(t₀ + s·h) ≈ H(s) =
//!    h₀₀(s)y₀ + h₁₀(s)·h·f₀ + h₀₁(s)y₁ + h₁₁(s)·h·f₁ with h₀₀ = 2s³ − 3s² + 1,
//!    h₁₀ = s³ − 2s² + s, h₀₁ = −2s³ + 3s², h₁₁ = s³ − s² (f = y′ = [`Ode::rhs`]: two
//!    right-hand sides per located event).
//! 3. **Root-finding** ([`locate`]): [`BISECTIONS`] bisections of g(H(s)) on the bracket,
//!    a fixed count (no convergence test), returning the bracket's midpoint.
//!
//! # Error
//!
//! - Interpolation: the Hermite cubic is exact for cubics; for a smooth solution
//!   |y(t) − H(t)| ≤ h⁴/384 · max|y⁽⁴⁾| (fourth order, the order of RK4 and of a 4th-order
//!   dense output for Dormand–Prince 5(4)). The event time carries that error divided by the
//!   event function's rate: Δt ≈ |∇g|·h⁴·max|y⁽⁴⁾| / (384·|ġ|), plus the integrator's own global
//!   error in y₀, y₁ (O(h⁴) for RK4) divided by |ġ|. Both vanish with the step as h⁴ — the
//!   located time converges with the step and does not depend on any output sampling.
//! - Root-finding: the bracket after n bisections is h·2⁻ⁿ wide; the midpoint is within
//!   h·2⁻⁽ⁿ⁺¹⁾ of the interpolant's root (2.3e-10·h for n = 32; `f32` stops shrinking at its
//!   resolution of t, which is coarser still).
//! - A step that holds two crossings (g goes down and back up within h) shows no sign change and
//!   is missed, as with any step-end test: the step must resolve the event function's fastest
//!   oscillation (the scenes' steps resolve their contact vibration, which is faster than
//!   anything their event functions follow).
//!
//! # Special cases
//!
//! - g exactly 0 at a step's end counts as crossed at that step (Falling: previous > 0 and
//!   now ≤ 0; Rising: previous < 0 and now ≥ 0).
//! - Non-finite g (a non-finite state) never brackets a crossing.
//! - Cost of a located event: 2 right-hand sides + [`BISECTIONS`] × (one Hermite evaluation of
//!   the N-vector, ≈ 7N multiply-adds, + one g), fixed; `no_std`, no allocation.
//!
//! # Example
//!
//! ```
//! use contensou::scenes::event::{Crossing, Direction};
//! use contensou::scenes::integrate::{Ode, rk4};
//! // y'' = −y from (1, 0): y falls through 0 at t = π/2.
//! struct Osc;
//! impl Ode<f64, 2> for Osc {
//!     fn rhs(&self, _t: f64, y: &[f64; 2]) -> [f64; 2] {
//!         [y[1], -y[0]]
//!     }
//! }
//! let mut zero = Crossing::new(Direction::Falling);
//! zero.start(0.0, &[1.0, 0.0], |y| y[0]);
//! rk4(&Osc, 0.0, [1.0, 0.0], 0.1, 20, |_, t, y| {
//!     zero.update(&Osc, t, y, |y| y[0]);
//! });
//! let t = zero.first().unwrap();
//! // Off by 1.3e-6 (8.2e-8 at h = 0.05: fourth order); the step's end, 1.6, is off by 0.03.
//! assert!((t - core::f64::consts::FRAC_PI_2).abs() < 1e-5);
//! ```
//!
//! # References
//!
//! E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed.,
//! Springer 1993, §II.6 (dense output, Hermite interpolation) and the event location of §II.6
//! ("discontinuities"); L. F. Shampine, I. Gladwell, S. Thompson, *Solving ODEs with MATLAB*,
//! CUP 2003, §2.3.2 (event location on the interpolant).

use super::integrate::Ode;
use crate::Real;

/// Bisections of the interpolant per located event: the root-finding error is ≤ h·2⁻³³.
pub const BISECTIONS: usize = 32;

/// Which sign changes of g count as the event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// g goes from > 0 to ≤ 0.
    Falling,
    /// g goes from < 0 to ≥ 0.
    Rising,
    /// Either.
    Either,
}

impl Direction {
    /// Whether g going from `before` to `after` is a crossing in this direction.
    #[inline]
    pub fn crossed<T: Real>(self, before: T, after: T) -> bool {
        let falling = before > T::ZERO && after <= T::ZERO;
        let rising = before < T::ZERO && after >= T::ZERO;
        match self {
            Direction::Falling => falling,
            Direction::Rising => rising,
            Direction::Either => falling || rising,
        }
    }
}

/// A state with its derivative at time t: one end of a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Knot<T, const N: usize> {
    /// Time (s).
    pub t: T,
    /// State.
    pub y: [T; N],
    /// Its derivative y′ (the right-hand side at (t, y)).
    pub dy: [T; N],
}

impl<T: Real, const N: usize> Knot<T, N> {
    /// The knot of an [`Ode`] at (t, y): one right-hand side.
    #[inline]
    pub fn of<S: Ode<T, N>>(sys: &S, t: T, y: &[T; N]) -> Self {
        Knot {
            t,
            y: *y,
            dy: sys.rhs(t, y),
        }
    }
}

/// The cubic Hermite interpolant of the step from `a` to `b` at the fraction s ∈ [0, 1] of it
/// (module docs: fourth-order accurate).
#[inline]
pub fn hermite<T: Real, const N: usize>(a: &Knot<T, N>, b: &Knot<T, N>, s: T) -> [T; N] {
    let h = b.t - a.t;
    let s2 = s * s;
    let s3 = s2 * s;
    let three = T::from_f64(3.0);
    let h01 = three * s2 - T::TWO * s3;
    let h00 = T::ONE - h01;
    let h10 = (s3 - T::TWO * s2 + s) * h;
    let h11 = (s3 - s2) * h;
    let mut out = [T::ZERO; N];
    for (i, o) in out.iter_mut().enumerate() {
        *o = h00 * a.y[i] + h10 * a.dy[i] + h01 * b.y[i] + h11 * b.dy[i];
    }
    out
}

/// The time in [a.t, b.t] at which g crosses zero on the step's Hermite interpolant, given that
/// g(a.y) and g(b.y) bracket a crossing (they differ in sign or one is 0): [`BISECTIONS`]
/// bisections on the fraction of the step, the midpoint of the last bracket. If they do not
/// bracket one, the bisection still returns a time in the step (the end nearer a sign change
/// of the interpolant, if any).
pub fn locate<T: Real, const N: usize>(
    a: &Knot<T, N>,
    b: &Knot<T, N>,
    g: impl Fn(&[T; N]) -> T,
) -> T {
    let (mut lo, mut hi) = (T::ZERO, T::ONE);
    let g_lo = g(&a.y);
    let lo_positive = g_lo > T::ZERO;
    for _ in 0..BISECTIONS {
        let mid = T::HALF * (lo + hi);
        let gm = g(&hermite(a, b, mid));
        // Keep the half whose ends differ in sign (g at lo has the sign of g(a)).
        if (gm > T::ZERO) == lo_positive && gm != T::ZERO {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    a.t + (b.t - a.t) * (T::HALF * (lo + hi))
}

/// Tracks one event function over the accepted steps of an integration and records its
/// crossings located between steps (module docs). Holds the previous step's end (t, y, g).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing<T, const N: usize> {
    direction: Direction,
    previous: Option<(T, [T; N], T)>,
    first: Option<T>,
    count: usize,
}

impl<T: Real, const N: usize> Crossing<T, N> {
    /// No crossing yet, no state seen.
    pub const fn new(direction: Direction) -> Self {
        Crossing {
            direction,
            previous: None,
            first: None,
            count: 0,
        }
    }

    /// The initial state (t₀, y₀) with event function g: the first step's left end.
    #[inline]
    pub fn start(&mut self, t: T, y: &[T; N], g: impl Fn(&[T; N]) -> T) {
        self.previous = Some((t, *y, g(y)));
    }

    /// After an accepted step ending at (t, y): if g changed sign in the wanted direction over
    /// the step, the crossing time located on the step (module docs), else `None`. The first
    /// call without [`Crossing::start`] only records the state.
    pub fn update<S: Ode<T, N>>(
        &mut self,
        sys: &S,
        t: T,
        y: &[T; N],
        g: impl Fn(&[T; N]) -> T,
    ) -> Option<T> {
        let now = g(y);
        self.update_with(sys, t, y, now, g)
    }

    /// [`Crossing::update`] with g(y) = `now` already evaluated (several events sharing one
    /// quantity compute it once per step).
    pub fn update_with<S: Ode<T, N>>(
        &mut self,
        sys: &S,
        t: T,
        y: &[T; N],
        now: T,
        g: impl Fn(&[T; N]) -> T,
    ) -> Option<T> {
        let found = match self.previous {
            Some((t0, y0, before)) if self.direction.crossed(before, now) => {
                let a = Knot::of(sys, t0, &y0);
                let b = Knot::of(sys, t, y);
                Some(locate(&a, &b, &g))
            }
            _ => None,
        };
        self.previous = Some((t, *y, now));
        if let Some(tc) = found {
            self.count += 1;
            self.first.get_or_insert(tc);
        }
        found
    }

    /// The first crossing located so far.
    pub fn first(&self) -> Option<T> {
        self.first
    }

    /// How many crossings were located so far.
    pub fn count(&self) -> usize {
        self.count
    }
}

#[cfg(test)]
mod tests {
    use super::super::integrate::tests::Osc;
    use super::super::integrate::{Tolerance, dopri45, rk4};
    use super::*;

    /// First time cos t = 0.3 with RK4 at step h (falling).
    fn rk4_event(h: f64) -> f64 {
        let g = |y: &[f64; 2]| y[0] - 0.3;
        let mut c = Crossing::new(Direction::Falling);
        c.start(0.0, &[1.0, 0.0], g);
        rk4(&Osc, 0.0, [1.0, 0.0], h, (2.0 / h) as usize, |_, t, y| {
            c.update(&Osc, t, y, g);
        });
        c.first().unwrap()
    }

    #[test]
    fn hermite_is_exact_for_cubics() {
        // y = t³ − 2t, y' = 3t² − 2 on [0.5, 1.7].
        let y = |t: f64| [t * t * t - 2.0 * t];
        let dy = |t: f64| [3.0 * t * t - 2.0];
        let a = Knot {
            t: 0.5,
            y: y(0.5),
            dy: dy(0.5),
        };
        let b = Knot {
            t: 1.7,
            y: y(1.7),
            dy: dy(1.7),
        };
        for s in [0.0, 0.1, 0.37, 0.5, 0.9, 1.0] {
            let t = 0.5 + 1.2 * s;
            assert!((hermite(&a, &b, s)[0] - y(t)[0]).abs() < 1e-14, "s = {s}");
        }
    }

    #[test]
    fn located_time_converges_at_fourth_order() {
        let exact = 0.3f64.acos();
        let e1 = (rk4_event(0.1) - exact).abs();
        let e2 = (rk4_event(0.05) - exact).abs();
        // Step end would be off by up to h; located: ≈ h⁴ (order 4 → ratio ≈ 16). Measured
        // 9.6e-7 and 6.1e-8 (ratio 15.8).
        assert!(e1 < 2e-6 && e2 < 1.5e-7, "{e1:e} {e2:e}");
        assert!(e1 / e2 > 10.0, "{}", e1 / e2);
    }

    #[test]
    fn direction_and_count() {
        // cos t over 0..7: falls through 0 at π/2, rises at 3π/2 (and falls again at 5π/2 > 7).
        let g = |y: &[f64; 2]| y[0];
        let mut fall = Crossing::new(Direction::Falling);
        let mut rise = Crossing::new(Direction::Rising);
        let mut any = Crossing::new(Direction::Either);
        for c in [&mut fall, &mut rise, &mut any] {
            c.start(0.0, &[1.0, 0.0], g);
        }
        rk4(&Osc, 0.0, [1.0, 0.0], 0.01, 700, |_, t, y| {
            fall.update(&Osc, t, y, g);
            rise.update(&Osc, t, y, g);
            any.update(&Osc, t, y, g);
        });
        let pi = core::f64::consts::PI;
        assert_eq!((fall.count(), rise.count(), any.count()), (1, 1, 2));
        assert!((fall.first().unwrap() - 0.5 * pi).abs() < 1e-9);
        assert!((rise.first().unwrap() - 1.5 * pi).abs() < 1e-9);
        assert_eq!(any.first(), fall.first());
        assert!(!Direction::Falling.crossed(f64::NAN, -1.0));
        assert!(!Direction::Rising.crossed(-1.0, f64::NAN));
    }

    #[test]
    fn works_on_dormand_prince_steps() {
        let g = |y: &[f64; 2]| y[0] - 0.3;
        let mut c = Crossing::new(Direction::Falling);
        c.start(0.0, &[1.0, 0.0], g);
        let tol = Tolerance {
            rtol: 1e-10,
            atol: [1e-10; 2],
        };
        dopri45(
            &Osc,
            0.0,
            [1.0, 0.0],
            2.0,
            0.1,
            0.5,
            &tol,
            10_000,
            |t, y| {
                c.update(&Osc, t, y, g);
            },
        );
        assert!((c.first().unwrap() - 0.3f64.acos()).abs() < 1e-8);
    }

    #[test]
    fn f32_locates_within_its_resolution() {
        let g = |y: &[f32; 2]| y[0];
        let mut c = Crossing::new(Direction::Falling);
        c.start(0.0, &[1.0, 0.0], g);
        rk4(&Osc, 0.0, [1.0f32, 0.0], 0.05, 40, |_, t, y| {
            c.update(&Osc, t, y, g);
        });
        assert!((c.first().unwrap() - core::f32::consts::FRAC_PI_2).abs() < 1e-5);
    }
}
