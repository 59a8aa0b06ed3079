//! The step-aware wrench: the contact wrench to apply over a whole time step Δt so that a
//! semi-implicit Euler step with it is the linearly implicit (backward Euler) step of the
//! contact — stable and right at control-rate steps (1–2 ms) where the plain wrench needs
//! steps below the contact's stiffest mode (Hertz normal mode, regularised friction, creep).
//!
//! # API shape
//!
//! ```text
//! TimeStep::new(dt)                         → validated Δt > 0          (Error::StepNotPositive, NonFinite "dt")
//! InverseMass::<T, K>::new(blocks)          → validated W, 4K × 4K      (NotSymmetric, NotPositiveSemidefinite, NonFinite "W")
//!   ::single([[T;4];4]) / ::from_upper([T;10])   (K = 1)
//!   Body::new / Body::fixed, InverseMass::from_bodies(&bodies, &contacts)  (W from rigid bodies)
//! Free::predicted(dt, &state, u_free) / Free::coasting(dt, &state) / Free::new(u_free, h_free)
//! step_wrench(&contact, dt, &W, &state, &free)            → Outcome { wrench, u_end, h_end, flags }
//! step_wrenches([&dyn Linearize; K], dt, &W, &states, &frees) → [Outcome; K]
//! step_wrenches_with(…, &Scheme::strang())  → for a Strang-split integrator (θ = γ = ½)
//! Free::with_drift(drift)                   → the slip's own change within the step
//! Numeric::new(wrench_fn, steps)            → a central-difference `Linearize` (reference adapter)
//! ```
//!
//! `contact` is anything implementing [`Linearize`] (the library's contacts; [`Numeric`] for a
//! wrench given as a function). Every call is total: validated inputs in, finite wrench out.
//! [`scheme`] says how the caller's integrator moves the bodies (where the friction is
//! evaluated, θ; the share γ of the step the pose moves with the new velocities; the drift);
//! [`step_wrench`] and [`step_wrenches`] assume semi-implicit Euler (θ = γ = 1).
//! Also: [`stable`] (the plain path's step limits, what this path tolerates), [`contract`]
//! (`contact_eval step`'s row), [`project`] (the limit set).
//!
//! # Example: a ball on a plane at 1 ms
//!
//! A 20 mm steel ball resting on a steel plane, pushed along x with half the force friction can
//! hold, stepped at 1 ms (the Hertz normal mode's explicit limit is 0.2 ms, the friction ramp's
//! ≈ 20 µs): semi-implicit Euler, the contact's wrench from [`step_wrench`].
//!
//! ```
//! use contensou::contact::Contact;
//! use contensou::frame::{Frame, MajorAxis};
//! use contensou::friction::{Friction, Slip};
//! use contensou::geometry::Curvatures;
//! use contensou::jacobian::State;
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::step::{step_wrench, Body, ContactPoint, Free, InverseMass, Numeric, TimeStep};
//!
//! let (r, m, g) = (10e-3, 32.67e-3, 9.81);
//! let contact = Contact::circular(
//!     &Curvatures::sphere_plane(r)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::<f64>::new(0.1, 1e-4)?,
//! )?;
//! // The contact's derivatives: here by central differences of its wrench (a contact of the
//! // library can be passed directly once it implements `Linearize`).
//! let lin = Numeric::new(
//!     |s: &State<f64>| {
//!         let w = contact.wrench(s.h, s.hdot, s.slip);
//!         [w.n, w.fx, w.fy, w.tz]
//!     },
//!     [1e-12, 1e-6, 1e-7, 1e-7, 1e-3],
//! );
//! // W at the contact point: the ball (centre above it) on the fixed plane.
//! let i = 0.4 * m * r * r;
//! let ball = Body::new(m, [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]], [0.0, 0.0, r])?;
//! let frame = Frame::new([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], MajorAxis::from_cos_sin(1.0, 0.0));
//! let point = ContactPoint { a: None, b: Some(0), point: [0.0; 3], frame };
//! let w = InverseMass::<f64, 1>::from_bodies(&[ball], &[point])?;
//!
//! let dt = TimeStep::new(1e-3)?;
//! let push = 0.5 * 0.1 * g; // tangential acceleration of the centre (m/s²)
//! let mut s = State { h: 7.6e-8, ..State::default() }; // resting, approach ≈ static
//! for _ in 0..200 {
//!     // The free end-of-step velocity (v_n = −ḣ): gravity and the push, without the contact.
//!     // (The push acts at the centre: the contact point's slip gains push·Δt.)
//!     let u = [-s.hdot - g * dt.get(), s.slip.vx() + push * dt.get(), 0.0, 0.0];
//!     let free = Free::predicted(dt, &s, u)?;
//!     let o = step_wrench(&lin, dt, &w, &s, &free);
//!     // Apply o.wrench (contact frame, on the ball) over the whole step; here the contact
//!     // velocity after the step is o.u_end and the approach o.h_end.
//!     s = State { h: o.h_end, hdot: -o.u_end[0], slip: Slip::new(o.u_end[1], 0.0, 0.0)?, ..s };
//!     assert!(o.u_end[1] >= 0.0 && o.u_end[1] < 1e-4); // sticks: slip below δ
//! }
//! assert!((-s.hdot).abs() < 1e-9); // at rest along the normal
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Conventions
//!
//! As the crate's: contact frame x (major axis), y, z (from A into B); the wrench
//! w = (N, F_x, F_y, T_z) on B from A; the contact velocity u = (v_n, v_x, v_y, ω) of B
//! relative to A with **v_n = −ḣ** (separation speed); h the approach (h > 0 in contact).
//! An impulse Δt·w on B (and −Δt·w on A) changes u by Δt·W·w ([`InverseMass`]).
//!
//! # The step (maths)
//!
//! The caller integrates its bodies by semi-implicit Euler: velocities first, with every force
//! of the step, then positions with the end velocities. Without this contact the end velocity
//! would be u_free (gravity, actuators, every other force over the step; default the start
//! velocity) and the end approach h_free (from the free motion: h − Δt·u_free,n by default, or
//! the caller's own prediction from the drifted pose). With the contact's wrench w̄ over the
//! step:
//!
//! ```text
//! u⁺ = u_free + Δt·W·w̄                        (end velocity)
//! h⁺ = h_free − Δt·(u⁺_n − u_free,n) = h_free − Δt²·(W·w̄)_n      (end approach)
//! ```
//!
//! Backward Euler asks w̄ = w(h⁺, u⁺): the wrench at the end of the step. Linearised about the
//! point ℓ = (h_free, u_free) (the predicted end state; rolling velocity V held fixed), with
//! the [`Jacobian`] J = ∂w/∂(h, ḣ, v_x, v_y, ω) there, K_h = J[:, h] and D = ∂w/∂u
//! (D[:, n] = −J[:, ḣ], D[:, x|y|ω] = J[:, v_x|v_y|ω]):
//!
//! ```text
//! w̄ = w_ℓ + K_h·(h⁺ − h_ℓ) + D·(u⁺ − u_ℓ)
//!   ⇒ (I − Δt·G·W)·w̄ = r,    G = D − Δt·K_h·e_nᵀ,
//!     r = w_ℓ + K_h·(h_free − h_ℓ) + D·(u_free − u_ℓ)
//! ```
//!
//! (r = w_ℓ when ℓ is the free state). One 4 × 4 solve per contact; for K contacts sharing
//! bodies, G is block-diagonal and W carries the cross blocks, one 4K × 4K solve. The normal
//! row is in the solve (the Hertz stiffness through Δt²·K_h·W_nn, the damping through Δt·D_nn):
//! treating only the tangential block implicitly still explodes above the normal mode's limit.
//! As Δt → 0, I − Δt·G·W → I and w̄ → w(h, u): the plain wrench.
//!
//! Then, in order (each a fixed, bounded amount of work):
//!
//! 0. **Where to linearise.** The normal direction is strongly nonlinear (N ∝ h^{3/2}): a
//!    body resting under gravity at 1 ms has h_free = h + g·Δt² ≈ 30× the static approach, and
//!    the tangent there under-predicts N̄ by a third (and the friction ramp's stiffness
//!    fN(h_ℓ)/δ is then 150× too high). So the first linearisation's gap is the **normal
//!    predictor**'s: the contact alone along its normal, h − h_free + Δt²·W_nn·N(h) = 0, by
//!    [`PREDICTOR_STEPS`] regula-falsi (Illinois) steps on a bracket that always holds (one
//!    wrench call each); then [`LINEARISATIONS`] − 1 **Newton corrections** re-linearise every
//!    active contact at the solved end state (h⁺, u⁺) and solve again. Measured (ball on a
//!    plane under gravity, against the nonlinear backward-Euler step by bisection,
//!    `host-tests/step_wrench.rs`): N within 1.8e-9 and a sticking friction force within
//!    9.6e-6 relative at 5 ms (one linearisation without the predictor: N 33 % low, the
//!    sticking force 100 % off).
//! 1. **Active set.** A contact with N_ℓ ≤ 0 (apart at the predicted gap, or a damped rebound)
//!    takes no part. After a solve, every contact with N̄ ≤ 0 is dropped (its rows become
//!    w̄ᵢ = 0) and the solve repeated: at most K + 1 solves; a dropped contact is not re-added
//!    within the step. Never clamped afterwards: the others then carry the load.
//! 2. **Slip reversal.** If the solved end slip reverses within the step — v⁺·v_ℓ < 0 for the
//!    sliding velocity, ω⁺·ω_ℓ < 0 for the spin — the linearisation at the free slip is the
//!    wrong branch (a dry-friction force would push the slip back and forth every step): the
//!    contact is re-linearised at zero slip for the reversed part(s) (ℓ' = (h_free, u_free with
//!    v or ω set to 0); r = w_ℓ' + D'·(u_free − u_ℓ')) and step 1 repeated. For a
//!    regularised law, the zero-slip Jacobian is the ramp's stiffness κ·fN/δ: a sticking
//!    contact keeps |v⁺| ≈ |v_free|·δ/(Δt·W·κ·fN) < δ.
//! 3. **Limit set.** The friction pair (F, T_z) of each contact is moved into the law's
//!    full-slip limit set at the solved N̄ ([`project`]'s supporting-plane test; for a law
//!    that is not maximally dissipative, [`Linearize::maximally_dissipative`] `false`, the
//!    cylinder |F| ≤ F_max, |T_z| ≤ T_max, which holds its plain values: as Δt → 0 the step
//!    tends to the plain wrench for every law).
//! 4. **Power.** With u⁺ recomputed, friction must inject no energy over the step, checked for
//!    the force and the drilling torque **separately** (the linear solve can return a drilling
//!    torque of the wrong sign; a combined check would then zero all friction) — for a rolling
//!    contact (V ≠ 0) only once their sum injects, since a creep law couples spin to lateral
//!    force and lateral creep to torque (each part alone may do positive work, the sum not): if
//!    F·v⁺ > 0 the force is scaled by α ∈ [0, 1) so that F·v⁺ = 0 (F·v⁺ is affine in α with
//!    slope Δt·Fᵀ·W_tt·F ≥ 0: the force that just stops the slip along itself — Kikuuwe's
//!    implicit dry friction), then the same for T_z·ω⁺, contact after contact, u⁺ updated after
//!    each scaling. A last pass zeroes any part still injecting power beyond rounding
//!    (64 ε of |F|·(|v_free| + Δt·|W·w̄|)) — at most 2K + 1 passes.
//! 5. **The normal force at the end state.** Steps 3 and 4 change the friction after the
//!    solve; through W's normal–friction coupling (a contact point off the centre of mass)
//!    that moves the end approach, and N̄ would no longer be the normal law's value there
//!    (measured before this step: off by more than 1e-3 on about half the random states of
//!    `host-tests/step_normal.rs`, up to 100 %). Each active contact's N is re-solved at the
//!    end state with the other rows fixed (its force scaling with N, its torque with N and the
//!    patch: a pair on the limit set's boundary stays on it), by Newton steps on the end
//!    approach, then the friction follows (limit set, power) — [`normal`]. Measured: within
//!    1e-3 of the law on every state for `coulomb` and `best` (damped or not).
//!
//! Flags in [`Outcome`] tell which of these acted.
//!
//! # Cost
//!
//! Per contact: at most [`PREDICTOR_STEPS`] + 2 [`Linearize::normal_force`] (the normal predictor),
//! [`project::PATCH_STEPS`] + 2 + 4 (the limit set: its patch, its full-slip points),
//! [`LINEARISATIONS`] [`Linearize::linearize`] (one more per reversal), a 4 × 4 (or 4K × 4K)
//! elimination with partial pivoting per solve (at most LINEARISATIONS·2·(K + 1) solves, one
//! per linearisation in the common case), one more wrench call for step 5's check (and, where
//! it acts, [`normal::NORMAL_STEPS`] + 2 and a limit set per re-solve, at most two per sweep). Fixed: no loop runs on a tolerance. Measured (host
//! x86-64, f64, `best`, a ball sliding and spinning at 1 ms, analytic Jacobians): 1.8 µs per
//! call, 42× the plain wrench (43 ns) — against ≈ 200 plain calls for the ≈ 50 RK4 substeps the
//! plain path needs over the same millisecond.
//!
//! # What it tolerates
//!
//! See [`stable`]: the step-aware path has no stability limit from the contact's own
//! stiffness (normal mode, friction ramp, creep: each enters the solve implicitly); its accuracy
//! is first order in Δt, and what it cannot see is how the slip changes by itself within the
//! step (a contact point running fast over a curved surface, a gyroscopic turn of ω):
//! that is the caller's u_free.

