//! Fuzz target `friction`: see host-tests/robust/checks.rs (`checks::friction`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, friction};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    friction::<f32>(&mut inp);
    friction::<f64>(&mut inp);
});
