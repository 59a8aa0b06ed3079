//! numpy broadcasting of the contract's input columns, and the index of a rejected row.
//!
//! Every argument becomes a [`Column`]: one value shared by every row (its size is 1) or one
//! value per row of the broadcast shape in C order — borrowed from the caller's array when it
//! already has that shape and layout, otherwise copied once through ndarray's broadcast.

use std::borrow::Cow;

use numpy::ndarray::IxDyn;
use numpy::{AllowTypeChange, Element, PyArrayLikeDyn, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::rows::Precision;

/// An argument converted to a numpy array of the chosen precision (numpy's `asarray`).
pub type Arg<'py, T> = PyArrayLikeDyn<'py, T, AllowTypeChange>;

/// Converts the argument `name` to an array of `T`; a value numpy cannot convert is a
/// `ValueError` naming the argument.
pub fn convert<'py, T>(name: &str, value: &Bound<'py, PyAny>) -> PyResult<Arg<'py, T>>
where
    T: Element + for<'a> FromPyObject<'a, 'py> + 'py,
{
    value.extract::<Arg<'py, T>>().map_err(|e| {
        PyValueError::new_err(format!("{name}: not convertible to a float array ({e})"))
    })
}

/// The numpy broadcast shape of the named arguments; a mismatch is a `ValueError` naming the
/// two arguments and their shapes.
pub fn broadcast_shape<T: Element>(args: &[(&str, &Arg<'_, T>)]) -> PyResult<Vec<usize>> {
    let ndim = args.iter().map(|(_, a)| a.ndim()).max().unwrap_or(0);
    let mut shape = vec![1usize; ndim];
    // Which argument fixed each dimension (for the message).
    let mut owner: Vec<Option<usize>> = vec![None; ndim];
    for (k, (name, arg)) in args.iter().enumerate() {
        let dims = arg.shape();
        let offset = ndim - dims.len();
        for (j, &d) in dims.iter().enumerate() {
            let axis = offset + j;
            if d == shape[axis] || d == 1 {
                continue;
            }
            if shape[axis] == 1 {
                shape[axis] = d;
                owner[axis] = Some(k);
                continue;
            }
            let other = owner[axis].map_or("?", |o| args[o].0);
            let other_shape = owner[axis].map_or(&[][..], |o| args[o].1.shape());
            return Err(PyValueError::new_err(format!(
                "shape mismatch: {name} has shape {} and {other} has shape {}; they cannot be \
                 broadcast together",
                tuple(dims),
                tuple(other_shape),
            )));
        }
    }
    Ok(shape)
}

/// The arguments `names` and the optional ones `optional_names` (`None`: not given) converted
/// to arrays of `T` (in that order: the first that numpy cannot convert is the error), then
/// broadcast together, handed to `then` as columns over the broadcast shape (shape, columns,
/// optional columns). Every shell function's arguments go through here.
pub fn with_columns<'py, T: Precision, R, const N: usize, const M: usize>(
    names: [&'static str; N],
    values: [&Bound<'py, PyAny>; N],
    optional_names: [&'static str; M],
    optional: [Option<&Bound<'py, PyAny>>; M],
    then: impl for<'a> FnOnce(
        &'a [usize],
        [Column<'a, T>; N],
        [Option<Column<'a, T>>; M],
    ) -> PyResult<R>,
) -> PyResult<R> {
    let mut args = Vec::with_capacity(N);
    for (name, value) in names.into_iter().zip(values) {
        args.push(T::convert(name, value)?);
    }
    let mut extra = [const { None }; M];
    for ((arg, name), value) in extra.iter_mut().zip(optional_names).zip(optional) {
        if let Some(v) = value {
            *arg = Some(T::convert(name, v)?);
        }
    }
    let given = optional_names.into_iter().zip(&extra);
    let named: Vec<_> = names
        .into_iter()
        .zip(&args)
        .chain(given.filter_map(|(name, arg)| Some((name, arg.as_ref()?))))
        .collect();
    let shape = broadcast_shape(&named)?;
    let mut columns = Vec::with_capacity(N);
    for arg in &args {
        columns.push(Column::new(arg, &shape)?);
    }
    let columns = columns
        .try_into()
        .map_err(|_| PyValueError::new_err("argument count"))?;
    let mut optional = [const { None }; M];
    for (column, arg) in optional.iter_mut().zip(&extra) {
        if let Some(a) = arg {
            *column = Some(Column::new(a, &shape)?);
        }
    }
    then(&shape, columns, optional)
}

/// One input column over the rows of the broadcast shape.
pub struct Column<'a, T: Clone> {
    values: Cow<'a, [T]>,
    /// 0: one value for every row; 1: one value per row.
    stride: usize,
}

impl<'a, T: Element + Copy> Column<'a, T> {
    /// The column of `arg` over `shape` (which `arg` broadcasts to).
    pub fn new(arg: &'a Arg<'_, T>, shape: &[usize]) -> PyResult<Self> {
        let view = arg.as_array();
        if view.len() == 1 {
            let value = view.iter().next().copied();
            let values = Cow::Owned(value.into_iter().collect());
            return Ok(Column { values, stride: 0 });
        }
        if view.shape() == shape
            && let Some(slice) = view.to_slice()
        {
            return Ok(Column {
                values: Cow::Borrowed(slice),
                stride: 1,
            });
        }
        let wide = view.broadcast(IxDyn(shape)).ok_or_else(|| {
            PyValueError::new_err(format!("shape {} does not broadcast", tuple(view.shape())))
        })?;
        Ok(Column {
            values: Cow::Owned(wide.iter().copied().collect()),
            stride: 1,
        })
    }

    /// The first `rows` values when the column has one value per row.
    pub fn rows(&self, rows: usize) -> Option<&[T]> {
        match self.stride {
            0 => None,
            _ => self.values.get(..rows),
        }
    }

    /// The value at row `i` (C order).
    #[inline(always)]
    pub fn at(&self, i: usize) -> T {
        self.values[i * self.stride]
    }
}

/// `(a, b, c)` as Python prints a tuple (`(a,)` for one element).
pub fn tuple(dims: &[usize]) -> String {
    match dims {
        [one] => format!("({one},)"),
        _ => format!(
            "({})",
            dims.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// The index of flat row `flat` (C order) in `shape`: `5` for a 1-D shape, `(1, 2)` otherwise.
pub fn index_of(flat: usize, shape: &[usize]) -> String {
    if shape.len() == 1 {
        return flat.to_string();
    }
    let mut rest = flat;
    let mut index = vec![0; shape.len()];
    for (axis, &d) in shape.iter().enumerate().rev() {
        index[axis] = rest % d.max(1);
        rest /= d.max(1);
    }
    tuple(&index)
}
