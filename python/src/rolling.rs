//! `contensou.rolling`: Kalker's rolling contact with the columns of `contact_eval rolling`
//! (`a,b,G,nu,f,N,V,xi,eta,phi` → `Fx,Fy,Mz`), row by row over broadcast arguments, bit for
//! bit that command's numbers (`RollingContact::wrench`); the GIL released; and the class
//! `RollingContact` (a contact built once).

use ::contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact as Rolling,
    RollingLaw, RollingSlip, Table,
};
use ::contensou::{Error, Real};
use numpy::PyArray1;
use numpy::PyArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::columns::{Column, broadcast_shape, index_of};
use crate::rows::Precision;
use crate::{columns_of, convert_all, is_f32, named};

/// The input columns, as `contact_eval rolling` reads them.
pub const INPUTS: [&str; 10] = ["a", "b", "G", "nu", "f", "N", "V", "xi", "eta", "phi"];
/// The output columns.
pub const OUTPUTS: [&str; 3] = ["Fx", "Fy", "Mz"];

/// The rolling laws, the default first (`contact_eval rolling --law`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Table,
    Blend,
    Fastsim,
    Fastsim16,
    FullSlip,
    Linear,
}

/// Every rolling law, the default first.
pub const LAWS: [Method; 6] = [
    Method::Table,
    Method::Blend,
    Method::Fastsim,
    Method::Fastsim16,
    Method::FullSlip,
    Method::Linear,
];

impl Method {
    /// The name `contact_eval rolling --law` takes.
    pub fn name(self) -> &'static str {
        match self {
            Method::Table => Table::NAME,
            Method::Blend => Blend::NAME,
            Method::Fastsim => Fastsim::NAME,
            Method::Fastsim16 => "fastsim-16",
            Method::FullSlip => FullSlip::NAME,
            Method::Linear => Linear::NAME,
        }
    }
}

/// A rejected row: the column (or `a/b`), its value, the error.
struct Rejected<T> {
    row: usize,
    column: &'static str,
    value: T,
    error: Error,
}

/// A contact built once (`RollingContact`): the contact and its G, ν.
struct Built<T> {
    contact: Rolling<T>,
    g: T,
    nu: T,
}

/// One row: `contact_eval rolling`'s validation order (G, ν; a, b, N, f; a/b; the slip).
struct Row<'a, T: Precision> {
    /// The columns in [`INPUTS`] order; `None` (G, ν) for a built contact's.
    columns: [Option<&'a Column<'a, T>>; 10],
    /// A contact built once, or `None`: a contact per row (reused while a/b, G, ν repeat).
    built: Option<&'a Built<T>>,
    law: Method,
    last: Option<([u64; 3], Rolling<T>)>,
}

