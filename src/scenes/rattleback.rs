//! The rattleback (celt): a rigid semi-ellipsoid whose principal axes of inertia are turned by
//! a small skew angle δ from its axes of curvature, on a rigid, fixed floor, with a compliant
//! contact whose geometry changes every step — the case [`VaryingContact`] exists for. Spun
//! one way it rocks, stops and reverses; spun the other way it keeps spinning.
//!
//! Parameters: Kane & Levinson (1982), *Realistic mathematical modeling of the rattleback*,
//! Int. J. Non-Linear Mech. 17, 175 — the body most later work (Garcia & Hubbard 1988,
//! Kondo & Nakanishi 2017) compares against; see [`Params::kane_levinson`].
//!
//! # Model
//!
//! - **Curvature frame** C (body-fixed): origin at the ellipsoid's centre O, axes along its
//!   semi-axes a₁ (long), a₂, a₃ (short: the symmetry axis, pointing out of the flat top). The
//!   surface is Σ xᵢ²/aᵢ² = 1; the centre of mass G lies on the symmetry axis at
//!   O − ε·e₃ (ε > 0: G below O, towards the rocking bottom).
//! - **Body frame** B: the principal axes of inertia at G, turned by +δ about e₃ from C (a
//!   vector with B coordinates v has C coordinates R_z(δ)·v). Euler's equations are written in
//!   B ([`euler_rate`]), the attitude q maps B to the world.
//! - **State** (13 scalars, [`State`]): G (m), Ġ (m/s), q = (w, x, y, z), ω in B (rad/s).
//! - **Contact, in closed form each step** (no iteration; [`Rattleback::geometry`]): with
//!   u = −ẑ in C coordinates (the world's "down" seen from the body) the lowest point of the
//!   ellipsoid is its support point in direction u,
//!
//!   ```text
//!   s = √(Σ aᵢ² uᵢ²),   x*ᵢ = aᵢ² uᵢ / s   (C frame),   approach h = −(height of x*)
//!   ```
//!
//!   The outward normal there is −ẑ, so the tangent plane is the floor's plane and the
//!   surface is, to second order, the graph z = ½ ξᵀKξ over the world (x, y) with
//!   K = s·Tᵀ diag(1/aᵢ²) T, T the world x̂, ŷ in C coordinates (the Hessian of xᵀAx = 1
//!   divided by |∇| = 2/s). The floor is flat, so the gap is z = ξᵀ(½K)ξ:
//!   [`Curvatures::from_quadratic`] gives P ≤ Q and the major axis' angle φ from world x.
//!   Cost: one `sqrt`, one `hypot`, one `atan2` and one `sin_cos`.
//! - **Contact frame**: z = world ẑ (floor = body A, rattleback = body B), x = (cos φ, sin φ, 0)
//!   along the patch's major axis, y = ẑ × x. The patch centre P is the floor point below x*.
//!   Slip: the velocity of the rattleback's material point at P, in (x, y); spin: ω·ẑ;
//!   ḣ = −(vertical velocity of that point).
//! - **Wrench**: [`VaryingContact::wrench`] — exact Hertz on this step's P, Q through
//!   [`crate::shape::Table`], Hunt–Crossley N = k h^{3/2}(1 + (3/2)c_d ḣ) clamped ≥ 0, friction
//!   by the law `L` (Best, Simplified, Ellipsoid, Coulomb). Slip, ḣ and the world force and
//!   torque about G through [`crate::frame`] (normal ẑ, reference tangent world x).
//! - **Rolling** ([`Creeping`], [`Rattleback::rolling`]): a rolling law (Kalker's creep,
//!   `Table`, `Blend`) through [`Rolling`] on the same contact with `Best`, fed the contact's
//!   rolling velocity V = v_P − ½u_B in closed form ([`Kinematics`]) and the pair's elasticity
//!   ([`Params::elasticity`]); the contact's δ is not used. Near V = 0 the creep rate grows
//!   as 1/|V| and an explicit step chatters there (the user guide, docs/guide/src/rattleback.md, "The rattleback rolling").
//!
//! # Diagnostics ([`Probe`])
//!
//! - Energy ½m|Ġ|² + ½ωᵀIω + m g G_z + (2/5)k_H h^{5/2}, k_H the Hertz constant of the current
//!   curvatures. Friction and damping dissipate; the elastic term is a potential only at fixed
//!   curvature; the error of that is O(N·h·Δk/k), below the 1e-6·E₀ that the tests allow.
//! - Spin ω·ẑ (rad/s, world vertical component), pitch = asin(a₁-axis · ẑ) (the long axis'
//!   elevation), roll = asin(a₂-axis · ẑ) (rad).

use super::event::{Crossing, Direction};
use super::integrate::Ode;
use super::rigid::{Quat, Vec3, euler_rate};
use super::step_aware::{
    Candidate, InvInertia, Site, StepContact, Warm, rigid_w, rotate_by, solve_consistent_gap,
    solve_library,
};
use crate::contact::Rolling;
use crate::contact::VaryingContact;
use crate::contact::Wrench;
use crate::frame::{ContactFrame, Frame, Load, MajorAxis, point_velocity};
use crate::friction::rolling::{Elasticity, RollingLaw, RollingVelocity};
use crate::friction::{Best, Friction, FrictionLaw, Slip};
use crate::geometry::Curvatures;
use crate::jacobian::State as StepState;
use crate::normal::{Hertz, HuntCrossley, Modulus, NormalLaw};
use crate::shape::Newton;
use crate::step::Scheme;
use crate::{Error, Real};
use core::marker::PhantomData;

/// The slip scale δ (m/s) for runs of this scene with `Best` (the default law): 0.1 mm/s, small
/// enough that the outcome and the event times are those of the limit δ → 0, whatever the
/// shape of the law's ramp below δ. Kane & Levinson's start at ω₀ = ∓2 rad/s: stall at
/// 0.83650 s / 1.17308 s (fine-step RK4), the same to 4 digits at δ = 0.5 … 0.02 mm/s with the
/// ramp by the ℓ¹ slip speed min(1, s/δ) or by the dissipation min(1, p/(3δ/8)) (the library's),
/// and at δ ≤ 0.1 mm/s with min(1, p/δ). At δ = 1 mm/s the ramp is a knob: the stall comes
/// 0.8432 s, 0.8631 s or, with p/δ, a reversal at 1.92 s (table and reason:
/// docs/guide/src/time-stepping.md, "The slip scale δ of the scenes"). The stall is at
/// |ω| = 0.2 rad/s; the ramp only acts below a|ω| ≈ δ (a ≈ 3 mm), so for δ ≲ 0.5 mm/s it does
/// not reach the event. RK4 needs h ≤ 20 µs at this δ (the ramp's stiffness fN/δ);
/// the step-aware integrator ([`Rattleback::step_aware`]) holds to 2 ms.
pub const BEST_DELTA: f64 = 1e-4;