// Dense 4K × 4K linear algebra reads best with index loops; `!(x > 0)` is the NaN-safe test
// used throughout (NaN fails it).
#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

pub mod bodies;
pub mod contract;
pub mod inverse_mass;
pub mod normal;
pub mod numeric;
pub mod project;
pub mod scheme;
mod solve;
pub mod stable;

pub use bodies::{Body, ContactPoint};
pub use inverse_mass::{InverseMass, PSD_TOLERANCE, SYMMETRY_TOLERANCE, TimeStep};
pub use numeric::Numeric;
pub use scheme::Scheme;

use crate::error::finite;
use crate::friction::Slip;
use crate::jacobian::{Jacobian, Linearize, State, input};
use crate::{Error, Real};
use solve::{Blocks, solve};

/// Linearisations per step: the first at the free end state, then Newton corrections at the
/// solved end state (h⁺, u⁺). A Hertz contact linearised at a free end gap far deeper than the
/// solved one (a body landing, or gravity's g·Δt² ≫ the static approach) under-predicts N
/// (the tangent of the convex h^{3/2} lies below it) and bounces; each correction moves the
/// linearisation to the last iterate (Newton's method on the backward-Euler equations,
/// monotone from that side for the normal row).
pub const LINEARISATIONS: usize = 2;

