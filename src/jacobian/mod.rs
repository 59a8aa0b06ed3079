//! Derivatives of the wrench: the linearisation a large-step (implicit) integrator needs.
//!
//! The per-step inputs are, in the contact frame of the crate conventions (see the crate docs),
//!
//! ```text
//! q = (h, ḣ, v_Px, v_Py, ω)        (m, m/s, m/s, m/s, rad/s)
//! ```
//!
//! with h the approach (h > 0 in contact; the gap is g = −h) and ḣ its rate (> 0:
//! compression). The wrench on B from A is w = (N, F_x, F_y, T_z) (N, N, N, N·m).
//! [`Jacobian`] carries w(q) and ∂w/∂q; [`Linearize`] gives both.
//!
//! A rolling contact also takes the rolling velocity V; it is an input of the step, held
//! fixed here (no derivative with respect to V). A varying contact's curvatures are not
//! differentiated either ([`At`]: the contact at this step's curvatures).
//!
//! # Example
//!
//! ```
//! use contensou::contact::Contact;
//! use contensou::friction::{Friction, Slip};
//! use contensou::friction::rolling::RollingVelocity;
//! use contensou::geometry::Curvatures;
//! use contensou::jacobian::{Linearize, State, input, output};
//! use contensou::normal::{Modulus, Undamped};
//! use contensou::shape::Newton;
//!
//! let contact = Contact::hertz::<Newton>(
//!     &Curvatures::new(40.0, 160.0)?,
//!     Modulus::new(1.15e11)?,
//!     Undamped,
//!     Friction::<f64>::new(0.2, 1e-4)?, // the default law, `best`
//! )?;
//! let s = State {
//!     h: 1e-6,
//!     hdot: 0.0,
//!     slip: Slip::new(0.01, 0.0, 50.0)?,
//!     rolling: RollingVelocity::ZERO,
//! };
//! let j = contact.linearize(&s);
//! let w = contact.wrench(s.h, s.hdot, s.slip);
//! assert_eq!(j.value, [w.n, w.fx, w.fy, w.tz]); // bit for bit
//! assert!(j.d[output::N][input::H] > 0.0); // stiffer as it compresses: 1.5 N/h
//! assert!(j.d[output::FX][input::VX] < 0.0); // friction damps the slip
//! # Ok::<(), contensou::Error>(())
//! ```
//!
//! # Method
//!
//! Forward-mode automatic differentiation: [`Dual`]`<T, 5>` ([`D5`]) is a value and its five
//! partial derivatives, made a (crate-sealed) [`Real`], so the wrench's own generic code runs
//! on it unchanged — normal law, damping, the friction wrapper (the slip state's
//! normalisation, δ's ramp) and the law's core. The contact's constants are lifted to duals
//! (derivative zero) at the call, nothing is stored: [`LinearNormal`], [`LinearDamping`] and
//! [`LinearLaw`] say how for each law (`best` lifts only the table piece it reads, not its
//! 1,404 bytes of per-contact tables; a rolling contact lifts its creep shape, 130 values, or
//! the skewed path, 216). No allocation, no iteration, `no_std`; the cost is fixed (see
//! below). Tables are read in the base precision ([`Real::of_precision`],
//! [`Real::from_base`]).
//!
//! The value part is computed by exactly the plain code's operations, so **[`Jacobian::value`]
//! is the wrench bit for bit** (asserted for every law, form and precision of the contract;
//! the `micromath` laws are the exception: a dual takes libm's functions, whose derivatives
//! micromath's bit tricks would drop, so their value is the exact-function one).
//!
//! Covered: every sliding law but the reference `Exact` (`best`, `simplified`, `pade`,
//! `ellipsoid`, `coulomb`, `BestSeries` and the micromath twins), every rolling law
//! (`table`, `blend`, `fastsim`, any FASTSIM grid, `linear`, `full-slip`), every normal law
//! (`Hertz`, `Volumetric`, `Fitted`, `HertzMicromath`) and damping law (`Undamped`,
//! `HuntCrossley`, `CompressionDamping`), fixed ([`crate::contact::Contact`]) and varying
//! ([`crate::contact::VaryingContact`] through [`At`]) geometry, [`crate::contact::Rolling`]
//! over either, and the run-time contract ([`crate::dynamic::DynContact::jacobian`],
//! `contact_eval jacobian`: columns [`OUTPUTS`]). `Exact` computes in `f64` internally; a
//! round trip through `f64` drops derivatives, so it is left out (the type system refuses it:
//! it is not a [`LinearLaw`]).
//!
//! Audit of the `to_f64`/`from_f64` round trips on the per-step path: the `Exact` law
//! (excluded); the rolling creep shape for a/b (`RollingShape::new`, `ShapePath`, built in
//! `f64`), whose input a/b does not depend on the step's inputs (a = a′√h, b = b′√h), so the
//! derivative dropped is zero; micromath's `f32` functions (a dual takes libm instead). No
//! other per-step code converts.
//!
//! # Domain and kinks
//!
//! Every input the wrench takes; total: wherever the wrench is finite, so is every derivative
//! (a derivative past the float's range saturates at ±`T::MAX`, and zero times an overflowed
//! intermediate — out of contact, f = 0, a slip speed near the smallest normal float — is 0;
//! asserted on every combination of extreme inputs, `host-tests/jacobian.rs`). Where the
//! wrench is not differentiable, the derivative is a one-sided one, by rule:
//!
//! | where | derivative returned |
//! |---|---|
//! | h ≤ 0 (apart, h = 0 included) | all zero: the side h < 0 (for h → 0⁺, ∂N/∂h = 1.5·N/h → 0 too, but ∂a/∂h ∝ 1/√h grows without bound) |
//! | a branch switch of a law (`best` inside/outside the ellipse and its table pieces in z, `simplified`'s and `coulomb`'s ramp knee at v = δ, `best`'s ramp at p = δ, the rolling laws' knees and FASTSIM's adhesion/slip cells, a clamp N ≥ 0 of a damped rebound) | that of the branch the value takes (its test reads the value only), i.e. the side of the switch where the state lies; at the switch itself the side whose test includes equality |
//! | a zero slip component (the ℓ¹ slip speed's \|v_x\|, \|v_y\|, a\|ω\|) | the side of its sign bit (+0: the right side) |
//! | exact rest v_P = 0, ω = 0, δ > 0, a law with a ramp (`best`, `simplified`, `coulomb`) | the slip columns are the law's slopes along each axis, w(η·eⱼ)/η with η = δ/4 inside the ramp (ω: η/a), where the law is homogeneous of degree one: the derivative itself for `coulomb` and `simplified`, for `best` (not differentiable at rest: its slope depends on the direction) the slope along each axis — which central differences along that axis also give (F is odd); three plain wrench calls, at rest only |
//! | exact rest with δ = 0, or a law without a ramp (`pade`, `ellipsoid`) | zero slip block (dry friction's jump) |
//! | a rolling contact at V = 0 and rest | zero (full slip has δ = 0) |
//!
//! # Accuracy (measured, `host-tests/jacobian.rs`)
//!
//! Against central differences of the wrench itself (f64, Richardson-extrapolated from steps
//! of 1e-5 and 5e-6 of each input's scale), in scaled units — ∂wᵢ/∂qⱼ·σⱼ/Wᵢ with
//! σ = (h, 1 cm/s, s, s, s/a) (s = |v_x| + |v_y| + a|ω|), W = (N, fN, fN, fNa), relative to
//! max(1, |scaled derivative|) — on 2,000 random states per law and form (P/Q from 1 to 1/50,
//! damped or not, δ = 0 or 1e-5…1e-3 m/s, h ∈ [1e-7, 1e-5] m, u = v/(aω) ∈ [0.03, 30], rolling
//! speeds 0.1–10 m/s along an axis or skewed): max error 1.9e-7 (`table`, varying), 1.5e-7
//! (`fastsim`, varying), 1.7e-8 (`fastsim`, fixed), ≤ 1.3e-10 for every other law and form;
//! states within ±1e-5 of a kink (the two differences disagree): ≤ 17 of 2,000 (`fastsim`),
//! 13 (`pade`), 0–8 elsewhere. Every normal and damping law: ≤ 7.6e-11. `f32` against `f64` on
//! the same inputs (100 states per law): ≤ 9.6e-6 (`best`), ≤ 5e-6 for the others.
//!
//! # The sliding laws' damping block
//!
//! B = −∂(F_x, F_y, T_z/a)/∂(v_x, v_y, aω) (N·s/m throughout: ω scaled by the major
//! semi-axis a and T_z divided by it, so the entries share a unit). A law that is the gradient
//! of a convex dissipation potential — the exact integrals are, −(F, T_z/a) = ∇ of
//! ∫σ|v_M| dA — has B symmetric positive semidefinite, and so has its ramp below δ by the
//! law's own dissipation p = −(F·v_P + T_z·ω)/(fN) (`best`'s,
//! [`FrictionLaw::RAMP_BELOW_DELTA`](crate::friction::FrictionLaw::RAMP_BELOW_DELTA): the
//! gradient of the convex fN·φ(p), φ′ = min(1, p/δ)). Measured smallest eigenvalue of B's
//! symmetric part over its largest |entry|, 1e5 random states per law (one in eight shrunk
//! towards rest; split by p ≥ δ and p < δ):
//!
//! | law | p ≥ δ | p < δ (in the ramp for `best`, `coulomb`, `simplified`) |
//! |---|---|---|
//! | `ellipsoid` | −8.1e-16 (PSD) | −6.4e-16 (PSD) |
//! | `coulomb` | −1.5e-8 (PSD: the eigenvalue formula's √ε at a double zero) | −2.1e-16 (PSD) |
//! | `best` | −1.3e-6 (PSD within its table approximation of the exact law) | −2.7e-7 (PSD: its ramp ends at p = 3δ/8; with the ramp ending at p = δ, +1.5e-3) |
//! | `simplified` | **−0.62** | −0.54 |
//! | `pade` | **−0.55** | −0.55 |
//!
//! `best` was ramped by the ℓ¹ slip speed before (min(1, s/δ), s = |v_x| + |v_y| + a|ω|):
//! passive but not a gradient, B down to −0.23 in its ramp. `simplified` and `pade` (the
//! paper's model and its approximant) are passive but not gradients, and a law homogeneous of
//! degree 0 in the slip cannot have B ⪰ 0 unless it is one (B·v = 0 along the slip v, so
//! vᵀ·sym(B)·v = 0, and sym(B) ⪰ 0 would need Bᵀ·v = 0 too: F = ∇(F·v)). Their blocks are
//! indefinite at almost every state (98–100 % of a (ψ, u) grid; most negative −0.17 … −0.57
//! for `simplified` over e² ∈ [0, 0.99], −0.55 for `pade`) — a documented exception: making
//! them gradients would make them other laws. The step-aware wrench ([`crate::step`]) does
//! not rely on B ⪰ 0: its limit-set projection and power check keep them passive at any Δt
//! (`host-tests/step_wrench.rs`, random steps to 10 ms; fuzz target `step`).
//!
//! # Cost (fixed)
//!
//! Host (x86-64, criterion, `benches/jacobian.rs`, the wrench benches' 209-bearing scene and
//! 64-slip mixed set; a loaded shared machine): `f32` `best` fixed 267 ns (wrench 59 ns:
//! 4.5×), varying 673 ns (204: 3.3×); `simplified` fixed 220 ns (26: 8.4×), varying 250 ns
//! (105: 2.4×); `f64` `best` fixed 324 ns (73: 4.4×). Cortex-M4F (`f32`, QEMU, stage
//! `jacobian` of `bench-results/qemu.csv`, same scene and slips): **1,542** instructions per
//! call with per-contact tables (`jacobian,fixed-best`; the wrench alone 184: 8.4×; ≈2,777
//! cycles by `bench-results/cycles.csv`), **3,217** with the shape by table each step
//! (`jacobian,table_each_step-best`; the wrench 521: 6.2×), the finiteness guard included
//! (one test on the derivatives' sum). The ratio is the dual numbers'
//! (each product carries five derivatives on a scalar FPU) — the price of one code path for
//! every law, bit-identical values and no per-law derivation; an analytic Jacobian of `best`
//! alone would be the route to ≈2×.

