//! `autostereo.Camera`: the CLI's camera flags (`--look-from`, `--look-at`, `--up`, `--view`,
//! `--fov`, `--separation`/`--baseline`, `--focal`/`--focal-scale`, `--camera`) as keyword
//! arguments, and `Camera.orbit(yaw, pitch, zoom)`: the framing turned about its pivot as the
//! viewer's mouse turns it (`autostereo::camera::Orbit`).

use autostereo::camera::{
    Bounds, CameraModel, CameraSettings, Focal, MultiViewCamera, Orbit, Side, Spread,
};
use autostereo::display::Display;
use glam::Vec3;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::errors::to_py;
use crate::names::by_name;

/// How a render's cameras are set up; `Camera()` is the CLI's default framing.
#[pyclass(name = "Camera", module = "autostereo", frozen)]
#[derive(Clone, Copy, Debug, Default)]
pub struct PyCamera {
    pub settings: CameraSettings,
    pub orbit: Orbit,
}

fn vec3(v: Option<(f32, f32, f32)>, what: &str) -> PyResult<Option<Vec3>> {
    match v.map(|(x, y, z)| Vec3::new(x, y, z)) {
        Some(v) if !v.is_finite() => Err(PyValueError::new_err(format!(
            "{what}: three finite numbers, not {v}"
        ))),
        v => Ok(v),
    }
}

/// The value of `table` named `value`.
fn named<T: Copy + 'static>(value: &str, what: &str, table: &[(&'static str, T)]) -> PyResult<T> {
    by_name(value, what, table, |(n, _)| n).map(|(_, t)| t)
}

const SIDES: [(&str, Side); 6] = [
    ("front", Side::Front),
    ("back", Side::Back),
    ("left", Side::Left),
    ("right", Side::Right),
    ("top", Side::Top),
    ("bottom", Side::Bottom),
];

const MODELS: [(&str, CameraModel); 3] = [
    ("skewed", CameraModel::Skewed),
    ("parallel", CameraModel::Parallel),
    ("toe-in", CameraModel::ToeIn),
];

impl PyCamera {
    /// The multi-view camera for `bounds` on `display` at `size`: the settings' camera, turned
    /// by the orbit about its pivot.
    pub fn camera(
        &self,
        bounds: Bounds,
        display: &Display,
        size: [u32; 2],
    ) -> PyResult<MultiViewCamera> {
        let base = self.settings.camera(bounds, display, size).map_err(to_py)?;
        let camera = self.orbit.apply(&base, self.settings.pivot(bounds));
        camera.validate().map_err(to_py)?;
        Ok(camera)
    }
}

#[pymethods]
impl PyCamera {
    /// A camera as the CLI's flags describe it; every argument left out is the CLI's default.
    #[new]
    #[pyo3(signature = (*, look_from = None, look_at = None, up = None, view = None, fov = 30.0,
        separation = None, baseline = None, focal = None, focal_scale = None, model = "skewed"))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        look_from: Option<(f32, f32, f32)>,
        look_at: Option<(f32, f32, f32)>,
        up: Option<(f32, f32, f32)>,
        view: Option<&str>,
        fov: f32,
        separation: Option<f32>,
        baseline: Option<f32>,
        focal: Option<f32>,
        focal_scale: Option<f32>,
        model: &str,
    ) -> PyResult<Self> {
        if !(fov > 0.0 && fov < 180.0) {
            return Err(PyValueError::new_err(format!(
                "fov: {fov} degrees; the field of view is between 0 and 180 (exclusive)"
            )));
        }
        let spread = match (separation, baseline) {
            (Some(_), Some(_)) => {
                return Err(PyValueError::new_err(
                    "separation and baseline: give one (baseline = separation · (N − 1))",
                ))
            }
            (Some(s), None) => Some(Spread::Separation(s)),
            (None, Some(b)) => Some(Spread::Baseline(b)),
            (None, None) => None,
        };
        let focal = match (focal, focal_scale) {
            (Some(_), Some(_)) => {
                return Err(PyValueError::new_err("focal and focal_scale: give one"))
            }
            (Some(d), None) => Some(Focal::Distance(d)),
            (None, Some(s)) => Some(Focal::Scale(s)),
            (None, None) => None,
        };
        let settings = CameraSettings {
            spread,
            focal,
            fov_degrees: fov,
            model: named(model, "model", &MODELS)?,
            look_from: vec3(look_from, "look_from")?,
            look_at: vec3(look_at, "look_at")?,
            up: vec3(up, "up")?,
            side: view.map(|v| named(v, "view", &SIDES)).transpose()?,
        };
        Ok(Self {
            settings,
            orbit: Orbit::default(),
        })
    }

    /// The default framing carried `yaw` degrees around the scene (positive: toward its right,
    /// +x; 90 looks from the right) and `pitch` degrees over it (positive: up; 90 looks down
    /// from the top), `zoom` halving the distance per unit, as the viewer's mouse does;
    /// `look_at` moves the pivot, `fov` and `separation` as for `Camera`.
    #[staticmethod]
    #[pyo3(signature = (yaw = 0.0, pitch = 0.0, zoom = 0.0, *, look_at = None, fov = 30.0,
        separation = None))]
    fn orbit(
        yaw: f32,
        pitch: f32,
        zoom: f32,
        look_at: Option<(f32, f32, f32)>,
        fov: f32,
        separation: Option<f32>,
    ) -> PyResult<Self> {
        if !(yaw.is_finite() && pitch.is_finite() && zoom.is_finite()) {
            return Err(PyValueError::new_err(format!(
                "orbit: yaw {yaw}, pitch {pitch}, zoom {zoom} must be finite"
            )));
        }
        let base = Self::new(
            None, look_at, None, None, fov, separation, None, None, None, "skewed",
        )?;
        Ok(Self {
            orbit: Orbit {
                zoom,
                ..Orbit::degrees(yaw, pitch)
            },
            ..base
        })
    }

    fn __repr__(&self) -> String {
        format!("autostereo.Camera({:?}, {:?})", self.settings, self.orbit)
    }
}