/// The slip scale δ (m/s) for runs of this scene with `Simplified`: 0.1 mm/s, the δ → 0 limit
/// as for [`BEST_DELTA`]. Kane & Levinson's start at ω₀ = ∓2 rad/s, fine-step RK4 (h = 0.1·δ/(1
/// mm/s) ms, the same to 1 µs at h/2): stall at 1.16606 s / 2.21118 s, the same to 1 µs at
/// 0.05, 0.02, 0.01 and 0.005 mm/s; at 0.2 mm/s the steady stall is 14 ms early (2.1972 s), at
/// 1 mm/s the unstable spin *reverses* (1.9351 s) and the steady one stalls at 2.3256 s (table:
/// bench-results/rattleback-delta.md; docs/guide/src/time-stepping.md, "The slip scale δ of the
/// scenes"). RK4 needs h ≤ 10 µs at this δ. The step-aware integrator gives the same outcome
/// at every step to 2 ms, within 0.01 % to 0.5 ms, 0.19 % at 1 ms and 0.71 % at 2 ms
/// (bench-results/step-sweep.md): `Simplified` is not maximally dissipative, so the step's
/// limit set for it is the cylinder |F| ≤ F_max, |T_z| ≤ T_max
/// ([`crate::friction::FrictionLaw::MAXIMALLY_DISSIPATIVE`]).
pub const SIMPLIFIED_DELTA: f64 = 1e-4;

/// The slip scale δ (m/s) for runs of this scene with `Coulomb` (point contact): 0.01 mm/s.
/// Unlike the Contensou laws, Coulomb's rolling is held by the regularisation alone (no
/// drilling torque, no patch): the contact creeps at |v_P| ≈ δ·|F_t|/(fN) and dissipates
/// ≈ |F_t|²δ/(fN), so the reversal moves linearly with δ, ≈ 80 ms per mm/s, down to δ → 0.
/// Fine-step RK4 at ω₀ = −2 rad/s (h = 0.2·δ/(1 mm/s) ms, the same to 1e-8 s at h/4): reversal
/// at 2.4305 s (δ = 1 mm/s), 2.3687 s (0.1), 2.3725 s (0.05), 2.3749 s (0.02), **2.37570 s**
/// (0.01), 2.3761 s (0.005): within 1 ms of the limit ≈ 2.3765 s from 0.01 mm/s down — the
/// rigid no-slip rolling model's 2.376 s (`tools/rattleback_noslip.py`, independent of the
/// crate). ω₀ = +2 rad/s neither reverses nor stalls within 3 s at any δ; at this δ it reverses
/// at 23.54 s (no-slip: 23.37 s).
/// RK4 needs h ≤ 2 µs at this δ; the step-aware integrator holds to 2 ms: the reversal
/// −0.11 % at 1 ms, −0.63 % at 2 ms (energy rise 5.3e-4 of E₀;
/// docs/guide/src/scenes-large-steps.md). `Ellipsoid` needs no
/// such constant: it ignores δ (Coulomb's sign law at rest).
pub const COULOMB_DELTA: f64 = 1e-5;

/// Number of scalars in the state.
pub const N: usize = 13;

/// The state [G (3), Ġ (3), q = (w, x, y, z) (4), ω body (3)].
pub type State<T> = [T; N];

/// The rattleback's physical parameters (SI).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params<T> {
    /// Semi-axes a₁ (long), a₂, a₃ (symmetry axis) of the ellipsoid (m).
    pub semi_axes: [T; 3],
    /// Distance ε from the ellipsoid's centre O down the symmetry axis to G (m).
    pub com_offset: T,
    /// Mass m (kg).
    pub mass: T,
    /// Principal moments of inertia about G (kg·m²), in the order of the axes nearest a₁, a₂, a₃.
    pub inertia: [T; 3],
    /// Skew angle δ (rad) from the curvature axis a₁ to the first principal axis of inertia,
    /// positive about e₃.
    pub skew: T,
    /// Effective modulus E* (Pa).
    pub estar: T,
    /// Hunt–Crossley damping c_d (s/m).
    pub damping: T,
    /// Gravity g (m/s²).
    pub gravity: T,
}

impl<T: Real> Params<T> {
    /// Kane & Levinson's rattleback (1982; also in the `RattleBack` PyPI package and the
    /// pydy rattleback examples): a = 0.2 m, b = 0.03 m, c = 0.02 m, ε = 0.01 m, m = 1 kg, and
    /// about G in the curvature frame I₁₁ = A = 2e-4, I₂₂ = B = 1.6e-3, I₃₃ = C = 1.7e-3,
    /// I₁₂ = D = −2e-5 kg·m² (D the tensor entry). Diagonalised here: δ = ½·atan(2D/(A − B))
    /// = +0.014283 rad (0.82°), I₁,₂ = (A+B)/2 ∓ √(((B−A)/2)² + D²).
    ///
    /// Contact (our choice, not in the sources): E* = 3 GPa (a hard polymer on glass), static
    /// approach ≈ 2.3 µm under mg (Hertz at the rest point: P = c/(2a²) = 0.25, Q = c/(2b²) =
    /// 11.1 m⁻¹, P/Q = 0.0225), vertical contact frequency √(1.5mg/h)/(2π√m) ≈ 400 Hz;
    /// c_d = 5 s/m as for the tippe top.
    pub fn kane_levinson() -> Self {
        let (a, b, c, d) = (2e-4f64, 1.6e-3f64, 1.7e-3f64, -2e-5f64);
        let mean = 0.5 * (a + b);
        let r = (0.5 * (b - a)).hypot(d);
        let skew = 0.5 * libm::atan(2.0 * d / (a - b));
        let t = T::from_f64;
        Params {
            semi_axes: [t(0.2), t(0.03), t(0.02)],
            com_offset: t(0.01),
            mass: t(1.0),
            inertia: [t(mean - r), t(mean + r), t(c)],
            skew: t(skew),
            estar: t(3e9),
            damping: t(5.0),
            gravity: t(9.81),
        }
    }

