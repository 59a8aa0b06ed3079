//! Rolling contact: creep forces and the spin moment from the bodies' elasticity (Kalker's
//! theory), meeting the exact Contensou–Erismann integrals at full slip.
//!
//! A rolling body's patch is mostly stuck: material crosses it in 2a/V and the tangential
//! elasticity carries the load, with micro-slip towards the trailing edge. The laws here give
//! the force and the moment in that regime from the creepages, and the full-slip law of the
//! library (`best`) at large creepage or V → 0.
//!
//! # Conventions (Kalker's, as in Kalker 1990 and Johnson, *Contact Mechanics*, ch. 8)
//!
//! - **Rolling frame**: x along the rolling direction, z the contact normal; the Hertz ellipse
//!   has semi-axis a along x and b along y (a may be smaller than b), c = √(ab),
//!   p = p₀√(1 − x²/a² − y²/b²), N = (2/3)πabp₀.
//! - **Rolling velocity** V > 0 along +x: the velocity at which the contact point moves over
//!   both surfaces, relative to their material, averaged; material flows through the patch
//!   towards −x and enters at the leading edge x = +a. V < 0 is the mirror image
//!   ([`RollingSlip`]).
//! - **Creepages**: ξ = v_x/V, η = v_y/V, φ = ω/V (1/m), (v_x, v_y) the rigid slip of body B
//!   relative to body A at the patch centre, ω their relative spin about z.
//! - **Outputs**: F_x, F_y (N) and M_z (N·m, about the patch centre) on body B from body A
//!   ([`Wrench`]; dimensionless [`Creep`]: F/(fN), M_z/(fNc)). Linear theory:
//!   F_x = −Gc²C₁₁ξ, F_y = −Gc²C₂₂η − Gc³C₂₃φ, M_z = Gc³C₂₃η − Gc⁴C₃₃φ ([`Kalker`]; the laws
//!   use the exact theory's coefficients, [`creep_matrix::aligned`], not Table E3).
//! - **Library frame** (the full-slip laws, [`crate::friction`]): x along the MAJOR axis. For
//!   a ≥ b it is the rolling frame; for a < b it is turned by 90° (x' = y, y' = −x), which
//!   [`RollingContact::full_slip`] does.
//! - **Rolling direction not along an axis of the ellipse**: Kalker's coefficients, FASTSIM and
//!   the exact reference are for a rolling direction along an axis. A caller with a skewed
//!   rolling velocity turns the frame to the rolling direction and uses the ellipse aligned with
//!   it whose semi-axis along the rolling direction is the patch's extent in that direction,
//!   r(θ) = ab/√(b²cos²θ + a²sin²θ), and the other one ab/r (same area, same c):
//!   [`aligned_ellipse`]. Exact along either axis and continuous in between. The per-step
//!   wrench [`crate::contact::Rolling`] does this from a rolling velocity in the contact frame
//!   ([`RollingVelocity`]) and takes the full slip from the real patch (exact in every
//!   direction); the creep shape of a skewed direction per call by [`ShapePath`], its
//!   coefficients turned into the real patch's creep matrix ([`CreepMatrix`]: diagonal and
//!   couplings) by [`skew_linear`], so that the linear limit is the patch's own in every
//!   direction.
//! - **Elasticity**: [`Elasticity`]: quasi-identical bodies (G, ν), or Kalker's combination
//!   of dissimilar bodies with the normal–tangential coupling neglected.
//!
//! # Laws
//!
//! - [`Table`] (default): [`Blend`] plus per-shape tables of its residual against the exact
//!   reference over the normalised creepage and the direction of the creepages (12 creep curves
//!   per shape, η and φ of both signs, the knee of the spin force refined), the limits kept:
//!   exact at both limits, passive, fixed cost (1,020 M4F f32 instructions); on held-out points
//!   of the creep curves 0.026 fN / 0.012 fNc from the exact theory at worst (`blend` 0.49 /
//!   0.49 on the same points), 0.064 / 0.055 at random directions; over the whole domain
//!   (patch shapes a/b 0.05–20, any skew and ν: `bench-results/rolling-heldout.md`) 0.148 /
//!   0.334 (the aim is 0.03 / 0.05; the worst are patches 10–20 times longer than wide,
//!   skewed to the rolling direction, with combined creepage).
//! - [`Blend`]: Kalker's linear theory and the exact full slip joined channel by
//!   channel with saturation shapes fitted to the exact reference; exact at both limits by
//!   construction, passive, fixed cost (443 M4F f32 instructions); 0.10 fN / 0.16 fNc from the
//!   exact theory at worst on the points it was fitted to, 0.165 / 0.169 between them
//!   (spin-dominated states).
//! - [`Fastsim`] ([`FastsimGrid`]): Kalker's FASTSIM with the elliptic traction bound on a fixed
//!   grid, saturating to the Contensou–Erismann integrals; 0.085 fN / 0.060 fNc from the exact
//!   theory on 32 × 32 (44,340 M4F instructions).
//! - [`FullSlip`]: the full-slip law (`best`) whatever V; [`Linear`]: Kalker's linear theory
//!   unsaturated (a reference, not a friction law).
//!
//! ```
//! use contensou::friction::rolling::{Elasticity, Patch, RollingContact, RollingSlip, Table};
//!
//! let el = Elasticity::new(80e9_f64, 0.28)?; // steel
//! let contact = RollingContact::new(1.5, el)?; // a/b = 1.5, built once
//! let patch = Patch::new(6e-3, 4e-3, 80e3, 0.3)?; // a, b (m), N (N), f
//! let slip = RollingSlip::from_creepages(1e-3, 0.0, 0.0, 30.0)?; // ξ = 0.1 %, V = 30 m/s
//! let w = contact.wrench::<Table>(&patch, &slip);
//! assert!(w.fx < 0.0 && w.fx.abs() <= 0.3 * 80e3);
//! # Ok::<(), contensou::Error>(())
//! ```

