//! The paper's validation scenes, built on the library's contact wrench (feature `scenes`,
//! off by default: firmware that needs only the wrench links only the wrench).
//!
//! - [`rigid`]: 3-vectors, quaternion attitude, Euler's equations in the body frame.
//! - [`integrate`]: fixed-step RK4 (MCU) and adaptive Dormand–Prince 5(4) (host reference).
//! - [`event`]: event times located between steps (sign change, Hermite interpolant, bisection).
//! - [`tippe_top`]: the tippe top of the paper's §5 with Hertz + damping + a friction law.
//! - [`bearing`]: a deep-groove ball bearing, balls in Hertz + friction contact with both races.
//! - [`ball`]: a steel ball launched sliding and spinning on a plane (analytic figures).
//! - [`step_aware`]: the scenes' glue to the library's step-aware wrench ([`crate::step`])
//!   behind their `step_aware` integrators: the ball at 5 ms, the tippe top at 2 ms, the
//!   rattleback at 1–2 ms and the creep bearing at 30 µs (figures: the guide chapter
//!   `docs/guide/src/scenes-large-steps.md`, `bench-results/step-sweep.md`).
//! - [`rattleback`]: the rattleback (celt), an ellipsoid whose contact geometry changes every step.
//!
//! All `no_std`, allocation-free, generic over [`Real`](crate::Real).

pub mod ball;
pub mod bearing;
pub mod event;
pub mod integrate;
pub mod rattleback;
pub mod rigid;
pub mod step_aware;
pub mod tippe_top;
