//! `contensou.rolling`: Kalker's rolling contact with the columns of `contact_eval rolling`
//! (`a,b,G,nu,f,N,V,xi,eta,phi` → `Fx,Fy,Mz`), row by row over broadcast arguments, bit for
//! bit that command's numbers; the GIL released; and the class `RollingContact` (a contact
//! built once). The rows, their validation and the column an error names are the library's
//! (`contensou::friction::rolling::row`, shared with `contact_eval` and the C API).

use ::contensou::friction::rolling::Wrench;
use ::contensou::friction::rolling::row::{
    COLUMNS, Column as Col, OUTPUTS as ROW_OUTPUTS, Rejected, RowContact, RowLaw, RowState, Rows,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::{index_of, with_columns};
use crate::rows::{Precision, dict_of, each_row};
use crate::{Either, each, is_f32, named};

/// The input columns, as `contact_eval rolling` reads them.
pub const INPUTS: [&str; 10] = COLUMNS;
/// The output columns.
pub const OUTPUTS: [&str; 3] = ROW_OUTPUTS;

/// The rolling laws, the default first (`contact_eval rolling --law`).
pub const LAWS: [RowLaw; 6] = RowLaw::ALL;

/// The per-call columns of a built contact, in its `wrench` order.
const STATE: [&str; 8] = ["a", "b", "f", "N", "V", "xi", "eta", "phi"];

fn rolling_in<'py, T: Precision>(
    py: Python<'py>,
    values: [&Bound<'py, PyAny>; 10],
    law: RowLaw,
) -> PyResult<Bound<'py, PyDict>> {
    with_columns::<T, _, 10, 0>(INPUTS, values, [], [], |shape, c, []| {
        let mut rows = Rows::new(law);
        run(py, shape, |i| rows.eval(&c.each_ref().map(|c| c.at(i))))
    })
}

/// The per-call columns `a, b, f, N, V, xi, eta, phi` of a built contact.
fn built_in<'py, T: Precision>(
    py: Python<'py>,
    contact: &RowContact<T>,
    values: [&Bound<'py, PyAny>; 8],
) -> PyResult<Bound<'py, PyDict>> {
    with_columns(STATE, values, [], [], |shape, c, []| {
        run(py, shape, |i| {
            let [a, b, f, n, v, xi, eta, phi] = c.each_ref().map(|c| c.at(i));
            contact.wrench(&RowState {
                a,
                b,
                f,
                n,
                v,
                xi,
                eta,
                phi,
            })
        })
    })
}

/// The rows of `shape` through `row` with the GIL released: the dict of [`OUTPUTS`] or the
/// `ValueError` naming the column, its value, the index and the reason.
fn run<'py, T: Precision>(
    py: Python<'py>,
    shape: &[usize],
    mut row: impl FnMut(usize) -> Result<Wrench<T>, Rejected<T>> + Send,
) -> PyResult<Bound<'py, PyDict>> {
    let rows: usize = shape.iter().product();
    let result = py.detach(|| each_row(rows, |i| row(i).map(|w| [w.fx, w.fy, w.mz])));
    match result {
        Ok(out) => dict_of(py, shape, &OUTPUTS, out),
        Err((i, r)) => Err(PyValueError::new_err(format!(
            "{} = {} at index {}: {}",
            r.column.name(),
            r.value,
            index_of(i, shape),
            r.error.as_str()
        ))),
    }
}

