//! The scenes' glue to the library's step-aware wrench, and the rigid-body pieces of their
//! large-step integrators.
//!
//! The scenes' `step_aware` integrators ([`super::ball`], [`super::tippe_top`],
//! [`super::rattleback`], [`super::bearing`]) build each step's [`Candidate`]s (free velocity,
//! predicted approach, the slip's drift, rolling velocity) and the inverse mass W
//! ([`rigid_w`]), and call [`solve_library`]: the library's
//! [`crate::step::step_wrenches_with`] with the integrator's [`crate::step::Scheme`] — the
//! same wrench a user of [`crate::step`] gets. [`solve_consistent_gap`] solves once more
//! with the free gap shifted by what the library's linear gap response missed of the
//! integrator's own end pose (the rattleback: a contact arm that turns within the step). Also here: the exact torque-free rotation of
//! the symmetric top ([`symmetric_free`]) and [`rotate_by`].
//!
//! [`solve_with`] is the scenes' former private step (central-difference Jacobian, an ellipse
//! projection), kept only as [`solve_library`]'s fallback for a W or Δt the library refuses
//! (never reached by the scenes' own W); it is described below.
//!
//! # The step
//!
//! For each contact k, u_k = (v_n, v_x, v_y, ω) is the velocity of B relative to A in the
//! contact frame (v_n = −ḣ, the normal component at the patch centre; ω the spin about the
//! normal) and w_k = (N, F_x, F_y, T_z) the wrench on B. With the inverse mass W (`W_kj =
//! J_k M⁻¹ J_jᵀ`, [`rigid_w`]) an impulse Δt·w changes the velocities by Δt·W·w. A step
//! from the free end-of-step velocity u_free (gravity, gyroscopic and every other force over the
//! step, no contact) and the gap predicted from the free motion, h_pred, looks for the wrench
//! w̄ that the contact law gives at the end of the step:
//!
//! ```text
//! u⁺ = u_free + Δt·W·w̄,   h⁺ = h_pred − Δt·(u⁺_n − u_free,n),   w̄ = w(h⁺, u⁺)
//! ```
//!
//! solved by [`ITERATIONS`] Newton iterations: each linearises the law at a point ℓ = (h_ℓ, u_ℓ)
//! (K = ∂w/∂h, D = ∂w/∂u) and solves, over all contacts at once (the cross blocks of W),
//!
//! ```text
//! (I − Δt·A·W) w̄ = w_ℓ + K (h_pred − h_ℓ) + D (u_free − u_ℓ),    A = D − Δt·K·e_nᵀ
//! ```
//!
//! - **Active set**: a contact whose solved N is negative is dropped (its w̄ = 0) and the system
//!   solved again (at most one pass per contact), not clamped afterwards; a contact whose
//!   linearisation point is open (h_ℓ ≤ 0) has w = 0 and drops out by itself.
//! - **Slip reversal**: ℓ is the end state of the previous iterate, except that a tangential
//!   slip (v_x, v_y) pointing against the free one, or a spin against the free spin, is
//!   replaced by zero: a slip that would reverse within the step is linearised at rest (the
//!   law's stiff ramp), where it sticks instead of flipping sign every step.
//! - **Projection** after the iterations: N ≥ 0; the friction pair (F, T_z) scaled into the
//!   ellipse (|F|/F_max)² + (T_z/T_max)² ≤ 1, F_max and T_max the law's own full-slip force and
//!   pure-spin torque at this N ([`StepContact::limits`]; the Contensou limit curve is close to
//!   that ellipse — it only acts where the linearisation overshoots); then no power injected by
//!   friction at the end velocity, checked for the force and the drilling torque separately
//!   (F·u⁺_t ≤ 0 and T_z·ω⁺ ≤ 0; a part that fails is set to zero).
//!
//! As Δt → 0 the solve tends to w(h_pred, u_free), the plain wrench. Cost per step and contact:
//! [`ITERATIONS`] linearisations (by default central differences of the wrench, 10 wrench
//! calls: [`central_differences`]; a contact with analytic derivatives overrides
//! [`StepContact::linearize`]), two wrench calls for the limits and one 4K × 4K solve
//! (Gaussian elimination with partial pivoting, K ≤ 2) per active-set pass. Fixed counts, no
//! allocation, `no_std`.

// `!(x > 0)` is meant: it is true for NaN too (a lost state drops the contact); the index
// loops run over small fixed blocks of the 4K × 4K system.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use crate::Real;
use crate::contact::Contact;
use crate::friction::rolling::RollingVelocity;
use crate::friction::{FrictionLaw, Slip};
use crate::jacobian::{Jacobian, Linearize, State, input};
use crate::normal::{Damping, NormalLaw};
use crate::step::{Free, InverseMass as LibInverseMass, Scheme, TimeStep, step_wrenches_with};

use super::rigid::{Quat, Vec3};

/// Contacts solved together (the tippe top's two spheres).
pub const MAX_CONTACTS: usize = 2;
/// Newton iterations per step.
pub const ITERATIONS: usize = 5;
const DIM: usize = 4 * MAX_CONTACTS;

