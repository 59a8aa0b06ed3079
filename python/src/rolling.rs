//! `contensou.rolling`: Kalker's rolling contact with the columns of `contact_eval rolling`
//! (`a,b,G,nu,f,N,V,xi,eta,phi` → `Fx,Fy,Mz`), row by row over broadcast arguments, bit for
//! bit that command's numbers ([`RollingContact::wrench`]); the GIL released.

use ::contensou::friction::rolling::{
    Blend, Elasticity, Fastsim, FastsimGrid, FullSlip, Linear, Patch, RollingContact, RollingLaw,
    RollingSlip, Table,
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

/// One row: `contact_eval rolling`'s validation order (G, ν; a, b, N, f; a/b; the slip).
struct Row<'a, T: Precision> {
    columns: &'a [Column<'a, T>; 10],
    law: Method,
    last: Option<([u64; 3], RollingContact<T>)>,
}

impl<T: Precision> Row<'_, T> {
    fn eval(&mut self, i: usize) -> Result<[T; 3], Rejected<T>> {
        let r: [T; 10] = core::array::from_fn(|k| self.columns[k].at(i));
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
        let el = Elasticity::new(r[2], r[3])
            .map_err(|e| named(if r[2] > T::ZERO { 3 } else { 2 }, e))?;
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
        if self.last.as_ref().is_none_or(|(k, _)| *k != key) {
            let contact = RollingContact::new(ratio, el).map_err(|error| Rejected {
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
        let Some((_, contact)) = self.last.as_ref() else {
            return Err(reject(0, Error::NonFinite("a"))); // never: set above
        };
        Ok(wrench_by(contact, self.law, &patch, &slip))
    }
}

/// The wrench of `contact` by `law`.
fn wrench_by<T: Real>(
    contact: &RollingContact<T>,
    law: Method,
    patch: &Patch<T>,
    slip: &RollingSlip<T>,
) -> [T; 3] {
    fn by<T: Real, L: RollingLaw>(
        c: &RollingContact<T>,
        p: &Patch<T>,
        s: &RollingSlip<T>,
    ) -> [T; 3] {
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
    let rows: usize = shape.iter().product();
    let result = py.detach(|| {
        let mut row = Row {
            columns: &columns,
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
                    _ => dict.set_item(*name, flat.reshape(shape.as_slice())?)?,
                }
            }
            Ok(dict)
        }
        Err(r) => Err(PyValueError::new_err(format!(
            "{} = {} at index {}: {}",
            r.column,
            r.value,
            index_of(r.row, &shape),
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
