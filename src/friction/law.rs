//! The friction-law interface: a dimensionless core chosen by generics, and the dimensional
//! wrapper that scales it by fN and fNa.

use core::fmt::Debug;
use core::marker::PhantomData;

use super::{Constants, Slip, SlipState, Traction, larger};
use crate::error::finite;
use crate::{Error, Real};

/// A friction law over the Hertz ellipse: a zero-sized type, chosen by generics so that only the
/// laws a program uses are linked.
///
/// Every law here is passive by construction (F·v_P + T_z·ω ≤ 0), bounded (|F| ≤ fN) and
/// continuous across its own branch switches; the only jump left is dry friction's own, at
/// v_P = 0 with ω = 0 and δ = 0 (F = 0 there, −fN·v_P/|v_P| beside it). See each law's docs
/// for its formula, error and cost.
pub trait FrictionLaw: Copy + Debug + PartialEq {
    /// Short name used by the evaluator CLI and the benchmark labels (`"simplified"`, …).
    const NAME: &'static str;
    /// Which formula piece produced a traction (for diagnostics, tests and plots).
    type Branch: Copy + Debug + PartialEq;

    /// Whether the dimensional wrapper regularizes the law near rest: for δ > 0 it scales the
    /// traction by min(1, p/(c·δ)), p = −(F·v_P + T_z·ω)/(fN) the full-slip law's own
    /// dissipation per unit fN (m/s; for the exact law the pressure-weighted mean slip speed
    /// over the patch, ∫σ|v_M| dA/N), c = 3/8. A non-negative factor keeps passivity,
    /// |F| ≤ fN, continuity and every symmetry; δ = 0 (or p ≥ c·δ) changes nothing. It replaces
    /// dry friction's jump at rest by a ramp, for laws whose core ignores δ (`best`); laws with
    /// their own g_δ switch (`simplified`, `coulomb`) leave it `false`.
    ///
    /// **Why p and not a slip speed:** a law that is the gradient of a convex, degree-one
    /// dissipation D (the exact integrals: F = −fN·∇D, p = D) stays a gradient, of the convex
    /// fN·φ(D) with φ′ = min(1, D/(cδ)) (Huber), so its damping matrix
    /// −∂(F, T_z/a)/∂(v_P, aω) = fN·(φ″∇D∇Dᵀ + φ′∇²D) stays symmetric positive semidefinite
    /// in the ramp as well (a large-step solver's Newton matrix; see [`crate::jacobian`]). A
    /// ramp by another speed (the ℓ¹ slip speed s = |v_Px| + |v_Py| + a|ω|, this wrapper's
    /// former min(1, s/δ)) is passive but not monotone. **What δ means:** the stick speed of
    /// every slip component. Since p ≥ |v_P| (Jensen) and p ≥ C·a|ω| (p is convex and even in
    /// v_P; C = (3/8)E(e²) ≥ 3/8, the mean point speed of a pure spin being C·a|ω|), a
    /// sticking contact (p < 3δ/8) keeps |v_P| < 3δ/8 and a|ω| < δ, as under the former ramp
    /// (s < δ); c = 3/8 keeps the ramp's stiffness within −3 … +27 % of the former one's
    /// (κ, κ_T: [`ramp_stiffness`](super::best::ramp_stiffness),
    /// [`spin_stiffness`](super::best::spin_stiffness)). **Why c = 3/8:** in pure spin the
    /// ramp's torque stiffness is C²·fN·a²/(cδ), the former ramp's C·fN·a²/δ: equal for c = C,
    /// and c = 3/8 = min C (elongated patches, e² → 1) keeps it there or stiffer, the ramp's
    /// spin width a|ω| < (c/C)·δ ≤ δ. In translation (p = |v_P|) it is 8/3 × the former fN/δ.
    /// **δ is a numerical width:** results that depend on it are not physics. Measured on the
    /// rattleback scene (`crate::scenes::rattleback::BEST_DELTA`): at δ = 1 mm/s the outcome
    /// depends on the ramp's shape (a stall at 0.8432 s with s/δ, 0.8631 s with this ramp, a
    /// reversal at 1.92 s with c = 1), at δ ≤ 0.1 mm/s every ramp gives the δ → 0 limit.
    const RAMP_BELOW_DELTA: bool = false;