/// Kalker's rolling contact, row by row over the broadcast arguments: the columns of
/// `contact_eval rolling` — semi-axes a (along the rolling direction +x) and b (m), G (Pa),
/// ν, f, N (N), V (m/s; only its sign matters, 0 = the limit V → 0⁺), creepages ξ, η and
/// φ (1/m) of body B relative to A — to the dict `{Fx, Fy, Mz}` on body B (N, N·m), bit for
/// bit that command's output. `law`: one of `contensou.ROLLING_LAWS` (default `"table"`).
/// Raises `ValueError` naming the argument (or `a/b`), its value, the index and the reason.
#[pyfunction]
#[pyo3(signature = (a, b, G, nu, f, N, V, xi, eta, phi, *, law = "table", precision = "f64"))]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub fn rolling<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
    G: &Bound<'py, PyAny>,
    nu: &Bound<'py, PyAny>,
    f: &Bound<'py, PyAny>,
    N: &Bound<'py, PyAny>,
    V: &Bound<'py, PyAny>,
    xi: &Bound<'py, PyAny>,
    eta: &Bound<'py, PyAny>,
    phi: &Bound<'py, PyAny>,
    law: &str,
    precision: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let law = named("law", law, &LAWS, RowLaw::name)?;
    let values = [a, b, G, nu, f, N, V, xi, eta, phi];
    if is_f32(precision)? {
        rolling_in::<f32>(py, values, law)
    } else {
        rolling_in::<f64>(py, values, law)
    }
}

/// A rolling contact built once: the shape a/b (a along the rolling direction), G, ν and the
/// rolling law; `wrench(a, b, f, N, V, xi, eta, phi)` per call (scalars or arrays), the dict
/// `{Fx, Fy, Mz}` of `contensou.rolling` on the same values with a/b = a / b. The call's a, b
/// set the patch size c = √(ab); the shape is the contact's (`RollingContact::new` and
/// `Patch::new` in Rust, `contensou_rolling_*` in C).
#[pyclass(module = "contensou")]
pub struct RollingContact {
    built: BuiltAny,
}

/// The built rolling contact in either precision.
type BuiltAny = Either<RowContact<f32>, RowContact<f64>>;

fn build<T: Precision>(ratio: f64, g: f64, nu: f64, law: RowLaw) -> PyResult<RowContact<T>> {
    let [ratio, g, nu] = [ratio, g, nu].map(T::from_f64);
    RowContact::new(ratio, g, nu, law).map_err(|r| {
        let name = match r.column {
            Col::AOverB => "a_over_b",
            c => c.name(),
        };
        PyValueError::new_err(format!("{name} = {}: {}", r.value, r.error.as_str()))
    })
}

#[pymethods]
impl RollingContact {
    /// Validates a/b ∈ [0.01, 100], G > 0, ν ∈ [0, 0.5] (rounded to f32 first for
    /// `precision="f32"`) and builds the contact; `ValueError` naming the argument otherwise.
    #[new]
    #[pyo3(signature = (a_over_b, G, nu, *, law = "table", precision = "f64"))]
    #[allow(non_snake_case)]
    fn new(a_over_b: f64, G: f64, nu: f64, law: &str, precision: &str) -> PyResult<Self> {
        let law = named("law", law, &LAWS, RowLaw::name)?;
        let built = if is_f32(precision)? {
            Either::F32(build(a_over_b, G, nu, law)?)
        } else {
            Either::F64(build(a_over_b, G, nu, law)?)
        };
        Ok(RollingContact { built })
    }

    /// F_x, F_y, M_z on body B for the per-call columns (scalars or arrays that broadcast).
    #[allow(non_snake_case, clippy::too_many_arguments)]
    fn wrench<'py>(
        &self,
        py: Python<'py>,
        a: &Bound<'py, PyAny>,
        b: &Bound<'py, PyAny>,
        f: &Bound<'py, PyAny>,
        N: &Bound<'py, PyAny>,
        V: &Bound<'py, PyAny>,
        xi: &Bound<'py, PyAny>,
        eta: &Bound<'py, PyAny>,
        phi: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let values = [a, b, f, N, V, xi, eta, phi];
        each!(&self.built, c => built_in(py, c, values))
    }

    /// The rolling law's name.
    #[getter]
    fn law(&self) -> &'static str {
        each!(&self.built, c => c.law().name())
    }

    /// `"f32"` or `"f64"`.
    #[getter]
    fn precision(&self) -> &'static str {
        self.built.precision()
    }
}
