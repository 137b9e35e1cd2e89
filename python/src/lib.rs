//! The `autostereo` Python module: numpy volumes, meshes, points and Gaussians in; spatial
//! images, quilts, views and previews out; the viewer window from a notebook; on the library's
//! `AnyScene` / `AnyRenderer` path (docs/PYTHON.md). One GPU device per process
//! ([`context`]); each scene is uploaded once and kept; a `Renderer` keeps its prepared state
//! between frames.

mod arrays;
mod camera;
mod context;
mod display;
mod errors;
mod gaussians;
mod geometry;
mod names;
mod renderer;
mod scene;
mod show;
mod volume;

use pyo3::prelude::*;

#[pymodule]
fn autostereo(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<display::PyDisplay>()?;
    m.add_class::<scene::PyScene>()?;
    m.add_class::<volume::PyVolume>()?;
    m.add_class::<geometry::PyMesh>()?;
    m.add_class::<geometry::PyPoints>()?;
    m.add_class::<gaussians::PyGaussians>()?;
    m.add_class::<camera::PyCamera>()?;
    m.add_class::<show::PyWindow>()?;
    m.add_function(wrap_pyfunction!(show::show, m)?)?;
    m.add_function(wrap_pyfunction!(scene::load, m)?)?;
    m.add_function(wrap_pyfunction!(renderer::render, m)?)?;
    m.add_class::<renderer::PyRenderer>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
