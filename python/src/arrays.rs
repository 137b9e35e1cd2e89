//! What the numpy readers of `Volume`, `Mesh` and `Points` say of an array they cannot read:
//! one wording for the wrong number of dimensions (`ValueError`) and the wrong dtype
//! (`TypeError`).

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The error for `array`, which `what` needs as `shape` (e.g. "a 3-dimensional array (Z, Y, X)")
/// of `ndim` dimensions and one of the real `dtypes`.
pub fn refused(
    array: &Bound<'_, PyAny>,
    what: &str,
    shape: &str,
    ndim: usize,
    dtypes: &str,
) -> PyErr {
    match array
        .getattr("ndim")
        .and_then(|n| n.extract::<usize>())
        .ok()
    {
        Some(n) if n != ndim => {
            PyValueError::new_err(format!("{what}: {shape}, not an array of {n} dimensions"))
        }
        _ => {
            let dtype = array
                .getattr("dtype")
                .map(|d| d.to_string())
                .unwrap_or_else(|_| array.get_type().to_string());
            PyTypeError::new_err(format!("{what}: real numbers ({dtypes}), not {dtype}"))
        }
    }
}