    /// Whether the law is maximally dissipative: its full-slip value for a slip direction s is
    /// the point of its limit set (the set of every friction pair it gives at a normal force)
    /// that dissipates most along s, so that the set is bounded by the supporting planes
    /// −p·s ≤ −p_fs(s)·s (the exact integrals, `best`, `ellipsoid`, `coulomb`). `false` for
    /// the approximations whose full-slip values are not support points (`simplified`,
    /// `pade`): the step-aware wrench ([`crate::step::project`]) then bounds the force and the
    /// drilling torque separately, |F| ≤ F_fs and |T_z| ≤ T_fs of pure translation and pure
    /// spin, a set that holds every value of such a law (its supporting-plane test would move
    /// its own plain values: `simplified`'s on 44 % of the steps of a rattleback at any Δt).
    const MAXIMALLY_DISSIPATIVE: bool = true;

    /// What the law precomputes once per contact shape (e² fixed). For most laws it is the
    /// [`Constants`] themselves (then `traction_prepared` is `traction`);
    /// [`crate::friction::Best`] builds its tables into [`crate::friction::BestContact`].
    type Prepared<T: Real>: Copy + Debug + PartialEq;

    /// The dimensionless core: the slip state (homogeneous form, see [`SlipState`]) →
    /// F/(fN), T_z/(fNa) on body B from body A, and the branch. Total: finite output for every
    /// state. This is the form for a shape that changes every call (nothing precomputed).
    fn traction<T: Real>(k: &Constants<T>, s: &SlipState<T>) -> (Traction<T>, Self::Branch);

    /// Precompute the per-contact form from the shape constants (once per contact). Total.
    fn prepare<T: Real>(k: &Constants<T>) -> Self::Prepared<T>;

    /// κ: the largest stiffness −∂F/∂v_P of the law's regularization near rest, in units of
    /// fN/δ, over every slip direction and every fixed spin, for the shape `k` — what
    /// [`Friction::stable_step`] divides by. `Coulomb` and `Simplified`: 1; `Best`:
    /// [`ramp_stiffness`](super::best::ramp_stiffness). `None` (the default) for a law with no ramp (`Pade`, `Ellipsoid`,
    /// `Exact` ignore δ: Coulomb's sign law at rest, no stable explicit step).
    fn slip_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        let _ = k;
        None
    }

    /// κ_T: the largest torque stiffness −∂T_z/∂ω of the law's regularization, in units of
    /// fN·a²/δ, over every slip with v_P fixed, for the shape `k` — what
    /// [`Friction::stable_spin_step`] divides by. `Coulomb`: 0 (no torque); `Simplified`: 2/5;
    /// `Best`: [`spin_stiffness`](super::best::spin_stiffness). `None` (the default) for a law
    /// with no ramp.
    fn spin_ramp<T: Real>(k: &Constants<T>) -> Option<T> {
        let _ = k;
        None
    }

    /// The dimensionless core with the per-contact form: same result as
    /// [`FrictionLaw::traction`] up to the law's stated error, usually cheaper. Total.
    fn traction_prepared<T: Real>(
        p: &Self::Prepared<T>,
        s: &SlipState<T>,
    ) -> (Traction<T>, Self::Branch);
}

/// Implements the per-contact items of [`FrictionLaw`] for a law that precomputes nothing
/// beyond the [`Constants`]: `Prepared = Constants`, `traction_prepared = traction`.
macro_rules! constants_are_prepared {
    () => {
        type Prepared<T: $crate::Real> = $crate::friction::Constants<T>;

        #[inline(always)]
        fn prepare<T: $crate::Real>(k: &$crate::friction::Constants<T>) -> Self::Prepared<T> {
            *k
        }

        #[inline(always)]
        fn traction_prepared<T: $crate::Real>(
            p: &Self::Prepared<T>,
            s: &$crate::friction::SlipState<T>,
        ) -> ($crate::friction::Traction<T>, Self::Branch) {
            Self::traction(p, s)
        }
    };
}
pub(crate) use constants_are_prepared;

