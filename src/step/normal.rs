//! Step 5 of the step-aware wrench: the normal force made consistent with the friction the
//! projections left, at the end state that friction produces.
//!
//! # Why
//!
//! The linear solve (steps 0–2 of the [module docs](super)) returns N̄ together with the
//! friction pair it solved for. Steps 3 and 4 then change the friction (into the limit set, to
//! no power) while N̄ stays. When W couples the normal row to the friction rows (w_nx, w_ny,
//! w_nω ≠ 0: a contact point off the body's centre of mass, as on a rattleback or a tippe top),
//! the friction impulse moves the end approach h⁺ = h_free − γ·Δt²·(W·w̄)_n, and N̄ is then no
//! longer the normal law's value there. Measured before this step (random bodies with the
//! contact point 0.5–3 R off the centre, `host-tests/step_normal.rs`): N̄ off the law at the
//! returned end state by up to 100 % (the body above the plane at the end of the step while
//! N̄ > 0) on most steps where the limit set acted; the plugin for MuJoCo saw N = 4.2 N
//! returned where the end approach gave 65 N (rolling rattleback, 1 ms).
//!
//! # The re-solve
//!
//! Per active contact i, with every other row of w̄ fixed and its own friction following N as
//! a point on the boundary of the limit set does (held fixed instead if that makes the row's
//! response to N non-positive), the end approach h⁺ falls linearly with N:
//! h⁺ = h₀ − c·N, c = γ·Δt²·(W_nn + (W_nF·F + W_nω·ρ·T_z)/N̄) > 0, h₀ the end approach at
//! N = 0. The limit set at N is N·diag(1, 1, a(N))·C₁ for the Contensou laws on a Hertz patch
//! (their full-slip force is fN times, their torque fNa times, a function of the slip's
//! direction aω/|v| only), so the force scales with N/N̄ and the torque with (N/N̄)·ρ,
//! ρ = a(N)/a(N̄) = (N/N̄)^{1/3}: a pair on the boundary at N̄ is on it at N, and a pair inside
//! stays inside. ρ is taken at the Hertz model's root (below) and from below (`cbrt_below`:
//! Newton steps on t³ = r, then r/t²), so that the torque never leaves the set by it. (With the
//! torque scaled as N alone, a torque at a falling N lay outside the set by (N̄/N)^{1/3}: the
//! friction then moved at every follow round below, and N with it, never settling on the
//! states where the slip reverses within the step.) N is found through h⁺, the root of
//!
//! ```text
//! ψ(h) = N_law(h, ḣ⁺(h)) − (h₀ − h)/c,   ḣ⁺(h) = −(u_free,n + drift_n + (h_free − h)/(γ·Δt))
//! ```
//!
//! increasing in h on [0, h₀] (N_law grows with h and ḣ), ψ(0) < 0 ≤ ψ(h₀). The start is the
//! root of the Hertz model k̂·h^{3/2} = (h₀ − h)/c through a known point of the law
//! ([`MODEL_STEPS`] arithmetic Newton steps in √h, no wrench call); then [`NORMAL_STEPS`]
//! Newton steps on ψ with dψ/dh ≈ (3/2)·N_law/h + 1/c, kept inside the bracket (bisection when
//! a step leaves it; one wrench call each). N = (h₀ − h)/c at the best h: its end approach is
//! that h exactly, and N differs from the law there by |ψ| only. (Regula falsi on N itself
//! stalled: at 1 ms the law spans 10⁴ between the bracket's ends.) It runs only when
//! |N̄ − N_law(h⁺)| > [`NORMAL_TOLERANCE`]·N̄ (one wrench call otherwise). Then the friction
//! follows the new N: into the limit set at the new N, to no power at the new u⁺ (step 4's
//! scaling), and, while that changes the friction, N is re-solved again and the friction
//! follows again, [`FOLLOW_ROUNDS`] rounds at most (the limit set and the power last: they
//! are the hard constraints). A
//! contact whose N falls to 0 (its end approach ≤ 0 even without a normal force) leaves the
//! active set with its friction. For K contacts, [`NORMAL_SWEEPS`] Gauss–Seidel sweeps over
//! them (the second only when the first changed an N and K > 1).
//!
//! # Cost and measured consistency
//!
//! One wrench call per active contact on a step where N̄ is already consistent; at most
//! NORMAL_SWEEPS·FOLLOW_ROUNDS·(NORMAL_STEPS + 2 + the limit set's
//! [`super::project::PATCH_STEPS`] + 5) = 76 wrench calls per contact otherwise (the second
//! round only while the friction still moves: rare, see [`FOLLOW_ROUNDS`]), and
//! [`MODEL_STEPS`] + [`CBRT_STEPS`] arithmetic Newton steps per re-solve.
//! Measured (`host-tests/step_normal.rs`, 3 × 3000 random states, ≈ 2530 in contact each; N
//! against the law at the returned h⁺, ḣ⁺): off by more than 1e-3 before / after this step on
//! 1218 / 0 (`best`, worst after 9.83e-4), 1111 / 0 (`coulomb`, 9.96e-4) and 1179 / 0 (`best`
//! with Hunt–Crossley damping, 9.98e-4) states. (With the torque scaled as N alone: 4 / 0 / 5
//! left after 4 rounds, up to 100 % off, N > 0 with the body apart at the end, all with the
//! slip reversing within the step.)

