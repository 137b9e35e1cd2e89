//! `autostereo.Gaussians` from numpy: 3D Gaussian splats as a trainer's PLY holds them once
//! activated: means, linear scales, unit rotations (w, x, y, z), opacities in 0..1 and either
//! colours (N, 3) in 0..1 or spherical-harmonics coefficients (N, K, 3), K = (degree + 1)².
//! Colours become the DC coefficient as the `.splat` reader makes them, so a render equals the
//! CLI's of the same values in a `.splat` file.

use autostereo::gaussians::{coefficients, sh::dc_from_color, unit_rotation, Gaussians};
use autostereo::AnyData;
use numpy::{PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::errors::to_py;
use crate::geometry::{rows, vec3s};
use crate::scene::PyScene;

/// 3D Gaussian splats.
#[pyclass(name = "Gaussians", module = "autostereo", extends = PyScene, frozen)]
pub struct PyGaussians {
    count: usize,
}

fn count_of<T>(values: &[T], n: usize, what: &str) -> PyResult<()> {
    if values.len() == n {
        return Ok(());
    }
    Err(PyValueError::new_err(format!(
        "{what}: {} rows for {n} Gaussians",
        values.len()
    )))
}

/// `sh` (N, K, 3) as (degree, coefficients Gaussian-major).
fn harmonics(sh: &Bound<'_, PyAny>, n: usize) -> PyResult<(u32, Vec<[f32; 3]>)> {
    macro_rules! as_sh {
        ($($t:ty),*) => {$(
            if let Ok(a) = sh.extract::<PyReadonlyArray3<'_, $t>>() {
                let [rows, k, c] = [a.shape()[0], a.shape()[1], a.shape()[2]];
                let degree = (0..=autostereo::gaussians::MAX_SH_DEGREE)
                    .find(|&d| coefficients(d) == k);
                let Some(degree) = degree.filter(|_| c == 3 && rows == n) else {
                    return Err(PyValueError::new_err(format!(
                        "sh: an (N, K, 3) array for {n} Gaussians, K = 1, 4, 9 or 16 \
                         (degree 0 to 3), not ({rows}, {k}, {c})"
                    )));
                };
                let flat: Vec<f32> = a.as_array().iter().map(|&v| v as f32).collect();
                let sh = flat.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect();
                return Ok((degree, sh));
            }
        )*};
    }
    as_sh!(f32, f64);
    Err(crate::arrays::refused(
        sh,
        "sh",
        "an (N, K, 3) array",
        3,
        "float32, float64",
    ))
}

#[pymethods]
impl PyGaussians {
    /// `positions` (N, 3), `scales` (N, 3) standard deviations, `rotations` (N, 4) quaternions
    /// (w, x, y, z; normalised here), `opacities` (N,) in 0..1, and `colors` (N, 3) in 0..1 or
    /// `sh` (N, K, 3) coefficients (graphdeco's order, DC first).
    #[new]
    #[pyo3(signature = (positions, scales, rotations, opacities, colors = None, sh = None))]
    fn new(
        positions: &Bound<'_, PyAny>,
        scales: &Bound<'_, PyAny>,
        rotations: &Bound<'_, PyAny>,
        opacities: &Bound<'_, PyAny>,
        colors: Option<&Bound<'_, PyAny>>,
        sh: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let positions = vec3s(positions, "positions")?;
        let n = positions.len();
        let scales = vec3s(scales, "scales")?;
        count_of(&scales, n, "scales")?;
        let quats = rows(rotations, 4, "rotations")?;
        count_of(&quats, n, "rotations")?;
        let rotations = quats
            .iter()
            .enumerate()
            .map(|(i, q)| {
                let [w, x, y, z] = [q[0], q[1], q[2], q[3]].map(|v| v as f32);
                unit_rotation(i, w, x, y, z)
                    .map_err(|e| PyValueError::new_err(format!("rotations: {e}")))
            })
            .collect::<PyResult<Vec<_>>>()?;
        if opacities.getattr("ndim")?.extract::<usize>()? != 1 {
            return Err(PyValueError::new_err("opacities: an (N,) array"));
        }
        let column = opacities.call_method1("reshape", ((-1i64, 1i64),))?;
        let opacities: Vec<f32> = rows(&column, 1, "opacities")?
            .iter()
            .map(|r| r[0] as f32)
            .collect();
        count_of(&opacities, n, "opacities")?;
        let (sh_degree, sh) = match (colors, sh) {
            (Some(_), Some(_)) => {
                return Err(PyValueError::new_err("colors and sh: give one"));
            }
            (Some(c), None) => {
                let c = rows(c, 3, "colors")?;
                count_of(&c, n, "colors")?;
                let dc = c
                    .iter()
                    .map(|r| [r[0], r[1], r[2]].map(|v| dc_from_color(v as f32)))
                    .collect();
                (0, dc)
            }
            (None, Some(sh)) => harmonics(sh, n)?,
            (None, None) => (0, vec![[0.0; 3]; n]),
        };
        let gaussians = Gaussians {
            positions,
            scales,
            rotations,
            opacities,
            sh_degree,
            sh,
        };
        gaussians.validate().map_err(to_py)?;
        let count = gaussians.len();
        Ok(
            PyClassInitializer::from(PyScene::new(AnyData::Gaussians(gaussians)))
                .add_subclass(Self { count }),
        )
    }

    fn __len__(&self) -> usize {
        self.count
    }
}