    /// The pair's tangential elastic constants for the rolling laws, consistent with `estar`:
    /// a hard polymer (E₁ = 2.744 GPa, ν₁ = 0.35: PMMA-like) on soda-lime glass (E₂ = 70 GPa,
    /// ν₂ = 0.22), whose E* = 1/((1−ν₁²)/E₁ + (1−ν₂²)/E₂) is the default 3.00 GPa, combined by
    /// Kalker's rule for dissimilar bodies ([`Elasticity::dissimilar`]; Gᵢ = Eᵢ/(2(1+νᵢ))):
    /// G = 1.963 GPa, ν = 0.346. For another `estar` (the stiffness study) G is scaled by
    /// estar/E*_pair (the same G/E* = 0.654 and ν).
    ///
    /// Errors: those of [`Elasticity::dissimilar`] (a non-positive or non-finite E*).
    pub fn elasticity(&self) -> Result<Elasticity<T>, Error> {
        let (e1, nu1, e2, nu2) = (2.744e9f64, 0.35f64, 70e9f64, 0.22f64);
        let pair_estar = 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
        let g = |e: f64, nu: f64| e / (2.0 * (1.0 + nu));
        let scale = self.estar / T::from_f64(pair_estar);
        let t = T::from_f64;
        Elasticity::dissimilar(t(g(e1, nu1)) * scale, t(nu1), t(g(e2, nu2)) * scale, t(nu2))
    }

    /// The same body with equal bottom curvatures (a₂ = a₁ = 0.2 m: a sphere-like bottom of
    /// radius a₁²/a₃ in every direction at rest) and no skew (δ = 0): nothing should reverse.
    pub fn sphere_like() -> Self {
        let p = Self::kane_levinson();
        Params {
            semi_axes: [p.semi_axes[0], p.semi_axes[0], p.semi_axes[2]],
            skew: T::ZERO,
            ..p
        }
    }
}

/// The contact geometry at one state, in closed form (see the [module docs](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry<T> {
    /// Approach h (m): depth of the ellipsoid's lowest point below the floor (negative: apart).
    pub h: T,
    /// G → patch centre P (the floor point below the lowest point), world frame (m).
    pub arm: Vec3<T>,
    /// The lowest point of the ellipsoid relative to G, world frame (m).
    pub lowest: Vec3<T>,
    /// P, Q of the gap z = P x² + Q y² and the major axis' angle from world x.
    pub curvatures: Curvatures<T>,
}

/// Where the energy change of one step-aware step went (J; [`Rattleback::step_aware_split`]).
/// The parts sum to the change of [`Probe::energy`] over the step, to rounding.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EnergySplit<T> {
    /// The rotation update's own error: the change of the rotational energy ½L·I⁻¹L over the
    /// two torque-free half-turns (L fixed in each; zero for an exact torque-free rotation).
    pub rotation: T,
    /// The normal force and gravity: the normal impulse's work, gravity's kick and the change
    /// of the potential energy m·g·G_z and of the contact's elastic energy. ≤ 0 on average for a
    /// step consistent with the normal law (the backward-Euler normal and Hunt–Crossley damp);
    /// its per-step value swings with the load (the step's bounded O(Δt²) energy error).
    pub normal: T,
    /// The friction impulse's work (F_x, F_y, T_z): at the mid-step pose, with the mean of the
    /// contact velocities before and after the impulse.
    pub friction: T,
}

/// What the contact does at a state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactState<T> {
    /// Approach h (m), negative when apart.
    pub h: T,
    /// Normal force N (N).
    pub n: T,
    /// Force on the rattleback, world frame (N).
    pub force: Vec3<T>,
    /// Torque on the rattleback about G, world frame (N·m).
    pub torque: Vec3<T>,
}

/// Diagnostics of a state (see the [module docs](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Probe<T> {
    /// Spin ω·ẑ (rad/s).
    pub spin: T,
    /// Pitch: elevation of the long axis a₁ (rad).
    pub pitch: T,
    /// Roll: elevation of the axis a₂ (rad).
    pub roll: T,
    /// Total mechanical energy incl. the contact's elastic energy (J).
    pub energy: T,
    /// Normal force (N).
    pub n: T,
    /// Friction ratio |F_t|/N (0 without contact).
    pub friction_ratio: T,
    /// Approach h (m).
    pub h: T,
}

/// The contact's kinematics at a state (world frame; horizontal vectors, z = 0).
///
/// - `contact_point` v_P: the velocity of the geometric contact point P, the floor point below
///   the support point x* — which moves over the body as it turns. With u the world's "down"
///   in curvature coordinates (world-fixed, so u̇ = −ω × u, ω in curvature coordinates) and
///   x*ᵢ = aᵢ²uᵢ/s, s² = Σaᵢ²uᵢ², in closed form:
///
///   ```text
///   ẋ* = (A u̇ − x* (x*·u̇)) / s,   A = diag(aᵢ²)     (ṡ = x*·u̇)
///   v_P = horizontal part of  Ġ + ω × (x* − G) + R ẋ*
///   ```
///
/// - `material` u_B: the rattleback's material velocity at P, Ġ + ω × (P − G), horizontal
///   (the slip the friction laws take; the floor, body A, is at rest: u_A = 0).
/// - `rolling` V = v_P − ½(u_A + u_B): the velocity at which the contact point moves over the
///   two surfaces relative to their material, averaged (Kalker's rolling velocity).
///
/// Rolling without slip about a principal axis of curvature: u_B = 0 and |V| = ρω, ρ the
/// radius of curvature in the rolling plane; a pure spin about the vertical through x*: V = 0
/// (`host-tests/rattleback.rs`). Cost: one quaternion rotation, three cross/dot products, ≈ 40
/// multiply-adds; no division beyond the geometry's 1/s, no root.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Kinematics<T> {
    /// v_P (m/s).
    pub contact_point: Vec3<T>,
    /// u_B (m/s).
    pub material: Vec3<T>,
    /// V = v_P − ½u_B (m/s).
    pub rolling: Vec3<T>,
}