use super::{Flags, Free, InverseMass, Part, injects_total, scale_part};
use crate::Real;
use crate::friction::Slip;
use crate::friction::rolling::RollingVelocity;
use crate::jacobian::{Jacobian, Linearize, State};

/// Newton steps (bracketed) of the normal re-solve on its end approach: one wrench call each.
pub const NORMAL_STEPS: usize = 8;

/// The relative residual |N̄ − N_law(h⁺, ḣ⁺)| / N̄ above which the normal force is re-solved.
pub const NORMAL_TOLERANCE: f64 = 1e-3;

/// Rounds of (the friction follows N, N re-solved at that friction) after a contact's first
/// re-solve; they stop as soon as the friction no longer moves. A fixed-point iteration: near
/// a contact whose friction lifts the body almost as much as N pushes it (W_nf·f ≈ −W_nn·N),
/// a friction the limit set moves at the new N moves N again. Measured on
/// `host-tests/step_normal.rs`'s 2 × 3000 `best` states (undamped / damped): N off the law by
/// more than 1e-3 after 1 round on 3 / 6 states, after 2 on 0 / 0 (before the torque followed
/// the patch, ρ: 18 / 17 after 2 rounds, 4 / 5 after 4, 1 / 2 after 8).
pub const FOLLOW_ROUNDS: usize = 2;

/// Gauss–Seidel sweeps over the contacts (the second only when K > 1 and an N changed).
pub const NORMAL_SWEEPS: usize = 2;

/// One contact's normal row: everything the residual needs.
struct Row<'a, T: Real> {
    contact: &'a dyn Linearize<T>,
    free: &'a Free<T>,
    dt: T,
    gamma: T,
    /// h⁺ at N = 0: h_free − γ·Δt²·c₀.
    h0: T,
    /// γ·Δt²·W_nn (the end approach's fall per newton of N).
    c: T,
    slip: Slip<T>,
    rolling: RollingVelocity<T>,
}

impl<T: Real> Row<'_, T> {
    /// The normal force whose end approach is `h`: (h₀ − h)/c.
    fn n_of(&self, h: T) -> T {
        (self.h0 - h) / self.c
    }

    /// N_law at the end approach `h` (ḣ⁺ from the same impulse); 0 when apart or not finite.
    fn law(&self, h: T) -> T {
        if !(h > T::ZERO) {
            return T::ZERO;
        }
        // (W·w̄)_n = (h_free − h)/(γ·Δt²): u⁺_n = u_free,n + drift_n + Δt·(W·w̄)_n.
        let un = self.free.u[0] + self.free.drift[0] + (self.free.h - h) / (self.gamma * self.dt);
        let s = State {
            h,
            hdot: -un,
            slip: self.slip,
            rolling: self.rolling,
        };
        let v = self.contact.wrench4(&s)[0];
        if v > T::ZERO && v.is_finite() {
            v
        } else {
            T::ZERO
        }
    }
}

