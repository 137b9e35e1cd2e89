//! `autostereo.Scene`: data the library renders (a volume, a mesh, points, Gaussians) and its
//! upload, made on first render and kept. `Volume`, `Mesh` and `Points` build one from numpy;
//! `load` from any file the library reads.

use std::path::PathBuf;
use std::sync::OnceLock;

use autostereo::render::{Method, StereoFormat};
use autostereo::{AnyData, AnyScene, LoadOptions};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;

use crate::context::context;
use crate::errors::to_py;
use crate::renderer::PyRenderer;

/// A scene to render.
#[pyclass(name = "Scene", module = "autostereo", subclass, frozen)]
pub struct PyScene {
    pub data: AnyData,
    uploaded: OnceLock<AnyScene>,
}

impl PyScene {
    pub fn new(data: AnyData) -> Self {
        Self {
            data,
            uploaded: OnceLock::new(),
        }
    }

    /// The scene on the shared device, uploaded the first time.
    pub fn uploaded(&self) -> PyResult<&AnyScene> {
        if let Some(s) = self.uploaded.get() {
            return Ok(s);
        }
        let ctx = context()?;
        let s = AnyScene::upload(&ctx.device, &ctx.queue, &self.data).map_err(to_py)?;
        Ok(self.uploaded.get_or_init(|| s))
    }
}

#[pymethods]
impl PyScene {
    /// `volume`, `mesh`, `points` or `gaussians`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.data.kind().name()
    }

    fn __repr__(&self) -> String {
        format!("autostereo.Scene({})", self.data.kind().name())
    }

    /// Jupyter's picture of the scene: a red-cyan anaglyph (Dubois) of two of hubner8's views,
    /// 480 × 360, the default framing (`Renderer.preview` gives any other).
    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        let display = autostereo::display::Display::parse("hubner8").map_err(to_py)?;
        let mut renderer = PyRenderer::with(display, [480, 360], Method::SinglePass);
        let image = renderer.stereo(py, self, None, StereoFormat::AnaglyphDubois, None)?;
        let png = image.png_bytes().map_err(PyValueError::new_err)?;
        Ok(PyBytes::new(py, &png))
    }
}

/// The scene in `path`, read as `autostereo.load` reads it (the kind its contents say).
#[pyfunction]
pub fn load(path: PathBuf) -> PyResult<PyScene> {
    let data = autostereo::load(&path, &LoadOptions::default()).map_err(to_py)?;
    Ok(PyScene::new(data))
}
