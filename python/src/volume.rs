//! `autostereo.Volume`: a numpy array (Z, Y, X) of any real dtype as the library's volume,
//! normalised as a raw file of that sample type is (8-bit: 0…255; others: their min…max), its
//! robust range measured and classified by a preset, exactly as `autostereo volume` prepares
//! the same samples written to a raw file. Uploaded on first render and kept.

use autostereo::volume::{TransferFunction, Volume, PRESETS};
use autostereo::{AnyData, VolumeData};
use glam::Mat4;
use numpy::{PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::errors::to_py;
use crate::scene::PyScene;

/// A scalar volume.
#[pyclass(name = "Volume", module = "autostereo", extends = PyScene, frozen)]
pub struct PyVolume {
    dims: [u32; 3],
}

/// The samples of `array` in x-fastest order and whether they are 8-bit, for the dtypes a
/// scan comes in; anything else is a `TypeError` naming the dtype.
fn samples(array: &Bound<'_, PyAny>) -> PyResult<(Vec<f32>, [usize; 3], bool)> {
    macro_rules! try_dtype {
        ($($t:ty),*) => {$(
            if let Ok(a) = array.extract::<PyReadonlyArray3<'_, $t>>() {
                let shape = a.shape();
                let values = a.as_array().iter().map(|&v| v as f32).collect();
                return Ok((values, [shape[0], shape[1], shape[2]], false));
            }
        )*};
    }
    if let Ok(a) = array.extract::<PyReadonlyArray3<'_, u8>>() {
        let shape = a.shape();
        let values = a.as_array().iter().map(|&v| f32::from(v)).collect();
        return Ok((values, [shape[0], shape[1], shape[2]], true));
    }
    try_dtype!(f32, f64, i8, u16, i16, u32, i32);
    Err(crate::arrays::refused(
        array,
        "a volume",
        "a 3-dimensional array (Z, Y, X)",
        3,
        "uint8, int8, uint16, int16, uint32, int32, float32, float64",
    ))
}

#[pymethods]
impl PyVolume {
    /// `array` (Z, Y, X), voxel `spacing` (x, y, z), classified by the preset `tf` (default:
    /// what the CLI gives a raw file, `ct-skin`).
    #[new]
    #[pyo3(signature = (array, spacing = (1.0, 1.0, 1.0), tf = None))]
    fn new(
        array: &Bound<'_, PyAny>,
        spacing: (f32, f32, f32),
        tf: Option<&str>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (values, [z, y, x], eight_bit) = samples(array)?;
        let to_u32 =
            |n: usize| u32::try_from(n).map_err(|_| PyValueError::new_err("too many voxels"));
        let dims = [to_u32(x)?, to_u32(y)?, to_u32(z)?];
        let range = eight_bit.then_some([0.0, 255.0]);
        let spacing = [spacing.0, spacing.1, spacing.2];
        let volume = Volume::from_samples(dims, spacing, values, range)
            .map_err(to_py)?
            .with_robust_range();
        let preset = match tf {
            Some(name) => PRESETS
                .iter()
                .copied()
                .find(|p| *p == name)
                .ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "unknown preset {name:?} (presets: {})",
                        PRESETS.join(", ")
                    ))
                })?,
            None => autostereo::default_preset_for(Some(autostereo::formats::Format::Raw), None),
        };
        let transfer = TransferFunction::preset_for(preset, &volume.values).map_err(to_py)?;
        let data = VolumeData {
            volume,
            transfer,
            preset: Some(preset),
            model: Mat4::IDENTITY,
            clip: Vec::new(),
        };
        let dims = data.volume.dims;
        Ok(
            PyClassInitializer::from(PyScene::new(AnyData::Volume(Box::new(data))))
                .add_subclass(Self { dims }),
        )
    }

    /// Voxels along x, y, z.
    #[getter]
    fn dims(&self) -> [u32; 3] {
        self.dims
    }
}