/// Re-solves contact i's N with every other row fixed (module docs). Returns true if N
/// changed; `wbar` and `u_end` are updated.
#[allow(clippy::too_many_arguments)]
fn resolve<T: Real, const K: usize>(
    contact: &dyn Linearize<T>,
    dt: T,
    gamma: T,
    w: &InverseMass<T, K>,
    free: &Free<T>,
    rolling: RollingVelocity<T>,
    i: usize,
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
) -> bool {
    let (Some(wi), Some(ui)) = (wbar.get(i).copied(), u_end.get(i).copied()) else {
        return false;
    };
    let n = wi[0];
    if !(n > T::ZERO) {
        return false;
    }
    // The friction's part of (W·w̄)_n, per newton of N: the force's (s_F) and the drilling
    // torque's (s_T). The friction follows N as a boundary point of the limit set does
    // (module docs): the force ∝ N, the torque ∝ N·ρ with ρ = a(N)/a(N̄) the patch's growth
    // — unless that would make the row's response to N non-positive (then the friction is
    // held fixed).
    let wnn = w.get(4 * i, 4 * i);
    let sf = (w.get(4 * i, 4 * i + 1) * wi[1] + w.get(4 * i, 4 * i + 2) * wi[2]) / n;
    let st = w.get(4 * i, 4 * i + 3) * wi[3] / n;
    let g = gamma * dt * dt;
    // h⁺ with contact i's N and friction removed; at N = N̄ (ρ = 1) the current end approach.
    let rest = w.row_times(4 * i, wbar) - (wnn + sf + st) * n;
    let scaled = g * (wnn + sf + st) > T::ZERO && g * (wnn + sf) > T::ZERO;
    let (h0, c1) = if scaled {
        (free.h - g * rest, g * (wnn + sf + st))
    } else {
        (free.h - g * (rest + (sf + st) * n), g * wnn)
    };
    if !(c1 > T::ZERO) || !c1.is_finite() {
        return false;
    }
    let mut row = Row {
        contact,
        free,
        dt,
        gamma,
        h0,
        c: c1,
        slip: Slip::or_rest(ui[1], ui[2], ui[3]),
        rolling,
    };
    // ψ(h) = N_law(h) − N(h), increasing in h; ψ(0) = −h₀/c < 0, ψ(h₀) = N_law(h₀) ≥ 0.
    let hn = row.h0 - c1 * n;
    let law_n = row.law(hn);
    let psi_n = law_n - n;
    if !(psi_n.abs() > T::from_f64(NORMAL_TOLERANCE) * n) {
        return false;
    }
    // The patch's growth ρ, from the Hertz model's root through a known point of the law (N
    // ∝ a³ on a Hertz patch: ρ = (N/N̄)^{1/3}, by `cbrt_below`, never above it: a torque on
    // the boundary at N̄ stays inside the set at N), and the row's compliance with it.
    let mut rho = T::ONE;
    let (hk, lk) = if hn > T::ZERO && law_n > T::ZERO {
        (hn, law_n)
    } else if row.h0 > T::ZERO {
        (row.h0, row.law(row.h0))
    } else {
        (row.h0, T::ZERO)
    };
    if scaled && wi[3] != T::ZERO && lk > T::ZERO && row.h0 > T::ZERO {
        let k = lk / (hk * hk.sqrt());
        let m = model_root(k * c1, row.h0);
        let nm = row.n_of(m);
        if nm > T::ZERO && nm.is_finite() {
            rho = cbrt_below(nm / n);
            let c = g * (wnn + sf + st * rho);
            if c > T::ZERO && c.is_finite() {
                row.c = c;
            } else {
                rho = T::ONE;
            }
        }
    }
    let c = row.c;
    let x = if row.h0 > T::ZERO {
        let (mut a, mut b) = (T::ZERO, row.h0);
        // The start: the root of the Hertz model N = k̂·h^{3/2} through the known point of the
        // law (h⁺ of N̄ if the contact is closed there, else h₀), then Newton's steps on the law.
        // (With ρ ≠ 1 the row's c changed: ψ at h⁺ of N̄ is then only known in sign when the
        // torque's share is small, so the bracket is narrowed only for ρ = 1.)
        if hk == hn && rho == T::ONE {
            if psi_n > T::ZERO {
                b = hn;
            } else {
                a = hn;
            }
        }
        let mut x = hk;
        if lk > T::ZERO {
            let k = lk / (hk * hk.sqrt());
            let m = model_root(k * c, row.h0);
            if m > a && m < b {
                x = m;
            }
        }
        let mut law_x = if x == hk { lk } else { row.law(x) };
        // The best end approach so far (smallest |ψ|): N is returned as N(h) there, so that
        // the end approach of the returned N is exactly that h and the law's value there
        // differs from N by |ψ| only (returning N_law(h) would move h by c·ψ, and the law
        // with it by (3/2)·N·c/h·ψ: orders of magnitude more at a stiff step).
        let (mut best, mut best_psi) = (x, (law_x - row.n_of(x)).abs());
        for _ in 0..NORMAL_STEPS {
            let psi = law_x - row.n_of(x);
            if psi.abs() < best_psi {
                best = x;
                best_psi = psi.abs();
            }
            if psi == T::ZERO {
                break;
            }
            if psi > T::ZERO {
                b = x;
            } else {
                a = x;
            }
            // dψ/dh ≈ (3/2)·N/h + 1/c: Hertz's exponent (the damping's share left out; the
            // bracket keeps the step safe for any law).
            let d = T::from_f64(1.5) * law_x / x + T::ONE / c;
            let mut next = x - psi / d;
            if !(next > a && next < b) {
                next = T::HALF * (a + b);
            }
            if next == x {
                break;
            }
            x = next;
            law_x = row.law(x);
        }
        if (law_x - row.n_of(x)).abs() < best_psi {
            best = x;
        }
        row.n_of(best).max(T::ZERO)
    } else {
        T::ZERO
    };
    // N(h) = (h₀ − h)/c overflows when h₀ is near the float's largest value and c is tiny
    // (its rounding alone, ulp(h₀)/c, is then beyond range): N̄ is kept, as finite as the
    // linear solve left it.
    if !x.is_finite() {
        return false;
    }
    // N to x; the friction with it if it was modelled as scaling with N (the torque with the
    // patch's growth ρ as well).
    let (kf, kt) = if scaled {
        (x / n - T::ONE, x / n * rho - T::ONE)
    } else {
        (T::ZERO, T::ZERO)
    };
    let d = [x - n, wi[1] * kf, wi[2] * kf, wi[3] * kt];
    add(dt, w, i, d, wbar, u_end)
}