/// A contact as the step sees it: its wrench (N, F_x, F_y, T_z) on B at a per-step state.
pub trait StepContact<T: Real> {
    /// The wrench at `s` (zero when h ≤ 0).
    fn wrench4(&self, s: &State<T>) -> [T; 4];

    /// The wrench and its Jacobian at `s`. Default: [`central_differences`].
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        central_differences(|s| self.wrench4(s), s)
    }

    /// (F_max, T_max): the law's full-slip friction force and pure-spin drilling torque at the
    /// normal force `n` and approach `h`. Default: the wrench at a slip of 10³ m/s and at a
    /// spin of 10⁶ rad/s (at rest in h), scaled by n / N(h).
    fn limits(&self, h: T, n: T) -> (T, T) {
        let at = |vx: T, w: T| {
            self.wrench4(&State {
                h,
                hdot: T::ZERO,
                slip: Slip::or_rest(vx, T::ZERO, w),
                rolling: RollingVelocity::default(),
            })
        };
        let slide = at(T::from_f64(1e3), T::ZERO);
        let spin = at(T::ZERO, T::from_f64(1e6));
        if slide[0] > T::ZERO {
            let k = n / slide[0];
            (
                slide[1].hypot(slide[2]) * k,
                spin[3].abs() * (n / spin[0].max(T::from_f64(1e-300))),
            )
        } else {
            (T::ZERO, T::ZERO)
        }
    }

    /// Whether the contact's friction law is maximally dissipative
    /// ([`crate::friction::FrictionLaw::MAXIMALLY_DISSIPATIVE`]): which limit set the
    /// library's step-aware wrench projects onto ([`crate::step::project`]). Default `true`.
    fn maximally_dissipative(&self) -> bool {
        true
    }
}

/// Every fixed-geometry contact is one (the rolling velocity is ignored: full slip).
impl<T: Real, N: NormalLaw<T>, D: Damping<T>, L: FrictionLaw> StepContact<T>
    for Contact<T, N, D, L>
{
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        if s.h <= T::ZERO {
            return [T::ZERO; 4];
        }
        let w = self.wrench(s.h, s.hdot, s.slip);
        [w.n, w.fx, w.fy, w.tz]
    }

    fn maximally_dissipative(&self) -> bool {
        L::MAXIMALLY_DISSIPATIVE
    }
}

/// The wrench of `wrench` at `s` and its Jacobian by central differences: steps
/// 1e-4·h (one-sided at h below it: the law's kink at contact) for h, 1e-8 + 1e-6·|x| for
/// ḣ and the slip (m/s) and 1e-6 + 1e-6·|ω| for the spin. 10 wrench calls beside the value.
/// Where the law is smooth its error is O(ε²) relative; across a kink (|v| ≈ δ) it is a
/// secant. The stand-in until the contacts' analytic `Linearize` is wired.
pub fn central_differences<T: Real>(
    wrench: impl Fn(&State<T>) -> [T; 4],
    s: &State<T>,
) -> Jacobian<T> {
    let value = wrench(s);
    let mut d = [[T::ZERO; 5]; 4];
    let q = [s.h, s.hdot, s.slip.vx(), s.slip.vy(), s.slip.omega()];
    let c = T::from_f64;
    let eps = [
        c(1e-4) * s.h.abs(),
        c(1e-8) + c(1e-6) * q[1].abs(),
        c(1e-8) + c(1e-6) * q[2].abs(),
        c(1e-8) + c(1e-6) * q[3].abs(),
        c(1e-6) + c(1e-6) * q[4].abs(),
    ];
    let at = |j: usize, x: T| {
        let mut p = q;
        p[j] = x;
        wrench(&State {
            h: p[0],
            hdot: p[1],
            slip: Slip::or_rest(p[2], p[3], p[4]),
            rolling: s.rolling,
        })
    };
    for j in 0..5 {
        let e = eps[j];
        if !(e > T::ZERO) {
            continue;
        }
        let (lo, hi, span) = if j == input::H && q[0] - e <= T::ZERO {
            (value, at(j, q[j] + e), e)
        } else {
            (at(j, q[j] - e), at(j, q[j] + e), e * T::TWO)
        };
        for i in 0..4 {
            d[i][j] = (hi[i] - lo[i]) / span;
        }
    }
    Jacobian { value, d }
}

/// One contact's data for a step: the predicted approach and the free end-of-step velocity.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Candidate<T> {
    /// The approach predicted at the end of the step from the free motion (m).
    pub h_pred: T,
    /// u_free = (v_n, v_x, v_y, ω) at the end of the step without this step's contact wrench.
    pub u_free: [T; 4],
    /// The rolling velocity (held over the step; rolling laws only).
    pub rolling: RollingVelocity<T>,
    /// The free velocity's own change over the second half of the step, from the pose the
    /// impulse acts at ([`Coupling::pose`]) to the end pose (the contact point running over
    /// the surface, the body turning): the velocity at the fraction θ of the step is
    /// u_free + θ·Δt·W·w̄ + (θ − pose)/(1 − pose)·drift — the end velocity (θ = 1)
    /// u_free + Δt·W·w̄ + drift. Zero when the caller reads u_free where the step ends.
    pub drift: [T; 4],
}

