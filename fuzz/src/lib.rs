//! The checks shared with the `robust` integration test (host-tests/robust/checks.rs).
#[path = "../../host-tests/robust/checks.rs"]
pub mod checks;