mod contact;
pub mod dual;
mod dynamic;
mod lift;
mod rolling;

pub use contact::At;
pub use dual::Dual;
pub use lift::{LinearDamping, LinearLaw, LinearNormal};

/// The dual number of the Jacobian: a value and its derivatives with respect to the five
/// per-step inputs (h, ḣ, v_Px, v_Py, ω), in that order ([`input`]).
pub type D5<T> = Dual<T, 5>;

use crate::Real;
use crate::friction::Slip;
use crate::friction::rolling::RollingVelocity;

/// Column indices of [`Jacobian::d`]: the per-step inputs q = (h, ḣ, v_Px, v_Py, ω).
pub mod input {
    /// The approach h (m).
    pub const H: usize = 0;
    /// Its rate ḣ (m/s).
    pub const HDOT: usize = 1;
    /// The slip v_Px (m/s).
    pub const VX: usize = 2;
    /// The slip v_Py (m/s).
    pub const VY: usize = 3;
    /// The relative spin ω about the normal (rad/s).
    pub const OMEGA: usize = 4;
}

/// Row indices of [`Jacobian::value`] and [`Jacobian::d`]: the wrench w = (N, F_x, F_y, T_z).
pub mod output {
    /// The normal force N (N).
    pub const N: usize = 0;
    /// The friction force F_x (N).
    pub const FX: usize = 1;
    /// The friction force F_y (N).
    pub const FY: usize = 2;
    /// The drilling torque T_z (N·m).
    pub const TZ: usize = 3;
}