/// Friction force and drilling torque on body B from body A, in the contact frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tangential<T, B> {
    /// F_x (N), along the major axis.
    pub fx: T,
    /// F_y (N), along the minor axis.
    pub fy: T,
    /// T_z (N·m), about the common normal.
    pub tz: T,
    /// The law's branch that produced it.
    pub branch: B,
}

/// A friction law with its dimensional parameters: the friction coefficient f and the
/// regularization speed δ (m/s; 0 disables regularization). Validated at construction; the
/// per-step [`Friction::tangential`] is total.
///
/// The law defaults to [`crate::friction::Best`], the exact-grade fast law:
/// [`Friction::new`] builds that one and needs no annotation where it is passed
/// (`Contact::hertz::<Newton>(…, Friction::new(0.1, 1e-4)?)`); [`Friction::with_law`] builds
/// any law, named by a turbofish or inferred from where the value goes (a
/// `contensou::select` scene's law, a struct field).
///
/// # Example
///
/// ```
/// use contensou::friction::{Constants, Explicit, Friction, Simplified, Slip};
///
/// // f = 0.3, regularization speed δ = 1e-4 m/s; the default law `Best`, and the paper's.
/// let best = Friction::<f64>::new(0.3, 1e-4)?;
/// let paper = Friction::<f64, Simplified>::with_law(0.3, 1e-4)?;
/// // On a circular patch (a = 0.1 mm, N = 10 N): pure spin gives the torque −(3π/16)·fN·a.
/// let k = Constants::circle();
/// let t = best.tangential(&k, 1e-4, 10.0, Slip::new(0.0, 0.0, 50.0)?);
/// assert!((t.tz / (-3.0 * std::f64::consts::PI / 16.0 * 0.3 * 10.0 * 1e-4) - 1.0).abs() < 1e-5);
/// assert!(paper.tangential(&k, 1e-4, 10.0, Slip::new(0.0, 0.0, 50.0)?).tz < 0.0);
/// // The explicit step the regularization allows (effective mass 1 g).
/// assert!(best.stable_step(&k, 1e-3, 10.0, Explicit::Euler) > 0.0);
/// assert!(Friction::<f64>::new(-0.1, 0.0).is_err()); // f < 0
/// # Ok::<(), contensou::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Friction<T, L = super::Best> {
    f: T,
    delta: T,
    law: PhantomData<L>,
}

impl<T: Real> Friction<T> {
    /// The default law ([`crate::friction::Best`]) from the friction coefficient `f` ≥ 0 and
    /// the regularization speed `delta` ≥ 0 (m/s). Not generic over the law, so it needs no
    /// annotation where it is built (`Contact::hertz::<Newton>(…, Friction::new(0.1, 1e-4)?)`);
    /// for another law name it: [`Friction::with_law`]. Errors as [`Friction::with_law`].
    ///
    /// ```
    /// use contensou::friction::{Best, Friction};
    ///
    /// let law = Friction::new(0.1_f64, 1e-4)?; // Friction<f64, Best>
    /// assert_eq!(law, Friction::<f64, Best>::with_law(0.1, 1e-4)?);
    /// # Ok::<(), contensou::Error>(())
    /// ```
    #[inline]
    pub fn new(f: T, delta: T) -> Result<Self, Error> {
        Self::with_law(f, delta)
    }
}

impl<T: Copy, L> Friction<T, L> {
    /// f and δ through `g` (the dual form of the Jacobian).
    #[inline(always)]
    pub(crate) fn map<U>(&self, g: impl Fn(T) -> U) -> Friction<U, L> {
        Friction {
            f: g(self.f),
            delta: g(self.delta),
            law: PhantomData,
        }
    }
}