/// Regula-falsi steps of the normal predictor (the first linearisation's gap; see the module
/// docs): one wrench call each.
pub const PREDICTOR_STEPS: usize = 6;

/// The free motion of one contact over the step: what its velocity u = (v_n, v_x, v_y, ω) and
/// approach h would be at the end of the step without this contact's wrench (see the
/// [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Free<T> {
    u: [T; 4],
    h: T,
    drift: [T; 4],
}

impl<T: Real> Free<T> {
    /// The end velocity `u` (v_n = −ḣ, v_x, v_y, ω) and end approach `h` without the contact.
    /// Errors: [`Error::NonFinite`] `"u_free"` or `"h_free"`.
    pub fn new(u: [T; 4], h: T) -> Result<Self, Error> {
        for x in u {
            finite(x, "u_free")?;
        }
        Ok(Free {
            u,
            h: finite(h, "h_free")?,
            drift: [T::ZERO; 4],
        })
    }

    /// The same with the free velocity's own change within the step, `drift` = (the free
    /// velocity read at the end pose) − u_free: a contact point running over a curved body
    /// ([`scheme`]'s module docs). The end velocity is u_free + Δt·W·w̄ + drift. Errors:
    /// [`Error::NonFinite`] `"drift"`.
    pub fn with_drift(self, drift: [T; 4]) -> Result<Self, Error> {
        for x in drift {
            finite(x, "drift")?;
        }
        Ok(Free { drift, ..self })
    }

