//! `contensou.step`: the step-aware wrench of the step contract (`contact_eval step`): the
//! wrench's columns plus the step Δt, the contact's inverse mass W (upper triangle) and the
//! optional free end-of-step velocity → (N, F_x, F_y, T_z) to apply over the step. Each row is
//! [`contract::step_row`] on the row's contact, bit for bit that command.

use ::contensou::dynamic::{DynContact, Form, INPUTS, Law, ROLLING_INPUTS, RollingStep, Step};
use ::contensou::step::contract::{self, FREE_INPUTS, STEP_INPUTS, STEP_OUTPUTS};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::broadcast_shape;
use crate::rows::{PerRow, Precision, evaluate_each_py};
use crate::{
    columns_of, convert_all, convert_named_optional, form_of, is_f32, law_of, optional_columns,
};

/// The required columns: the wrench's, then `dt` and W's upper triangle.
const REQUIRED: [&str; 22] = {
    let mut out = [""; 22];
    let mut k = 0;
    while k < 22 {
        out[k] = if k < 11 {
            INPUTS[k]
        } else {
            STEP_INPUTS[k - 11]
        };
        k += 1;
    }
    out
};

/// The optional columns: `G, nu, vrx, vry`, then the free end-of-step velocity.
const OPTIONAL: [&str; 8] = {
    let mut out = [""; 8];
    let mut k = 0;
    while k < 8 {
        out[k] = if k < 4 {
            ROLLING_INPUTS[k]
        } else {
            FREE_INPUTS[k - 4]
        };
        k += 1;
    }
    out
};

/// The per-row step-aware wrench in precision `T`.
fn step_in<'py, T: Precision>(
    py: Python<'py>,
    values: [&Bound<'py, PyAny>; 22],
    optional: [Option<&Bound<'py, PyAny>>; 8],
    law: Law,
    form: Form,
) -> PyResult<Bound<'py, PyDict>> {
    let args = convert_all::<T, 22>(REQUIRED, values)?;
    let extra = convert_named_optional::<T, 8>(OPTIONAL, optional)?;
    let mut named: Vec<_> = REQUIRED.iter().copied().zip(args.iter()).collect();
    for (name, arg) in OPTIONAL.iter().zip(&extra) {
        if let Some(a) = arg {
            named.push((name, a));
        }
    }
    let shape = broadcast_shape(&named)?;
    let [
        p,
        q,
        estar,
        cd,
        f,
        delta,
        h,
        hdot,
        vx,
        vy,
        omega,
        dt,
        w @ ..,
    ] = columns_of(&args, &shape)?;
    let [g, nu, vrx, vry, free @ ..] = optional_columns(&extra, &shape)?;
    let spec = [p, q, estar, cd, f, delta];
    let steps = [h, hdot, vx, vy, omega];
    let contacts = PerRow::new(&spec, [g.as_ref(), nu.as_ref()], law, form);
    let row = |c: &DynContact<T>, i: usize| {
        let [h, hdot, vx, vy, omega] = steps.each_ref().map(|c| c.at(i));
        let [vrx, vry] = [&vrx, &vry].map(|c| c.as_ref().map_or(T::ZERO, |c| c.at(i)));
        let step = Step {
            h,
            hdot,
            vx,
            vy,
            omega,
        };
        let w_upper = w.each_ref().map(|c| c.at(i));
        let u_free = free.each_ref().map(|c| c.as_ref().map(|c| c.at(i)));
        contract::step_row(
            c,
            &step,
            &RollingStep { vrx, vry },
            dt.at(i),
            w_upper,
            u_free,
        )
    };
    let given = spec.iter().chain(&steps).chain([&dt]).chain(&w).map(Some);
    let mut inputs: Vec<_> = REQUIRED.iter().copied().zip(given).collect();
    let optional = [&g, &nu, &vrx, &vry]
        .into_iter()
        .chain(&free)
        .map(Option::as_ref);
    inputs.extend(OPTIONAL.iter().copied().zip(optional));
    evaluate_each_py(py, &shape, contacts, row, &STEP_OUTPUTS, &inputs)
}

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
#[pyfunction]
#[pyo3(signature = (P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega, dt, w_nn, w_nx, w_ny, w_nw, w_xx, w_xy, w_xw, w_yy, w_yw, w_ww, *, law = "best", precision = "f64", form = "fixed", G = None, nu = None, vrx = None, vry = None, un_free = None, ux_free = None, uy_free = None, uw_free = None))]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub fn step<'py>(
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
    dt: &Bound<'py, PyAny>,
    w_nn: &Bound<'py, PyAny>,
    w_nx: &Bound<'py, PyAny>,
    w_ny: &Bound<'py, PyAny>,
    w_nw: &Bound<'py, PyAny>,
    w_xx: &Bound<'py, PyAny>,
    w_xy: &Bound<'py, PyAny>,
    w_xw: &Bound<'py, PyAny>,
    w_yy: &Bound<'py, PyAny>,
    w_yw: &Bound<'py, PyAny>,
    w_ww: &Bound<'py, PyAny>,
    law: &str,
    precision: &str,
    form: &str,
    G: Option<&Bound<'py, PyAny>>,
    nu: Option<&Bound<'py, PyAny>>,
    vrx: Option<&Bound<'py, PyAny>>,
    vry: Option<&Bound<'py, PyAny>>,
    un_free: Option<&Bound<'py, PyAny>>,
    ux_free: Option<&Bound<'py, PyAny>>,
    uy_free: Option<&Bound<'py, PyAny>>,
    uw_free: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (law, form) = (law_of(law)?, form_of(form)?);
    let values = [
        P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega, dt, w_nn, w_nx, w_ny, w_nw, w_xx, w_xy,
        w_xw, w_yy, w_yw, w_ww,
    ];
    let optional = [G, nu, vrx, vry, un_free, ux_free, uy_free, uw_free];
    if is_f32(precision)? {
        step_in::<f32>(py, values, optional, law, form)
    } else {
        step_in::<f64>(py, values, optional, law, form)
    }
}
