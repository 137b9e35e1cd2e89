//! `autostereo.Mesh` and `autostereo.Points` from numpy: (V, 3) positions, (F, 3) triangle
//! indices, optional (N, 3) linear RGB colours in 0..1. Prepared as the OBJ and PLY readers
//! prepare the same data (normals from the triangles, the readers' default colour; a cloud's
//! normals and radii estimated), so a render equals the CLI's of that file.

use autostereo::mesh::{Mesh, DEFAULT_COLOR};
use autostereo::points::PointCloud;
use autostereo::{AnyData, PointLoad};
use glam::Vec3;
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::errors::to_py;
use crate::scene::PyScene;

/// The rows of an (N, `width`) array of `what` as f64, for float and integer dtypes.
pub fn rows(array: &Bound<'_, PyAny>, width: usize, what: &str) -> PyResult<Vec<Vec<f64>>> {
    macro_rules! as_rows {
        ($($t:ty),*) => {$(
            if let Ok(a) = array.extract::<PyReadonlyArray2<'_, $t>>() {
                if a.shape()[1] != width {
                    return Err(PyValueError::new_err(format!(
                        "{what}: an (N, {width}) array, not {:?}", a.shape()
                    )));
                }
                return Ok(a.as_array().rows().into_iter()
                    .map(|r| r.iter().map(|&v| v as f64).collect()).collect());
            }
        )*};
    }
    as_rows!(f32, f64, i32, i64, u32, u64, i16, u16, u8);
    Err(crate::arrays::refused(
        array,
        what,
        &format!("an (N, {width}) array"),
        2,
        "uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64",
    ))
}

pub fn vec3s(array: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Vec3>> {
    Ok(rows(array, 3, what)?
        .iter()
        .map(|r| Vec3::new(r[0] as f32, r[1] as f32, r[2] as f32))
        .collect())
}

fn colors(array: Option<&Bound<'_, PyAny>>, count: usize) -> PyResult<Option<Vec<[f32; 3]>>> {
    let Some(array) = array else {
        return Ok(None);
    };
    let c = rows(array, 3, "colors")?;
    if c.len() != count {
        return Err(PyValueError::new_err(format!(
            "colors: {} rows for {count} vertices",
            c.len()
        )));
    }
    Ok(Some(
        c.iter()
            .map(|r| [r[0] as f32, r[1] as f32, r[2] as f32])
            .collect(),
    ))
}

/// A triangle mesh.
#[pyclass(name = "Mesh", module = "autostereo", extends = PyScene, frozen)]
pub struct PyMesh {
    triangles: usize,
}

#[pymethods]
impl PyMesh {
    /// `vertices` (V, 3), `faces` (F, 3) indices into them, `colors` (V, 3) or none (the OBJ
    /// reader's grey).
    #[new]
    #[pyo3(signature = (vertices, faces, colors = None))]
    fn new(
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        colors: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let positions = vec3s(vertices, "vertices")?;
        let n = positions.len();
        let mut indices = Vec::new();
        for face in rows(faces, 3, "faces")? {
            for i in face {
                if !(i.fract() == 0.0 && i >= 0.0 && (i as usize) < n) {
                    return Err(PyValueError::new_err(format!(
                        "faces: index {i} is not a vertex (0 to {})",
                        n.saturating_sub(1)
                    )));
                }
                indices.push(i as u32);
            }
        }
        let colors = self::colors(colors, n)?
            .map(|c| c.into_iter().map(|[r, g, b]| [r, g, b, 1.0]).collect())
            .unwrap_or_else(|| vec![DEFAULT_COLOR; n]);
        let mut mesh = Mesh {
            positions,
            normals: vec![Vec3::Z; n],
            colors,
            indices,
            ..Mesh::default()
        };
        mesh.compute_normals();
        for normal in &mut mesh.normals {
            *normal = normal.try_normalize().unwrap_or(Vec3::Z);
        }
        mesh.validate().map_err(to_py)?;
        let triangles = mesh.triangle_count();
        Ok(PyClassInitializer::from(PyScene::new(AnyData::Mesh(mesh)))
            .add_subclass(Self { triangles }))
    }

    /// Number of triangles.
    #[getter]
    fn triangles(&self) -> usize {
        self.triangles
    }
}

/// A point cloud, drawn as splats.
#[pyclass(name = "Points", module = "autostereo", extends = PyScene, frozen)]
pub struct PyPoints {
    count: usize,
}

#[pymethods]
impl PyPoints {
    /// `positions` (P, 3) and `colors` (P, 3) or none; normals and radii are estimated.
    #[new]
    #[pyo3(signature = (positions, colors = None))]
    fn new(
        positions: &Bound<'_, PyAny>,
        colors: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let positions = vec3s(positions, "positions")?;
        let colors = self::colors(colors, positions.len())?;
        let cloud = PointCloud {
            positions,
            colors,
            ..PointCloud::default()
        };
        let data = autostereo::complete(&cloud, &PointLoad::default()).map_err(to_py)?;
        let count = data.splats.positions.len();
        Ok(
            PyClassInitializer::from(PyScene::new(AnyData::Points(data)))
                .add_subclass(Self { count }),
        )
    }

    fn __len__(&self) -> usize {
        self.count
    }
}
