//! Robustness (issue 8): the fuzz checks of `robust/checks.rs` (shared with the cargo-fuzz
//! targets in `fuzz/`) on proptest's random byte strings — a short run for `cargo test`; the
//! long runs are cargo-fuzz's (`bench-results/fuzz.md`).
#![allow(clippy::excessive_precision)]

#[path = "robust/checks.rs"]
mod checks;

use checks::Input;
use proptest::prelude::*;

/// Byte strings per check and precision pair (each decodes to dozens of inputs).
const CASES: u32 = 10_000;

fn run(check: fn(&mut Input<'_>)) {
    let config = ProptestConfig {
        cases: CASES,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    proptest!(config, |(data in prop::collection::vec(any::<u8>(), 0..400))| {
        check(&mut Input::new(&data));
    });
}

/// One test per area, each in `f32` then `f64` on the same bytes.
macro_rules! areas {
    ($($area:ident),*) => {$(
        #[test]
        fn $area() {
            run(|i| {
                checks::$area::<f32>(i);
                checks::$area::<f64>(i)
            });
        }
    )*};
}

areas!(elliptic, geometry, normal, friction, wrench);
