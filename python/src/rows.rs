//! The row loop: every row of the broadcast shape through [`DynContact::wrench`], the GIL
//! released, the first rejected row reported as a `ValueError` (argument, index, reason).

use ::contensou::Real;
use ::contensou::dynamic::{DynContact, Form, INPUTS, Invalid, Law, OUTPUTS, Output, Spec, Step};
use numpy::{Element, PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::{Arg, Column, convert, index_of};

/// A float type the package evaluates in: the crate's [`Real`] and a numpy element.
pub trait Precision: Real + Element + Send + Sync + std::fmt::Display {
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

/// Where each row's contact comes from.
pub trait Contacts<T: Real> {
    /// The contact of row `i`.
    fn at(&mut self, i: usize) -> Result<&DynContact<T>, Invalid>;
}

/// One contact for every row (a built `Contact`).
impl<T: Real> Contacts<T> for &DynContact<T> {
    #[inline(always)]
    fn at(&mut self, _: usize) -> Result<&DynContact<T>, Invalid> {
        Ok(self)
    }
}

/// A contact per row from the contact columns (the per-row `wrench`). A row whose contact
/// columns have the bits of the previous row's reuses its contact: construction is
/// deterministic, so the result is the one a fresh build gives.
pub struct PerRow<'a, T: Real> {
    columns: &'a SpecColumns<'a, T>,
    law: Law,
    form: Form,
    last: Option<([u64; 6], DynContact<T>)>,
}

impl<'a, T: Precision> PerRow<'a, T> {
    /// Contacts of `law` and `form` from `columns`.
    pub fn new(columns: &'a SpecColumns<'a, T>, law: Law, form: Form) -> Self {
        PerRow {
            columns,
            law,
            form,
            last: None,
        }
    }
}

impl<T: Precision> Contacts<T> for PerRow<'_, T> {
    #[inline]
    fn at(&mut self, i: usize) -> Result<&DynContact<T>, Invalid> {
        let [p, q, estar, cd, f, delta] = self.columns.each_ref().map(|c| c.at(i));
        let key = [p, q, estar, cd, f, delta].map(Precision::bits);
        if self.last.as_ref().is_none_or(|(k, _)| *k != key) {
            let spec = Spec {
                p,
                q,
                estar,
                cd,
                f,
                delta,
            };
            self.last = Some((key, DynContact::new(&spec, self.law, self.form)?));
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
    contacts: impl Contacts<T>,
) -> Result<Outputs<T>, (usize, Invalid)> {
    let [h, hdot, vx, vy, omega] = steps;
    // The common case, every step column an array: plain slices of length `rows`, so the
    // loop indexes without bounds checks.
    match steps.each_ref().map(|c| c.rows(rows)) {
        [Some(h), Some(hdot), Some(vx), Some(vy), Some(omega)] => fill(rows, contacts, |i| Step {
            h: h[i],
            hdot: hdot[i],
            vx: vx[i],
            vy: vy[i],
            omega: omega[i],
        }),
        _ => fill(rows, contacts, |i| Step {
            h: h.at(i),
            hdot: hdot.at(i),
            vx: vx.at(i),
            vy: vy.at(i),
            omega: omega.at(i),
        }),
    }
}

/// The row loop over `step(i)`, into output columns allocated once.
#[inline(always)]
fn fill<T: Precision>(
    rows: usize,
    mut contacts: impl Contacts<T>,
    step: impl Fn(usize) -> Step<T>,
) -> Result<Outputs<T>, (usize, Invalid)> {
    let mut columns: [Vec<T>; 7] = core::array::from_fn(|_| vec![T::ZERO; rows]);
    let [n, fx, fy, tz, a, b, e2] = columns.each_mut().map(|c| &mut c[..rows]);
    for i in 0..rows {
        let out: Output<T> = contacts
            .at(i)
            .and_then(|c| c.wrench(&step(i)))
            .map_err(|e| (i, e))?;
        (n[i], fx[i], fy[i], tz[i]) = (out.n, out.fx, out.fy, out.tz);
        (a[i], b[i], e2[i]) = (out.a, out.b, out.e2);
    }
    Ok(Outputs { columns })
}

/// [`evaluate`] with the GIL released, its result as the Python dict or the `ValueError`.
/// `inputs` are the 11 columns in [`INPUTS`] order (`None` for those fixed by a built contact),
/// only read to name the rejected value.
pub fn evaluate_py<'py, T: Precision>(
    py: Python<'py>,
    shape: &[usize],
    steps: &StepColumns<'_, T>,
    contacts: impl Contacts<T> + Send,
    inputs: [Option<&Column<'_, T>>; 11],
) -> PyResult<Bound<'py, PyDict>> {
    let rows = shape.iter().product();
    match py.detach(|| evaluate(rows, steps, contacts)) {
        Ok(outputs) => to_dict(py, shape, outputs),
        Err((row, invalid)) => {
            let value = INPUTS
                .iter()
                .position(|&c| c == invalid.column)
                .and_then(|k| inputs[k])
                .map_or(String::new(), |c| format!(" = {}", c.at(row)));
            Err(PyValueError::new_err(format!(
                "{}{value} at index {}: {}",
                invalid.column,
                index_of(row, shape),
                invalid.error.as_str()
            )))
        }
    }
}

/// The dict `{N, Fx, Fy, Tz, a, b, e2}` of arrays of `shape` (numpy scalars for shape `()`,
/// as a ufunc returns).
fn to_dict<'py, T: Precision>(
    py: Python<'py>,
    shape: &[usize],
    outputs: Outputs<T>,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (name, column) in OUTPUTS.iter().zip(outputs.columns) {
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
