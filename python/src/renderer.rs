//! `autostereo.Renderer`: a display, an image size and a method. `render(scene)` gives the
//! spatial image as a (H, W, 4) uint8 array; `quilt`, `views` and `preview` the CLI's other
//! `--output`s of the same frame (a Looking Glass quilt, every view, a stereo pair). The camera
//! frames the scene as the CLI's does by default (a volume on what its classification shows),
//! so each equals the CLI's output of the same data with the same flags (python/tests).

use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::quilt_image::QuiltChoice;
use autostereo::render::{default_eyes, Method, Renderer, StereoFormat};
use autostereo::{AnyData, AnyRenderer, RendererOptions};
use numpy::{PyArray3, PyArray4, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::camera::PyCamera;
use crate::context::context;
use crate::display::PyDisplay;
use crate::errors::to_py;
use crate::names::by_name;
use crate::scene::PyScene;

/// A renderer for one display and size; it keeps its prepared state between frames.
#[pyclass(name = "Renderer", module = "autostereo", unsendable)]
pub struct PyRenderer {
    display: autostereo::display::Display,
    size: [u32; 2],
    options: RendererOptions,
    renderer: Option<AnyRenderer>,
}

pub fn method(name: &str) -> PyResult<Method> {
    by_name(name, "method", &Method::ALL, Method::name)
}

fn stereo_format(name: &str) -> PyResult<StereoFormat> {
    by_name(
        name,
        "stereo format",
        &StereoFormat::ALL,
        StereoFormat::name,
    )
}

/// The box the camera frames for `data`: a volume's visible voxels (the CLI's `--fit visible`),
/// else the data's bounds.
pub fn framed(data: &AnyData) -> Option<autostereo::camera::Bounds> {
    match data {
        AnyData::Volume(v) => Some(v.framed_bounds(Default::default(), 0.5).0),
        other => other.bounds(),
    }
}

/// `image` as a (H, W, 4) uint8 array, alpha 255.
pub fn rgba<'py>(py: Python<'py>, image: &RgbImage) -> PyResult<Bound<'py, PyArray3<u8>>> {
    let [w, h] = [image.width as usize, image.height as usize];
    numpy::PyArray1::from_vec(py, rgba_bytes(image)).reshape([h, w, 4])
}

fn rgba_bytes(image: &RgbImage) -> Vec<u8> {
    let mut rgba = Vec::with_capacity(image.data.len() / 3 * 4);
    for p in image.data.chunks_exact(3) {
        rgba.extend_from_slice(&[p[0], p[1], p[2], 255]);
    }
    rgba
}

impl PyRenderer {
    /// A renderer of `size` pixels for `display` by `method`.
    pub fn with(display: autostereo::display::Display, size: [u32; 2], method: Method) -> Self {
        Self {
            display,
            size,
            options: RendererOptions::new(method),
            renderer: None,
        }
    }

    /// The frame of `scene` through `camera` (the default framing where none).
    fn frame(&self, scene: &PyScene, camera: Option<&PyCamera>) -> PyResult<Frame> {
        let bounds = framed(&scene.data)
            .ok_or_else(|| PyValueError::new_err("the scene has nothing to frame"))?;
        let camera =
            camera
                .copied()
                .unwrap_or_default()
                .camera(bounds, &self.display, self.size)?;
        let frame = Frame::new(camera, self.display.clone(), self.size).map_err(to_py)?;
        frame.validate().map_err(to_py)?;
        Ok(frame)
    }

    /// Run `work` with the prepared renderer for `scene` (made for its primitive the first
    /// time, kept after), the GIL released.
    pub fn run<T: Send>(
        &mut self,
        py: Python<'_>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
        work: impl Send
            + FnOnce(
                &autostereo::gpu::GpuContext,
                &mut AnyRenderer,
                &autostereo::AnyScene,
                &Frame,
            ) -> autostereo::Result<T>,
    ) -> PyResult<T> {
        let ctx = context()?;
        let uploaded = scene.uploaded()?;
        let frame = self.frame(scene, camera)?;
        let stale = self
            .renderer
            .as_ref()
            .is_some_and(|r| r.primitive() != uploaded.primitive());
        if self.renderer.is_none() || stale {
            let r = AnyRenderer::new(&ctx.device, uploaded, &self.options).map_err(to_py)?;
            self.renderer = Some(r);
        }
        let renderer = self.renderer.as_mut().expect("made above");
        py.detach(|| work(ctx, renderer, uploaded, &frame))
            .map_err(to_py)
    }

    /// The spatial image of `scene`.
    pub fn spatial(
        &mut self,
        py: Python<'_>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
    ) -> PyResult<RgbImage> {
        self.run(py, scene, camera, |ctx, r, s, frame| {
            r.render_image(&ctx.device, &ctx.queue, s, frame)
        })
    }

    /// The stereo pair `eyes` (default: the CLI's `--eyes`) composed as `format`.
    pub fn stereo(
        &mut self,
        py: Python<'_>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
        format: StereoFormat,
        eyes: Option<(u32, u32)>,
    ) -> PyResult<RgbImage> {
        let views = self.display.views();
        let eyes = match eyes {
            Some((l, r)) if l.max(r) >= views => {
                return Err(PyValueError::new_err(format!(
                    "eyes ({l}, {r}): the display has views 0 to {}",
                    views - 1
                )))
            }
            Some((l, r)) => [l, r],
            None => default_eyes(views),
        };
        let size = self.size;
        self.run(py, scene, camera, move |ctx, r, s, frame| {
            autostereo::render::render_stereo(
                &ctx.device,
                &ctx.queue,
                r,
                s,
                frame,
                format,
                size,
                eyes,
            )
        })
    }
}