/// Newton steps on the Hertz model's end approach (arithmetic only, no wrench call).
pub const MODEL_STEPS: usize = 24;

/// The root h of k·c·h^{3/2} = h₀ − h (the Hertz model of the normal row, kc = k·c > 0,
/// h₀ > 0): with s = √h, kc·s³ + s² − h₀ = 0, convex and increasing in s ≥ 0, by
/// [`MODEL_STEPS`] Newton steps from s = √h₀ (monotone from the right; the stiff end, where
/// kc·s³ dominates, shrinks s by 2/3 per step before the quadratic phase).
fn model_root<T: Real>(kc: T, h0: T) -> T {
    let mut s = h0.sqrt();
    for _ in 0..MODEL_STEPS {
        let f = (kc * s + T::ONE) * s * s - h0;
        let d = (T::from_f64(3.0) * kc * s + T::TWO) * s;
        if !(f > T::ZERO) || !(d > T::ZERO) {
            break;
        }
        s -= f / d;
    }
    s * s
}

/// Newton steps of the re-solve's cube root from below (`cbrt_below`: the patch's growth ρ).
pub const CBRT_STEPS: usize = 12;

/// A lower bound of r^{1/3} (r > 0; 1 otherwise), tight to rounding for r within
/// [1e-9, 1e9]: [`CBRT_STEPS`] Newton steps on t³ = r from t₀ = r^{1/4} (every step's
/// t = (2t + r/t²)/3 ≥ r^{1/3} by the arithmetic–geometric mean inequality), then r/t² ≤ r^{1/3}.
fn cbrt_below<T: Real>(r: T) -> T {
    if !(r > T::ZERO) || !r.is_finite() {
        return T::ONE;
    }
    let mut t = r.sqrt().sqrt();
    for _ in 0..CBRT_STEPS {
        t = (t + t + r / (t * t)) / T::from_f64(3.0);
    }
    let b = r / (t * t);
    if b > T::ZERO && b.is_finite() {
        b
    } else {
        T::ONE
    }
}

/// Adds `d` to contact i's wrench and Δt·W·d to every end velocity, all or nothing: false (and
/// nothing changed) when a sum is not finite — far outside the physical range, where N(h) or the
/// friction scaled with it overflows the float, the step keeps what it had.
fn add<T: Real, const K: usize>(
    dt: T,
    w: &InverseMass<T, K>,
    i: usize,
    d: [T; 4],
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
) -> bool {
    let mut delta = [[T::ZERO; 4]; K];
    let mut wi = match (delta.get_mut(i), wbar.get(i)) {
        (Some(di), Some(&wi)) => {
            *di = d;
            wi
        }
        _ => return false,
    };
    for c in 0..4 {
        wi[c] += d[c];
    }
    let mut u = *u_end;
    for (j, uj) in u.iter_mut().enumerate() {
        for (a, x) in uj.iter_mut().enumerate() {
            *x += dt * w.row_times(4 * j + a, &delta);
        }
    }
    let finite = wi.iter().chain(u.iter().flatten()).all(|x| x.is_finite());
    if finite {
        if let Some(slot) = wbar.get_mut(i) {
            *slot = wi;
        }
        *u_end = u;
    }
    finite
}

