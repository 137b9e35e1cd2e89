//! The library's errors as Python exceptions, with its message: `OSError` for a file that
//! cannot be read, `ValueError` for everything a caller gave wrong.

use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::PyErr;

/// `error` as the exception a Python caller expects.
pub fn to_py(error: autostereo::Error) -> PyErr {
    let message = error.to_string();
    match error {
        autostereo::Error::Io { .. } => PyOSError::new_err(message),
        _ => PyValueError::new_err(message),
    }
}