impl<T: Real, L: FrictionLaw> Friction<T, L> {
    /// The law `L` (named by a turbofish, `Friction::<f64, Simplified>::with_law(0.3, 1e-4)`,
    /// or inferred from where the value goes) from the friction coefficient `f` ≥ 0 and the
    /// regularization speed `delta` ≥ 0 (m/s). [`Friction::new`] is this for the default law.
    /// Errors: [`Error::NonFinite`] (`"f"`, `"delta"`) for NaN or ±∞,
    /// [`Error::FrictionCoefficientNegative`] for f < 0, [`Error::RegularizationSpeedNegative`]
    /// for δ < 0 (δ = 0 is allowed and means no regularization).
    pub fn with_law(f: T, delta: T) -> Result<Self, Error> {
        let f = finite(f, "f")?;
        let delta = finite(delta, "delta")?;
        if f < T::ZERO {
            return Err(Error::FrictionCoefficientNegative);
        }
        if delta < T::ZERO {
            return Err(Error::RegularizationSpeedNegative);
        }
        Ok(Friction {
            f,
            delta,
            law: PhantomData,
        })
    }

    /// The friction coefficient f.
    #[inline(always)]
    pub fn coefficient(&self) -> T {
        self.f
    }

    /// The regularization speed δ (m/s).
    #[inline(always)]
    pub fn delta(&self) -> T {
        self.delta
    }

    /// One per-step call: patch constants `k`, major semi-axis `a` (m), normal force `n` (N) and
    /// the slip → force (N) and drilling torque (N·m) on body B from body A.
    ///
    /// N ≤ 0 (or NaN) gives the zero wrench (no contact, no adhesion); `a` ≤ 0 (or NaN) is a
    /// point contact (no spin effect, no torque). Total: finite output for finite `a` and `n`.
    /// Cost: the law's core plus a normalisation (two additions, one division, four
    /// multiplications, an integer range test) and five multiplications: 122 instructions for
    /// `Friction::<f32, Simplified>` on the Cortex-M4F (QEMU stage `friction`, method
    /// `simplified-dimensional`, with the branch; the core alone is 66, without its branch).
    /// A law with [`FrictionLaw::RAMP_BELOW_DELTA`] adds a gate δ > s/2 before the core (a
    /// multiplication and a compare; p, its compare and the ramp's division only near rest):
    /// `Friction::<f32, Best>::tangential_prepared` 147 (146 with the former ramp by the ℓ¹
    /// slip speed); the full `Contact::wrench` 188 (184), the varying one 516 (521), the
    /// Jacobian 1,587 (1,542) — QEMU counts of the firmware's main binary (the benchmark's
    /// slips are all outside the ramp, δ = 0).
    #[inline(always)]
    pub fn tangential(
        &self,
        k: &Constants<T>,
        a: T,
        n: T,
        slip: Slip<T>,
    ) -> Tangential<T, L::Branch> {
        self.tangential_with(PerCall(k), true, a, n, slip)
    }

    /// [`Friction::tangential`] with the law's per-contact form `p` (from
    /// [`FrictionLaw::prepare`]): the call a contact of fixed shape makes every step.
    #[inline(always)]
    pub fn tangential_prepared(
        &self,
        p: &L::Prepared<T>,
        a: T,
        n: T,
        slip: Slip<T>,
    ) -> Tangential<T, L::Branch> {
        self.tangential_with(PerContact(p), true, a, n, slip)
    }

