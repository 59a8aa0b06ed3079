//! The projections after the linear solve: the friction pair into the law's full-slip limit
//! set, and the power checks (force and drilling torque separately).
//!
//! # The limit set
//!
//! At normal force N the friction pair p = (F_x, F_y, T_z) of every law here lies in the
//! convex set C(N) whose boundary is the law's **full-slip** value: for a slip direction
//! s = (v_x, v_y, ω), p_fs(s) = lim_{λ→∞} w(λs). For the Contensou laws p_fs(s) is the point
//! of C extreme in the direction −s (maximal dissipation), so C = {p : −p·s ≤ −p_fs(s)·s ∀s}.
//! The projection tests the one supporting plane whose contact point has (nearly) p's
//! direction: with F_max = |F_fs| of a pure translation along p's force, T_max = |T_fs| of a
//! pure spin of p's sign and R̄ = T_max/F_max, the ellipsoidal dual s* = −(F_x, F_y, T_z/R̄²)
//! (exact for [`crate::friction::Ellipsoid`], close for the others), corrected once
//! (s₁ = dual(2p̂ − p̂_fs(s*)), normalised in the metric diag(1, 1, 1/R̄²): one more wrench
//! call; without it the other supporting planes were missed by up to 7.4e-3 for `best`); p is
//! accepted when
//! −p·s* ≤ (1 + [`LIMIT_TOLERANCE`])·(−p_fs(s*)·s*), else replaced by p_fs(s*) (a value of the
//! law itself, so inside C exactly). Measured over 26 supporting planes on 1e5 random states
//! and bodies (`host-tests/step_wrench.rs`): within 1.4e-3 (`best`), 1.0e-3 (`coulomb`,
//! `ellipsoid`) of the set.
//!
//! `simplified` and `pade` are not maximally dissipative
//! ([`crate::friction::FrictionLaw::MAXIMALLY_DISSIPATIVE`] `false`, read through
//! [`Linearize::maximally_dissipative`]): their full-slip value is not the support point of
//! their own set, and the supporting-plane test moved their own plain values (`simplified`'s
//! friction on 44 % of a rattleback's steps at any Δt, so that the step did not tend to the
//! plain wrench as Δt → 0). For them the set is the cylinder |F| ≤ F_max, |T_z| ≤ T_max (the
//! full slip of a pure translation along F and of a pure spin), which holds every value of
//! these laws (each bounds its force by fN and its torque by its pure-spin value): a pair
//! outside has its force scaled to F_max and its torque clamped to ±T_max. The full slip is evaluated at the patch of N̄ (the gap
//! where the law's N equals N̄, by [`PATCH_STEPS`] regula-falsi steps from the
//! linearisation's gap; the remaining mismatch scaled out by N̄/N, the limit set being
//! proportional to N at a fixed patch), at [`FULL_SLIP_SPEED`] (and [`FULL_SLIP_SPIN`] for
//! pure spin). Cost: four wrench calls plus the patch's ([`PATCH_STEPS`] + 1).

use crate::Real;
use crate::friction::Slip;
use crate::jacobian::{Linearize, State};

/// The slip speed (m/s) at which a friction pair is taken as full slip (must exceed the law's
/// regularisation δ and, for a rolling law, its saturation creep speed, by far): 1e3 m/s.
pub const FULL_SLIP_SPEED: f64 = 1e3;

/// The spin (rad/s) of the pure-spin full-slip evaluation: 1e9 rad/s (a·ω ≥ 1e3 m/s for a
/// patch of a ≥ 1 µm).
pub const FULL_SLIP_SPIN: f64 = 1e9;

/// The relative tolerance of the limit-set test: a friction pair within 1e-3 of the supporting
/// plane is kept as it is (the laws' own maximal-dissipation defect; `best` is exact-grade).
pub const LIMIT_TOLERANCE: f64 = 1e-3;

fn full_slip<T: Real>(c: &dyn Linearize<T>, l: &State<T>, vx: T, vy: T, w: T) -> [T; 4] {
    c.wrench4(&State {
        slip: Slip::or_rest(vx, vy, w),
        ..*l
    })
}

/// Regula-falsi steps of the search for the patch of N̄ (the gap where the law's N equals the
/// solved N̄; module docs): one wrench call each.
pub const PATCH_STEPS: usize = 4;

