//! `contensou.jacobian`: the wrench of the contract and its 20 derivatives with respect to
//! (h, ḣ, v_x, v_y, ω), row by row over broadcast arguments — each row
//! [`DynContact::jacobian_rolling`], bit for bit `contact_eval jacobian`.

use ::contensou::dynamic::{DynContact, Invalid};
use ::contensou::jacobian::OUTPUTS;

use crate::columns::Column;
use crate::rows::{Precision, StepColumns, evaluate_each_py, step_at};
use crate::{contract_function, with_contract_rows};

/// The Jacobian of row i from the step columns and the optional rolling velocity.
pub fn row_of<'a, T: Precision>(
    steps: &'a StepColumns<'a, T>,
    rolling: [Option<&'a Column<'a, T>>; 2],
) -> impl Fn(&DynContact<T>, usize) -> Result<[T; 24], Invalid> + Send + Sync + 'a {
    move |c, i| {
        let (step, rolling) = step_at(steps, rolling, i);
        c.jacobian_rolling(&step, &rolling).map(|j| j.to_array())
    }
}

contract_function! {
    /// The wrench of the contract and its Jacobian, row by row over the broadcast arguments.
    ///
    /// Arguments as `contensou.wrench` (the 11 columns, optional `G`, `nu`, `vrx`, `vry`; the
    /// rolling velocity is held fixed, not differentiated). Returns the dict of
    /// `contensou.JACOBIAN_OUTPUTS`: `N, Fx, Fy, Tz` (bit for bit `wrench`'s) and the 20
    /// derivatives `dN_dh, dN_dhdot, dN_dvx, dN_dvy, dN_domega, dFx_dh, …, dTz_domega` (SI), arrays
    /// of the broadcast shape — bit for bit `contact_eval jacobian`. Forward-mode dual numbers
    /// through the library's code: at a law's kink the derivative of the branch the value takes;
    /// h ≤ 0 gives zeros. `ValueError` as `wrench` (argument, index, reason).
    pub fn jacobian[][] => |py, values, optional, law, form| {
        with_contract_rows::<T, _>(values, optional, law, form, |shape, steps, rolling, c, named| {
            evaluate_each_py(py, shape, c, row_of(steps, rolling), &OUTPUTS, named)
        })
    }
}