    /// The per-step call with the core `core`; `clamp = false` (a constant at every call site)
    /// is for a caller that guarantees a ≥ 0 and N ≥ 0, neither NaN (the patch of a
    /// [`crate::normal::NormalLaw::NON_NEGATIVE`] law), where the clamps change nothing.
    ///
    /// The core is a trait call (inlined), not a closure: a closure holding `best`'s core was
    /// left out of line, with the slip state passed through memory.
    #[inline(always)]
    pub(crate) fn tangential_with(
        &self,
        core: impl Core<T, L>,
        clamp: bool,
        a: T,
        n: T,
        slip: Slip<T>,
    ) -> Tangential<T, L::Branch> {
        // `x > 0` is false for NaN: both clamps map NaN to 0.
        let a = if !clamp || a > T::ZERO { a } else { T::ZERO };
        let mut fn_ = if !clamp || n > T::ZERO {
            self.f * n
        } else {
            T::ZERO
        };
        let (aw, s) = SlipState::scale_of(slip, a);
        // The ramp min(1, p/(c·δ)) by the law's own dissipation per unit fN,
        // p = −(F·v_P + T_z·ω)/(fN), c = 3/8: in the state's units p/(c·s) = −t·(x, y, w)·(8/3)
        // and δ/s = d. p/(c·s) > P_FLOOR, so δ ≤ P_FLOOR·s (δ well below the slip scale, the
        // common case) skips it; gated on s before the division (one multiplication and a
        // compare; d is not formed at all when the core ignores it, as `best`'s does).
        let near = L::RAMP_BELOW_DELTA && self.delta > s * T::from_f64(P_FLOOR);
        let state = SlipState::from_scale(slip, aw, s, self.delta);
        let (t, branch) = core.eval(&state);
        if near {
            fn_ = ramped(fn_, &t, &state, s, self.delta);
        }
        Tangential {
            fx: fn_ * t.fx,
            fy: fn_ * t.fy,
            tz: fn_ * (a * t.tz),
            branch,
        }
    }
}

/// A law's dimensionless core with what it reads besides the slip state (for
/// [`Friction::tangential_with`]).
pub(crate) trait Core<T: Real, L: FrictionLaw> {
    /// [`FrictionLaw::traction`] or [`FrictionLaw::traction_prepared`].
    fn eval(self, s: &SlipState<T>) -> (Traction<T>, L::Branch);
}

/// The per-call core: [`FrictionLaw::traction`] on the shape's constants.
pub(crate) struct PerCall<'a, T>(pub(crate) &'a Constants<T>);

/// The per-contact core: [`FrictionLaw::traction_prepared`] on the law's prepared form.
pub(crate) struct PerContact<'a, T: Real, L: FrictionLaw>(pub(crate) &'a L::Prepared<T>);

impl<T: Real, L: FrictionLaw> Core<T, L> for PerCall<'_, T> {
    #[inline(always)]
    fn eval(self, s: &SlipState<T>) -> (Traction<T>, L::Branch) {
        L::traction(self.0, s)
    }
}

impl<T: Real, L: FrictionLaw> Core<T, L> for PerContact<'_, T, L> {
    #[inline(always)]
    fn eval(self, s: &SlipState<T>) -> (Traction<T>, L::Branch) {
        L::traction_prepared(self.0, s)
    }
}

/// 1/c: the ramp ends at p = c·δ, c = 3/8 = min C over every patch shape (C = (3/8)E(e²),
/// the pure-spin torque), so that a sticking contact keeps every slip component below δ:
/// |v_P| ≤ p < 3δ/8 and a|ω| ≤ p/C < δ (see [`FrictionLaw::RAMP_BELOW_DELTA`]).
pub(crate) const RAMP_GAIN: f64 = 8.0 / 3.0;

/// A lower bound of p/(c·s), the ramp's variable over its width and the ℓ¹ slip scale, for the
/// exact law (and `best`, within 1e-4 of it): p ≥ |v_P| (Jensen: the pressure-weighted mean of
/// |v_M| is at least the norm of the mean v_P) and p ≥ C·a|ω| (p is convex and even in v_P,
/// smallest at v_P = 0, where it is C·a|ω|, C ≥ 3/8); with s ≤ √2|v_P| + a|ω| this gives
/// p/s ≥ C/(1 + √2·C) ≥ 0.245, p/(c·s) ≥ 0.65. Taken as 1/2: where δ ≤ s/2, p > c·δ and the
/// ramp does not act (the gate, before the core's division: one multiplication, a compare).
pub(crate) const P_FLOOR: f64 = 0.5;

