//! The dimensional wrapper of [`crate::friction::Friction::tangential_with`] lane by lane:
//! fN, the ramp below δ, the homogeneous slip state ([`crate::friction::SlipState`]) and the
//! scaling of the dimensionless traction back to N and N·m. Mirrors the scalar code operation
//! for operation (see each function).

use super::lanes::Lanes;
use crate::Real;

/// The slip state (x, y, w, d) = (v_Px, v_Py, aω, δ)/s of a few contacts.
#[derive(Clone, Copy, Debug)]
pub struct State<V> {
    pub x: V,
    pub y: V,
    pub w: V,
    pub d: V,
}

impl<V: Lanes> State<V> {
    /// Lane by lane `if m { a } else { b }`.
    #[inline(always)]
    fn select(m: V::Mask, a: Self, b: Self) -> Self {
        State {
            x: V::select(m, a.x, b.x),
            y: V::select(m, a.y, b.y),
            w: V::select(m, a.w, b.w),
            d: V::select(m, a.d, b.d),
        }
    }
}

/// The dimensionless traction F/(fN), T_z/(fNa) of a few contacts.
#[derive(Clone, Copy, Debug)]
pub struct Tr<V> {
    pub fx: V,
    pub fy: V,
    pub tz: V,
}

impl<V: Lanes> Tr<V> {
    /// `Traction::default()`: +0 everywhere.
    #[inline(always)]
    pub(crate) fn zero() -> Self {
        let z = V::splat(V::T::ZERO);
        Tr {
            fx: z,
            fy: z,
            tz: z,
        }
    }

    /// Lane by lane `if m { a } else { b }`.
    #[inline(always)]
    pub(crate) fn select(m: V::Mask, a: Self, b: Self) -> Self {
        Tr {
            fx: V::select(m, a.fx, b.fx),
            fy: V::select(m, a.fy, b.fy),
            tz: V::select(m, a.tz, b.tz),
        }
    }
}

/// The dimensional friction of a few contacts: (fN, a, state) in, (F_x, F_y, T_z) out.
#[derive(Clone, Copy, Debug)]
pub struct Scaled<V> {
    /// fN (the ramp below δ comes after the core: [`ramp`]).
    pub fn_: V,
    /// The ℓ¹ slip scale s = |v_Px| + |v_Py| + a|ω| (the ramp's gate and scale).
    pub s: V,
    /// The slip state.
    pub state: State<V>,
}

/// `Friction::tangential_with(core, clamp = false, a, n, slip)` up to the core: a ≥ 0 and
/// N ≥ 0 (the patch of a non-negative normal law, so no clamp), [f, δ] splatted, the slip
/// [v_Px, v_Py, ω].
#[inline(always)]
pub(crate) fn scaled<V: Lanes>(
    [f, delta]: [V; 2],
    a: V,
    n: V,
    [vx, vy, omega]: [V; 3],
) -> Scaled<V> {
    let fn_ = f * n;
    // SlipState::from_clamped: aω, then s = |vx| + |vy| + |aω|.
    let aw = a * omega;
    let s = vx.abs() + vy.abs() + aw.abs();
    Scaled {
        fn_,
        s,
        state: divided(vx, vy, aw, s, delta),
    }
}

/// The ramp of `Friction::tangential_with` after the core (a law with `RAMP_BELOW_DELTA`), the
/// same arithmetic: where δ > `P_FLOOR`·s and δ > r, r = −(t_x·x + t_y·y + t_z·w)·`RAMP_GAIN`·s
/// (p/c), fN·(max(r, 0)/δ) (`ramped`); fN unchanged elsewhere or without a ramp.
#[inline(always)]
pub(crate) fn ramp<V: Lanes>(ramp: bool, sc: &Scaled<V>, delta: V, t: &Tr<V>) -> V {
    let fn_ = sc.fn_;
    if !ramp {
        return fn_;
    }
    let floor = V::splat(V::T::from_f64(crate::friction::law::P_FLOOR));
    let near = delta.gt(sc.s * floor);
    if !V::any(near) {
        return fn_;
    }
    let st = &sc.state;
    let p = -(t.fx * st.x + t.fy * st.y + t.tz * st.w)
        * V::splat(V::T::from_f64(crate::friction::law::RAMP_GAIN));
    let r = p * sc.s;
    let zero = V::splat(V::T::ZERO);
    V::select(
        V::and(near, delta.gt(r)),
        fn_ * (r.larger(zero) / delta),
        fn_,
    )
}

/// `SlipState::divided`: by 1/s where s is a positive normal number, else (`unusual`) by the
/// largest magnitude, pure spin for an overflowed aω, or rest.
#[inline(always)]
fn divided<V: Lanes>(vx: V, vy: V, aw: V, s: V, delta: V) -> State<V> {
    let min_pos = V::splat(V::T::MIN_POSITIVE);
    let one = V::splat(V::T::ONE);
    // MIN_POSITIVE ≤ s ≤ MAX (s ≥ 0 or +∞ here: the inputs are finite).
    let normal = V::and(s.ge(min_pos), s.le(V::splat(V::T::MAX)));
    let inv = one / s;
    let common = State {
        x: vx * inv,
        y: vy * inv,
        w: aw * inv,
        d: (delta * inv).larger(min_pos),
    };
    if !V::any(V::not(normal)) {
        return common;
    }
    let unusual = unusual(vx, vy, aw, delta);
    State::select(normal, common, unusual)
}

/// `SlipState::unusual` with its three cases as masks.
/// Always inlined (like every kernel function): out of line it would be compiled without the
/// caller's vector features.
#[inline(always)]
fn unusual<V: Lanes>(vx: V, vy: V, aw: V, delta: V) -> State<V> {
    let zero = V::splat(V::T::ZERO);
    let one = V::splat(V::T::ONE);
    let min_pos = V::splat(V::T::MIN_POSITIVE);
    let m = vx.abs().larger(vy.abs()).larger(aw.abs());
    let infinite = V::not(aw.abs().le(V::splat(V::T::MAX)));
    let positive = m.gt(zero);
    let by_m = State {
        x: vx / m,
        y: vy / m,
        w: aw / m,
        d: (delta / m).larger(min_pos),
    };
    let rest = State {
        x: zero,
        y: zero,
        w: zero,
        d: min_pos,
    };
    let spin = State {
        x: zero,
        y: zero,
        w: one.copysign(aw),
        d: min_pos,
    };
    let by_m = State::select(positive, by_m, rest);
    State::select(infinite, spin, by_m)
}
