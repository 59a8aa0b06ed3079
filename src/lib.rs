//! # contensou
//!
//! The contact wrench between two elastic bodies, in real time: the Hertz normal force on an
//! elliptic contact patch plus Contensou–Erismann dry friction — the sliding force *and* the
//! drilling torque, integrated over that patch. `no_std`, allocation-free, generic over
//! `f32`/`f64`, fixed cost per call.
//!
//! The design follows I. I. Kosenko & E. B. Aleksandrov (2009), *Implementation of the
//! Contensou–Erismann model for tangent forces in the Hertz contact problem*.
//!
//! **New here? Read the [`guide`]**: using a contact in your own loop — the contact frame,
//! bodies A and B, h and ḣ, slip and spin from body states, where N, F and T_z act, and the
//! wrench back to a force and a torque about each body's centre of mass ([`frame`]), with a
//! worked example tested against the analytic solution (`examples/ball_on_plane.rs`).
//!
//! # Conventions
//!
//! These hold in every module; doc comments refer back here.
//!
//! - **Units**: SI throughout (m, N, Pa, s, rad).
//! - **Bodies**: body A is "below", body B "above"; every force and torque is the one
//!   **on B from A**.
//! - **Contact frame** P x y z: origin at the patch centre P; z the common normal, pointing
//!   from A into B; x along the **major** semi-axis a of the contact ellipse; y along the minor
//!   semi-axis b = a√(1 − e²).
//! - **Relative surface**: z = P x² + Q y² with 0 < P ≤ Q (the major axis lies along the
//!   direction of the smaller coefficient P).
//! - **Elliptic integrals** take the **parameter** m = e² = 1 − b²/a² (never the modulus k).
//!   [`elliptic::Parameter`] carries m and m₁ = 1 − m separately.
//! - **Slip**: v_P is the velocity of B relative to A at P, in the contact plane; ω the relative
//!   spin about z. A point M(x, y) of the patch slips with v_M = (v_Px − ωy, v_Py + ωx).
//! - **Dimensionless friction**: v_P = v(cos ψ, sin ψ), u = v/(aω); forces scale with fN,
//!   the drilling torque with fNa (f the friction coefficient).
//!
//! # Errors and panics
//!
//! Constructors validate and return [`Result`] with [`Error`]; per-step calls take validated
//! types and are total: no panic, no NaN or ∞ for finite valid input.
#![no_std]
// docs.rs (nightly, `--cfg docsrs`): each feature-gated item is marked with its feature.
#![cfg_attr(docsrs, feature(doc_cfg))]
#![deny(unsafe_code)]
#![warn(missing_docs, missing_debug_implementations, rust_2018_idioms)]
#![cfg_attr(
    not(test),
    warn(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod batch;
pub mod contact;
#[cfg(feature = "defmt")]
mod defmt_impls;
pub mod dynamic;
pub mod elliptic;
pub mod error;
pub mod frame;
pub mod friction;
pub mod geometry;
pub mod guide;
mod hw_sqrt;
pub mod jacobian;
pub mod math;
pub mod normal;
pub mod real;
#[cfg(feature = "scenes")]
#[cfg_attr(docsrs, doc(cfg(feature = "scenes")))]
pub mod scenes;
pub mod select;
pub mod shape;
pub mod step;

pub use error::Error;
pub use real::Real;

/// The README's Rust examples compile and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

/// The user guide's Rust examples (docs/guide/src/, the mdBook) compile and run as doctests:
/// every chapter is listed, so a Rust block added to any of them is tested. `#[cfg(doctest)]`
/// drops these items before `include_str!` is expanded in every other build, so the published
/// crate (which ships no docs/) builds without the files.
#[cfg(doctest)]
mod guide_doctests {
    macro_rules! chapters {
        ($($name:ident = $file:literal),* $(,)?) => {
            $(
                #[doc = include_str!(concat!("../docs/guide/src/", $file))]
                struct $name;
            )*
        };
    }
    chapters! {
        Introduction = "introduction.md",
        Rust = "rust.md",
        Cli = "cli.md",
        C = "c.md",
        Python = "python.md",
        Mujoco = "mujoco.md",
        Conventions = "conventions.md",
        Model = "model.md",
        Elliptic = "elliptic.md",
        Hertz = "hertz.md",
        Friction = "friction.md",
        Best = "best.md",
        Select = "select.md",
        Batch = "batch.md",
        Rolling = "rolling.md",
        Scenes = "scenes.md",
        TippeTop = "tippe-top.md",
        Bearing = "bearing.md",
        Rattleback = "rattleback.md",
        Events = "events.md",
        TimeStepping = "time-stepping.md",
        ScenesLargeSteps = "scenes-large-steps.md",
        Mcu = "mcu.md",
        Robustness = "robustness.md",
        Report = "report.md",
    }
}
