//! Fuzz target `rolling_wrench`: see host-tests/robust/checks.rs (`checks::rolling_wrench`: contact::Rolling), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, rolling_wrench};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    rolling_wrench::<f32>(&mut inp);
    rolling_wrench::<f64>(&mut inp);
});
