//! The MCU configuration of the paper's tippe top: the largest fixed RK4 step for `f32` whose
//! small-sphere touch-down time stays within 5 ms of the `f64`, 10 µs run, and that the
//! library's stable-step bound allows. The firmware binary `firmware/src/bin/tippe.rs` runs the
//! chosen step for 8 s (row `scene,tippe_top_8s,f32` of bench-results/qemu.csv, cycles.csv).
//!
//! ```sh
//! cargo run --release --features scenes --example tippe_top_step
//! ```
//!
//! Touch-down: the time the small sphere first reaches the floor ([`TippeTop::penetrations`]
//! = 0), located inside the step where it changes sign ([`Events`]: Hermite interpolant +
//! bisection; before event location: the end of that step, up to one step later). Start θ₀ = 0.1 rad, ω₃ = 180 rad/s, simplified Contensou
//! friction f = 0.3, δ = 1e-4 m/s (as examples/tippe_top.rs). Stable-step bound:
//! [`Friction::stable_step`] for RK4 with the top's mass and its weight as the normal force
//! (the ramp below δ; the rotational spin step is far larger here).

use contensou::Real;
use contensou::friction::{Constants, Explicit, Friction, Simplified};
use contensou::scenes::integrate::rk4_step;
use contensou::scenes::tippe_top::{Events, Params, TippeTop};

const T_END: f64 = 8.0;
const TOLERANCE: f64 = 5e-3;

/// First touch-down time of the small sphere with a fixed step h (None: not within T_END).
fn touch_down<T: Real>(h: T) -> Option<f64> {
    let p = Params::<T>::paper();
    let top = TippeTop::new(
        &p,
        Friction::<T, Simplified>::with_law(T::from_f64(0.3), T::from_f64(1e-4)).unwrap(),
    )
    .unwrap();
    let mut y = top.initial_state(T::from_f64(0.1), T::from_f64(180.0));
    let mut events = Events::new(&top, T::ZERO, &y);
    let steps = (T_END / h.to_f64()).ceil() as usize;
    for i in 0..steps {
        let t = h * T::from_usize(i);
        y = rk4_step(&top, t, &y, h);
        events.update(&top, t + h, &y);
        if let Some(t) = events.touch_down() {
            return Some(t.to_f64());
        }
    }
    None
}

fn main() {
    let p = Params::<f32>::paper();
    let friction = Friction::<f32, Simplified>::with_law(0.3, 1e-4).unwrap();
    let bound = friction.stable_step(
        &Constants::circle(),
        p.mass,
        p.mass * p.gravity,
        Explicit::Rk4,
    );
    let reference = touch_down(1e-5f64).expect("the f64 10 µs run touches down");
    println!("f64 RK4 h = 10 µs: small sphere touches down at {reference:.6} s");
    println!(
        "stable-step bound (Friction::stable_step, RK4, m, N = mg): {:.1} µs",
        bound * 1e6
    );
    let mut best = None;
    // Round steps, then the bound itself in whole µs, then one past it.
    let at_bound = (bound * 1e6).floor() as u32;
    for us in [10u32, 20, 25, 40, 50, 64, 80, 90, at_bound, at_bound + 1] {
        let h = us as f32 * 1e-6;
        let td = touch_down(h);
        let ok = h <= bound && td.is_some_and(|t| (t - reference).abs() <= TOLERANCE);
        println!(
            "f32 RK4 h = {us:3} µs: touch-down {}{}",
            td.map_or("never".into(), |t| format!(
                "{t:.6} s ({:+.2} ms)",
                (t - reference) * 1e3
            )),
            if h > bound {
                ", above the stable-step bound"
            } else if ok {
                ", ok"
            } else {
                ""
            }
        );
        if ok {
            best = Some(us);
        }
    }
    match best {
        Some(us) => println!(
            "largest admissible step: {us} µs ({} steps reach {T_END} s)",
            (T_END / (us as f64 * 1e-6)).ceil()
        ),
        None => println!("no admissible step"),
    }
}