impl<T: Precision> Row<'_, T> {
    fn eval(&mut self, i: usize) -> Result<[T; 3], Rejected<T>> {
        let fixed = |k: usize| match self.built {
            Some(b) if k == 2 => b.g,
            Some(b) if k == 3 => b.nu,
            _ => T::ZERO,
        };
        let r: [T; 10] =
            core::array::from_fn(|k| self.columns[k].map_or_else(|| fixed(k), |c| c.at(i)));
        let reject = |k: usize, error: Error| Rejected {
            row: i,
            column: INPUTS[k],
            value: r[k],
            error,
        };
        // the column a NonFinite error names, else `fallback`
        let named = |fallback: usize, e: Error| match e {
            Error::NonFinite(n) => {
                reject(INPUTS.iter().position(|&c| c == n).unwrap_or(fallback), e)
            }
            _ => reject(fallback, e),
        };
        let el = match self.built {
            Some(_) => None,
            None => Some(
                Elasticity::new(r[2], r[3])
                    .map_err(|e| named(if r[2] > T::ZERO { 3 } else { 2 }, e))?,
            ),
        };
        let culprit = if r[0] <= T::ZERO {
            0
        } else if r[1] <= T::ZERO {
            1
        } else {
            4
        };
        let patch = Patch::new(r[0], r[1], r[5], r[4]).map_err(|e| named(culprit, e))?;
        let ratio = r[0] / r[1];
        let key = [ratio.bits(), r[2].bits(), r[3].bits()];
        if let Some(el) = el
            && self.last.as_ref().is_none_or(|(k, _)| *k != key)
        {
            let contact = Rolling::new(ratio, el).map_err(|error| Rejected {
                row: i,
                column: "a/b",
                value: ratio,
                error,
            })?;
            self.last = Some((key, contact));
        }
        for k in 6..10 {
            if !r[k].is_finite() {
                return Err(reject(k, Error::NonFinite(INPUTS[k])));
            }
        }
        // V = 0: the limit V → 0⁺ at the given creepages (only V's sign matters)
        let v = if r[6] == T::ZERO { T::ONE } else { r[6] };
        let slip = RollingSlip::from_creepages(r[7], r[8], r[9], v).map_err(|e| {
            let k = match e {
                Error::NonFinite("v_y") => 8,
                Error::NonFinite("omega") => 9,
                _ => 7,
            };
            reject(k, e)
        })?;
        let contact = match (self.built, self.last.as_ref()) {
            (Some(b), _) => &b.contact,
            (None, Some((_, c))) => c,
            (None, None) => return Err(reject(0, Error::NonFinite("a"))), // never: set above
        };
        Ok(wrench_by(contact, self.law, &patch, &slip))
    }
}

/// The wrench of `contact` by `law`.
fn wrench_by<T: Real>(
    contact: &Rolling<T>,
    law: Method,
    patch: &Patch<T>,
    slip: &RollingSlip<T>,
) -> [T; 3] {
    fn by<T: Real, L: RollingLaw>(c: &Rolling<T>, p: &Patch<T>, s: &RollingSlip<T>) -> [T; 3] {
        let w = c.wrench::<L>(p, s);
        [w.fx, w.fy, w.mz]
    }
    match law {
        Method::Table => by::<T, Table>(contact, patch, slip),
        Method::Blend => by::<T, Blend>(contact, patch, slip),
        Method::Fastsim => by::<T, Fastsim>(contact, patch, slip),
        Method::Fastsim16 => by::<T, FastsimGrid<16, 16>>(contact, patch, slip),
        Method::FullSlip => by::<T, FullSlip>(contact, patch, slip),
        Method::Linear => by::<T, Linear>(contact, patch, slip),
    }
}

fn rolling_in<'py, T: Precision>(
    py: Python<'py>,
    values: [&Bound<'py, PyAny>; 10],
    law: Method,
) -> PyResult<Bound<'py, PyDict>> {
    let args = convert_all::<T, 10>(INPUTS, values)?;
    let named: Vec<_> = INPUTS.iter().copied().zip(args.iter()).collect();
    let shape = broadcast_shape(&named)?;
    let columns = columns_of(&args, &shape)?;
    run(py, &shape, columns.each_ref().map(Some), None, law)
}

/// The per-call columns `a, b, f, N, V, xi, eta, phi` of a built contact.
fn built_in<'py, T: Precision>(
    py: Python<'py>,
    built: &Built<T>,
    values: [&Bound<'py, PyAny>; 8],
    law: Method,
) -> PyResult<Bound<'py, PyDict>> {
    const NAMES: [&str; 8] = ["a", "b", "f", "N", "V", "xi", "eta", "phi"];
    let args = convert_all::<T, 8>(NAMES, values)?;
    let named: Vec<_> = NAMES.iter().copied().zip(args.iter()).collect();
    let shape = broadcast_shape(&named)?;
    let c = columns_of(&args, &shape)?;
    let columns = [
        Some(&c[0]),
        Some(&c[1]),
        None,
        None,
        Some(&c[2]),
        Some(&c[3]),
        Some(&c[4]),
        Some(&c[5]),
        Some(&c[6]),
        Some(&c[7]),
    ];
    run(py, &shape, columns, Some(built), law)
}