#[pymethods]
impl PyRenderer {
    /// A renderer of `size` (width, height) pixels for `display` by `method` (the CLI's
    /// `--method` names); `views` sets the number of views as the CLI's `--views` does (a
    /// Looking Glass: any; other displays: their own).
    #[new]
    #[pyo3(signature = (display, size, method = "single-pass", views = None))]
    fn new(
        display: &PyDisplay,
        size: (u32, u32),
        method: &str,
        views: Option<u32>,
    ) -> PyResult<Self> {
        let mut d = display.display.clone();
        if let Some(n) = views {
            d = d.with_views(n).map_err(to_py)?;
        }
        Ok(Self::with(d, [size.0, size.1], self::method(method)?))
    }

    /// Views the renderer renders.
    #[getter]
    fn view_count(&self) -> u32 {
        self.display.views()
    }

    /// The spatial image of `scene` (a Volume, Mesh, Points, Gaussians or a loaded Scene)
    /// through `camera` (default: the CLI's framing), (H, W, 4) uint8 (alpha 255). The GIL is
    /// released while the GPU renders.
    #[pyo3(signature = (scene, camera = None))]
    fn render<'py>(
        &mut self,
        py: Python<'py>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
    ) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let image = self.spatial(py, scene, camera)?;
        rgba(py, &image)
    }

    /// Every view in a Looking Glass quilt (view 0 bottom-left; a Looking Glass display: its
    /// family's quilt, else the views' grid), as the CLI's `--output quilt`; `grid` (columns,
    /// rows) and `size` (the quilt's pixels) override it as `--quilt` and `--quilt-size` do.
    /// Returns (quilt, name suffix), e.g. `_qs7x7a0.75`.
    #[pyo3(signature = (scene, camera = None, grid = None, size = None))]
    fn quilt<'py>(
        &mut self,
        py: Python<'py>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
        grid: Option<(u32, u32)>,
        size: Option<(u32, u32)>,
    ) -> PyResult<(Bound<'py, PyArray3<u8>>, String)> {
        let choice = QuiltChoice {
            grid: grid.map(|(c, r)| [c, r]),
            size: size.map(|(w, h)| [w, h]),
            tile: None,
        };
        let quilt = self
            .display
            .quilt(self.display.views(), self.size, &choice)
            .map_err(to_py)?;
        let suffix = quilt.suffix();
        let image = self.run(py, scene, camera, move |ctx, r, s, frame| {
            autostereo::render::render_quilt(&ctx.device, &ctx.queue, r, s, frame, &quilt)
        })?;
        Ok((rgba(py, &image)?, suffix))
    }

    /// Every view alone at the renderer's size, as the CLI's `--output views`: (N, H, W, 4)
    /// uint8, view 0 first.
    #[pyo3(name = "views", signature = (scene, camera = None))]
    fn views_of<'py>(
        &mut self,
        py: Python<'py>,
        scene: &PyScene,
        camera: Option<&PyCamera>,
    ) -> PyResult<Bound<'py, PyArray4<u8>>> {
        let views = self.display.views();
        let size = self.size;
        let images = self.run(py, scene, camera, move |ctx, r, s, frame| {
            (0..views)
                .map(|v| {
                    autostereo::render::render_view(
                        &ctx.device,
                        &ctx.queue,
                        r,
                        s,
                        frame,
                        v,
                        frame.view_size(),
                        None,
                    )?
                    .read(&ctx.device, &ctx.queue)
                })
                .collect::<autostereo::Result<Vec<_>>>()
        })?;
        let [w, h] = images
            .first()
            .map_or([size[0] as usize, size[1] as usize], |i| {
                [i.width as usize, i.height as usize]
            });
        let bytes: Vec<u8> = images.iter().flat_map(rgba_bytes).collect();
        numpy::PyArray1::from_vec(py, bytes).reshape([views as usize, h, w, 4])
    }

    /// Two views composed for an ordinary screen (`format`: the CLI's stereo `--output`
    /// names: anaglyph-dubois, side-by-side, …), `eyes` (left, right) the views (default: a
    /// quarter of the views apart about the middle, the CLI's `--eyes`).
    #[pyo3(signature = (scene, format = "anaglyph-dubois", camera = None, eyes = None))]
    fn preview<'py>(
        &mut self,
        py: Python<'py>,
        scene: &PyScene,
        format: &str,
        camera: Option<&PyCamera>,
        eyes: Option<(u32, u32)>,
    ) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let image = self.stereo(py, scene, camera, stereo_format(format)?, eyes)?;
        rgba(py, &image)
    }
}

/// One call: `scene` rendered for `display` (a spec) at `size` by `method`, as
/// `Renderer(Display(display), size, method).render(scene, camera)`.
#[pyfunction]
#[pyo3(signature = (scene, display = "hubner8", size = (512, 512), method = "single-pass", camera = None))]
pub fn render<'py>(
    py: Python<'py>,
    scene: &PyScene,
    display: &str,
    size: (u32, u32),
    method: &str,
    camera: Option<&PyCamera>,
) -> PyResult<Bound<'py, PyArray3<u8>>> {
    let display = PyDisplay::parse(display)?;
    PyRenderer::new(&display, size, method, None)?.render(py, scene, camera)
}