/// The wrench w = (N, F_x, F_y, T_z) at a per-step input q = (h, ḣ, v_Px, v_Py, ω) and its
/// Jacobian `d[i][j]` = ∂wᵢ/∂qⱼ (rows [`output`], columns [`input`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Jacobian<T> {
    /// (N, F_x, F_y, T_z) on B from A in the contact frame.
    pub value: [T; 4],
    /// ∂wᵢ/∂qⱼ: rows (N, F_x, F_y, T_z), columns (h, ḣ, v_Px, v_Py, ω).
    pub d: [[T; 5]; 4],
}

/// One contact's per-step input: the approach, its rate, the slip and (for a rolling law) the
/// rolling velocity (zero: full slip, and ignored by the sliding laws).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State<T> {
    /// The approach h (m); h ≤ 0 is out of contact.
    pub h: T,
    /// Its rate ḣ (m/s).
    pub hdot: T,
    /// The slip (v_Px, v_Py, ω) of B relative to A.
    pub slip: Slip<T>,
    /// The rolling velocity V in the contact frame (rolling laws only).
    pub rolling: RollingVelocity<T>,
}

/// The contract's output columns of the Jacobian (`contact_eval jacobian`, in
/// [`Jacobian::to_array`] order): the wrench, then ∂wᵢ/∂qⱼ row by row.
pub const OUTPUTS: [&str; 24] = [
    "N",
    "Fx",
    "Fy",
    "Tz",
    "dN_dh",
    "dN_dhdot",
    "dN_dvx",
    "dN_dvy",
    "dN_domega",
    "dFx_dh",
    "dFx_dhdot",
    "dFx_dvx",
    "dFx_dvy",
    "dFx_domega",
    "dFy_dh",
    "dFy_dhdot",
    "dFy_dvx",
    "dFy_dvy",
    "dFy_domega",
    "dTz_dh",
    "dTz_dhdot",
    "dTz_dvx",
    "dTz_dvy",
    "dTz_domega",
];