/// The support point in the curvature frame: the direction u, x* and 1/s.
#[derive(Clone, Copy, Debug)]
struct Support<T> {
    u: Vec3<T>,
    x: Vec3<T>,
    inv_len: T,
}

impl<T: Real> Support<T> {
    /// ẋ* (curvature frame) for the angular velocity `omega_c` (curvature frame) and the
    /// squared semi-axes `axes2`: (A u̇ − x*(x*·u̇))/s with u̇ = −ω × u ([`Kinematics`]).
    #[inline(always)]
    fn rate(&self, axes2: &[T; 3], omega_c: Vec3<T>) -> Vec3<T> {
        let du = self.u.cross(omega_c);
        let a_du = Vec3::new(axes2[0] * du.x, axes2[1] * du.y, axes2[2] * du.z);
        (a_du - self.x * self.x.dot(du)) * self.inv_len
    }
}

/// What a step hands the floor contact's law, in the contact frame (x along the major axis).
#[derive(Clone, Copy, Debug)]
pub struct Step<'a, T> {
    /// This step's curvatures.
    pub curvatures: &'a Curvatures<T>,
    /// Approach h (m).
    pub h: T,
    /// ḣ (m/s).
    pub hdot: T,
    /// The slip of the rattleback's material at P over the floor, and its spin.
    pub slip: Slip<T>,
    /// The rolling velocity V (m/s, [`Kinematics::rolling`]) along x, y.
    pub rolling: [T; 2],
}

/// The floor contact's law: how the scene turns a step's geometry and kinematics into the
/// contact's wrench. Every [`FrictionLaw`] is one (full
/// slip through [`VaryingContact`]: the rolling velocity is ignored, bit for bit the scene
/// before it existed).
pub trait FloorLaw<T: Real> {
    /// The contact built once per scene.
    type Contact: Clone + core::fmt::Debug;
    /// The wrench's branch tag ([`FrictionLaw::Branch`]; `()` for the rolling laws).
    type Branch;
    /// Whether the law is maximally dissipative
    /// ([`FrictionLaw::MAXIMALLY_DISSIPATIVE`]; `true` for the rolling laws): the step-aware
    /// wrench's limit set.
    const MAXIMALLY_DISSIPATIVE: bool;
    /// The wrench on the rattleback (contact frame) for `step`.
    fn wrench(contact: &Self::Contact, step: &Step<'_, T>) -> Wrench<T, Self::Branch>;
}

impl<T: Real, L: FrictionLaw> FloorLaw<T> for L {
    type Contact = VaryingContact<T, HuntCrossley<T>, L>;
    type Branch = L::Branch;
    const MAXIMALLY_DISSIPATIVE: bool = L::MAXIMALLY_DISSIPATIVE;

    #[inline(always)]
    fn wrench(contact: &Self::Contact, step: &Step<'_, T>) -> Wrench<T, L::Branch> {
        contact.wrench(step.curvatures, step.h, step.hdot, step.slip)
    }
}

/// A rolling law `L` ([`RollingLaw`]: `Table`, `Blend`, …) on the floor contact, as a
/// [`FloorLaw`]: [`Rolling`] over the scene's [`VaryingContact`] with `Best` (its δ is not
/// used), fed the step's rolling velocity ([`Kinematics::rolling`], contact frame). Build it
/// with [`Rattleback::rolling`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Creeping<L>(PhantomData<L>);

impl<T: Real, L: RollingLaw> FloorLaw<T> for Creeping<L> {
    type Contact = Rolling<T, VaryingContact<T, HuntCrossley<T>, Best>, L>;
    type Branch = ();
    const MAXIMALLY_DISSIPATIVE: bool = true;

    #[inline(always)]
    fn wrench(contact: &Self::Contact, step: &Step<'_, T>) -> Wrench<T, ()> {
        // Non-finite only if the state is (then the step is rejected anyway): V = 0, full slip.
        let v = RollingVelocity::new(step.rolling[0], step.rolling[1]).unwrap_or_default();
        contact.wrench(step.curvatures, step.h, step.hdot, step.slip, v)
    }
}

/// The rattleback with the floor contact's law `L`: a friction law (full slip) or a rolling
/// law ([`FloorLaw`]; see the [module docs](self)).
#[derive(Clone, Debug)]
pub struct Rattleback<T: Real, L: FloorLaw<T>> {
    mass: T,
    gravity: T,
    inertia: Vec3<T>,
    /// aᵢ².
    axes2: [T; 3],
    /// 1/aᵢ².
    inv_axes2: [T; 3],
    com_offset: T,
    /// cos δ, sin δ.
    skew: (T, T),
    /// The curvatures at rest (fallback for a degenerate state).
    rest: Curvatures<T>,
    estar: Modulus<T>,
    contact: L::Contact,
}

impl<T: Real, L: FrictionLaw> Rattleback<T, L> {
    /// The rattleback `p` with the friction law `friction` (full slip: the rolling velocity is
    /// not used).
    ///
    /// Errors: [`Error::LengthNotPositive`] for a semi-axis ≤ 0, [`Error::NonFinite`], and
    /// those of [`Modulus::new`] and [`HuntCrossley::new`].
    pub fn new(p: &Params<T>, friction: Friction<T, L>) -> Result<Self, Error> {
        Self::build(p, |estar, damping| {
            Ok(VaryingContact::new(estar, damping, friction))
        })
    }
}

impl<T: Real, L: RollingLaw> Rattleback<T, Creeping<L>> {
    /// The rattleback `p` with the rolling law `L` (Kalker's creep, saturating to `Best`'s
    /// full slip on the real patch): coefficient of friction from `friction` (its δ is not
    /// used), the pair's tangential elastic constants `elasticity` ([`Params::elasticity`] for
    /// the default polymer on glass).
    ///
    /// Errors: those of [`Rattleback::new`].
    pub fn rolling(
        p: &Params<T>,
        friction: Friction<T, Best>,
        elasticity: Elasticity<T>,
    ) -> Result<Self, Error> {
        Self::build(p, |estar, damping| {
            Rolling::new(VaryingContact::new(estar, damping, friction), elasticity)
        })
    }
}

impl<T: Real, L: FloorLaw<T>> Rattleback<T, L> {
    /// The parameters' common part, validated, with the contact `contact` makes from E* and
    /// the damping.
    fn build(
        p: &Params<T>,
        contact: impl FnOnce(Modulus<T>, HuntCrossley<T>) -> Result<L::Contact, Error>,
    ) -> Result<Self, Error> {
        let mut axes2 = [T::ZERO; 3];
        let mut inv_axes2 = [T::ZERO; 3];
        for ((a2, inv), a) in axes2.iter_mut().zip(inv_axes2.iter_mut()).zip(p.semi_axes) {
            let a = crate::error::finite(a, "semi-axis")?;
            if a <= T::ZERO {
                return Err(Error::LengthNotPositive);
            }
            *a2 = a * a;
            *inv = T::ONE / (a * a);
        }
        let estar = Modulus::new(p.estar)?;
        let a3 = p.semi_axes[2];
        let rest = Curvatures::new(T::HALF * a3 * inv_axes2[0], T::HALF * a3 * inv_axes2[1])?;
        let (sin, cos) = crate::error::finite(p.skew, "skew")?.sin_cos();
        Ok(Rattleback {
            mass: p.mass,
            gravity: p.gravity,
            inertia: Vec3::new(p.inertia[0], p.inertia[1], p.inertia[2]),
            axes2,
            inv_axes2,
            com_offset: crate::error::finite(p.com_offset, "com offset")?,
            skew: (cos, sin),
            rest,
            estar,
            contact: contact(estar, HuntCrossley::new(p.damping)?)?,
        })
    }