    /// The drift given by [`Free::with_drift`] (zero by default).
    pub fn drift(&self) -> [T; 4] {
        self.drift
    }

    /// End velocity `u` given, end approach predicted by the semi-implicit step:
    /// h_free = h − Δt·u_n. Errors as [`Free::new`].
    pub fn predicted(dt: TimeStep<T>, state: &State<T>, u: [T; 4]) -> Result<Self, Error> {
        Self::new(u, state.h - dt.get() * u[0])
    }

    /// No other force over the step: u_free = the start velocity (−ḣ, v_x, v_y, ω),
    /// h_free = h + Δt·ḣ. Total for a finite state (a non-finite one gives the rest state at
    /// h = 0: apart).
    pub fn coasting(dt: TimeStep<T>, state: &State<T>) -> Self {
        let s = &state.slip;
        let u = [-state.hdot, s.vx(), s.vy(), s.omega()];
        Self::predicted(dt, state, u).unwrap_or(Free {
            u: [T::ZERO; 4],
            h: T::ZERO,
            drift: [T::ZERO; 4],
        })
    }

    /// The free end velocity (v_n, v_x, v_y, ω).
    pub fn u(&self) -> [T; 4] {
        self.u
    }

    /// The free end approach h (m).
    pub fn h(&self) -> T {
        self.h
    }
}

/// What acted in a step-aware wrench (see the [module docs](self), steps 1–5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Flags {
    /// The contact was in the final active set (N̄ > 0).
    pub active: bool,
    /// The sliding velocity reversed within the step: re-linearised at zero sliding velocity.
    pub reversed_slip: bool,
    /// The spin reversed within the step: re-linearised at zero spin.
    pub reversed_spin: bool,
    /// The friction pair was moved into the limit set.
    pub limited: bool,
    /// The force was scaled (or zeroed) so as to inject no power.
    pub force_scaled: bool,
    /// The drilling torque was scaled (or zeroed) so as to inject no power.
    pub torque_scaled: bool,
    /// The linear solve failed (a zero or non-finite pivot): the plain wrench at the
    /// linearisation point was used, then projected.
    pub fallback: bool,
    /// The normal force was re-solved at the end state of the projected friction (step 5,
    /// [`normal`]).
    pub normal_resolved: bool,
}

/// One contact's step-aware result.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outcome<T> {
    /// w̄ = (N, F_x, F_y, T_z) on B from A, contact frame: apply it over the whole step.
    pub wrench: [T; 4],
    /// The predicted end velocity u⁺ = u_free + Δt·(W·w̄) (v_n, v_x, v_y, ω).
    pub u_end: [T; 4],
    /// The predicted end approach h⁺ = h_free − Δt²·(W·w̄)_n (m).
    pub h_end: T,
    /// What acted.
    pub flags: Flags,
}

/// The step-aware wrench of one contact (see the [module docs](self)): Δt, its 4 × 4 W, the
/// start state (its rolling velocity is used; h, ḣ and the slip only through `free`) and the
/// free end-of-step motion. Total.
pub fn step_wrench<T: Real, C: Linearize<T>>(
    contact: &C,
    dt: TimeStep<T>,
    w: &InverseMass<T, 1>,
    state: &State<T>,
    free: &Free<T>,
) -> Outcome<T> {
    let [o] = step_wrenches([contact as &dyn Linearize<T>], dt, w, &[*state], &[*free]);
    o
}

/// The step-aware wrenches of K contacts sharing bodies (W with its cross blocks): one solve
/// with an active set (see the [module docs](self)). Designed for K ≤ 4 (the cost grows as
/// (4K)³). Total.
pub fn step_wrenches<T: Real, const K: usize>(
    contacts: [&dyn Linearize<T>; K],
    dt: TimeStep<T>,
    w: &InverseMass<T, K>,
    states: &[State<T>; K],
    free: &[Free<T>; K],
) -> [Outcome<T>; K] {
    step_wrenches_with(contacts, dt, w, states, free, &Scheme::backward_euler())
}