/// The approach h at which the law's normal force is `n` (ḣ and the rest of `l` held), from
/// the linearisation's (h_ℓ, N_ℓ): the root lies between h_ℓ and h_ℓ·n/N_ℓ for every normal
/// law with N(0) = 0 and N(h)/h non-decreasing (Hertz h^{3/2}, every law here), so
/// [`PATCH_STEPS`] regula-falsi steps on that bracket (one wrench call each). Returns the state
/// there and its normal force (the end with the smaller residual).
fn patch_of<T: Real>(c: &dyn Linearize<T>, l: &State<T>, n_l: T, n: T) -> (State<T>, T) {
    let at = |h: T| {
        let s = State { h, ..*l };
        let v = c.normal_force(&s);
        (s, if v.is_finite() { v } else { T::ZERO })
    };
    let h2 = l.h * (n / n_l);
    let (mut a, mut b) = if h2 < l.h { (h2, l.h) } else { (l.h, h2) };
    if !(a < b) || !b.is_finite() {
        return (*l, n_l);
    }
    let (mut sa, mut na) = at(a);
    let (mut sb, mut nb) = if h2 < l.h { (*l, n_l) } else { at(b) };
    for _ in 0..PATCH_STEPS {
        let (fa, fb) = (na - n, nb - n);
        if !(fb > fa) {
            break;
        }
        let x = a - fa * (b - a) / (fb - fa);
        if !(x > a && x < b) {
            break;
        }
        let (sx, nx) = at(x);
        if nx < n {
            a = x;
            sa = sx;
            na = nx;
        } else {
            b = x;
            sb = sx;
            nb = nx;
        }
    }
    if (nb - n).abs() < (n - na).abs() && nb > T::ZERO {
        (sb, nb)
    } else if na > T::ZERO {
        (sa, na)
    } else {
        (sb, nb)
    }
}

