//! The paper's tippe top as the tests and examples start it (host-tests/tippe_top.rs,
//! examples/tippe_top.rs: `#[path = …] mod paper_top;`): `Params::paper()`, friction
//! coefficient 0.3, tilted by 0.1 rad and spun at 180 rad/s; the adaptive runs' tolerance.
#![allow(dead_code)]

use contensou::Real;
use contensou::friction::{Friction, FrictionLaw};
use contensou::scenes::integrate::Tolerance;
use contensou::scenes::tippe_top::{N, Params, State, TippeTop};

/// The friction coefficient of the paper's top.
pub const F: f64 = 0.3;
/// The initial tilt θ₀ (rad).
pub const THETA0: f64 = 0.1;
/// The initial spin (rad/s).
pub const SPIN: f64 = 180.0;

/// The paper's top in `T` with law `L` at regularization speed `delta` (m/s), and its initial
/// state.
pub fn paper_top<T: Real, L: FrictionLaw>(delta: f64) -> (TippeTop<T, L>, State<T>) {
    let t = T::from_f64;
    let friction = Friction::<T, L>::with_law(t(F), t(delta)).unwrap();
    let top = TippeTop::new(&Params::paper(), friction).unwrap();
    let y0 = top.initial_state(t(THETA0), t(SPIN));
    (top, y0)
}

/// The adaptive runs' tolerance: relative `rtol`; absolute 1e-9 m on G, 1e-6 m/s on Ġ, 1e-8
/// on q, 1e-4 rad/s on ω.
pub fn tolerance(rtol: f64) -> Tolerance<f64, N> {
    let mut atol = [1e-9; N];
    atol[3..6].fill(1e-6);
    atol[6..10].fill(1e-8);
    atol[10..13].fill(1e-4);
    Tolerance { rtol, atol }
}