/// [`step_wrenches`] for an integrator described by `scheme` ([`Scheme`]: where the friction
/// is evaluated, θ, and the share γ of the step the pose moves with the new velocities).
/// Total.
pub fn step_wrenches_with<T: Real, const K: usize>(
    contacts: [&dyn Linearize<T>; K],
    dt: TimeStep<T>,
    w: &InverseMass<T, K>,
    states: &[State<T>; K],
    free: &[Free<T>; K],
    scheme: &Scheme<T>,
) -> [Outcome<T>; K] {
    let dt_ = dt.get();
    let gamma = scheme.gap();
    // θ per contact: the scheme's, 1 for a contact whose slip reverses within the step.
    let mut theta = [scheme.theta(); K];
    let mut flags = [Flags::default(); K];
    // Linearisation states and their Jacobians.
    let mut lin = [State::default(); K];
    let mut jac = [Jacobian::default(); K];
    let mut active = [false; K];
    for i in 0..K {
        lin[i] = at_free(&free[i], &states[i], scheme.drift_share(theta[i]));
        let c = gamma * dt_ * dt_ * w.block(i, i)[0][0];
        lin[i].h = predict_gap(contacts[i], &lin[i], c);
        jac[i] = contacts[i].linearize(&lin[i]);
        active[i] = finite_jacobian(&jac[i]) && jac[i].value[0] > T::ZERO;
    }
    let mut wbar = [[T::ZERO; 4]; K];
    let mut ok = true;
    for pass in 0..LINEARISATIONS {
        if pass > 0 {
            // Newton correction: re-linearise at the solved state (h⁺, u_θ).
            let u_end = end_velocity(dt_, w, free, &wbar);
            for i in 0..K {
                if !active[i] {
                    continue;
                }
                let u = at_theta(&free[i], &u_end[i], theta[i], scheme);
                let l = State {
                    h: end_gap(dt_, gamma, &free[i], &u_end[i]),
                    hdot: -u[0],
                    slip: Slip::or_rest(u[1], u[2], u[3]),
                    rolling: states[i].rolling,
                };
                let j = contacts[i].linearize(&l);
                if finite_jacobian(&j) && j.value[0] > T::ZERO {
                    lin[i] = l;
                    jac[i] = j;
                }
            }
        }
        ok = active_set_solve(
            dt_,
            w,
            &lin,
            &jac,
            free,
            &theta,
            scheme,
            &mut active,
            &mut wbar,
        ) && reversal(
            dt_,
            contacts,
            w,
            free,
            scheme,
            &mut theta,
            &mut lin,
            &mut jac,
            &mut active,
            &mut wbar,
            &mut flags,
        );
        if !ok {
            break;
        }
    }
    if !ok {
        // Fallback: the plain wrench at the linearisation point.
        for i in 0..K {
            flags[i].fallback = true;
            wbar[i] = if active[i] {
                jac[i].value
            } else {
                [T::ZERO; 4]
            };
            if !(wbar[i][0] > T::ZERO) {
                wbar[i] = [T::ZERO; 4];
                active[i] = false;
            }
        }
    }

    // Step 3: the limit set.
    for i in 0..K {
        flags[i].active = active[i];
        if active[i] {
            flags[i].limited =
                project::into_limit_set(contacts[i], &lin[i], jac[i].value[0], &mut wbar[i]);
        } else {
            wbar[i] = [T::ZERO; 4];
        }
    }

    // Step 4: power, force and torque separately — for a rolling contact (V ≠ 0) only once
    // their sum injects (its creep law couples the spin to the lateral force and the lateral
    // creep to the torque: each part alone may do positive work while the sum is passive).
    let mut u_end = end_velocity(dt_, w, free, &wbar);
    let coupled: [bool; K] = core::array::from_fn(|i| {
        let v = states[i].rolling;
        v.vx() != T::ZERO || v.vy() != T::ZERO
    });
    // `get`, not `coupled[i]`: i < K at every call, but at opt-level z this closure is not
    // inlined and the index would keep a bounds check (a panic path; tools/no-panic.sh).
    let gate = |i: usize, wbar: &[[T; 4]; K], u_end: &[[T; 4]; K]| match coupled.get(i) {
        Some(true) => injects_total(dt_, w, free, i, wbar, u_end),
        _ => true,
    };
    for i in 0..K {
        if active[i] && gate(i, &wbar, &u_end) {
            if scale_part(dt_, w, i, Part::Force, &mut wbar, &mut u_end) {
                flags[i].force_scaled = true;
            }
            if scale_part(dt_, w, i, Part::Torque, &mut wbar, &mut u_end) {
                flags[i].torque_scaled = true;
            }
        }
    }
    // Step 5: N re-solved at the end state of the projected friction, the friction following.
    normal::settle(
        contacts,
        dt_,
        gamma,
        w,
        states,
        free,
        &lin,
        &jac,
        &coupled,
        &mut active,
        &mut wbar,
        &mut u_end,
        &mut flags,
    );
    // The end velocity afresh from the final wrench: the re-solve's and the scalings' updates
    // were incremental, and where N̄ fell by orders of magnitude (f32: 9.3e7 N → 8 N) their
    // rounding left u⁺ off by more than the power it decides (a fuzz finding).
    u_end = end_velocity(dt_, w, free, &wbar);
    for pass in 0..(2 * K + 1) {
        let mut clean = true;
        for i in 0..K {
            if !gate(i, &wbar, &u_end) {
                continue;
            }
            for part in [Part::Force, Part::Torque] {
                if injects(dt_, w, free, i, part, &wbar, &u_end) {
                    clean = false;
                    // To no power first (step 4's scaling at the exact u⁺; first pass only:
                    // scaling one part moves the other's u⁺ and a scaled part can be left
                    // just injecting again, so the later passes zero), to zero if that leaves
                    // it injecting.
                    if pass == 0 {
                        scale_part(dt_, w, i, part, &mut wbar, &mut u_end);
                        u_end = end_velocity(dt_, w, free, &wbar);
                    }
                    if injects(dt_, w, free, i, part, &wbar, &u_end) {
                        rescale(dt_, w, i, part, T::ZERO, &mut wbar, &mut u_end);
                        u_end = end_velocity(dt_, w, free, &wbar);
                    }
                    match part {
                        Part::Force => flags[i].force_scaled = true,
                        Part::Torque => flags[i].torque_scaled = true,
                    }
                }
            }
        }
        if clean {
            break;
        }
    }

    let mut out = [Outcome::default(); K];
    for i in 0..K {
        out[i] = Outcome {
            wrench: wbar[i],
            u_end: u_end[i],
            h_end: end_gap(dt_, gamma, &free[i], &u_end[i]),
            flags: flags[i],
        };
    }
    out
}