    /// Kane & Levinson's start: roll and pitch `tilt` (rad) each (a₂- and a₁-axis rotations of
    /// the curvature frame), spin `spin` (rad/s) about the world vertical, the lowest point at
    /// the static approach and at rest (rolling: Ġ = −ω × (G → P)).
    pub fn initial_state(&self, tilt: T, spin: T) -> State<T> {
        let (c, s) = self.skew;
        // Curvature frame → world: roll about a₁ (x), then pitch about the turned a₂ (y); the
        // body frame is the curvature frame turned by δ about e₃.
        let q = Quat::about_x(tilt)
            .product(Quat::about_y(tilt))
            .product(Quat::about_z(s.atan2(c)))
            .normalized();
        let omega_w = Vec3::new(T::ZERO, T::ZERO, spin);
        let omega = q.rotate_inv(omega_w);
        let mut y = pack(Vec3::zero(), Vec3::zero(), q, omega);
        let g0 = self.geometry(&y);
        let h0 = self.static_approach(&g0.curvatures);
        let r = Vec3::new(T::ZERO, T::ZERO, -g0.lowest.z - h0);
        y = pack(r, Vec3::zero(), q, omega);
        let arm = self.geometry(&y).arm;
        pack(r, -omega_w.cross(arm), q, omega)
    }

    /// The static approach (mg/k_H)^{2/3} at the given curvatures (exact Hertz).
    fn static_approach(&self, c: &Curvatures<T>) -> T {
        let k = Hertz::new::<Newton>(c, self.estar)
            .map(|h| h.stiffness())
            .unwrap_or(T::ONE);
        let x = self.mass * self.gravity / k;
        // x^{2/3} = (x²)^{1/3}, host-side only (initial state).
        (x * x).cbrt()
    }

    /// The contact geometry at state `y` in closed form (module docs). Total; a degenerate
    /// (non-finite) state gives the curvatures of the body at rest.
    pub fn geometry(&self, y: &State<T>) -> Geometry<T> {
        let (r, _, q, _) = split(y);
        self.geometry_at(r, q.normalized()).0
    }

    /// The geometry, and the support point's data in the curvature frame that its rate
    /// ([`Support::rate`]) needs.
    #[inline(always)]
    fn geometry_at(&self, r: Vec3<T>, q: Quat<T>) -> (Geometry<T>, Support<T>) {
        let [wx, wy, wz] = q.world_axes_in_body();
        let (c, s) = self.skew;
        let to_c = |v: Vec3<T>| self.to_curvature(v);
        let [a1, a2, a3] = self.axes2;
        let [i1, i2, i3] = self.inv_axes2;
        let u = -to_c(wz);
        let su = Vec3::new(a1 * u.x, a2 * u.y, a3 * u.z);
        let len = su.dot(u).sqrt();
        let inv = T::ONE / len;
        // Lowest point in curvature, then body coordinates, relative to G.
        let xc = su * inv;
        let lowest_b = Vec3::new(
            c * xc.x + s * xc.y,
            -s * xc.x + c * xc.y,
            xc.z + self.com_offset,
        );
        let lowest = q.rotate(lowest_b);
        let h = -(r.z + lowest.z);
        // Curvature matrix of the graph over world (x, y): K = s·Tᵀ A T; the gap is ½K.
        let tx = to_c(wx);
        let ty = to_c(wy);
        let form = |p: Vec3<T>, q: Vec3<T>| p.x * q.x * i1 + p.y * q.y * i2 + p.z * q.z * i3;
        let half_len = T::HALF * len;
        let curvatures = Curvatures::from_quadratic(
            half_len * form(tx, tx),
            half_len * form(ty, ty),
            half_len * form(tx, ty),
        )
        .unwrap_or(self.rest);
        (
            Geometry {
                h,
                arm: Vec3::new(lowest.x, lowest.y, -r.z),
                lowest,
                curvatures,
            },
            Support {
                u,
                x: xc,
                inv_len: inv,
            },
        )
    }

    /// Body (principal) → curvature coordinates: R_z(δ)·v.
    #[inline(always)]
    fn to_curvature(&self, v: Vec3<T>) -> Vec3<T> {
        let (c, s) = self.skew;
        Vec3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
    }

    /// Curvature → body (principal) coordinates: R_z(−δ)·v.
    #[inline(always)]
    fn to_body(&self, v: Vec3<T>) -> Vec3<T> {
        let (c, s) = self.skew;
        Vec3::new(c * v.x + s * v.y, -s * v.x + c * v.y, v.z)
    }

    /// The contact's kinematics at state `y` (see [`Kinematics`]): the velocity of the
    /// geometric contact point, the rattleback's material velocity there and the rolling
    /// velocity, in closed form.
    pub fn kinematics(&self, y: &State<T>) -> Kinematics<T> {
        let (r, v, q, omega) = split(y);
        let q = q.normalized();
        let (g, support) = self.geometry_at(r, q);
        self.kinematics_at(v, q, omega, &g, &support)
    }

