//! The exact Contensou–Erismann integrals (reference path). Filled in by the `exact` work.
