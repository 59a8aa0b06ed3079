//! `contensou` for Python: the wrench contract of [`contensou::dynamic`] over numpy arrays.
//!
//! A shell and nothing more: it converts the arguments to arrays of the chosen precision,
//! broadcasts them (numpy's rules), validates and loops over the rows with the GIL released;
//! every number comes from [`DynContact::wrench`], so a row gives the bits that
//! `contact_eval wrench`, the C API and the generic contacts give.
//!
//! - `wrench(P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega, *, law, precision, form)`:
//!   the per-row function (a contact per row; rows that repeat the previous row's contact
//!   columns reuse its contact).
//! - `Contact(P, Q, estar, cd, f, delta, *, law, precision, form)`: built once;
//!   `.wrench(h, hdot, vx, vy, omega)` per step (`.jacobian(...)`: with its derivatives),
//!   `.set_curvatures(P, Q)`.
//!
//! Both return the dict `{N, Fx, Fy, Tz, a, b, e2}` of arrays of the broadcast shape (f32
//! arrays for `precision="f32"`; numpy scalars when every argument is a scalar). Bad input is
//! a `ValueError` naming the argument, the index into the broadcast shape and the reason.
//! - `jacobian(...)`: `wrench`'s arguments → the wrench and its 20 derivatives
//!   (`JACOBIAN_OUTPUTS`, `contact_eval jacobian`); `step(..., dt, w_nn, …, w_ww, *, …,
//!   un_free, …)`: the step-aware wrench (`STEP_OUTPUTS`, `contact_eval step`). Row by row
//!   (no batch path), bit for bit those commands.

mod columns;
mod jacobian;
mod rolling;
mod rows;
mod step;

use ::contensou::dynamic::{
    DynContact, Form, INPUTS, Law, OUTPUTS, ROLLING_INPUTS, RollingSpec, RollingStep, Spec, Step,
};
use ::contensou::friction::rolling::row::RowLaw;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use columns::{Column, with_columns};
use rows::{
    Named, PerRow, Precision, StepColumns, contract_named, evaluate_each_py, evaluate_py,
    step_named,
};

/// The value of `option` called `name` among `all`, or a `ValueError` listing the names.
fn named<V: Copy>(
    option: &str,
    name: &str,
    all: &[V],
    name_of: fn(V) -> &'static str,
) -> PyResult<V> {
    // the alias "rolling" names the default rolling law (resolved by the library)
    let resolved = RowLaw::resolve(name);
    all.iter()
        .copied()
        .find(|&v| name_of(v) == resolved)
        .ok_or_else(|| {
            let names: Vec<_> = all.iter().map(|&v| name_of(v)).collect();
            PyValueError::new_err(format!(
                "{option}: unknown '{name}'; expected one of {}",
                names.join(", ")
            ))
        })
}

fn law_of(name: &str) -> PyResult<Law> {
    named("law", name, &Law::ALL, Law::name)
}

fn form_of(name: &str) -> PyResult<Form> {
    named("form", name, &Form::ALL, Form::name)
}

/// `true` for `"f32"`, `false` for `"f64"`.
fn is_f32(precision: &str) -> PyResult<bool> {
    named("precision", precision, &[false, true], |f32| {
        if f32 { "f32" } else { "f64" }
    })
}

