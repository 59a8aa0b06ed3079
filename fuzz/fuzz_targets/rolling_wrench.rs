//! Fuzz target `rolling_wrench`: see host-tests/robust/checks.rs (`checks::rolling_wrench`:
//! `contact::Rolling`; `checks::dynamic_rolling`: `DynContact::new_rolling`/`wrench_rolling`),
//! in f32 then f64.
#![no_main]

use contensou_fuzz::checks::{Input, dynamic_rolling, rolling_wrench};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    rolling_wrench::<f32>(&mut inp);
    rolling_wrench::<f64>(&mut inp);
    dynamic_rolling::<f32>(&mut inp);
    dynamic_rolling::<f64>(&mut inp);
});
