//! Fuzz target `wrench`: see host-tests/robust/checks.rs (`checks::wrench`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, wrench};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    wrench::<f32>(&mut inp);
    wrench::<f64>(&mut inp);
});
