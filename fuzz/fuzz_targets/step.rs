//! Fuzz target `step`: see host-tests/robust/checks.rs (`checks::step`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, step};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    step::<f32>(&mut inp);
    step::<f64>(&mut inp);
});
