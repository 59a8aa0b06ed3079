//! The row loop: the rows of the broadcast shape through [`DynContact::wrench_many`] (the
//! batch path, SIMD lanes; each run of rows sharing one contact in one call), the GIL
//! released, the first rejected row reported as a `ValueError` (argument, index, reason).
//! Every row is bit for bit [`DynContact::wrench`]'s.

use std::borrow::Cow;

use ::contensou::Real;
use ::contensou::batch::{BatchReal, Steps, Wrenches};
use ::contensou::dynamic::{
    DynContact, Form, INPUTS, Invalid, Law, OUTPUTS, ROLLING_INPUTS, RollingSpec, RollingStep,
    RollingSteps, Spec, Step,
};
use numpy::{Element, PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::{Arg, Column, convert, index_of};

/// A float type the package evaluates in: the crate's [`Real`] and a numpy element.
pub trait Precision: Real + BatchReal + Element + Send + Sync + std::fmt::Display {
    /// The bit pattern, to recognise a row whose contact columns repeat the previous row's.
    fn bits(self) -> u64;

    /// The argument `name` as an array of this type ([`crate::columns::convert`]).
    fn convert<'py>(name: &str, value: &Bound<'py, PyAny>) -> PyResult<Arg<'py, Self>>;
}

impl Precision for f32 {
    fn bits(self) -> u64 {
        u64::from(self.to_bits())
    }

    fn convert<'py>(name: &str, value: &Bound<'py, PyAny>) -> PyResult<Arg<'py, Self>> {
        convert(name, value)
    }
}

impl Precision for f64 {
    fn bits(self) -> u64 {
        self.to_bits()
    }

    fn convert<'py>(name: &str, value: &Bound<'py, PyAny>) -> PyResult<Arg<'py, Self>> {
        convert(name, value)
    }
}

/// The step columns `h, hdot, vx, vy, omega`, in [`INPUTS`] order.
pub type StepColumns<'a, T> = [Column<'a, T>; 5];
/// The contact columns `P, Q, estar, cd, f, delta`, in [`INPUTS`] order.
pub type SpecColumns<'a, T> = [Column<'a, T>; 6];
/// The input columns by name, only read to name the value of a rejected row (`None`: fixed by
/// a built contact or not given).
pub type Named<'c, 'a, T> = Vec<(&'static str, Option<&'c Column<'a, T>>)>;

/// The contract's columns by name: [`INPUTS`] (the contact's, then the step's), then
/// [`ROLLING_INPUTS`] (`G, nu, vrx, vry`, each when given).
pub fn contract_named<'c, 'a, T: Precision>(
    spec: &'c SpecColumns<'a, T>,
    steps: &'c StepColumns<'a, T>,
    rolling: [Option<&'c Column<'a, T>>; 4],
) -> Named<'c, 'a, T> {
    let given = spec.iter().chain(steps).map(Some);
    let mut named: Vec<_> = INPUTS.into_iter().zip(given).collect();
    named.extend(ROLLING_INPUTS.into_iter().zip(rolling));
    named
}

/// A built contact's per-step columns by name: the step's, then `vrx, vry` when given.
pub fn step_named<'c, 'a, T: Precision>(
    steps: &'c StepColumns<'a, T>,
    [vrx, vry]: [Option<&'c Column<'a, T>>; 2],
) -> Named<'c, 'a, T> {
    let mut named: Vec<_> = INPUTS[6..]
        .iter()
        .copied()
        .zip(steps.iter().map(Some))
        .collect();
    named.extend(ROLLING_INPUTS[2..].iter().copied().zip([vrx, vry]));
    named
}

/// Row `i`'s step (`h, hdot, vx, vy, omega`) and rolling velocity (`vrx, vry`; 0 when not
/// given).
pub fn step_at<T: Precision>(
    steps: &StepColumns<'_, T>,
    rolling: [Option<&Column<'_, T>>; 2],
    i: usize,
) -> (Step<T>, RollingStep<T>) {
    let [h, hdot, vx, vy, omega] = steps.each_ref().map(|c| c.at(i));
    let [vrx, vry] = rolling.map(|c| c.map_or(T::ZERO, |c| c.at(i)));
    let step = Step {
        h,
        hdot,
        vx,
        vy,
        omega,
    };
    (step, RollingStep { vrx, vry })
}

/// Where each row's contact comes from.
pub trait Contacts<T: Real> {
    /// The contact of row `i`.
    fn at(&mut self, i: usize) -> Result<&DynContact<T>, Invalid>;

    /// The end of the run of rows from `i` (< `rows`) that share row `i`'s contact.
    fn run_end(&self, i: usize, rows: usize) -> usize;
}

/// One contact for every row (a built `Contact`).
impl<T: Real> Contacts<T> for &DynContact<T> {
    #[inline(always)]
    fn at(&mut self, _: usize) -> Result<&DynContact<T>, Invalid> {
        Ok(self)
    }

    fn run_end(&self, _: usize, rows: usize) -> usize {
        rows
    }
}

/// A contact per row from the contact columns (the per-row `wrench`). A row whose contact
/// columns have the bits of the previous row's reuses its contact: construction is
/// deterministic, so the result is the one a fresh build gives.
pub struct PerRow<'a, T: Real> {
    columns: &'a SpecColumns<'a, T>,
    /// The optional contact columns `G, nu`.
    rolling: [Option<&'a Column<'a, T>>; 2],
    law: Law,
    form: Form,
    last: Option<([u64; 8], DynContact<T>)>,
}

impl<'a, T: Precision> PerRow<'a, T> {
    /// Contacts of `law` and `form` from `columns` and the optional `G, nu` columns.
    pub fn new(
        columns: &'a SpecColumns<'a, T>,
        rolling: [Option<&'a Column<'a, T>>; 2],
        law: Law,
        form: Form,
    ) -> Self {
        PerRow {
            columns,
            rolling,
            law,
            form,
            last: None,
        }
    }
}

impl<T: Precision> PerRow<'_, T> {
    /// The bits of row `i`'s contact columns (an absent optional column: a NaN pattern no
    /// valid value has).
    fn key(&self, i: usize) -> [u64; 8] {
        let [p, q, estar, cd, f, delta] = self.columns.each_ref().map(|c| c.at(i).bits());
        let [g, nu] = self.rolling.map(|c| c.map_or(u64::MAX, |c| c.at(i).bits()));
        [p, q, estar, cd, f, delta, g, nu]
    }

    /// Row `i`'s optional `G, nu`.
    fn rolling_spec(&self, i: usize) -> RollingSpec<T> {
        let [g, nu] = self.rolling.map(|c| c.map(|c| c.at(i)));
        RollingSpec { g, nu }
    }
}