/// The rows of `shape` with the GIL released: the dict of [`OUTPUTS`] or the `ValueError`.
fn run<'py, T: Precision>(
    py: Python<'py>,
    shape: &[usize],
    columns: [Option<&Column<'_, T>>; 10],
    built: Option<&Built<T>>,
    law: Method,
) -> PyResult<Bound<'py, PyDict>> {
    let rows: usize = shape.iter().product();
    let result = py.detach(|| {
        let mut row = Row {
            columns,
            built,
            law,
            last: None,
        };
        let mut out: [Vec<T>; 3] = core::array::from_fn(|_| Vec::with_capacity(rows));
        for i in 0..rows {
            let w = row.eval(i)?;
            for (o, x) in out.iter_mut().zip(w) {
                o.push(x);
            }
        }
        Ok::<_, Rejected<T>>(out)
    });
    match result {
        Ok(out) => {
            let dict = PyDict::new(py);
            for (name, column) in OUTPUTS.iter().zip(out) {
                let flat = PyArray1::from_vec(py, column);
                match shape.len() {
                    0 => dict.set_item(*name, flat.get_item(0)?)?,
                    1 => dict.set_item(*name, flat)?,
                    _ => dict.set_item(*name, flat.reshape(shape)?)?,
                }
            }
            Ok(dict)
        }
        Err(r) => Err(PyValueError::new_err(format!(
            "{} = {} at index {}: {}",
            r.column,
            r.value,
            index_of(r.row, shape),
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
    let law = named("law", law, &LAWS, Method::name)?;
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
    law: Method,
}

/// The built contact in either precision (as `Contact`: the size difference is not worth a box).
#[allow(clippy::large_enum_variant)]
enum BuiltAny {
    F32(Built<f32>),
    F64(Built<f64>),
}

fn build<T: Precision>(ratio: f64, g: f64, nu: f64) -> PyResult<Built<T>> {
    let [ratio, g, nu] = [ratio, g, nu].map(T::from_f64);
    let fail = |name: &str, value: T, e: Error| {
        PyValueError::new_err(format!("{name} = {value}: {}", e.as_str()))
    };
    let el = Elasticity::new(g, nu).map_err(|e| match e {
        Error::NonFinite("nu") | Error::RollingPoissonRatioOutOfRange => fail("nu", nu, e),
        _ => fail("G", g, e),
    })?;
    let contact = Rolling::new(ratio, el).map_err(|e| fail("a_over_b", ratio, e))?;
    Ok(Built { contact, g, nu })
}

#[pymethods]
impl RollingContact {
    /// Validates a/b ∈ [0.01, 100], G > 0, ν ∈ [0, 0.5] (rounded to f32 first for
    /// `precision="f32"`) and builds the contact; `ValueError` naming the argument otherwise.
    #[new]
    #[pyo3(signature = (a_over_b, G, nu, *, law = "table", precision = "f64"))]
    #[allow(non_snake_case)]
    fn new(a_over_b: f64, G: f64, nu: f64, law: &str, precision: &str) -> PyResult<Self> {
        let law = named("law", law, &LAWS, Method::name)?;
        let built = if is_f32(precision)? {
            BuiltAny::F32(build(a_over_b, G, nu)?)
        } else {
            BuiltAny::F64(build(a_over_b, G, nu)?)
        };
        Ok(RollingContact { built, law })
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
        match &self.built {
            BuiltAny::F32(c) => built_in(py, c, values, self.law),
            BuiltAny::F64(c) => built_in(py, c, values, self.law),
        }
    }

    /// The rolling law's name.
    #[getter]
    fn law(&self) -> &'static str {
        self.law.name()
    }

    /// `"f32"` or `"f64"`.
    #[getter]
    fn precision(&self) -> &'static str {
        match self.built {
            BuiltAny::F32(_) => "f32",
            BuiltAny::F64(_) => "f64",
        }
    }
}