/// A `#[pyfunction]` over the contract's columns: `P, Q, estar, cd, f, delta, h, hdot, vx, vy,
/// omega`, then the `[$extra]` ones; keyword-only `law`, `precision`, `form`, the optional
/// `G, nu, vrx, vry`, then the optional `[$optional]` ones. Its body is `$body` with `values`
/// (the required arguments in that order), `optional` (`Option`s in that order), `law`, `form`
/// and `py` bound to the names given, once for each precision: `T` is `f32` or `f64` as asked.
macro_rules! contract_function {
    (
        $(#[$doc:meta])*
        $vis:vis fn $name:ident[$($extra:ident),*][$($optional:ident),*]
            => |$py:ident, $values:ident, $optionals:ident, $law:ident, $form:ident| $body:expr
    ) => {
        $(#[$doc])*
        #[::pyo3::pyfunction]
        #[pyo3(signature = (P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega, $($extra,)* *, law = "best", precision = "f64", form = "fixed", G = None, nu = None, vrx = None, vry = None $(, $optional = None)*))]
        #[allow(non_snake_case, clippy::too_many_arguments)]
        $vis fn $name<'py>(
            $py: ::pyo3::Python<'py>,
            P: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            Q: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            estar: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            cd: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            f: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            delta: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            h: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            hdot: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            vx: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            vy: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            omega: &::pyo3::Bound<'py, ::pyo3::PyAny>,
            $($extra: &::pyo3::Bound<'py, ::pyo3::PyAny>,)*
            law: &str,
            precision: &str,
            form: &str,
            G: Option<&::pyo3::Bound<'py, ::pyo3::PyAny>>,
            nu: Option<&::pyo3::Bound<'py, ::pyo3::PyAny>>,
            vrx: Option<&::pyo3::Bound<'py, ::pyo3::PyAny>>,
            vry: Option<&::pyo3::Bound<'py, ::pyo3::PyAny>>,
            $($optional: Option<&::pyo3::Bound<'py, ::pyo3::PyAny>>,)*
        ) -> ::pyo3::PyResult<::pyo3::Bound<'py, ::pyo3::types::PyDict>> {
            let ($law, $form) = ($crate::law_of(law)?, $crate::form_of(form)?);
            let $values = [P, Q, estar, cd, f, delta, h, hdot, vx, vy, omega $(, $extra)*];
            let $optionals = [G, nu, vrx, vry $(, $optional)*];
            if $crate::is_f32(precision)? {
                type T = f32;
                $body
            } else {
                type T = f64;
                $body
            }
        }
    };
}
pub(crate) use contract_function;

/// The contract's arguments (the 11 columns, the optional `G, nu, vrx, vry`) as columns over
/// their broadcast shape, handed to `then` with the rows' contacts of `law` and `form`: the
/// shape, the step columns, the rolling velocity `[vrx, vry]`, the contacts and every column
/// by name ([`Named`]).
fn with_contract_rows<'py, T: Precision, R>(
    values: [&Bound<'py, PyAny>; 11],
    optional: [Option<&Bound<'py, PyAny>>; 4],
    law: Law,
    form: Form,
    then: impl for<'a> FnOnce(
        &'a [usize],
        &'a StepColumns<'a, T>,
        [Option<&'a Column<'a, T>>; 2],
        PerRow<'a, T>,
        &'a Named<'a, 'a, T>,
    ) -> PyResult<R>,
) -> PyResult<R> {
    with_columns(
        INPUTS,
        values,
        ROLLING_INPUTS,
        optional,
        |shape, c, rolling| {
            let [p, q, estar, cd, f, delta, h, hdot, vx, vy, omega] = c;
            let spec = [p, q, estar, cd, f, delta];
            let steps = [h, hdot, vx, vy, omega];
            let [g, nu, vrx, vry] = rolling.each_ref().map(Option::as_ref);
            let contacts = PerRow::new(&spec, [g, nu], law, form);
            let named = contract_named(&spec, &steps, [g, nu, vrx, vry]);
            then(shape, &steps, [vrx, vry], contacts, &named)
        },
    )
}

contract_function! {
    /// The wrench of the contract, row by row over the broadcast arguments.
    ///
    /// Arguments are the contract's input columns (`contensou.INPUTS`) and, optionally, the
    /// rolling columns `G`, `nu` (contact) and `vrx`, `vry` (step; `contensou.ROLLING_INPUTS`,
    /// read by the rolling laws only; defaults G = E*·(1 − ν), ν = 0.3, V = 0): scalars or
    /// arrays that broadcast together. Returns a dict of arrays `N, Fx, Fy, Tz, a, b, e2` of the broadcast
    /// shape (numpy scalars if every argument is a scalar), dtype float32 for `precision="f32"`.
    /// Raises `ValueError` naming the argument, the index and the reason for any invalid value,
    /// an unknown `law`, `precision` or `form`, or shapes that do not broadcast.
    fn wrench[][] => |py, values, optional, law, form| {
        with_contract_rows::<T, _>(values, optional, law, form, |shape, steps, rolling, c, named| {
            evaluate_py(py, shape, steps, rolling, c, named)
        })
    }
}

/// A value in either precision: a built contact (one per `Contact` or `RollingContact`
/// object; the size difference is not worth a box).
#[allow(clippy::large_enum_variant)]
enum Either<A, B> {
    F32(A),
    F64(B),
}

impl<A, B> Either<A, B> {
    /// `"f32"` or `"f64"`.
    fn precision(&self) -> &'static str {
        match self {
            Either::F32(_) => "f32",
            Either::F64(_) => "f64",
        }
    }
}

/// `$body` with `$c` bound to the value of an [`Either`], whichever its precision.
macro_rules! each {
    ($e:expr, $c:ident => $body:expr) => {
        match $e {
            $crate::Either::F32($c) => $body,
            $crate::Either::F64($c) => $body,
        }
    };
}
pub(crate) use each;

/// A built contact of the contract in either precision.
type Built = Either<DynContact<f32>, DynContact<f64>>;

/// A scalar argument of the chosen precision (numpy's conversion, then one value).
fn scalar<T: Precision>(name: &'static str, value: &Bound<'_, PyAny>) -> PyResult<T> {
    let array = T::convert(name, value)?;
    let view = array.as_array();
    match (view.ndim(), view.iter().next()) {
        (0, Some(&x)) => Ok(x),
        _ => Err(PyValueError::new_err(format!(
            "{name}: a Contact's contact columns are scalars, got shape {}",
            columns::tuple(view.shape())
        ))),
    }
}

/// The contact of `values` (P, Q, estar, cd, f, delta) in precision `T`.
fn build<T: Precision>(
    values: [&Bound<'_, PyAny>; 6],
    optional: [Option<&Bound<'_, PyAny>>; 2],
    law: Law,
    form: Form,
) -> PyResult<DynContact<T>> {
    let mut x = [T::from_f64(0.0); 8];
    for (k, value) in values.into_iter().enumerate() {
        x[k] = scalar::<T>(INPUTS[k], value)?;
    }
    let mut rolling = RollingSpec::default();
    for (k, value) in optional.into_iter().enumerate() {
        if let Some(v) = value {
            x[6 + k] = scalar::<T>(ROLLING_INPUTS[k], v)?;
            *(if k == 0 {
                &mut rolling.g
            } else {
                &mut rolling.nu
            }) = Some(x[6 + k]);
        }
    }
    let [p, q, estar, cd, f, delta, ..] = x;
    let spec = Spec {
        p,
        q,
        estar,
        cd,
        f,
        delta,
    };
    DynContact::new_rolling(&spec, &rolling, law, form).map_err(|e| {
        let names = INPUTS[..6].iter().chain(&ROLLING_INPUTS[..2]);
        let k = names.into_iter().position(|&c| c == e.column).unwrap_or(0);
        PyValueError::new_err(format!("{} = {}: {}", e.column, x[k], e.error.as_str()))
    })
}

/// A built contact's step arguments (`h, hdot, vx, vy, omega`, the optional `vrx, vry`) as
/// columns over their broadcast shape, handed to `then`: the shape, the step columns,
/// `[vrx, vry]` and every column by name ([`Named`]).
fn with_step_columns<'py, T: Precision, R>(
    values: [&Bound<'py, PyAny>; 5],
    rolling: [Option<&Bound<'py, PyAny>>; 2],
    then: impl for<'a> FnOnce(
        &'a [usize],
        &'a StepColumns<'a, T>,
        [Option<&'a Column<'a, T>>; 2],
        &'a Named<'a, 'a, T>,
    ) -> PyResult<R>,
) -> PyResult<R> {
    let names = [INPUTS[6], INPUTS[7], INPUTS[8], INPUTS[9], INPUTS[10]];
    let optional = [ROLLING_INPUTS[2], ROLLING_INPUTS[3]];
    with_columns(names, values, optional, rolling, |shape, steps, rolling| {
        let rolling = rolling.each_ref().map(Option::as_ref);
        then(shape, &steps, rolling, &step_named(&steps, rolling))
    })
}

/// A built contact's step columns in precision `T`: the dict of `wrench`, or with `jacobian`
/// that of `jacobian`.
fn steps_in<'py, T: Precision>(
    py: Python<'py>,
    contact: &DynContact<T>,
    values: [&Bound<'py, PyAny>; 5],
    rolling: [Option<&Bound<'py, PyAny>>; 2],
    jacobian: bool,
) -> PyResult<Bound<'py, PyDict>> {
    with_step_columns::<T, _>(values, rolling, |shape, steps, rolling, named| {
        if jacobian {
            let row = jacobian::row_of(steps, rolling);
            evaluate_each_py(
                py,
                shape,
                contact,
                row,
                &::contensou::jacobian::OUTPUTS,
                named,
            )
        } else {
            evaluate_py(py, shape, steps, rolling, contact, named)
        }
    })
}

/// A contact of the contract built once (validated, the shape solved for `form="fixed"`),
/// evaluated per step with `wrench(h, hdot, vx, vy, omega)` — scalars or arrays.
#[pyclass(module = "contensou")]
struct Contact {
    built: Built,
}

#[pymethods]
impl Contact {
    /// Validates the contact columns (scalars) and builds the contact; `ValueError` naming
    /// the argument otherwise.
    #[new]
    #[pyo3(signature = (P, Q, estar, cd, f, delta, *, law = "best", precision = "f64", form = "fixed", G = None, nu = None))]
    #[allow(non_snake_case, clippy::too_many_arguments)]
    fn new(
        P: &Bound<'_, PyAny>,
        Q: &Bound<'_, PyAny>,
        estar: &Bound<'_, PyAny>,
        cd: &Bound<'_, PyAny>,
        f: &Bound<'_, PyAny>,
        delta: &Bound<'_, PyAny>,
        law: &str,
        precision: &str,
        form: &str,
        G: Option<&Bound<'_, PyAny>>,
        nu: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let (law, form) = (law_of(law)?, form_of(form)?);
        let values = [P, Q, estar, cd, f, delta];
        let built = if is_f32(precision)? {
            Either::F32(build(values, [G, nu], law, form)?)
        } else {
            Either::F64(build(values, [G, nu], law, form)?)
        };
        Ok(Contact { built })
    }

    /// The wrench at the step columns (scalars or arrays that broadcast), optionally with the
    /// rolling velocity `vrx`, `vry` (m/s, contact frame; default 0): the dict of
    /// `contensou.wrench`.
    #[pyo3(signature = (h, hdot, vx, vy, omega, vrx = None, vry = None))]
    #[allow(clippy::too_many_arguments)]
    fn wrench<'py>(
        &self,
        py: Python<'py>,
        h: &Bound<'py, PyAny>,
        hdot: &Bound<'py, PyAny>,
        vx: &Bound<'py, PyAny>,
        vy: &Bound<'py, PyAny>,
        omega: &Bound<'py, PyAny>,
        vrx: Option<&Bound<'py, PyAny>>,
        vry: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let values = [h, hdot, vx, vy, omega];
        each!(&self.built, c => steps_in(py, c, values, [vrx, vry], false))
    }

    /// The wrench and its Jacobian at the step columns (scalars or arrays that broadcast),
    /// optionally with the rolling velocity `vrx`, `vry`: the dict of `contensou.jacobian`
    /// (`JACOBIAN_OUTPUTS`), bit for bit.
    #[pyo3(signature = (h, hdot, vx, vy, omega, vrx = None, vry = None))]
    #[allow(clippy::too_many_arguments)]
    fn jacobian<'py>(
        &self,
        py: Python<'py>,
        h: &Bound<'py, PyAny>,
        hdot: &Bound<'py, PyAny>,
        vx: &Bound<'py, PyAny>,
        vy: &Bound<'py, PyAny>,
        omega: &Bound<'py, PyAny>,
        vrx: Option<&Bound<'py, PyAny>>,
        vry: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let values = [h, hdot, vx, vy, omega];
        each!(&self.built, c => steps_in(py, c, values, [vrx, vry], true))
    }

    /// One scalar step for tight Python loops (a physics engine's callback): Python floats in,
    /// the tuple `(N, Fx, Fy, Tz, a, b, e2)` of Python floats out (for `precision="f32"` the
    /// inputs are rounded to f32 and the f32 results widened exactly) — the values of
    /// `wrench` on the same step, without building numpy objects. `ValueError` as `wrench`.
    #[pyo3(signature = (h, hdot, vx, vy, omega, vrx = 0.0, vry = 0.0))]
    #[allow(clippy::too_many_arguments)]
    fn step(
        &self,
        h: f64,
        hdot: f64,
        vx: f64,
        vy: f64,
        omega: f64,
        vrx: f64,
        vry: f64,
    ) -> PyResult<(f64, f64, f64, f64, f64, f64, f64)> {
        fn one<T: Precision>(c: &DynContact<T>, x: [f64; 7]) -> PyResult<[f64; 7]> {
            let [h, hdot, vx, vy, omega, vrx, vry] = x.map(T::from_f64);
            let step = Step {
                h,
                hdot,
                vx,
                vy,
                omega,
            };
            match c.wrench_rolling(&step, &RollingStep { vrx, vry }) {
                Ok(out) => Ok(out.to_array().map(T::to_f64)),
                Err(e) => {
                    let names = INPUTS.iter().chain(&ROLLING_INPUTS);
                    let k = match names.into_iter().position(|&n| n == e.column) {
                        Some(k) if k >= 13 => k - 2, // vrx, vry: x[5], x[6]
                        Some(k) => k,
                        None => 6,
                    };
                    let value = x.get(k.saturating_sub(6)).copied().unwrap_or(f64::NAN);
                    Err(PyValueError::new_err(format!(
                        "{} = {}: {}",
                        e.column,
                        T::from_f64(value),
                        e.error.as_str()
                    )))
                }
            }
        }
        let x = [h, hdot, vx, vy, omega, vrx, vry];
        let [n, fx, fy, tz, a, b, e2] = each!(&self.built, c => one(c, x)?);
        Ok((n, fx, fy, tz, a, b, e2))
    }

    /// New curvatures (scalars): the per-step update of a `form="varying"` contact; a `fixed`
    /// one is rebuilt. `ValueError` (and the contact unchanged) for invalid values.
    #[allow(non_snake_case)]
    fn set_curvatures(&mut self, P: &Bound<'_, PyAny>, Q: &Bound<'_, PyAny>) -> PyResult<()> {
        fn set<T: Precision>(
            c: &mut DynContact<T>,
            p: &Bound<'_, PyAny>,
            q: &Bound<'_, PyAny>,
        ) -> PyResult<()> {
            let (p, q) = (scalar::<T>("P", p)?, scalar::<T>("Q", q)?);
            c.set_curvatures(p, q).map_err(|e| {
                let value = if e.column == "Q" { q } else { p };
                PyValueError::new_err(format!("{} = {value}: {}", e.column, e.error.as_str()))
            })
        }
        each!(&mut self.built, c => set(c, P, Q))
    }

    /// The friction law's name.
    #[getter]
    fn law(&self) -> &'static str {
        each!(&self.built, c => c.law().name())
    }

    /// `"fixed"` or `"varying"`.
    #[getter]
    fn form(&self) -> &'static str {
        each!(&self.built, c => c.form().name())
    }

    /// `"f32"` or `"f64"`.
    #[getter]
    fn precision(&self) -> &'static str {
        self.built.precision()
    }

    /// The contact columns as a dict `{P, Q, estar, cd, f, delta}` (Python floats).
    #[getter]
    fn spec<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let s: Spec<f64> = match &self.built {
            Either::F32(c) => {
                let s = c.spec();
                Spec {
                    p: s.p.into(),
                    q: s.q.into(),
                    estar: s.estar.into(),
                    cd: s.cd.into(),
                    f: s.f.into(),
                    delta: s.delta.into(),
                }
            }
            Either::F64(c) => *c.spec(),
        };
        let dict = PyDict::new(py);
        for (name, value) in INPUTS.iter().zip([s.p, s.q, s.estar, s.cd, s.f, s.delta]) {
            dict.set_item(*name, value)?;
        }
        Ok(dict)
    }

    fn __repr__(&self) -> PyResult<String> {
        Python::attach(|py| {
            let spec = self.spec(py)?;
            let body: Vec<String> = INPUTS[..6]
                .iter()
                .map(|n| {
                    Ok(format!(
                        "{n}={}",
                        spec.get_item(n)?.map_or(String::new(), |v| v.to_string())
                    ))
                })
                .collect::<PyResult<_>>()?;
            Ok(format!(
                "Contact({}, law='{}', precision='{}', form='{}')",
                body.join(", "),
                self.law(),
                self.precision(),
                self.form()
            ))
        })
    }
}