/// Moves the friction pair of `w` (solved N̄ = w[0] > 0) into the limit set at N̄ (module
/// docs). `l` is the linearisation state, `n_l` > 0 its normal force. Returns whether anything
/// changed.
pub(crate) fn into_limit_set<T: Real>(
    c: &dyn Linearize<T>,
    l: &State<T>,
    n_l: T,
    w: &mut [T; 4],
) -> bool {
    let [n, fx, fy, tz] = *w;
    let had = fx != T::ZERO || fy != T::ZERO || tz != T::ZERO;
    if !had {
        return false;
    }
    if !(n > T::ZERO) || !(n_l > T::ZERO) {
        w[1] = T::ZERO;
        w[2] = T::ZERO;
        w[3] = T::ZERO;
        return true;
    }
    // The patch of N̄: the limit set's size (fN, fNa) at the gap where the law gives N̄.
    let (ls, n_at) = patch_of(c, l, n_l, n);
    let l = &ls;
    if !(n_at > T::ZERO) {
        w[1] = T::ZERO;
        w[2] = T::ZERO;
        w[3] = T::ZERO;
        return true;
    }
    let sigma = n / n_at;
    let vfs = T::from_f64(FULL_SLIP_SPEED);
    let wfs = T::from_f64(FULL_SLIP_SPIN);
    let fmag = fx.hypot(fy);
    let (ex, ey) = if fmag > T::ZERO {
        (fx / fmag, fy / fmag)
    } else {
        (T::ONE, T::ZERO)
    };
    let tr = full_slip(c, l, -ex * vfs, -ey * vfs, T::ZERO);
    let f_max = sigma * tr[1].hypot(tr[2]);
    let sign = if tz > T::ZERO { T::ONE } else { -T::ONE };
    let sp = full_slip(c, l, T::ZERO, T::ZERO, -sign * wfs);
    let t_max = sigma * sp[3].abs();
    let f_ok = f_max > T::ZERO && f_max.is_finite();
    let t_ok = t_max > T::ZERO && t_max.is_finite();
    let (mut fx, mut fy, mut tz) = (fx, fy, tz);
    let mut changed = false;
    if !f_ok && fmag > T::ZERO {
        fx = T::ZERO;
        fy = T::ZERO;
        changed = true;
    }
    if !t_ok && tz != T::ZERO {
        tz = T::ZERO;
        changed = true;
    }
    if !c.maximally_dissipative() {
        // The law's full-slip values are not support points (module docs): the force and the
        // drilling torque bounded separately, |F| ≤ F_max, |T_z| ≤ T_max — every value of the
        // law lies there, so its plain wrench is never moved.
        let tol = T::ONE + T::from_f64(LIMIT_TOLERANCE);
        let fm = fx.hypot(fy);
        if f_ok && fm > f_max * tol {
            let k = f_max / fm;
            fx *= k;
            fy *= k;
            changed = true;
        }
        if t_ok && tz.abs() > t_max * tol {
            tz = sign * t_max;
            changed = true;
        }
        w[1] = fx;
        w[2] = fy;
        w[3] = tz;
        return changed;
    }
    // The dual slip direction s* and the full-slip point p_b there.
    let (sx, sy, sw, pb) = match (f_ok, t_ok) {
        (false, false) => {
            w[1] = T::ZERO;
            w[2] = T::ZERO;
            w[3] = T::ZERO;
            return true;
        }
        (true, false) => {
            let (sx, sy) = (-fx, -fy);
            let m = sx.abs().max(sy.abs());
            if !(m > T::ZERO) {
                w[1] = fx;
                w[2] = fy;
                w[3] = tz;
                return changed;
            }
            let k = vfs / m;
            (sx, sy, T::ZERO, full_slip(c, l, sx * k, sy * k, T::ZERO))
        }
        (false, true) => {
            if tz == T::ZERO {
                w[1] = fx;
                w[2] = fy;
                w[3] = tz;
                return changed;
            }
            (T::ZERO, T::ZERO, -tz, sp)
        }
        (true, true) => {
            let rbar = t_max / f_max;
            let sw = -tz / (rbar * rbar);
            let (sx, sy) = (-fx, -fy);
            let m = sx.abs().max(sy.abs()).max(rbar * sw.abs());
            if !(m > T::ZERO) || !m.is_finite() {
                w[1] = fx;
                w[2] = fy;
                w[3] = tz;
                return changed;
            }
            let k = vfs / m;
            let pb0 = full_slip(c, l, sx * k, sy * k, sw * k);
            // One correction of the dual direction: where p_fs(s*) misses p's direction
            // (both normalised in the metric diag(1, 1, 1/R̄²)), aim as far the other way:
            // s₁ = dual(2p̂ − p̂_b).
            let norm = |x: T, y: T, t: T| (x * x + y * y + t * t / (rbar * rbar)).sqrt();
            let (np, nb) = (norm(fx, fy, tz), norm(pb0[1], pb0[2], pb0[3]));
            if !(np > T::ZERO) || !(nb > T::ZERO) || !(np * nb).is_finite() {
                (sx, sy, sw, pb0)
            } else {
                let q = |a: T, b: T| (a / np) * T::TWO - b / nb;
                let (qx, qy, qt) = (q(fx, pb0[1]), q(fy, pb0[2]), q(tz, pb0[3]));
                let (sx1, sy1, sw1) = (-qx, -qy, -qt / (rbar * rbar));
                let m1 = sx1.abs().max(sy1.abs()).max(rbar * sw1.abs());
                if m1 > T::ZERO && m1.is_finite() {
                    let k1 = vfs / m1;
                    (sx1, sy1, sw1, full_slip(c, l, sx1 * k1, sy1 * k1, sw1 * k1))
                } else {
                    (sx, sy, sw, pb0)
                }
            }
        }
    };
    let (bx, by, bt) = (sigma * pb[1], sigma * pb[2], sigma * pb[3]);
    // −p·s* (> 0) against −p_b·s* (the support value D(s*)).
    let dp = -(fx * sx + fy * sy + tz * sw);
    let db = -(bx * sx + by * sy + bt * sw);
    if dp > db * (T::ONE + T::from_f64(LIMIT_TOLERANCE)) {
        let (bx, by, bt) = if t_ok {
            (bx, by, bt)
        } else {
            (bx, by, T::ZERO)
        };
        let (bx, by) = if f_ok { (bx, by) } else { (T::ZERO, T::ZERO) };
        if (bx + by + bt).is_finite() {
            fx = bx;
            fy = by;
            tz = bt;
        } else {
            fx = T::ZERO;
            fy = T::ZERO;
            tz = T::ZERO;
        }
        changed = true;
    }
    w[1] = fx;
    w[2] = fy;
    w[3] = tz;
    changed
}