    #[inline(always)]
    fn kinematics_at(
        &self,
        v: Vec3<T>,
        q: Quat<T>,
        omega: Vec3<T>,
        g: &Geometry<T>,
        support: &Support<T>,
    ) -> Kinematics<T> {
        let w = q.rotate(omega);
        let flat = |p: Vec3<T>| Vec3::new(p.x, p.y, T::ZERO);
        // The floor point below x* moves with x*'s horizontal velocity: the material velocity
        // of x* plus the support point's own travel over the body.
        let travel = q.rotate(self.to_body(support.rate(&self.axes2, self.to_curvature(omega))));
        let contact_point = flat(v + w.cross(g.lowest) + travel);
        let material = flat(v + w.cross(g.arm));
        Kinematics {
            contact_point,
            material,
            rolling: contact_point - material * T::HALF,
        }
    }

    /// The contact at state `y`.
    pub fn contact(&self, y: &State<T>) -> ContactState<T> {
        let (r, v, q, omega) = split(y);
        self.contact_at(r, v, q.normalized(), omega).0
    }

    /// The contact at G = `r`, Ġ = `v`, unit attitude `q`, body angular velocity `omega`;
    /// also the geometry it used.
    #[inline(always)]
    fn contact_at(
        &self,
        r: Vec3<T>,
        v: Vec3<T>,
        q: Quat<T>,
        omega: Vec3<T>,
    ) -> (ContactState<T>, Geometry<T>) {
        let (g, support) = self.geometry_at(r, q);
        if g.h <= T::ZERO {
            return (
                ContactState {
                    h: g.h,
                    ..ContactState::default()
                },
                g,
            );
        }
        // Contact frame: z up (floor = A → rattleback = B), reference tangent world x (the
        // frame `Curvatures::from_quadratic` measured the major angle in).
        let z = [T::ZERO, T::ZERO, T::ONE];
        let frame = Frame::new(z, [T::ONE, T::ZERO, T::ZERO], MajorAxis::of(&g.curvatures));
        let w = q.rotate(omega);
        let (arm, w) = (g.arm.into(), w.into());
        // The floor is at rest: v_rel is the rattleback's material point at P.
        let v_rel = point_velocity(v.into(), w, arm);
        // Non-finite only if the state is: then no friction (the step is rejected anyway).
        let slip = frame.slip(v_rel, w).unwrap_or_default();
        // The rolling velocity in the contact frame (dead code for the full-slip laws).
        let [vx, vy, _] =
            frame.to_contact(self.kinematics_at(v, q, omega, &g, &support).rolling.into());
        let step = Step {
            curvatures: &g.curvatures,
            h: g.h,
            hdot: frame.approach_rate(v_rel),
            slip,
            rolling: [vx, vy],
        };
        let wr = L::wrench(&self.contact, &step);
        let Load { force, torque } = frame.on_b(&wr, arm);
        (
            ContactState {
                h: g.h,
                n: wr.n,
                force: force.into(),
                torque: torque.into(),
            },
            g,
        )
    }

    /// The contact's elastic energy (2/5)k_H h^{5/2} at the geometry `g` (0 when apart).
    fn elastic(&self, g: &Geometry<T>) -> T {
        if g.h > T::ZERO {
            Hertz::new::<Newton>(&g.curvatures, self.estar)
                .map(|k| k.energy(g.h))
                .unwrap_or(T::ZERO)
        } else {
            T::ZERO
        }
    }

    /// [`Rattleback::elastic`] at G = `r` and the unit attitude `q`.
    fn elastic_at(&self, r: Vec3<T>, q: Quat<T>) -> T {
        self.elastic(&self.geometry_at(r, q).0)
    }

    /// The spin ω·ẑ (rad/s, world vertical component) at state `y`: the event function of
    /// [`SpinEvents`], cheaper than [`Rattleback::probe`] (no contact evaluation).
    #[inline]
    pub fn spin(&self, y: &State<T>) -> T {
        let (_, _, q, omega) = split(y);
        q.normalized().rotate(omega).z
    }

    /// Spin, pitch, roll, energy, normal force and friction ratio at state `y`.
    pub fn probe(&self, y: &State<T>) -> Probe<T> {
        let (r, v, q, omega) = split(y);
        let q = q.normalized();
        let (contact, g) = self.contact_at(r, v, q, omega);
        let elastic = self.elastic(&g);
        let energy = T::HALF * (self.mass * v.dot(v) + omega.dot(self.inertia.mul_elem(omega)))
            + self.mass * self.gravity * r.z
            + elastic;
        let (c, s) = self.skew;
        // Curvature axes a₁, a₂ in body coordinates: R_z(−δ) of the unit vectors.
        let e1 = q.rotate(Vec3::new(c, -s, T::ZERO));
        let e2 = q.rotate(Vec3::new(s, c, T::ZERO));
        let ft = contact.force.x.hypot(contact.force.y);
        Probe {
            spin: q.rotate(omega).z,
            pitch: elevation(e1),
            roll: elevation(e2),
            energy,
            n: contact.n,
            friction_ratio: if contact.n > T::ZERO {
                ft / contact.n
            } else {
                T::ZERO
            },
            h: contact.h,
        }
    }
}

impl<T: Real, L: FloorLaw<T>> Rattleback<T, L> {
    /// One large step of `dt` from `y` ([`super::step_aware`]): a Strang splitting of the
    /// whole pose around the contact impulse — over the first Δt/2, G drifts with Ġ and the
    /// attitude turns torque-free at constant angular momentum L (world; the midpoint rule),
    /// then the impulse, then Δt/2 with Ġ⁺ and L⁺ (G⁺ = G + ½Δt·(Ġ + Ġ⁺)). The contact's
    /// geometry, frame, curvatures, W and rolling velocity are taken at the mid-step pose;
    /// its gap is predicted at the free end pose, with the response G = ½W (both halves of
    /// the pose move with the new velocities over the second half-step only); the friction
    /// by the trapezoidal rule while the slip keeps its direction, with the slip's own change
    /// from the mid-step to the end pose (the contact point running over the surface, the
    /// body turning: [`super::step_aware::Candidate::drift`]) weighted by 2θ − 1.
    ///
    /// Why the translation is split as the rotation: moving G with the end velocity over the
    /// whole step while the attitude turns half with the old and half with the new angular
    /// momentum makes the pose inconsistent with the rolling contact by O(Δt) every step; the
    /// stiff normal turns that into a dissipation ∝ Δt (frictionless, 1.5 s at 0.1 ms: 2.7×
    /// the RK4 loss) that damps the rocking which drives the reversal — the reversal came
    /// 1.1 % late even at 10 µs and 10.6 % at 0.1 ms (`coulomb`). Split, `coulomb` reverses
    /// within 0.004 % at 0.1 ms and 0.06 % at 1 ms. The drift term then makes 0.5–1 ms
    /// right (without it, −9 % at 0.5 ms and −14 % at 1 ms).
    ///
    /// The normal force is solved at the approach the step really ends at
    /// ([`super::step_aware::solve_consistent_gap`]): the end pose's approach responds to
    /// the impulse through the contact arm over the second half-step, which turns as the patch
    /// runs over the body; the library's linear response (W at the mid-step pose) missed it by
    /// up to 1.3 µm at 2 ms, over half the static approach, and the normal and gravity gained energy
    /// ([`EnergySplit`]; `coulomb` −2 at 2 ms: +1.1e-2 of E₀ over 3 s, the runner's energy
    /// check failing at 1.24 s; now −2.6e-3, the reversal 0.63 % early). Cost: a second
    /// library solve per step.
    ///
    /// `warm` carries the solution ([`Warm::default`] at the start).
    pub fn step_aware(&self, y: &State<T>, dt: T, warm: &mut Warm<T>) -> State<T> {
        self.step_aware_inner(y, dt, warm, None)
    }