impl<T: Copy> Jacobian<T> {
    /// The values in [`OUTPUTS`] order: (N, F_x, F_y, T_z), then `d` row by row.
    pub fn to_array(&self) -> [T; 24] {
        let [n, fx, fy, tz] = self.value;
        let mut out = [n; 24];
        for (o, &x) in out.iter_mut().skip(4).zip(self.d.iter().flatten()) {
            *o = x;
        }
        out[1] = fx;
        out[2] = fy;
        out[3] = tz;
        out
    }
}

/// A contact that can give its wrench and the wrench's Jacobian at a per-step state.
pub trait Linearize<T: Real> {
    /// The wrench (N, F_x, F_y, T_z) alone.
    fn wrench4(&self, s: &State<T>) -> [T; 4];
    /// The normal force N alone, bit for bit `wrench4(s)[0]` (the default). The step-aware
    /// wrench's normal predictor and its limit set's patch search need nothing else (13 of
    /// its ≈ 17 wrench calls per contact); the library's sliding contacts evaluate only their
    /// normal law here, not the friction.
    fn normal_force(&self, s: &State<T>) -> T {
        self.wrench4(s)[0]
    }
    /// The wrench and its Jacobian with respect to (h, ḣ, v_Px, v_Py, ω).
    fn linearize(&self, s: &State<T>) -> Jacobian<T>;
    /// Whether the friction law is maximally dissipative
    /// ([`crate::friction::FrictionLaw::MAXIMALLY_DISSIPATIVE`]): which limit set the
    /// step-aware wrench projects onto ([`crate::step::project`]). Default `true`.
    fn maximally_dissipative(&self) -> bool {
        true
    }
}
