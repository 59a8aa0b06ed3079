//! The step contract with the law chosen at run time: one row of `contact_eval step` — the
//! wrench's contract ([`crate::dynamic`]) plus the step Δt, the contact's inverse mass W and the
//! free end-of-step velocity — to the step-aware wrench (N, F_x, F_y, T_z).
//!
//! | columns | meaning |
//! |---|---|
//! | [`crate::dynamic::INPUTS`] (+ optional `G,nu,vrx,vry`) | the contact and its start state, as `contact_eval wrench` |
//! | `dt` | the step Δt (s), > 0 ([`crate::Error::StepNotPositive`]) |
//! | `w_nn,w_nx,w_ny,w_nw,w_xx,w_xy,w_xw,w_yy,w_yw,w_ww` | W's upper triangle over u = (v_n, v_x, v_y, ω) ([`InverseMass::from_upper`]; w = spin); not positive semidefinite: column `W` |
//! | optional `un_free,ux_free,uy_free,uw_free` | the free end-of-step velocity (v_n = −ḣ); each absent one: the start velocity's |
//! | → `N,Fx,Fy,Tz` | the step-aware wrench ([`super::step_wrench`]); h_free = h − Δt·un_free |
//!
//! The contact is linearised by [`Linearize`] on the run-time contact ([`Row`]).

use super::{Free, InverseMass, TimeStep, step_wrench};
use crate::Real;
use crate::dynamic::{DynContact, Invalid, RollingStep, Step};
use crate::error::finite;
use crate::friction::Slip;
use crate::jacobian::{Jacobian, Linearize, State};

/// The step columns after the wrench's: `dt` and W's upper triangle.
pub const STEP_INPUTS: [&str; 11] = [
    "dt", "w_nn", "w_nx", "w_ny", "w_nw", "w_xx", "w_xy", "w_xw", "w_yy", "w_yw", "w_ww",
];

/// The optional free end-of-step velocity columns.
pub const FREE_INPUTS: [&str; 4] = ["un_free", "ux_free", "uy_free", "uw_free"];

/// The output columns.
pub const STEP_OUTPUTS: [&str; 4] = ["N", "Fx", "Fy", "Tz"];

/// A run-time contact at a fixed rolling velocity, as a [`Linearize`]: the wrench of
/// [`DynContact::wrench_rolling`] (an invalid state, which a validated [`State`] never is,
/// gives the zero wrench) and its Jacobian by central differences with relative steps
/// (1e-6 of |h| and of the slip's scale, 1e-9 m/s or 1e-9 m at the least).
#[derive(Clone, Copy, Debug)]
pub struct Row<'a, T: Real> {
    contact: &'a DynContact<T>,
    rolling: RollingStep<T>,
}

impl<'a, T: Real> Row<'a, T> {
    /// The contact with the rolling velocity (V_x, V_y) of the row.
    pub fn new(contact: &'a DynContact<T>, rolling: RollingStep<T>) -> Self {
        Row { contact, rolling }
    }
}

impl<T: Real> Linearize<T> for Row<'_, T> {
    fn maximally_dissipative(&self) -> bool {
        self.contact.law().maximally_dissipative()
    }

    fn wrench4(&self, s: &State<T>) -> [T; 4] {
        let step = Step {
            h: s.h,
            hdot: s.hdot,
            vx: s.slip.vx(),
            vy: s.slip.vy(),
            omega: s.slip.omega(),
        };
        match self.contact.wrench_rolling(&step, &self.rolling) {
            Ok(o) => [o.n, o.fx, o.fy, o.tz],
            Err(_) => [T::ZERO; 4],
        }
    }

    fn linearize(&self, s: &State<T>) -> Jacobian<T> {
        let step = Step {
            h: s.h,
            hdot: s.hdot,
            vx: s.slip.vx(),
            vy: s.slip.vy(),
            omega: s.slip.omega(),
        };
        // The analytic (dual-number) Jacobian of the same wrench; a state the contract refuses
        // cannot reach here (the row was validated), so the default is never used in practice.
        self.contact
            .jacobian_rolling(&step, &self.rolling)
            .unwrap_or_default()
    }
}

fn at<X>(column: &'static str, r: Result<X, crate::Error>) -> Result<X, Invalid> {
    r.map_err(|error| Invalid { column, error })
}

/// One row: the contact (built from the row's contact columns), the start step, its rolling
/// columns, then `dt`, W's upper triangle and the optional free velocity (`None`: the start
/// velocity's component). Errors name the column (`W` for a W that is not positive
/// semidefinite).
pub fn step_row<T: Real>(
    contact: &DynContact<T>,
    step: &Step<T>,
    rolling: &RollingStep<T>,
    dt: T,
    w_upper: [T; 10],
    u_free: [Option<T>; 4],
) -> Result<[T; 4], Invalid> {
    // The start state, validated as the wrench validates it.
    contact.wrench_rolling(step, rolling)?;
    let v = if contact.law().is_rolling() {
        rolling.velocity()?
    } else {
        crate::friction::rolling::RollingVelocity::ZERO
    };
    let dt = at("dt", TimeStep::new(dt))?;
    for (k, &x) in w_upper.iter().enumerate() {
        at(STEP_INPUTS[k + 1], finite(x, "W"))?;
    }
    let w = at("W", InverseMass::from_upper(w_upper))?;
    let state = State {
        h: step.h,
        hdot: step.hdot,
        slip: at("vx", Slip::new(step.vx, step.vy, step.omega))?,
        rolling: v,
    };
    let u0 = [-step.hdot, step.vx, step.vy, step.omega];
    let mut u = u0;
    for k in 0..4 {
        if let Some(x) = u_free[k] {
            u[k] = at(FREE_INPUTS[k], finite(x, FREE_INPUTS[k]))?;
        }
    }
    let free = at("un_free", Free::predicted(dt, &state, u))?;
    let row = Row::new(contact, *rolling);
    Ok(step_wrench(&row, dt, &w, &state, &free).wrench)
}
