//! `contensou.jacobian`: the wrench of the contract and its 20 derivatives with respect to
//! (h, ḣ, v_x, v_y, ω), row by row over broadcast arguments — each row
//! [`DynContact::jacobian_rolling`], bit for bit `contact_eval jacobian`.

use ::contensou::dynamic::{
    DynContact, Form, INPUTS, Invalid, Law, ROLLING_INPUTS, RollingStep, Step,
};
use ::contensou::jacobian::OUTPUTS;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::Column;
use crate::rows::{PerRow, Precision, StepColumns, evaluate_each_py};
use crate::{form_of, is_f32, law_of, with_contract_columns, with_step_columns};

/// The per-row Jacobian in precision `T`.
fn jacobian_in<'py, T: Precision>(
    py: Python<'py>,
    values: [&Bound<'py, PyAny>; 11],
    optional: [Option<&Bound<'py, PyAny>>; 4],
    law: Law,
    form: Form,
) -> PyResult<Bound<'py, PyDict>> {
    with_contract_columns::<T, _>(values, optional, |shape, spec, steps, rolling| {
        let [g, nu, vrx, vry] = rolling.each_ref().map(Option::as_ref);
        let contacts = PerRow::new(spec, [g, nu], law, form);
        let given = spec.iter().chain(steps).map(Some);
        let mut inputs: Vec<_> = INPUTS.iter().copied().zip(given).collect();
        inputs.extend(ROLLING_INPUTS.iter().copied().zip([g, nu, vrx, vry]));
        let row = row_of(steps, [vrx, vry]);
        evaluate_each_py(py, shape, contacts, row, &OUTPUTS, &inputs)
    })
}

/// The Jacobian of row i from the step columns and the optional rolling velocity.
fn row_of<'a, T: Precision>(
    steps: &'a StepColumns<'a, T>,
    rolling: [Option<&'a Column<'a, T>>; 2],
) -> impl Fn(&DynContact<T>, usize) -> Result<[T; 24], Invalid> + Send + Sync + 'a {
    move |c, i| {
        let [h, hdot, vx, vy, omega] = steps.each_ref().map(|c| c.at(i));
        let [vrx, vry] = rolling.map(|c| c.map_or(T::ZERO, |c| c.at(i)));
        let step = Step {
            h,
            hdot,
            vx,
            vy,
            omega,
        };
        c.jacobian_rolling(&step, &RollingStep { vrx, vry })
            .map(|j| j.to_array())
    }
}

/// `Contact.jacobian`: the step columns of a built contact.
pub fn built_in<'py, T: Precision>(
    py: Python<'py>,
    contact: &DynContact<T>,
    values: [&Bound<'py, PyAny>; 5],
    rolling: [Option<&Bound<'py, PyAny>>; 2],
) -> PyResult<Bound<'py, PyDict>> {
    with_step_columns::<T, _>(values, rolling, |shape, steps, [vrx, vry]| {
        let given = steps.iter().map(Some);
        let mut inputs: Vec<_> = INPUTS[6..].iter().copied().zip(given).collect();
        inputs.extend(ROLLING_INPUTS[2..].iter().copied().zip([vrx, vry]));
        let row = row_of(steps, [vrx, vry]);
        evaluate_each_py(py, shape, contact, row, &OUTPUTS, &inputs)
    })
}

/// The wrench of the contract and its Jacobian, row by row over the broadcast arguments.
///
/// Arguments as `contensou.wrench` (the 11 columns, optional `G`, `nu`, `vrx`, `vry`; the
/// rolling velocity is held fixed, not differentiated). Returns the dict of
/// `contensou.JACOBIAN_OUTPUTS`: `N, Fx, Fy, Tz` (bit for bit `wrench`'s) and the 20
/// derivatives `dN_dh, dN_dhdot, dN_dvx, dN_dvy, dN_domega, dFx_dh, …, dTz_domega` (SI), arrays
/// of the broadcast shape — bit for bit `contact_eval jacobian`. Forward-mode dual numbers
/// through the library's code: at a law's kink the derivative of the branch the value takes;
/// h ≤ 0 gives zeros. `ValueError` as `wrench` (argument, index, reason).
#[pyfunction]
#[pyo3(signature = (P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega, *, law = "best", precision = "f64", form = "fixed", G = None, nu = None, vrx = None, vry = None))]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub fn jacobian<'py>(
    py: Python<'py>,
    P: &Bound<'py, PyAny>,
    Q: &Bound<'py, PyAny>,
    estar: &Bound<'py, PyAny>,
    cd: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    delta: &Bound<'py, PyAny>,
    h: &Bound<'py, PyAny>,
    hdot: &Bound<'py, PyAny>,
    vx: &Bound<'py, PyAny>,
    vy: &Bound<'py, PyAny>,
    omega: &Bound<'py, PyAny>,
    law: &str,
    precision: &str,
    form: &str,
    G: Option<&Bound<'py, PyAny>>,
    nu: Option<&Bound<'py, PyAny>>,
    vrx: Option<&Bound<'py, PyAny>>,
    vry: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (law, form) = (law_of(law)?, form_of(form)?);
    let values = [P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega];
    let optional = [G, nu, vrx, vry];
    if is_f32(precision)? {
        jacobian_in::<f32>(py, values, optional, law, form)
    } else {
        jacobian_in::<f64>(py, values, optional, law, form)
    }
}