/// The result of [`solve`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Solution<T> {
    /// The wrench w̄ = (N, F_x, F_y, T_z) per contact, to apply over the step.
    pub w: [[T; 4]; MAX_CONTACTS],
    /// The end-of-step relative velocity u⁺ per contact.
    pub u: [[T; 4]; MAX_CONTACTS],
    /// The end-of-step approach h⁺ per contact (m).
    pub h: [T; MAX_CONTACTS],
}

/// The inverse mass over a step: `w[4k + a][4j + b]` couples contact k's component a with
/// contact j's b (components (n, x, y, spin)).
pub type InverseMass<T> = [[T; DIM]; DIM];

/// The contact frame of one contact and its arm (G → patch centre), world vectors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Site<T> {
    /// G → P (m).
    pub arm: Vec3<T>,
    /// The contact frame's x, y, z (z the normal from A into B).
    pub axes: [Vec3<T>; 3],
}

impl<T: Real> Site<T> {
    /// The rows of J (u = J·(v, ω)): (linear, angular) parts for v_n, v_x, v_y, ω.
    #[inline]
    pub fn rows(&self) -> [(Vec3<T>, Vec3<T>); 4] {
        let [x, y, z] = self.axes;
        let r = self.arm;
        [
            (z, r.cross(z)),
            (x, r.cross(x)),
            (y, r.cross(y)),
            (Vec3::zero(), z),
        ]
    }

    /// u = J·(v, ω) for the body velocity `v` (of G) and angular velocity `w` (world).
    #[inline]
    pub fn velocity(&self, v: Vec3<T>, w: Vec3<T>) -> [T; 4] {
        self.rows().map(|(l, a)| l.dot(v) + a.dot(w))
    }

    /// The force (at P) and the torque about G on B of the wrench `w` (world).
    #[inline]
    pub fn load(&self, w: &[T; 4]) -> (Vec3<T>, Vec3<T>) {
        let [x, y, z] = self.axes;
        let f = z * w[0] + x * w[1] + y * w[2];
        (f, self.arm.cross(f) + z * w[3])
    }
}

/// A rigid body's inverse inertia in the world frame, R diag(1/I) Rᵀ, as a function.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InvInertia<T> {
    q: Quat<T>,
    inv: Vec3<T>,
}

impl<T: Real> InvInertia<T> {
    /// For the unit attitude `q` (body → world) and the principal inverse moments `inv`.
    pub fn new(q: Quat<T>, inv: Vec3<T>) -> Self {
        InvInertia { q, inv }
    }
    /// I⁻¹·x (world).
    #[inline]
    pub fn apply(&self, x: Vec3<T>) -> Vec3<T> {
        self.q.rotate(self.q.rotate_inv(x).mul_elem(self.inv))
    }
}

/// W for one rigid body (inverse mass `inv_mass`, world inverse inertia `inv_inertia`)
/// against fixed bodies at the contact `sites`: W_kj = J_k M⁻¹ J_jᵀ.
pub fn rigid_w<T: Real, const K: usize>(
    inv_mass: T,
    inv_inertia: &InvInertia<T>,
    sites: &[Site<T>; K],
) -> InverseMass<T> {
    rigid_w_split(inv_mass, inv_inertia, sites, T::ONE)
}

/// [`rigid_w`] with the rotational part (through I⁻¹) weighted by `rot`: ½ gives the gap
/// response G of an integrator that turns the body with the new angular velocity over half the
/// step ([`Coupling::gap`]).
pub fn rigid_w_split<T: Real, const K: usize>(
    inv_mass: T,
    inv_inertia: &InvInertia<T>,
    sites: &[Site<T>; K],
    rot: T,
) -> InverseMass<T> {
    rigid_w_between(inv_mass, inv_inertia, sites, sites, rot)
}

/// W_kj = J_k M⁻¹ J_jᵀ with the velocity rows J_k of the sites `seen` (where the end velocity
/// is read: the contact point at the end of the step) and the impulse columns J_j of the sites
/// `pushed` (where the impulse acts: mid-step), the rotational part weighted by `rot`. Not
/// symmetric when the sites differ: the contact point of a rolling body runs over its surface
/// within the step, and the slip the next step starts from is read at the end point.
pub fn rigid_w_between<T: Real, const K: usize>(
    inv_mass: T,
    inv_inertia: &InvInertia<T>,
    seen: &[Site<T>; K],
    pushed: &[Site<T>; K],
    rot: T,
) -> InverseMass<T> {
    const { assert!(K <= MAX_CONTACTS) };
    let mut w = [[T::ZERO; DIM]; DIM];
    for (k, sk) in seen.iter().enumerate() {
        let rk = sk.rows();
        for (j, sj) in pushed.iter().enumerate() {
            let rj = sj.rows();
            for a in 0..4 {
                let ia = inv_inertia.apply(rk[a].1);
                for b in 0..4 {
                    w[4 * k + a][4 * j + b] =
                        inv_mass * rk[a].0.dot(rj[b].0) + rot * ia.dot(rj[b].1);
                }
            }
        }
    }
    w
}

