//! One of a fixed set chosen by its name (a method, a stereo format, a preview, a side, a camera
//! model): one lookup and one wording of the refusal, a `ValueError` that lists the names.

use pyo3::exceptions::PyValueError;
use pyo3::PyResult;

/// The item of `all` whose `name` is `value`; else "unknown {what} {value:?} ({what}s: …)".
pub fn by_name<T: Copy>(
    value: &str,
    what: &str,
    all: &[T],
    name: impl Fn(T) -> &'static str,
) -> PyResult<T> {
    all.iter()
        .copied()
        .find(|&t| name(t) == value)
        .ok_or_else(|| {
            let names: Vec<&str> = all.iter().map(|&t| name(t)).collect();
            PyValueError::new_err(format!(
                "unknown {what} {value:?} ({what}s: {})",
                names.join(", ")
            ))
        })
}
