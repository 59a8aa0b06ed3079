//! `contensou.step`: the step-aware wrench of the step contract (`contact_eval step`): the
//! wrench's columns plus the step Δt, the contact's inverse mass W (upper triangle) and the
//! optional free end-of-step velocity → (N, F_x, F_y, T_z) to apply over the step. Each row is
//! [`contract::step_row`] on the row's contact, bit for bit that command.

use ::contensou::dynamic::{DynContact, INPUTS, ROLLING_INPUTS};
use ::contensou::step::contract::{self, FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS};

use crate::columns::with_columns;
use crate::contract_function;
use crate::rows::{PerRow, contract_named, evaluate_each_py, step_at};

/// `a` then `b` (`N` = their lengths' sum).
const fn concat<const N: usize>(a: &[&'static str], b: &[&'static str]) -> [&'static str; N] {
    let mut out = [""; N];
    let mut k = 0;
    while k < N {
        out[k] = if k < a.len() { a[k] } else { b[k - a.len()] };
        k += 1;
    }
    out
}

/// The required columns: the wrench's, then `dt` and W's upper triangle.
const REQUIRED: [&str; 22] = concat(&INPUTS, &STEP_INPUTS);

/// The optional columns: `G, nu, vrx, vry`, then the free end-of-step velocity.
const OPTIONAL: [&str; 8] = concat(&ROLLING_INPUTS, &FREE_INPUTS);

contract_function! {
    /// The step-aware wrench, row by row over the broadcast arguments (`contact_eval step`).
    ///
    /// Arguments: `contensou.wrench`'s 11 columns (the contact and its state at the start of the
    /// step), then `dt` (s, > 0) and the contact's inverse mass W over u = (v_n, v_x, v_y, ω)
    /// (v_n = −ḣ; an impulse Δt·(N, F_x, F_y, T_z) on B changes u by Δt·W·(N, F_x, F_y, T_z)) as
    /// its upper triangle `w_nn, w_nx, w_ny, w_nw, w_xx, w_xy, w_xw, w_yy, w_yw, w_ww`
    /// (`contensou.STEP_INPUTS`; symmetric positive semidefinite within the library's tolerance).
    /// Optional: `G`, `nu`, `vrx`, `vry` as `wrench`; the free end-of-step velocity `un_free`,
    /// `ux_free`, `uy_free`, `uw_free` (`contensou.FREE_INPUTS`: u after the step without this
    /// contact; each absent one: the start velocity's). Returns the dict `{N, Fx, Fy, Tz}`
    /// (`contensou.STEP_OUTPUTS`): the wrench to apply over the whole step (semi-implicit Euler),
    /// bit for bit `contact_eval step`. `ValueError` naming the argument (`W` for a matrix that
    /// is not symmetric positive semidefinite), the index and the reason.
    pub fn step[dt, w_nn, w_nx, w_ny, w_nw, w_xx, w_xy, w_xw, w_yy, w_yw, w_ww]
        [un_free, ux_free, uy_free, uw_free]
        => |py, values, optional, law, form| {
            with_columns(REQUIRED, values, OPTIONAL, optional, |shape, c, extra| {
                let [p, q, estar, cd, f, delta, rest @ ..] = c;
                let [h, hdot, vx, vy, omega, dt, w @ ..] = rest;
                let [g, nu, vrx, vry, free @ ..] = extra;
                let spec = [p, q, estar, cd, f, delta];
                let steps = [h, hdot, vx, vy, omega];
                let rolling = [&g, &nu, &vrx, &vry].map(Option::as_ref);
                let contacts = PerRow::new(&spec, [rolling[0], rolling[1]], law, form);
                let row = |c: &DynContact<T>, i: usize| {
                    let (step, rolling) = step_at(&steps, [rolling[2], rolling[3]], i);
                    let w_upper = w.each_ref().map(|c| c.at(i));
                    let u_free = free.each_ref().map(|c| c.as_ref().map(|c| c.at(i)));
                    contract::step_row(c, &step, &rolling, dt.at(i), w_upper, u_free)
                };
                let mut named = contract_named(&spec, &steps, rolling);
                named.extend(
                    STEP_INPUTS
                        .into_iter()
                        .zip([&dt].into_iter().chain(&w).map(Some)),
                );
                named.extend(
                    FREE_INPUTS
                        .into_iter()
                        .zip(free.each_ref().map(Option::as_ref)),
                );
                evaluate_each_py(py, shape, contacts, row, &STEP_OUTPUTS, &named)
            })
        }
}