/// How the step couples the contacts to the body (see [`solve_with`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coupling<'a, T> {
    /// W: an impulse Δt·w̄ changes the end velocities by Δt·W·w̄.
    pub w: &'a InverseMass<T>,
    /// The gap's response: an impulse Δt·w̄ changes the end approaches by −Δt²·(G·w̄)ₙ (the
    /// normal rows are read). W itself when the pose moves with the end velocity over the
    /// whole step; an integrator that turns the body with the new angular velocity over half
    /// a step only (Strang splitting) halves the rotational part.
    pub gap: &'a InverseMass<T>,
    /// θ: the friction (slip and spin) is evaluated at u_θ = u_free + θ·Δt·W·w̄ — 1: backward
    /// Euler (L-stable: damps a stiff friction mode); ½: the trapezoidal rule (second order,
    /// used while the slip keeps its direction: a contact whose slip or spin would reverse
    /// within the step switches to θ = 1 for that step).
    pub theta: T,
    /// The fraction of the step at which u_free (and W) are read: the pose the impulse acts
    /// at (½ for a Strang splitting; 1 when everything is read at the end). A contact's
    /// [`Candidate::drift`] (the free velocity's change from that pose to the end) enters the
    /// velocity at θ with the weight (θ − pose)/(1 − pose).
    pub pose: T,
}

/// The step-aware wrench of K ≤ [`MAX_CONTACTS`] contacts sharing one inverse mass `w`, over
/// the step `dt` (see the [module docs](self)): backward Euler (θ = 1, G = W). `warm` carries
/// the previous step's solution (the first iterate and linearisation point) and receives this
/// one's.
pub fn solve<T: Real, C: StepContact<T>, const K: usize>(
    dt: T,
    w: &InverseMass<T>,
    contacts: &[&C; K],
    cand: &[Candidate<T>; K],
    warm: &mut Warm<T>,
) -> Solution<T> {
    let c = Coupling {
        w,
        gap: w,
        theta: T::ONE,
        pose: T::ONE,
    };
    solve_with(dt, &c, contacts, cand, warm)
}

