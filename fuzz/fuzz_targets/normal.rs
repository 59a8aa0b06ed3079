//! Fuzz target `normal`: see host-tests/robust/checks.rs (`checks::normal`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, normal};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    normal::<f32>(&mut inp);
    normal::<f64>(&mut inp);
});
