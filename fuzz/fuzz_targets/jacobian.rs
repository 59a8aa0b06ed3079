//! Fuzz target `jacobian`: see host-tests/robust/checks.rs (`checks::jacobian`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, jacobian};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    jacobian::<f32>(&mut inp);
    jacobian::<f64>(&mut inp);
});