impl<T: Precision> Contacts<T> for PerRow<'_, T> {
    fn run_end(&self, i: usize, rows: usize) -> usize {
        // Every contact column one shared value: one contact for all rows.
        let shared = |c: &Column<'_, T>| c.rows(rows).is_none();
        if self.columns.iter().all(shared) && self.rolling.iter().flatten().all(|c| shared(c)) {
            return rows;
        }
        let key = self.key(i);
        (i + 1..rows).find(|&j| self.key(j) != key).unwrap_or(rows)
    }

    #[inline]
    fn at(&mut self, i: usize) -> Result<&DynContact<T>, Invalid> {
        let [p, q, estar, cd, f, delta] = self.columns.each_ref().map(|c| c.at(i));
        let key = self.key(i);
        if self.last.as_ref().is_none_or(|(k, _)| *k != key) {
            let spec = Spec {
                p,
                q,
                estar,
                cd,
                f,
                delta,
            };
            let rolling = self.rolling_spec(i);
            let contact = DynContact::new_rolling(&spec, &rolling, self.law, self.form)?;
            self.last = Some((key, contact));
        }
        // Set just above when it was absent; the error arm is never taken.
        self.last.as_ref().map(|(_, c)| c).ok_or(Invalid {
            column: "P",
            error: ::contensou::Error::NonFinite("P"),
        })
    }
}

/// The output columns, one vector each, in [`OUTPUTS`] order.
pub struct Outputs<T> {
    columns: [Vec<T>; 7],
}

