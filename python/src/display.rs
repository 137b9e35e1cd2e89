//! `autostereo.Display`: a display by its `--display` spec ("hubner8", "lenticular:8",
//! "lkg:calibration.json", …), parsed by the library.

use autostereo::display::Display;
use pyo3::prelude::*;

use crate::errors::to_py;

/// A multi-view display.
#[pyclass(name = "Display", module = "autostereo", frozen)]
pub struct PyDisplay {
    pub display: Display,
    pub spec: String,
}

#[pymethods]
impl PyDisplay {
    /// The display of `spec`, as the CLI's `--display` takes it.
    #[new]
    pub fn parse(spec: &str) -> PyResult<Self> {
        Ok(Self {
            display: Display::parse(spec).map_err(to_py)?,
            spec: spec.to_string(),
        })
    }

    /// A Looking Glass from its calibration (`visual.json`, as the panel's drive holds it): the
    /// display `lkg:PATH`.
    #[staticmethod]
    fn from_calibration(path: &str) -> PyResult<Self> {
        Self::parse(&format!("lkg:{path}"))
    }

    /// Views the display shows.
    #[getter]
    fn views(&self) -> u32 {
        self.display.views()
    }

    fn __repr__(&self) -> String {
        format!("Display({:?}, views={})", self.spec, self.display.views())
    }
}