/// Step 2: where the solved end slip reverses against the linearisation's slip, re-linearise
/// that contact at zero sliding velocity and/or spin and solve again. `false` if the solve
/// failed.
#[allow(clippy::too_many_arguments)]
fn reversal<T: Real, const K: usize>(
    dt: T,
    contacts: [&dyn Linearize<T>; K],
    w: &InverseMass<T, K>,
    free: &[Free<T>; K],
    scheme: &Scheme<T>,
    theta: &mut [T; K],
    lin: &mut [State<T>; K],
    jac: &mut [Jacobian<T>; K],
    active: &mut [bool; K],
    wbar: &mut [[T; 4]; K],
    flags: &mut [Flags; K],
) -> bool {
    let u_end = end_velocity(dt, w, free, wbar);
    let mut any = false;
    for i in 0..K {
        if !active[i] {
            continue;
        }
        let u = u_end[i];
        let sl = lin[i].slip;
        let rv = u[1] * sl.vx() + u[2] * sl.vy() < T::ZERO;
        let rw = u[3] * sl.omega() < T::ZERO;
        if rv || rw {
            any = true;
            flags[i].reversed_slip |= rv;
            flags[i].reversed_spin |= rw;
            // Reversing within the step: the end of the step (θ = 1) decides, at rest.
            theta[i] = T::ONE;
            let l = State {
                slip: Slip::or_rest(
                    if rv { T::ZERO } else { sl.vx() },
                    if rv { T::ZERO } else { sl.vy() },
                    if rw { T::ZERO } else { sl.omega() },
                ),
                ..lin[i]
            };
            let j = contacts[i].linearize(&l);
            if finite_jacobian(&j) && j.value[0] > T::ZERO {
                lin[i] = l;
                jac[i] = j;
            }
        }
    }
    !any || active_set_solve(dt, w, lin, jac, free, theta, scheme, active, wbar)
}

/// The normal predictor: the end approach h of the contact alone along its normal,
/// h − h_free + c·N(h) = 0 with c = Δt²·W_nn (ḣ, slip held at the free state), by
/// [`PREDICTOR_STEPS`] Illinois (regula falsi) steps on the bracket
/// [max(0, h_free − c·N(h_free)), h_free] (φ ≤ 0 at its left end since N is non-decreasing in
/// h and 0 at h = 0, ≥ 0 at its right). One [`Linearize::normal_force`] per step. Returns the
/// last interpolation inside the bracket: the first linearisation goes there instead of
/// h_free.
fn predict_gap<T: Real>(contact: &dyn Linearize<T>, l: &State<T>, c: T) -> T {
    let phi = |h: T| {
        let n = contact.normal_force(&State { h, ..*l });
        let n = if n.is_finite() { n } else { T::ZERO };
        h - l.h + c * n
    };
    let fb = phi(l.h);
    if !(fb > T::ZERO) {
        return l.h;
    }
    // N(0) = 0 for every normal law: h = 0 is a left end as well.
    let (mut a, mut b) = ((l.h - fb).max(T::ZERO), l.h);
    let mut fa = phi(a);
    let mut fb = fb;
    if !(fa < T::ZERO) {
        return a;
    }
    // Illinois: the retained end's value is halved when the same end is kept twice.
    let mut side = 0i8;
    for _ in 0..PREDICTOR_STEPS {
        let x = b - fb * (b - a) / (fb - fa);
        if !(x > a && x < b) {
            break;
        }
        let fx = phi(x);
        if fx > T::ZERO {
            b = x;
            fb = fx;
            if side == 1 {
                fa *= T::HALF;
            }
            side = 1;
        } else if fx < T::ZERO {
            a = x;
            fa = fx;
            if side == -1 {
                fb *= T::HALF;
            }
            side = -1;
        } else {
            return x;
        }
    }
    // The last interpolation of the bracket (N > 0 there unless it lands at h ≤ 0: then the
    // deep end, where φ ≥ 0 makes N > 0).
    let x = b - fb * (b - a) / (fb - fa);
    if x > a && x <= b { x } else { b }
}

/// The linearisation state at the free motion: u_free + share·drift (the drift's share at
/// the evaluation time θ).
fn at_free<T: Real>(free: &Free<T>, s: &State<T>, share: T) -> State<T> {
    let u: [T; 4] = core::array::from_fn(|c| {
        if free.drift[c] == T::ZERO {
            free.u[c]
        } else {
            free.u[c] + share * free.drift[c]
        }
    });
    State {
        h: free.h,
        hdot: -u[0],
        slip: Slip::or_rest(u[1], u[2], u[3]),
        rolling: s.rolling,
    }
}

fn finite_jacobian<T: Real>(j: &Jacobian<T>) -> bool {
    j.value.iter().all(|v| v.is_finite()) && j.d.iter().flatten().all(|v| v.is_finite())
}