/// The friction of contact i after its N changed: into the limit set at the new N (the
/// re-solve scaled it with N), then to no power at the new u⁺ (step 4's scaling). Returns
/// true if the friction changed.
#[allow(clippy::too_many_arguments)]
fn follow<T: Real, const K: usize>(
    contact: &dyn Linearize<T>,
    lin: &State<T>,
    jac: &Jacobian<T>,
    dt: T,
    w: &InverseMass<T, K>,
    free: &[Free<T>; K],
    coupled: bool,
    i: usize,
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
    flags: &mut Flags,
) -> bool {
    let Some(before) = wbar.get(i).copied() else {
        return false;
    };
    if !(before[0] > T::ZERO) {
        // Apart at the end of the step: no normal force, no friction.
        let d = [-before[0], -before[1], -before[2], -before[3]];
        if !add(dt, w, i, d, wbar, u_end) {
            return false;
        }
        flags.active = false;
        return before[1] != T::ZERO || before[2] != T::ZERO || before[3] != T::ZERO;
    }
    let mut p = before;
    if super::project::into_limit_set(contact, lin, jac.value[0], &mut p) {
        let d = [
            p[0] - before[0],
            p[1] - before[1],
            p[2] - before[2],
            p[3] - before[3],
        ];
        if add(dt, w, i, d, wbar, u_end) {
            flags.limited = true;
        }
    }
    if !coupled || injects_total(dt, w, free, i, wbar, u_end) {
        if scale_part(dt, w, i, Part::Force, wbar, u_end) {
            flags.force_scaled = true;
        }
        if scale_part(dt, w, i, Part::Torque, wbar, u_end) {
            flags.torque_scaled = true;
        }
    }
    // No closure indexing here: at opt-level z it would keep a bounds check (a panic path,
    // tools/no-panic.sh).
    match wbar.get(i) {
        Some(&[_, fx, fy, tz]) => fx != before[1] || fy != before[2] || tz != before[3],
        None => false,
    }
}

/// Step 5 (module docs): every active contact's N re-solved at the end state of its final
/// friction, the friction following. `coupled[i]`: contact i rolls (its power gate is the sum
/// of force and torque, as in step 4).
#[allow(clippy::too_many_arguments)]
pub(super) fn settle<T: Real, const K: usize>(
    contacts: [&dyn Linearize<T>; K],
    dt: T,
    gamma: T,
    w: &InverseMass<T, K>,
    states: &[State<T>; K],
    free: &[Free<T>; K],
    lin: &[State<T>; K],
    jac: &[Jacobian<T>; K],
    coupled: &[bool; K],
    active: &mut [bool; K],
    wbar: &mut [[T; 4]; K],
    u_end: &mut [[T; 4]; K],
    flags: &mut [Flags; K],
) {
    for sweep in 0..NORMAL_SWEEPS {
        if sweep > 0 && K == 1 {
            break;
        }
        let mut changed = false;
        for i in 0..K {
            if !active[i] {
                continue;
            }
            let rolling = states[i].rolling;
            let c = contacts[i];
            if !resolve(c, dt, gamma, w, &free[i], rolling, i, wbar, u_end) {
                continue;
            }
            changed = true;
            flags[i].normal_resolved = true;
            // The friction follows; while it moves, N again and the friction again.
            let mut moved = true;
            for round in 0..FOLLOW_ROUNDS {
                if round > 0 {
                    if !(moved && flags[i].active) {
                        break;
                    }
                    resolve(c, dt, gamma, w, &free[i], rolling, i, wbar, u_end);
                }
                moved = follow(
                    c,
                    &lin[i],
                    &jac[i],
                    dt,
                    w,
                    free,
                    coupled[i],
                    i,
                    wbar,
                    u_end,
                    &mut flags[i],
                );
            }
            active[i] = flags[i].active;
        }
        if !changed {
            break;
        }
    }
}
