//! Exact steady-rolling reference for the contensou rolling laws: Kalker's exact half-space
//! theory on the Hertz ellipse (see README.md).

pub mod cases;
pub mod extrapolate;
pub mod grid;
pub mod influence;
pub mod kalker;
pub mod reference;
pub mod solver;