/// fN·min(1, p/(c·δ)): the ramp below c·δ, from the state's units (p/(c·s) =
/// −(t_x·x + t_y·y + t_z·w)·(8/3), times the state's scale s: p/c against δ; five
/// multiplications, two additions, a compare, a division), only where δ > [`P_FLOOR`]·s.
/// Inline, and without the state's d = δ/s (which `best`'s core does not read, so the common
/// path does not form it): out of line and with d, it cost 15 M4F instructions per
/// `Contact::wrench` on the common path (199 against 184 for the former ramp; now 188). p is
/// clamped at 0 (a rounding below 0 must not reverse the force), so the factor lies in [0, 1].
/// Where s is not a normal number (a slip below 1.2e-38 m/s in f32, 2.2e-308 in f64) the state
/// is scaled by the largest component m instead (`SlipState`), and p·s/m over-states the
/// factor by s/m ≤ 3: still in [0, 1], passive, and ≤ 3.6e-38/δ (f32) in absolute terms.
#[inline(always)]
fn ramped<T: Real>(fn_: T, t: &Traction<T>, st: &SlipState<T>, s: T, delta: T) -> T {
    // p/(c·s) in the state's units; the factor p/(c·δ) = (p/(c·s))·s/δ.
    let p = -(t.fx * st.x() + t.fy * st.y() + t.tz * st.w()) * T::from_f64(RAMP_GAIN);
    let r = p * s;
    if delta > r {
        fn_ * (larger(r, T::ZERO) / delta)
    } else {
        fn_
    }
}

/// An explicit one-step integrator, for [`Friction::stable_step`]: its stability limit on the
/// real axis, the largest h·k for which y' = −k·y decays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Explicit {
    /// Forward Euler, y ← (1 − hk)·y: decays for hk < 2; oscillates (changes sign every step)
    /// for hk > 1.
    Euler,
    /// Classic fourth-order Runge–Kutta: decays for hk < 2.785 (the real root of
    /// |1 − x + x²/2 − x³/6 + x⁴/24| = 1).
    Rk4,
}

impl Explicit {
    /// The real-axis stability limit h·k: 2 (Euler), 2.7852935634 (RK4).
    pub const fn limit(self) -> f64 {
        match self {
            Explicit::Euler => 2.0,
            Explicit::Rk4 => 2.785_293_563_405_282,
        }
    }
}

/// m·δ/(fN)·limit: the stable explicit step of a mass on a ramp of slope fN/δ (see
/// [`Friction::stable_step`] for the edge cases). Total.
pub(super) fn ramp_step<T: Real>(f: T, delta: T, mass: T, n: T, scheme: Explicit) -> T {
    let fn_ = f * n;
    // `x > 0` is false for NaN: NaN mass → 0, NaN fN → MAX.
    match (mass > T::ZERO, fn_ > T::ZERO) {
        (false, _) => T::ZERO,
        (true, false) => T::MAX,
        (true, true) => {
            let h = T::from_f64(scheme.limit()) * mass * delta / fn_;
            if h.is_finite() { h } else { T::MAX }
        }
    }
}