    /// [`Rattleback::step_aware`], and where the step's energy change went
    /// ([`EnergySplit`]; its parts sum to the change of [`Probe::energy`] to rounding).
    /// Costs about one more contact evaluation per step than [`Rattleback::step_aware`].
    pub fn step_aware_split(
        &self,
        y: &State<T>,
        dt: T,
        warm: &mut Warm<T>,
    ) -> (State<T>, EnergySplit<T>) {
        let mut split = EnergySplit::default();
        let y1 = self.step_aware_inner(y, dt, warm, Some(&mut split));
        (y1, split)
    }

    fn step_aware_inner(
        &self,
        y: &State<T>,
        dt: T,
        warm: &mut Warm<T>,
        audit: Option<&mut EnergySplit<T>>,
    ) -> State<T> {
        let (r, v, q, omega) = split(y);
        let q = q.normalized();
        let inv = Vec3::new(
            T::ONE / self.inertia.x,
            T::ONE / self.inertia.y,
            T::ONE / self.inertia.z,
        );
        let l = q.rotate(self.inertia.mul_elem(omega));
        let (first, second) = (T::HALF * dt, T::HALF * dt);
        // Torque-free over `tau` from `q0` with L = `l`: the midpoint rule.
        let turn = |q0: Quat<T>, l: Vec3<T>, tau: T| {
            let mid = rotate_by(q0, InvInertia::new(q0, inv).apply(l), T::HALF * tau);
            rotate_by(q0, InvInertia::new(mid, inv).apply(l), tau)
        };
        let z = [T::ZERO, T::ZERO, T::ONE];
        let site_of = |g: &Geometry<T>| {
            let frame = Frame::new(z, [T::ONE, T::ZERO, T::ZERO], MajorAxis::of(&g.curvatures));
            (
                Site {
                    arm: g.arm,
                    axes: [frame.x().into(), frame.y().into(), Vec3::unit_z()],
                },
                frame,
            )
        };
        let v_free = v - Vec3::unit_z() * (self.gravity * dt);
        // G drifts with Ġ over the first half-step, as the attitude turns with L: the
        // translation split like the rotation (position Verlet), G⁺ = G + ½Δt·(Ġ + Ġ⁺).
        let r_mid = r + v * first;
        let q_mid = turn(q, l, first);
        let iw = InvInertia::new(q_mid, inv);
        let w_free = iw.apply(l);
        let (g, support) = self.geometry_at(r_mid, q_mid);
        let (site, frame) = site_of(&g);
        let q_end = turn(q_mid, l, second);
        let g_end = self.geometry_at(r_mid + v_free * second, q_end).0;
        let h_pred = g_end.h;
        let u_free = site.velocity(v_free, w_free);
        let u_end = site_of(&g_end)
            .0
            .velocity(v_free, InvInertia::new(q_end, inv).apply(l));
        let [vx, vy, _] = frame.to_contact(
            self.kinematics_at(v_free, q_mid, q_mid.rotate_inv(w_free), &g, &support)
                .rolling
                .into(),
        );
        let cand = [Candidate {
            h_pred,
            u_free,
            rolling: RollingVelocity::new(vx, vy).unwrap_or_default(),
            drift: [0, 1, 2, 3].map(|i| {
                if i == 0 {
                    T::ZERO
                } else {
                    u_end[i] - u_free[i]
                }
            }),
        }];
        let wm = rigid_w(T::ONE / self.mass, &iw, &[site]);
        let floor = FloorStep::<T, L> {
            contact: &self.contact,
            curvatures: &g.curvatures,
        };
        // The library's step-aware wrench, Strang scheme: θ = ½ (the drift's share 0 unless
        // the slip reverses), the gap's response ½W (both halves of the pose move with the
        // new velocities over the second half-step only).
        // The second half-step with the wrench w: Ġ⁺, L⁺, G⁺, q⁺.
        let end = |w: &[T; 4]| {
            let (f, t) = site.load(w);
            let v1 = v_free + f * (dt / self.mass);
            let l1 = l + t * dt;
            (v1, l1, r_mid + v1 * second, turn(q_mid, l1, second))
        };
        let sol = solve_consistent_gap(
            &cand,
            |c| solve_library(dt, &wm, &[&floor], c, &Scheme::strang(), warm),
            |w| {
                let (_, _, r1, q1) = end(&w[0]);
                [self.geometry_at(r1, q1).0.h]
            },
        );
        let (v1, l1, r1, q1) = end(&sol.w[0]);
        let w1 = q1.rotate_inv(l1).mul_elem(inv);
        if let Some(e) = audit {
            let rot = |q: Quat<T>, l: Vec3<T>| T::HALF * l.dot(InvInertia::new(q, inv).apply(l));
            let w = &sol.w[0];
            // The impulse's work at the mid-step pose: w̄·Δt times the mean of the contact
            // velocities before (u_free) and after it (exact for a rigid body).
            let after = site.velocity(v1, iw.apply(l1));
            let work = |i: usize| dt * w[i] * T::HALF * (u_free[i] + after[i]);
            e.rotation = rot(q_mid, l) - rot(q, l) + rot(q1, l1) - rot(q_mid, l1);
            e.normal = work(0)
                + self.mass * self.gravity * (r1.z - r.z)
                + T::HALF * self.mass * (v_free.dot(v_free) - v.dot(v))
                + self.elastic_at(r1, q1)
                - self.elastic_at(r, q);
            e.friction = work(1) + work(2) + work(3);
        }
        pack(r1, v1, q1, w1)
    }
}

/// The floor contact at one step's curvatures, as the step sees it.
struct FloorStep<'a, T: Real, L: FloorLaw<T>> {
    contact: &'a L::Contact,
    curvatures: &'a Curvatures<T>,
}