pub mod blend;
pub mod contact;
pub mod creep_matrix;
mod creep_matrix_data;
pub mod elastic;
pub mod fastsim;
mod fitted;
pub mod kalker;
mod residual;
pub mod row;
pub mod skew;
pub mod skew_linear;
pub mod slip;
pub mod table;
mod table_data;
pub mod velocity;

pub use blend::Blend;
pub use contact::{
    Creep, FullSlip, Input, Linear, Patch, RollingContact, RollingLaw, RollingShape, Wrench,
};
pub use creep_matrix::CreepMatrix;
pub use elastic::Elasticity;
pub use fastsim::{Fastsim, FastsimGrid};
pub use kalker::Kalker;
pub use skew::{ShapePath, aligned_ellipse};
pub use skew_linear::{SkewGrid, SkewRow};
pub use slip::{RollingSlip, Scaled};
pub use table::Table;
pub use velocity::RollingVelocity;

/// Cubic Hermite through `y(i)`, i < n, at the node coordinate `t` (node i at t = i; clamped
/// to [0, n − 1]), finite-difference slopes (one-sided at the ends): Table E3's columns
/// ([`Kalker::new`]) and the creep-matrix tables. Total (`y` out of range: whatever `y` says).
pub(crate) fn hermite(n: usize, y: impl Fn(usize) -> f64, t: f64) -> f64 {
    let last = n.saturating_sub(1);
    let t = within(t, 0.0, last as f64);
    let i = (t as usize).min(n.saturating_sub(2));
    let u = t - i as f64;
    let slope = |k: usize| {
        if k == 0 {
            y(1) - y(0)
        } else if k >= last {
            y(last) - y(last - 1)
        } else {
            0.5 * (y(k + 1) - y(k - 1))
        }
    };
    let (y0, y1, m0, m1) = (y(i), y(i + 1), slope(i), slope(i + 1));
    let (u2, u3) = (u * u, u * u * u);
    (2.0 * u3 - 3.0 * u2 + 1.0) * y0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * y1
        + (u3 - u2) * m1
}

/// `x.clamp(lo, hi)` for constant bounds lo ≤ hi without `clamp`'s bounds assertion (a panic
/// path that survives at `opt-level = "z"`, `tools/no-panic.sh`'s variant); the same value for
/// every x, NaN included.
#[inline(always)]
pub(crate) fn within(x: f64, lo: f64, hi: f64) -> f64 {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}
