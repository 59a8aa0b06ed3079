//! Fuzz target `elliptic`: see host-tests/robust/checks.rs (`checks::elliptic`), in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, elliptic};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    elliptic::<f32>(&mut inp);
    elliptic::<f64>(&mut inp);
});