/// [`solve`] with a [`Coupling`]: the gap's own response matrix and the friction's θ.
pub fn solve_with<T: Real, C: StepContact<T>, const K: usize>(
    dt: T,
    cp: &Coupling<'_, T>,
    contacts: &[&C; K],
    cand: &[Candidate<T>; K],
    warm: &mut Warm<T>,
) -> Solution<T> {
    const { assert!(K <= MAX_CONTACTS) };
    let n = 4 * K;
    let mut wbar = [[T::ZERO; 4]; MAX_CONTACTS];
    // The approach each iteration linearises at: the previous step's end approach first (the
    // root is near it; the predicted h_pred can be far deeper — the free fall over the step —
    // and Newton from there on N ∝ h^{3/2} needs many iterations), then the iterate's own.
    let mut h_lin = [T::ZERO; MAX_CONTACTS];
    let mut theta = [cp.theta; MAX_CONTACTS];
    for k in 0..K {
        wbar[k] = warm.w[k];
        if !(wbar[k][0] > T::ZERO) || !wbar[k].iter().all(|x| x.is_finite()) {
            wbar[k] = [T::ZERO; 4];
        }
        h_lin[k] = if warm.h[k] > T::ZERO && wbar[k][0] > T::ZERO {
            warm.h[k]
        } else {
            cand[k].h_pred
        };
    }
    for it in 0..ITERATIONS {
        let (u, h) = end_state(dt, cp, cand, &wbar);
        let mut a = [[[T::ZERO; 4]; 4]; MAX_CONTACTS];
        let mut kh = [[T::ZERO; 4]; MAX_CONTACTS];
        let mut b = [[T::ZERO; 4]; MAX_CONTACTS];
        for k in 0..K {
            // After the first iteration: the iterate's approach if the contact is closed there;
            // an iterate that overshot to an open gap while the contact pushes keeps the last
            // linearisation point's (the linear model is then re-solved from it).
            if it > 0 && (h[k] > T::ZERO || !(wbar[k][0] > T::ZERO)) {
                h_lin[k] = h[k];
            }
            if !(h_lin[k] > T::ZERO) {
                continue;
            }
            let free = cand[k].u_free;
            // Slip reversal: at the end velocity, against the free slip → θ = 1 and linearise
            // the friction at rest.
            let reversed = u[k][1] * free[1] + u[k][2] * free[2] < T::ZERO;
            let spun = u[k][3] * free[3] < T::ZERO;
            if reversed || spun {
                theta[k] = T::ONE;
            }
            let th = theta[k];
            // u_θ = u_free + t·Δt·W·w̄ + (2t − 1)·drift, t = 1 for the normal.
            let mut ul = [T::ZERO; 4];
            let mut shift = [T::ZERO; 4];
            for c in 0..4 {
                let t = if c == 0 { T::ONE } else { th };
                let dr = cand[k].drift[c];
                shift[c] = if cp.pose < T::ONE {
                    (t - cp.pose) / (T::ONE - cp.pose) * dr
                } else {
                    dr
                };
                ul[c] = free[c] + t * (u[k][c] - dr - free[c]) + shift[c];
            }
            if reversed {
                (ul[1], ul[2]) = (T::ZERO, T::ZERO);
            }
            if spun {
                ul[3] = T::ZERO;
            }
            let s = State {
                h: h_lin[k],
                hdot: -ul[0],
                slip: Slip::or_rest(ul[1], ul[2], ul[3]),
                rolling: cand[k].rolling,
            };
            let jac = contacts[k].linearize(&s);
            // D over u = (v_n, v_x, v_y, ω): ∂/∂v_n = −∂/∂ḣ; the friction columns take θ.
            for i in 0..4 {
                let row = jac.d[i];
                let d = [
                    -row[input::HDOT],
                    row[input::VX],
                    row[input::VY],
                    row[input::OMEGA],
                ];
                kh[k][i] = row[input::H];
                a[k][i] = [d[0], th * d[1], th * d[2], th * d[3]];
                let mut bi = jac.value[i] + kh[k][i] * (cand[k].h_pred - h_lin[k]);
                for c in 0..4 {
                    bi += d[c] * (free[c] + shift[c] - ul[c]);
                }
                b[k][i] = bi;
            }
        }
        // (I − Δt·A·W + Δt²·K·G_n) w̄ = b; a contact whose N comes out negative is dropped
        // and the system solved again.
        let mut active = [true; MAX_CONTACTS];
        let mut x = [T::ZERO; DIM];
        for _ in 0..=K {
            let mut m = [[T::ZERO; DIM]; DIM];
            let mut r = [T::ZERO; DIM];
            for k in 0..K {
                for i in 0..4 {
                    let row = 4 * k + i;
                    m[row][row] = T::ONE;
                    if !active[k] {
                        continue;
                    }
                    r[row] = b[k][i];
                    for col in 0..n {
                        let mut s = T::ZERO;
                        for c in 0..4 {
                            s += a[k][i][c] * cp.w[4 * k + c][col];
                        }
                        m[row][col] -= dt * s;
                        m[row][col] += dt * dt * kh[k][i] * cp.gap[4 * k][col];
                    }
                }
            }
            x = gauss(m, r, n);
            let mut dropped = false;
            for k in 0..K {
                if active[k] && x[4 * k] < T::ZERO {
                    active[k] = false;
                    dropped = true;
                }
            }
            if !dropped {
                break;
            }
        }
        for k in 0..K {
            for i in 0..4 {
                wbar[k][i] = if active[k] { x[4 * k + i] } else { T::ZERO };
            }
        }
    }
    // Projection: N ≥ 0, friction into the law's limit ellipse, then passivity.
    let (_, h) = end_state(dt, cp, cand, &wbar);
    for k in 0..K {
        let wk = &mut wbar[k];
        if !(wk[0] > T::ZERO) || !wk.iter().all(|x| x.is_finite()) {
            *wk = [T::ZERO; 4];
            continue;
        }
        let (fmax, tmax) = contacts[k].limits(h[k].max(h_lin[k]), wk[0]);
        let mut r = T::ZERO;
        if fmax > T::ZERO {
            r += (wk[1] * wk[1] + wk[2] * wk[2]) / (fmax * fmax);
        }
        if tmax > T::ZERO {
            r += wk[3] * wk[3] / (tmax * tmax);
        }
        if r > T::ONE {
            let s = T::ONE / r.sqrt();
            wk[1] *= s;
            wk[2] *= s;
            wk[3] *= s;
        }
    }
    let (u, _) = end_state(dt, cp, cand, &wbar);
    for k in 0..K {
        let wk = &mut wbar[k];
        let force = wk[1] * u[k][1] + wk[2] * u[k][2];
        let torque = wk[3] * u[k][3];
        // A rolling law's force and spin moment are passive together, not each (Kalker's
        // spin–lateral coupling): only a positive total zeroes the part that injects.
        if force + torque > T::ZERO {
            if force > T::ZERO {
                (wk[1], wk[2]) = (T::ZERO, T::ZERO);
            }
            if torque > T::ZERO {
                wk[3] = T::ZERO;
            }
        }
    }
    let (u, h) = end_state(dt, cp, cand, &wbar);
    warm.w = wbar;
    warm.h = h;
    Solution { w: wbar, u, h }
}

/// A scene contact as the library's [`Linearize`]: its wrench, and its Jacobian by
/// [`StepContact::linearize`].
struct AsLinearize<'a, C>(&'a C);

impl<T: Real, C: StepContact<T>> Linearize<T> for AsLinearize<'_, C> {
    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        self.0.wrench4(s)
    }
    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        self.0.linearize(s)
    }
    fn maximally_dissipative(&self) -> bool {
        self.0.maximally_dissipative()
    }
}

