//! Fuzz target `geometry`: see host-tests/robust/checks.rs (`checks::geometry`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, geometry};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    geometry::<f32>(&mut inp);
    geometry::<f64>(&mut inp);
});
