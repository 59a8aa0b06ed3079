//! Fuzz target `rolling`: see host-tests/robust/checks.rs (`checks::rolling`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, rolling};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    rolling::<f32>(&mut inp);
    rolling::<f64>(&mut inp);
});