impl<T: Real, L: FrictionLaw> Friction<T, L> {
    /// The largest stable step of an explicit `scheme` for the slip v_P of a body of effective
    /// mass `mass` (kg) under this law at normal force `n` (N), for the patch shape `k`:
    /// h* = limit·m·δ/(κ·fN), κ = [`FrictionLaw::slip_ramp`] (limit 2 for Euler, 2.785 for
    /// RK4, [`Explicit::limit`]). One signature for every law; from a built contact:
    /// [`Contact::stable_step`](crate::contact::Contact::stable_step).
    ///
    /// | law | κ |
    /// |---|---|
    /// | `Coulomb`, `Simplified` | 1 (the ramp F = −fN·v_P/δ) |
    /// | `Best` (default) | [`ramp_stiffness`](super::best::ramp_stiffness)`(k)`: 3.205 for a circle, 3.755 at e² = 0.9, 5.317 at 0.99 |
    /// | `Pade`, `Ellipsoid`, `Exact` | none: they ignore δ (Coulomb's sign law at rest) → 0 |
    ///
    /// # The effective mass
    ///
    /// `mass` is the mass that the friction force accelerates **at the contact point**, not the
    /// body's mass: a force F at P changes the slip at the rate F·(1/m + r²/I) for a body of
    /// mass m and moment of inertia I about the axis through its centre perpendicular to the
    /// lever r = |P − G| and to F. So m_eff = 1/(1/m + r²/I); for a solid ball rolling on its
    /// surface (r = R, I = (2/5)mR²) **m_eff = 2m/7**, and using m overstates the stable step by
    /// 3.5×. When both bodies move, add their 1/m_eff. A body held fixed contributes nothing.
    ///
    /// # Why
    ///
    /// Below the regularization speed δ the law is a ramp: the stiffness −∂F/∂v_P is κ·fN/δ
    /// at most, so v_P obeys v′ = −k·v with k ≤ κ·fN/(mδ), and an explicit step must keep h·k
    /// under the scheme's limit. Past h* the slip is not damped but kept oscillating at
    /// amplitude ≈ δ (bounded: the law saturates at fN); Euler already flips sign every step
    /// past h*/2. The step shrinks ∝ δ: as δ → 0 the law becomes Coulomb's sign law, for which
    /// no explicit step is stable. `simplified`'s spin only widens its ramp (width aω/A, aω/B
    /// where that exceeds δ), so κ = 1 holds for every ω. `best`'s core ignores δ; the wrapper
    /// ramps it below its own dissipation p < 3δ/8 ([`FrictionLaw::RAMP_BELOW_DELTA`]); the
    /// stiffness there is fN/δ times a symmetric positive semidefinite matrix that depends on
    /// the slip direction and spin ratio only, largest (κ) in between rest with spin
    /// ((8/3)·C·diag(A, B)) and pure translation (8/3), derivation in [`ramp_stiffness`](super::best::ramp_stiffness). So h* holds
    /// for every slip direction and every fixed spin; it is conservative by the ratio of κ to
    /// the stiffness where a given motion settles. The spin has its own limit,
    /// [`Friction::stable_spin_step`]. Not covered: the coupling of translation and spin when
    /// both move.
    ///
    /// # Edge cases and accuracy
    ///
    /// δ = 0 → 0 (no stable explicit step); `mass` ≤ 0 or NaN → 0; fN ≤ 0 or NaN (no contact
    /// or f = 0) → `T::MAX` (friction sets no limit); an overflowing quotient → `T::MAX`; a law
    /// without a ramp → 0 (where friction acts). Measured by integrating a block under the law
    /// and bisecting the step at which its velocity stops decaying (`host-tests/stability.rs`;
    /// `examples/stability.rs` → `docs/report/stability/coulomb_step.csv`, `best_step.csv`):
    /// `coulomb` and `simplified` agree with h* to 0.02 % for δ from 1e-2 to 1e-6 m/s, both
    /// schemes; for `best` (e² ∈ {0, 0.5, 0.9, 0.99}, ψ ∈ {0, π/8, π/4, π/2} plus the
    /// derivation's stiffest slip, aω/δ ∈ {0, 0.3, 1, 3}, both schemes) every measured step is
    /// ≥ h* and the stiffest case's within 0.4 % of it; a given case is looser by κ over its own
    /// stiffness (up to 6.4× h* in the test: circle, aω = 3δ). Cost: a division, plus
    /// [`ramp_stiffness`](super::best::ramp_stiffness) for `best` (construction/host use).
    pub fn stable_step(&self, k: &Constants<T>, mass: T, n: T, scheme: Explicit) -> T {
        match L::slip_ramp(k) {
            Some(kappa) => ramp_step(self.f * kappa, self.delta, mass, n, scheme),
            None => no_ramp_step(self.f, mass, n),
        }
    }
}

/// The step for a law with no ramp: 0 where friction acts, `T::MAX` where it does not
/// (fN ≤ 0 or NaN), 0 for an invalid `mass` (as [`ramp_step`]). Total.
pub(super) fn no_ramp_step<T: Real>(f: T, mass: T, n: T) -> T {
    // `x > 0` is false for NaN: NaN mass → 0, NaN fN → MAX.
    match (mass > T::ZERO, f * n > T::ZERO) {
        (true, false) => T::MAX,
        _ => T::ZERO,
    }
}

/// The branch of the laws with one smooth formula ([`crate::friction::Pade`],
/// [`crate::friction::Ellipsoid`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Smooth {
    /// No slip: zero traction.
    Rest,
    /// Slipping: the law's single formula.
    Slip,
}
