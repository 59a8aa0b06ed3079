//! Step limits: what the plain (explicit) path needs and what the step-aware path tolerates.
//!
//! Work in progress: filled in by the stable-step extension (normal mode and creep law).