/// The velocity the law sees at θ from the end velocity `u_end` (= u_free + Δt·W·w̄ + drift):
/// u_free + t·(Δt·W·w̄) + s(t)·drift, t = 1 for the normal component (backward Euler), θ for
/// the friction's.
fn at_theta<T: Real>(free: &Free<T>, u_end: &[T; 4], theta: T, scheme: &Scheme<T>) -> [T; 4] {
    core::array::from_fn(|c| {
        let t = if c == 0 { T::ONE } else { theta };
        if t == T::ONE {
            return u_end[c];
        }
        let push = u_end[c] - free.u[c] - free.drift[c];
        free.u[c] + t * push + scheme.drift_share(t) * free.drift[c]
    })
}

/// h⁺ = h_free − γ·Δt·(u⁺_n − drift_n − u_free,n) = h_free − γ·Δt²·(W·w̄)_n.
fn end_gap<T: Real>(dt: T, gamma: T, free: &Free<T>, u_end: &[T; 4]) -> T {
    free.h - gamma * dt * (u_end[0] - free.drift[0] - free.u[0])
}

/// D = ∂w/∂u (columns v_n, v_x, v_y, ω) from the Jacobian.
fn d_u<T: Real>(j: &Jacobian<T>) -> [[T; 4]; 4] {
    let mut d = [[T::ZERO; 4]; 4];
    for r in 0..4 {
        d[r] = [
            -j.d[r][input::HDOT],
            j.d[r][input::VX],
            j.d[r][input::VY],
            j.d[r][input::OMEGA],
        ];
    }
    d
}

/// Steps 1 (and the solve): assemble (I − Δt·G·W)·w̄ = r over the active contacts, solve,
/// drop contacts with N̄ ≤ 0 and repeat (at most K + 1 solves). `false` if a solve failed.
#[allow(clippy::too_many_arguments)]
fn active_set_solve<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    lin: &[State<T>; K],
    jac: &[Jacobian<T>; K],
    free: &[Free<T>; K],
    theta: &[T; K],
    scheme: &Scheme<T>,
    active: &mut [bool; K],
    wbar: &mut [[T; 4]; K],
) -> bool {
    // G and r per contact.
    let mut g = [[[T::ZERO; 4]; 4]; K];
    let mut r = [[T::ZERO; 4]; K];
    for i in 0..K {
        let d = d_u(&jac[i]);
        let ul = [
            -lin[i].hdot,
            lin[i].slip.vx(),
            lin[i].slip.vy(),
            lin[i].slip.omega(),
        ];
        // u_θ = u_free + s·drift + Θ·Δt·W·w̄ (Θ = diag(1, θ, θ, θ)), h⁺ = h_free − γ·Δt²·(W·w̄)_n.
        let th = theta[i];
        let shifted: [T; 4] = core::array::from_fn(|b| {
            let t = if b == 0 { T::ONE } else { th };
            if free[i].drift[b] == T::ZERO {
                free[i].u[b]
            } else {
                free[i].u[b] + scheme.drift_share(t) * free[i].drift[b]
            }
        });
        for a in 0..4 {
            g[i][a] = [d[a][0], th * d[a][1], th * d[a][2], th * d[a][3]];
            g[i][a][0] = d[a][0] - scheme.gap() * dt * jac[i].d[a][input::H];
            let mut ra = jac[i].value[a] + jac[i].d[a][input::H] * (free[i].h - lin[i].h);
            for b in 0..4 {
                ra += d[a][b] * (shifted[b] - ul[b]);
            }
            r[i][a] = ra;
        }
    }
    // A contact whose normal row, alone, pushes (N_ℓ > 0 at the predicted gap) but whose
    // coupled solve gives N̄ ≤ 0 is re-solved once with its normal row blind to the friction
    // impulses (W_n,friction dropped from that row) before it may be dropped: a creep law's
    // stiff tangential rows, through W's normal–tangential cross terms of an offset contact
    // point, can drive the linear model's N̄ negative while the body is landing (measured on
    // the rolling rattleback at 1 ms: dropped at an approach of 7.5 µm, 3× the static one).
    let mut blind = [false; K];
    for _ in 0..=(2 * K) {
        let mut m = Blocks::<T, K>::zero();
        let mut x = [[T::ZERO; 4]; K];
        for i in 0..K {
            for a in 0..4 {
                let row = 4 * i + a;
                if active[i] {
                    for j in 0..K {
                        let wij = w.block(i, j);
                        for b in 0..4 {
                            // (G_i·W_ij)[a][b]
                            let mut gw = T::ZERO;
                            for c in 0..4 {
                                if blind[i] && a == 0 && c == 0 && b != 0 {
                                    continue;
                                }
                                gw += g[i][a][c] * wij[c][b];
                            }
                            let id = if i == j && a == b { T::ONE } else { T::ZERO };
                            m.set(row, 4 * j + b, id - dt * gw);
                        }
                    }
                    x[i][a] = r[i][a];
                } else {
                    m.set(row, row, T::ONE);
                }
            }
        }
        if !solve(&mut m, &mut x) {
            return false;
        }
        let mut dropped = false;
        for i in 0..K {
            if active[i] && !(x[i][0] > T::ZERO) {
                if !blind[i] && jac[i].value[0] > T::ZERO {
                    blind[i] = true;
                } else {
                    active[i] = false;
                }
                dropped = true;
            }
            wbar[i] = if active[i] { x[i] } else { [T::ZERO; 4] };
        }
        if !dropped {
            return true;
        }
    }
    true
}