impl<T: Real, L: FloorLaw<T>> StepContact<T> for FloorStep<'_, T, L> {
    fn wrench4(&self, s: &StepState<T>) -> [T; 4] {
        if s.h <= T::ZERO {
            return [T::ZERO; 4];
        }
        let step = Step {
            curvatures: self.curvatures,
            h: s.h,
            hdot: s.hdot,
            slip: s.slip,
            rolling: [s.rolling.vx(), s.rolling.vy()],
        };
        let w = L::wrench(self.contact, &step);
        [w.n, w.fx, w.fy, w.tz]
    }

    fn maximally_dissipative(&self) -> bool {
        L::MAXIMALLY_DISSIPATIVE
    }
}

/// Spin reversal and stall located between integration steps ([`crate::scenes::event`]),
/// from a start with spin ω₀ and a threshold fraction k (the guide's 0.1):
///
/// - **reversal**: the first time the spin has turned and reached k·|ω₀| the other way,
///   ω·ẑ·sgn ω₀ = −k|ω₀|;
/// - **stall**: no reversal (so far), and the first time the spin was braked to k·|ω₀|,
///   ω·ẑ·sgn ω₀ = k|ω₀|.
///
/// Feed it every accepted step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpinEvents<T: Real> {
    sign: T,
    level: T,
    reversal: Crossing<T, N>,
    braked: Crossing<T, N>,
}

impl<T: Real> SpinEvents<T> {
    /// Tracking from the start (t₀, y₀) with initial spin `spin0` and fraction `fraction`.
    pub fn new<L: FloorLaw<T>>(
        rb: &Rattleback<T, L>,
        t0: T,
        y0: &State<T>,
        spin0: T,
        fraction: T,
    ) -> Self {
        let mut e = SpinEvents {
            sign: T::ONE.copysign(spin0),
            level: fraction * spin0.abs(),
            reversal: Crossing::new(Direction::Falling),
            braked: Crossing::new(Direction::Falling),
        };
        let (sign, level) = (e.sign, e.level);
        e.reversal.start(t0, y0, |y| rb.spin(y) * sign + level);
        e.braked.start(t0, y0, |y| rb.spin(y) * sign - level);
        e
    }

    /// After an accepted step ending at (t, y). Cost: one spin evaluation (a quaternion
    /// normalisation and rotation), plus two right-hand sides and the bisections on a step that
    /// crosses.
    pub fn update<L: FloorLaw<T>>(&mut self, rb: &Rattleback<T, L>, t: T, y: &State<T>) {
        let (sign, level) = (self.sign, self.level);
        let s = rb.spin(y) * sign;
        self.reversal
            .update_with(rb, t, y, s + level, |y| rb.spin(y) * sign + level);
        self.braked
            .update_with(rb, t, y, s - level, |y| rb.spin(y) * sign - level);
    }

    /// The reversal time (s), if any so far.
    pub fn reversal(&self) -> Option<T> {
        self.reversal.first()
    }

    /// The stall time (s): the first braking to k|ω₀| if there was no reversal so far.
    pub fn stall(&self) -> Option<T> {
        match self.reversal.first() {
            Some(_) => None,
            None => self.braked.first(),
        }
    }
}

/// asin(e·ẑ) of a unit vector e: its elevation above the floor's plane (rad).
fn elevation<T: Real>(e: Vec3<T>) -> T {
    e.z.atan2(e.x.hypot(e.y))
}

impl<T: Real, L: FloorLaw<T>> Ode<T, N> for Rattleback<T, L> {
    #[inline]
    fn rhs(&self, _t: T, y: &State<T>) -> State<T> {
        let (r, v, q, omega) = split(y);
        let qn = q.normalized();
        let (c, _) = self.contact_at(r, v, qn, omega);
        let force = c.force - Vec3::new(T::ZERO, T::ZERO, self.mass * self.gravity);
        let a = force * (T::ONE / self.mass);
        let dq = q.derivative(omega);
        let dw = euler_rate(self.inertia, omega, qn.rotate_inv(c.torque));
        [
            v.x, v.y, v.z, a.x, a.y, a.z, dq.w, dq.x, dq.y, dq.z, dw.x, dw.y, dw.z,
        ]
    }

    #[inline]
    fn project(&self, y: &mut State<T>) {
        let (r, v, q, omega) = split(y);
        *y = pack(r, v, q.normalized(), omega);
    }
}

/// The state's parts: G, Ġ, q (as stored), ω (body).
#[inline(always)]
fn split<T: Real>(y: &State<T>) -> (Vec3<T>, Vec3<T>, Quat<T>, Vec3<T>) {
    let [rx, ry, rz, vx, vy, vz, w, x, y, z, wx, wy, wz] = *y;
    (
        Vec3::new(rx, ry, rz),
        Vec3::new(vx, vy, vz),
        Quat { w, x, y, z },
        Vec3::new(wx, wy, wz),
    )
}

#[inline(always)]
fn pack<T: Real>(r: Vec3<T>, v: Vec3<T>, q: Quat<T>, w: Vec3<T>) -> State<T> {
    [
        r.x, r.y, r.z, v.x, v.y, v.z, q.w, q.x, q.y, q.z, w.x, w.y, w.z,
    ]
}