/// The step-aware wrench of the library ([`crate::step::step_wrenches_with`]) for K ≤
/// [`MAX_CONTACTS`] contacts sharing the inverse mass `w` (validated by
/// [`crate::step::InverseMass::new`]), integrated as `scheme` says ([`Scheme`]: backward Euler,
/// or a Strang splitting whose gap response is ½W). What the scenes run: the same wrench as a
/// user of [`crate::step`] gets. `warm` receives the solution (the library starts from its
/// own normal predictor, not from `warm`). A W or Δt the library refuses (not symmetric
/// positive semidefinite within its tolerance, Δt ≤ 0) falls back to [`solve_with`].
pub fn solve_library<T: Real, C: StepContact<T>, const K: usize>(
    dt: T,
    w: &InverseMass<T>,
    contacts: &[&C; K],
    cand: &[Candidate<T>; K],
    scheme: &Scheme<T>,
    warm: &mut Warm<T>,
) -> Solution<T> {
    const { assert!(K <= MAX_CONTACTS) };
    let blocks: [[[[T; 4]; 4]; K]; K] = core::array::from_fn(|i| {
        core::array::from_fn(|j| {
            core::array::from_fn(|a| core::array::from_fn(|b| w[4 * i + a][4 * j + b]))
        })
    });
    let frees: [Result<Free<T>, crate::Error>; K] = core::array::from_fn(|k| {
        Free::new(cand[k].u_free, cand[k].h_pred).and_then(|f| f.with_drift(cand[k].drift))
    });
    let (Ok(dts), Ok(wm)) = (TimeStep::new(dt), LibInverseMass::<T, K>::new(blocks)) else {
        return fallback(dt, w, scheme, contacts, cand, warm);
    };
    let mut free = [Free::coasting(dts, &State::default()); K];
    for k in 0..K {
        match frees[k] {
            Ok(f) => free[k] = f,
            Err(_) => return fallback(dt, w, scheme, contacts, cand, warm),
        }
    }
    let lins: [AsLinearize<'_, C>; K] = core::array::from_fn(|k| AsLinearize(contacts[k]));
    let dyns: [&dyn Linearize<T>; K] = core::array::from_fn(|k| &lins[k] as &dyn Linearize<T>);
    let states: [State<T>; K] = core::array::from_fn(|k| State {
        h: cand[k].h_pred,
        hdot: -cand[k].u_free[0],
        slip: Slip::or_rest(cand[k].u_free[1], cand[k].u_free[2], cand[k].u_free[3]),
        rolling: cand[k].rolling,
    });
    let out = step_wrenches_with(dyns, dts, &wm, &states, &free, scheme);
    let mut sol = Solution::default();
    for k in 0..K {
        sol.w[k] = out[k].wrench;
        sol.u[k] = out[k].u_end;
        sol.h[k] = out[k].h_end;
    }
    warm.w = sol.w;
    warm.h = sol.h;
    sol
}

/// A step (`solve`: [`solve_library`] with the step's W, contacts and scheme) with the end
/// approach the integrator's own pose update gives: the library models the gap's response to
/// the wrench as linear, h⁺ = h_free − γ·Δt²·(W·w̄)ₙ with W read at the impulse's pose;
/// `end_gap(w̄)` returns the approach per contact at the pose the integrator would reach with
/// w̄ (a few geometry evaluations, no wrench call). The first solve's miss
/// e = end_gap(w̄₁) − h⁺(w̄₁) shifts each free gap of `cand`, h_free + e, and the step is
/// solved once more: one chord step on h⁺(w̄) = end_gap(w̄), so that N̄ is the normal law's at
/// the approach the step really ends at. Fixed cost: two solves and one `end_gap` (one solve
/// when the miss is zero: every contact open, or a response that is linear).
///
/// Why: a body that rolls over a curved surface turns its contact arm within the step (the
/// rattleback's long axis has a 2 m radius of curvature: the patch runs ≈ 2 m × the pitch
/// angle over the body), so its end approach responds to the impulse through an arm that is
/// not W's. Measured on the rattleback (`coulomb`, ω₀ = −2 rad/s, 2 ms): the miss reaches
/// 1.3 µm, over half the static approach (2.3 µm), and correlates with the approach's own change;
/// the elastic energy then ends at V(h_end) while the impulse paid for V(h⁺), and the
/// normal and gravity gain 1.1e-2 of E₀ over 3 s (`scenes::rattleback`'s energy split). With
/// the second solve they lose 2.6e-3 (the backward-Euler normal's own damping), the largest
/// miss left is 33 nm (2 % of the correction on average), and a second chord step changes the
/// energy rise by < 1 %.
pub fn solve_consistent_gap<T: Real, const K: usize>(
    cand: &[Candidate<T>; K],
    mut solve: impl FnMut(&[Candidate<T>; K]) -> Solution<T>,
    end_gap: impl Fn(&[[T; 4]; MAX_CONTACTS]) -> [T; K],
) -> Solution<T> {
    let first = solve(cand);
    let reached = end_gap(&first.w);
    let mut moved = *cand;
    let mut missed = false;
    for k in 0..K {
        let miss = reached[k] - first.h[k];
        if miss.is_finite() && miss != T::ZERO {
            moved[k].h_pred += miss;
            missed = true;
        }
    }
    if !missed {
        return first;
    }
    solve(&moved)
}

/// [`solve_with`] with the coupling `scheme` describes (G = γ·W).
fn fallback<T: Real, C: StepContact<T>, const K: usize>(
    dt: T,
    w: &InverseMass<T>,
    scheme: &Scheme<T>,
    contacts: &[&C; K],
    cand: &[Candidate<T>; K],
    warm: &mut Warm<T>,
) -> Solution<T> {
    let mut gap = *w;
    for row in gap.iter_mut() {
        for x in row.iter_mut() {
            *x *= scheme.gap();
        }
    }
    let cp = Coupling {
        w,
        gap: &gap,
        theta: scheme.theta(),
        pose: T::ONE - scheme.gap(),
    };
    solve_with(dt, &cp, contacts, cand, warm)
}

/// u⁺ = u_free + Δt·W·w̄ and h⁺ = h_pred − Δt²·(G·w̄)ₙ per contact.
fn end_state<T: Real, const K: usize>(
    dt: T,
    cp: &Coupling<'_, T>,
    cand: &[Candidate<T>; K],
    wbar: &[[T; 4]; MAX_CONTACTS],
) -> ([[T; 4]; MAX_CONTACTS], [T; MAX_CONTACTS]) {
    let mut u = [[T::ZERO; 4]; MAX_CONTACTS];
    let mut h = [T::ZERO; MAX_CONTACTS];
    for k in 0..K {
        let mut g = T::ZERO;
        for a in 0..4 {
            let mut s = T::ZERO;
            for j in 0..K {
                for b in 0..4 {
                    s += cp.w[4 * k + a][4 * j + b] * wbar[j][b];
                    if a == 0 {
                        g += cp.gap[4 * k][4 * j + b] * wbar[j][b];
                    }
                }
            }
            u[k][a] = cand[k].u_free[a] + dt * s + cand[k].drift[a];
        }
        h[k] = cand[k].h_pred - dt * dt * g;
    }
    (u, h)
}

/// x with m·x = r over the leading n × n block, Gaussian elimination with partial pivoting; a
/// zero pivot leaves that unknown at 0.
fn gauss<T: Real>(mut m: [[T; DIM]; DIM], mut r: [T; DIM], n: usize) -> [T; DIM] {
    for c in 0..n {
        let mut p = c;
        for i in c + 1..n {
            if m[i][c].abs() > m[p][c].abs() {
                p = i;
            }
        }
        m.swap(c, p);
        r.swap(c, p);
        let piv = m[c][c];
        if piv == T::ZERO {
            continue;
        }
        for i in c + 1..n {
            let f = m[i][c] / piv;
            if f == T::ZERO {
                continue;
            }
            for j in c..n {
                let mcj = m[c][j];
                m[i][j] -= f * mcj;
            }
            let rc = r[c];
            r[i] -= f * rc;
        }
    }
    let mut x = [T::ZERO; DIM];
    for c in (0..n).rev() {
        let mut s = r[c];
        for j in c + 1..n {
            s -= m[c][j] * x[j];
        }
        x[c] = if m[c][c] == T::ZERO {
            T::ZERO
        } else {
            s / m[c][c]
        };
    }
    x
}

/// What a step hands the next: the wrenches (the first iterate) and the end approaches (the
/// first linearisation point). [`Warm::default`] at the start.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Warm<T> {
    /// The last step's wrench per contact.
    pub w: [[T; 4]; MAX_CONTACTS],
    /// The last step's end approach per contact (m).
    pub h: [T; MAX_CONTACTS],
}