/// u⁺ = u_free + Δt·W·w̄ for every contact.
fn end_velocity<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    free: &[Free<T>; K],
    wbar: &[[T; 4]; K],
) -> [[T; 4]; K] {
    let mut u = [[T::ZERO; 4]; K];
    for i in 0..K {
        for a in 0..4 {
            u[i][a] = free[i].u[a] + dt * w.row_times(4 * i + a, wbar);
            if free[i].drift[a] != T::ZERO {
                u[i][a] += free[i].drift[a];
            }
        }
    }
    u
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    Force,
    Torque,
}

impl Part {
    fn range(self) -> core::ops::Range<usize> {
        match self {
            Part::Force => 1..3,
            Part::Torque => 3..4,
        }
    }
}

/// Adds Δt·W·δ (δ on contact i's components `part`, scaled by `by − 1`) to u⁺ and scales the part.
fn rescale<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    i: usize,
    part: Part,
    by: T,
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
) {
    let mut delta = [[T::ZERO; 4]; K];
    if let (Some(d), Some(wi)) = (delta.get_mut(i), wbar.get_mut(i)) {
        for c in part.range() {
            if let (Some(dc), Some(wc)) = (d.get_mut(c), wi.get_mut(c)) {
                *dc = *wc * (by - T::ONE);
                *wc *= by;
            }
        }
    }
    for j in 0..K {
        for a in 0..4 {
            u_end[j][a] += dt * w.row_times(4 * j + a, &delta);
        }
    }
}

/// Power of contact i's `part` at u⁺ and its slope Δt·pᵀ·W_ii·p in the part's scale.
fn power<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    i: usize,
    part: Part,
    wbar: &[[T; 4]; K],
    u_end: &[[T; 4]; K],
) -> (T, T) {
    let (Some(wi), Some(ui)) = (wbar.get(i), u_end.get(i)) else {
        return (T::ZERO, T::ZERO);
    };
    let b = w.block(i, i);
    let at = |x: &[T; 4], k: usize| x.get(k).copied().unwrap_or(T::ZERO);
    let mut p = T::ZERO;
    let mut slope = T::ZERO;
    for a in part.range() {
        p += at(wi, a) * at(ui, a);
        let row = b.get(a).copied().unwrap_or([T::ZERO; 4]);
        for c in part.range() {
            slope += at(wi, a) * at(&row, c) * at(wi, c);
        }
    }
    (p, dt * slope)
}

/// Scales contact i's `part` so that it injects no power (module docs, step 4). True if scaled.
fn scale_part<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    i: usize,
    part: Part,
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
) -> bool {
    let (p, slope) = power(dt, w, i, part, wbar, u_end);
    if !(p > T::ZERO) {
        return false;
    }
    // p(α) = p − (1 − α)·slope; zero at α = 1 − p/slope, kept a little below.
    let alpha = if slope > p {
        (T::ONE - p / slope) * (T::ONE - T::EPSILON * T::from_f64(16.0))
    } else {
        T::ZERO
    };
    rescale(dt, w, i, part, alpha.max(T::ZERO), wbar, u_end);
    true
}

/// Whether contact i's friction (force and torque together) injects power beyond rounding.
fn injects_total<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    free: &[Free<T>; K],
    i: usize,
    wbar: &[[T; 4]; K],
    u_end: &[[T; 4]; K],
) -> bool {
    let (pf, _) = power(dt, w, i, Part::Force, wbar, u_end);
    let (pt, _) = power(dt, w, i, Part::Torque, wbar, u_end);
    let scale = power_scale(free, i, Part::Force, wbar, u_end)
        + power_scale(free, i, Part::Torque, wbar, u_end);
    pf + pt > T::EPSILON * T::from_f64(64.0) * scale
}

/// |w_part|·(|u_free| + |u⁺ − u_free|) over the part's components: the rounding scale of its
/// power.
fn power_scale<T: Real, const K: usize>(
    free: &[Free<T>; K],
    i: usize,
    part: Part,
    wbar: &[[T; 4]; K],
    u_end: &[[T; 4]; K],
) -> T {
    let (Some(fi), Some(wi), Some(ui)) = (free.get(i), wbar.get(i), u_end.get(i)) else {
        return T::ZERO;
    };
    let at = |x: &[T; 4], k: usize| x.get(k).copied().unwrap_or(T::ZERO);
    let mut scale = T::ZERO;
    for a in part.range() {
        let du = (at(ui, a) - at(&fi.u, a)).abs();
        scale += at(wi, a).abs() * (at(&fi.u, a).abs() + du);
    }
    scale
}

/// Whether contact i's `part` injects power beyond rounding: p > 64 ε·|w_part|·(|u_free| +
/// Δt·|W·w̄|) over the part's components.
fn injects<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    free: &[Free<T>; K],
    i: usize,
    part: Part,
    wbar: &[[T; 4]; K],
    u_end: &[[T; 4]; K],
) -> bool {
    let (p, _) = power(dt, w, i, part, wbar, u_end);
    p > T::EPSILON * T::from_f64(64.0) * power_scale(free, i, part, wbar, u_end)
}