/// Evaluates `rows` rows; the first rejected row stops the loop: `(row, why)`.
pub fn evaluate<T: Precision>(
    rows: usize,
    steps: &StepColumns<'_, T>,
    rolling: [Option<&Column<'_, T>>; 2],
    mut contacts: impl Contacts<T>,
) -> Result<Outputs<T>, (usize, Invalid)> {
    // Every step column as `rows` values (a shared value expanded once).
    fn expand<'c, T: Precision>(c: &'c Column<'_, T>, rows: usize) -> Cow<'c, [T]> {
        match c.rows(rows) {
            Some(s) => Cow::Borrowed(s),
            None => Cow::Owned((0..rows).map(|i| c.at(i)).collect::<Vec<T>>()),
        }
    }
    let [h, hdot, vx, vy, omega] = steps.each_ref().map(|c| expand(c, rows));
    // The rolling velocity columns when either is given (the other one 0).
    let [vrx, vry] =
        rolling.map(|c| c.map_or(Cow::Owned(vec![T::ZERO; rows]), |c| expand(c, rows)));
    let rolling = rolling.iter().any(Option::is_some);
    let mut columns: [Vec<T>; 7] = core::array::from_fn(|_| vec![T::ZERO; rows]);
    let mut i = 0;
    while i < rows {
        let end = contacts.run_end(i, rows);
        let contact = contacts.at(i).map_err(|e| (i, e))?;
        let [n, fx, fy, tz, a, b, e2] = columns.each_mut().map(|c| &mut c[i..end]);
        let steps = Steps {
            h: &h[i..end],
            hdot: &hdot[i..end],
            vx: &vx[i..end],
            vy: &vy[i..end],
            omega: &omega[i..end],
        };
        let mut out = Wrenches {
            n,
            fx,
            fy,
            tz,
            a,
            b,
            e2,
        };
        let done = if rolling {
            let r = RollingSteps {
                vrx: &vrx[i..end],
                vry: &vry[i..end],
            };
            contact.wrench_many_rolling(&steps, &r, &mut out)
        } else {
            contact.wrench_many(&steps, &mut out)
        };
        done.map_err(|e| {
            let why = Invalid {
                column: e.column,
                error: e.error,
            };
            (i + e.row, why)
        })?;
        i = end;
    }
    Ok(Outputs { columns })
}

/// [`evaluate`] with the GIL released, its result as the Python dict or the `ValueError`
/// ([`rejected`]); `rolling` (`vrx, vry`) are the rolling step columns when given.
pub fn evaluate_py<'py, T: Precision>(
    py: Python<'py>,
    shape: &[usize],
    steps: &StepColumns<'_, T>,
    rolling: [Option<&Column<'_, T>>; 2],
    contacts: impl Contacts<T> + Send,
    named: &[(&str, Option<&Column<'_, T>>)],
) -> PyResult<Bound<'py, PyDict>> {
    let rows = shape.iter().product();
    match py.detach(|| evaluate(rows, steps, rolling, contacts)) {
        Ok(outputs) => dict_of(py, shape, &OUTPUTS, outputs.columns),
        Err((row, invalid)) => Err(rejected(named, row, shape, invalid)),
    }
}

/// The `ValueError` of row `i` (flat, in `shape`) rejected for `invalid`: the column, its
/// value when `named` holds that column (`(name, column)` of every input), the index and the
/// reason.
fn rejected<T: Precision>(
    named: &[(&str, Option<&Column<'_, T>>)],
    i: usize,
    shape: &[usize],
    invalid: Invalid,
) -> PyErr {
    let value = named
        .iter()
        .find(|(n, _)| *n == invalid.column)
        .and_then(|(_, c)| *c)
        .map_or(String::new(), |c| format!(" = {}", c.at(i)));
    PyValueError::new_err(format!(
        "{}{value} at index {}: {}",
        invalid.column,
        index_of(i, shape),
        invalid.error.as_str()
    ))
}

/// The dict `{names[k]: columns[k]}` of arrays of `shape` (numpy scalars for shape `()`, as a
/// ufunc returns).
pub fn dict_of<'py, T: Precision, const K: usize>(
    py: Python<'py>,
    shape: &[usize],
    names: &[&str; K],
    columns: [Vec<T>; K],
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (name, column) in names.iter().zip(columns) {
        let flat = PyArray1::from_vec(py, column);
        if shape.is_empty() {
            dict.set_item(*name, flat.get_item(0)?)?;
        } else if shape.len() == 1 {
            dict.set_item(*name, flat)?;
        } else {
            dict.set_item(*name, flat.reshape(shape)?)?;
        }
    }
    Ok(dict)
}

/// Rows `0..rows` through `row` (row i → its K outputs) into K columns; the first rejected
/// row stops the loop: `(row, why)`.
pub fn each_row<T, E, const K: usize>(
    rows: usize,
    mut row: impl FnMut(usize) -> Result<[T; K], E>,
) -> Result<[Vec<T>; K], (usize, E)> {
    let mut out: [Vec<T>; K] = core::array::from_fn(|_| Vec::with_capacity(rows));
    for i in 0..rows {
        let values = row(i).map_err(|e| (i, e))?;
        for (o, x) in out.iter_mut().zip(values) {
            o.push(x);
        }
    }
    Ok(out)
}

/// Rows one at a time through `row` (the contact of row i and i → K outputs; the Jacobian and
/// the step-aware wrench have no batch path), the GIL released: the dict `{names[k]: …}` of
/// arrays of `shape`, or the first rejected row's `ValueError` ([`rejected`]).
pub fn evaluate_each_py<'py, T: Precision, const K: usize>(
    py: Python<'py>,
    shape: &[usize],
    mut contacts: impl Contacts<T> + Send,
    row: impl Fn(&DynContact<T>, usize) -> Result<[T; K], Invalid> + Send + Sync,
    names: &[&str; K],
    named: &[(&str, Option<&Column<'_, T>>)],
) -> PyResult<Bound<'py, PyDict>> {
    let rows: usize = shape.iter().product();
    let result = py.detach(|| each_row(rows, |i| contacts.at(i).and_then(|c| row(c, i))));
    match result {
        Ok(out) => dict_of(py, shape, names, out),
        Err((i, invalid)) => Err(rejected(named, i, shape, invalid)),
    }
}