/// The exact torque-free rotation of a symmetric body (I₁ = I₂ = `i_eq`, I₃ = `i_polar` about
/// e₃) over `dt` from the attitude `q` with the world angular momentum `l`:
/// q(t) = rot(L̂, |L|t/I₁) ⊗ q ⊗ rot(e₃, (1/I₃ − 1/I₁)·L₃·t), L₃ = L·e₃ (the precession about L
/// and the body's own turn about e₃; ω = L/I₁ + (1/I₃ − 1/I₁)L₃e₃ in the world).
pub fn symmetric_free<T: Real>(q: Quat<T>, l: Vec3<T>, i_eq: T, i_polar: T, dt: T) -> Quat<T> {
    let lb = q.rotate_inv(l);
    let c = (T::ONE / i_polar - T::ONE / i_eq) * lb.z;
    let lw = l.norm();
    let precess = if lw > T::ZERO {
        let (s, co) = (T::HALF * lw * dt / i_eq).sin_cos();
        let ax = l * (s / lw);
        Quat {
            w: co,
            x: ax.x,
            y: ax.y,
            z: ax.z,
        }
    } else {
        Quat::identity()
    };
    precess
        .product(q)
        .product(Quat::about_z(c * dt))
        .normalized()
}

/// The rotation exp(dt·ω) ⊗ q by the world angular velocity `w` (rad/s) over `dt`.
pub fn rotate_by<T: Real>(q: Quat<T>, w: Vec3<T>, dt: T) -> Quat<T> {
    let n = w.norm();
    if !(n > T::ZERO) {
        return q;
    }
    let (s, c) = (T::HALF * n * dt).sin_cos();
    let ax = w * (s / n);
    Quat {
        w: c,
        x: ax.x,
        y: ax.y,
        z: ax.z,
    }
    .product(q)
    .normalized()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A linear spring-damper normal and a linear friction damper: the solve is exact.
    struct Linear;
    impl StepContact<f64> for Linear {
        fn wrench4(&self, s: &State<f64>) -> [f64; 4] {
            if s.h <= 0.0 {
                return [0.0; 4];
            }
            [
                1e6 * s.h + 10.0 * s.hdot,
                -50.0 * s.slip.vx(),
                -50.0 * s.slip.vy(),
                -1e-3 * s.slip.omega(),
            ]
        }
        fn limits(&self, _h: f64, n: f64) -> (f64, f64) {
            (1e3 * n, 1e3 * n)
        }
    }

    #[test]
    fn linear_contact_is_backward_euler() {
        // A point mass m = 1 on a spring k = 1e6 (ω = 1000 rad/s) at dt = 10 ms (h·ω = 10):
        // backward Euler v⁺ = v_free + dt·(k h⁺ − c v⁺)/m, h⁺ = h_pred − dt(v⁺ − v_free).
        let dt = 1e-2;
        let site = Site {
            arm: Vec3::new(0.0, 0.0, -0.01),
            axes: [
                Vec3::new(1.0, 0.0, 0.0),
                Vec3::new(0.0, 1.0, 0.0),
                Vec3::unit_z(),
            ],
        };
        let w = rigid_w(
            1.0,
            &InvInertia::new(Quat::identity(), Vec3::new(1e3, 1e3, 1e3)),
            &[site],
        );
        let cand = [Candidate {
            h_pred: 1e-3,
            u_free: [-0.1, 0.2, 0.0, 3.0],
            rolling: RollingVelocity::default(),
            drift: [0.0; 4],
        }];
        let s = solve(dt, &w, &[&Linear], &cand, &mut Warm::default());
        let (wn, k, c) = (w[0][0], 1e6, 10.0);
        // N = k h⁺ − c v⁺ with v⁺ = v_f + dt·wn·N, h⁺ = h_p − dt·dt·wn·N.
        let n = (k * 1e-3 - c * -0.1) / (1.0 + k * dt * dt * wn + c * dt * wn);
        assert!((s.w[0][0] - n).abs() < 1e-9 * n, "{} {n}", s.w[0][0]);
        assert!(s.u[0].iter().all(|x| x.is_finite()));
        // Friction: passive at the end velocity.
        assert!(s.w[0][1] * s.u[0][1] <= 0.0 && s.w[0][3] * s.u[0][3] <= 0.0);
    }

    #[test]
    fn symmetric_free_rotation_matches_a_fine_integration() {
        let (i1, i3) = (8e-7, 7e-7);
        let q0 = Quat::<f64>::about_x(0.3);
        let wb = Vec3::new(0.5, -1.0, 180.0);
        let l = q0.rotate(Vec3::new(i1 * wb.x, i1 * wb.y, i3 * wb.z));
        let exact = symmetric_free(q0, l, i1, i3, 0.05);
        // Fine RK4 of Euler's equations + q̇ = ½ q ⊗ ω.
        let (mut q, mut w) = (q0, wb);
        let inertia = Vec3::new(i1, i1, i3);
        let n = 50_000;
        let h = 0.05 / n as f64;
        for _ in 0..n {
            let f = |q: Quat<f64>, w: Vec3<f64>| {
                (
                    q.derivative(w),
                    super::super::rigid::euler_rate(inertia, w, Vec3::zero()),
                )
            };
            let add = |q: Quat<f64>, d: Quat<f64>, s: f64| Quat {
                w: q.w + s * d.w,
                x: q.x + s * d.x,
                y: q.y + s * d.y,
                z: q.z + s * d.z,
            };
            let (q1, w1) = f(q, w);
            let (q2, w2) = f(add(q, q1, h / 2.0), w + w1 * (h / 2.0));
            let (q3, w3) = f(add(q, q2, h / 2.0), w + w2 * (h / 2.0));
            let (q4, w4) = f(add(q, q3, h), w + w3 * h);
            q = add(q, add(add(q1, q4, 1.0), add(q2, q3, 1.0), 2.0), h / 6.0);
            w = w + (w1 + w4 + (w2 + w3) * 2.0) * (h / 6.0);
            q = q.normalized();
        }
        let e = Vec3::new(1.0, 2.0, 3.0);
        assert!(
            (exact.rotate(e) - q.rotate(e)).norm() < 1e-8,
            "{:?} {:?}",
            exact,
            q
        );
    }
}
