//! `autostereo.Renderer`: a display, an image size and a method; `render(scene)` gives the
//! spatial image as a (H, W, 4) uint8 array. The camera frames the scene as the CLI's does by
//! default (`CameraSettings::default()`, a volume on what its classification shows), so a
//! render equals `autostereo volume FILE --display D --size WxH` of the same data.

use autostereo::camera::CameraSettings;
use autostereo::frame::Frame;
use autostereo::render::{Method, Renderer};
use autostereo::{AnyData, AnyRenderer, RendererOptions};
use numpy::{PyArray3, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::context::context;
use crate::display::PyDisplay;
use crate::errors::to_py;
use crate::scene::PyScene;

/// A renderer for one display and size; it keeps its prepared state between frames.
#[pyclass(name = "Renderer", module = "autostereo", unsendable)]
pub struct PyRenderer {
    display: autostereo::display::Display,
    size: [u32; 2],
    options: RendererOptions,
    renderer: Option<AnyRenderer>,
}

fn method(name: &str) -> PyResult<Method> {
    Method::ALL
        .iter()
        .copied()
        .find(|m| m.name() == name)
        .ok_or_else(|| {
            let names: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
            PyValueError::new_err(format!(
                "unknown method {name:?} (methods: {})",
                names.join(", ")
            ))
        })
}

/// The box the camera frames for `data`: a volume's visible voxels (the CLI's `--fit visible`),
/// else the data's bounds.
fn framed(data: &AnyData) -> Option<autostereo::camera::Bounds> {
    match data {
        AnyData::Volume(v) => Some(v.framed_bounds(Default::default(), 0.5).0),
        other => other.bounds(),
    }
}

#[pymethods]
impl PyRenderer {
    /// A renderer of `size` (width, height) pixels for `display` by `method` (the CLI's
    /// `--method` names).
    #[new]
    #[pyo3(signature = (display, size, method = "single-pass"))]
    fn new(display: &PyDisplay, size: (u32, u32), method: &str) -> PyResult<Self> {
        Ok(Self {
            display: display.display.clone(),
            size: [size.0, size.1],
            options: RendererOptions::new(self::method(method)?),
            renderer: None,
        })
    }

    /// The spatial image of `scene` (a Volume, Mesh, Points or a loaded Scene), (H, W, 4)
    /// uint8 (alpha 255). The GIL is released while the GPU renders.
    fn render<'py>(
        &mut self,
        py: Python<'py>,
        scene: &PyScene,
    ) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let ctx = context()?;
        let uploaded = scene.uploaded()?;
        let bounds = framed(&scene.data)
            .ok_or_else(|| PyValueError::new_err("the scene has nothing to frame"))?;
        let camera = CameraSettings::default()
            .camera(bounds, &self.display, self.size)
            .map_err(to_py)?;
        let frame = Frame::new(camera, self.display.clone(), self.size).map_err(to_py)?;
        frame.validate().map_err(to_py)?;
        if self.renderer.is_none() {
            let r = AnyRenderer::new(&ctx.device, uploaded, &self.options).map_err(to_py)?;
            self.renderer = Some(r);
        }
        let renderer = self.renderer.as_mut().expect("made above");
        let image = py
            .detach(|| renderer.render_image(&ctx.device, &ctx.queue, uploaded, &frame))
            .map_err(to_py)?;
        let [w, h] = [image.width as usize, image.height as usize];
        let mut rgba = Vec::with_capacity(w * h * 4);
        for p in image.data.chunks_exact(3) {
            rgba.extend_from_slice(&[p[0], p[1], p[2], 255]);
        }
        let array = numpy::PyArray1::from_vec(py, rgba);
        array.reshape([h, w, 4])
    }
}

/// One call: `scene` rendered for `display` (a spec) at `size` by `method`, as
/// `Renderer(Display(display), size, method).render(scene)`.
#[pyfunction]
#[pyo3(signature = (scene, display = "hubner8", size = (512, 512), method = "single-pass"))]
pub fn render<'py>(
    py: Python<'py>,
    scene: &PyScene,
    display: &str,
    size: (u32, u32),
    method: &str,
) -> PyResult<Bound<'py, PyArray3<u8>>> {
    let display = PyDisplay::parse(display)?;
    PyRenderer::new(&display, size, method)?.render(py, scene)
}