/// The Python module `contensou`.
#[pymodule(name = "contensou")]
fn contensou_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wrench, m)?)?;
    m.add_function(wrap_pyfunction!(jacobian::jacobian, m)?)?;
    m.add_function(wrap_pyfunction!(step::step, m)?)?;
    m.add("JACOBIAN_OUTPUTS", ::contensou::jacobian::OUTPUTS.to_vec())?;
    m.add(
        "STEP_INPUTS",
        ::contensou::step::contract::STEP_INPUTS.to_vec(),
    )?;
    m.add(
        "FREE_INPUTS",
        ::contensou::step::contract::FREE_INPUTS.to_vec(),
    )?;
    m.add(
        "STEP_OUTPUTS",
        ::contensou::step::contract::STEP_OUTPUTS.to_vec(),
    )?;
    m.add_function(wrap_pyfunction!(rolling::rolling, m)?)?;
    m.add_class::<rolling::RollingContact>()?;
    m.add("ROLLING_INPUTS", ROLLING_INPUTS.to_vec())?;
    m.add("ROLLING_EVAL_INPUTS", rolling::INPUTS.to_vec())?;
    m.add("ROLLING_EVAL_OUTPUTS", rolling::OUTPUTS.to_vec())?;
    m.add(
        "ROLLING_LAWS",
        rolling::LAWS.iter().map(|l| l.name()).collect::<Vec<_>>(),
    )?;
    m.add_class::<Contact>()?;
    m.add("INPUTS", INPUTS.to_vec())?;
    m.add("OUTPUTS", OUTPUTS.to_vec())?;
    m.add(
        "LAWS",
        Law::ALL.iter().map(|l| l.name()).collect::<Vec<_>>(),
    )?;
    m.add(
        "FORMS",
        Form::ALL.iter().map(|f| f.name()).collect::<Vec<_>>(),
    )?;
    m.add("PRECISIONS", vec!["f32", "f64"])?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
