//! Volume file formats: raw (dimensions, type, endianness, spacing given), NRRD (raw and gzip
//! encodings, attached or detached data), VolPack `.den`, MetaImage, NIfTI-1, DICOM series and
//! VTK image data (`.vti`, legacy `.vtk`) (features `nifti`, `dicom`, `vti`). Headers are
//! validated and sizes checked against the file before anything large is allocated.

mod den;
#[cfg(feature = "dicom")]
mod dicom;
mod metaimage;
#[cfg(feature = "nifti")]
mod nifti;
mod nrrd;
mod raw;
#[cfg(feature = "vti")]
mod vti;
#[cfg(feature = "vti")]
mod vtk_legacy;

pub use den::{load_den, parse_den};
#[cfg(feature = "dicom")]
pub use dicom::{load_dicom, parse_dicom};
pub use metaimage::{load_metaimage, parse_metaimage};
#[cfg(feature = "nifti")]
pub use nifti::{load_nifti, parse_nifti};
pub use nrrd::{load_nrrd, parse_nrrd};
pub use raw::{load_raw, parse_raw, RawSpec};
#[cfg(feature = "vti")]
pub use vti::{load_vti, parse_vti};
#[cfg(feature = "vti")]
pub use vtk_legacy::{load_vtk, parse_vtk};

use std::path::Path;

use super::{check_dims, Volume};
use crate::advice::{Advice, Setting};
use crate::error::{Error, Result};

/// Sample types the loaders understand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleType {
    /// Unsigned 8-bit (normalised by 255).
    U8,
    /// Signed 8-bit.
    I8,
    /// Unsigned 16-bit.
    U16,
    /// Signed 16-bit.
    I16,
    /// Unsigned 32-bit.
    U32,
    /// Signed 32-bit.
    I32,
    /// 32-bit float.
    F32,
    /// 64-bit float.
    F64,
}

impl SampleType {
    /// Bytes per sample.
    pub fn size(self) -> u64 {
        match self {
            SampleType::U8 | SampleType::I8 => 1,
            SampleType::U16 | SampleType::I16 => 2,
            SampleType::U32 | SampleType::I32 | SampleType::F32 => 4,
            SampleType::F64 => 8,
        }
    }

    /// The short name ([`SampleType::parse`] reads it): `u8` … `f64`.
    pub fn name(self) -> &'static str {
        match self {
            SampleType::U8 => "u8",
            SampleType::I8 => "i8",
            SampleType::U16 => "u16",
            SampleType::I16 => "i16",
            SampleType::U32 => "u32",
            SampleType::I32 => "i32",
            SampleType::F32 => "f32",
            SampleType::F64 => "f64",
        }
    }

    /// Parse a name: u8 uint8 uchar "unsigned char", i8 int8 char, u16 uint16 ushort, i16 int16
    /// short, u32 uint32 uint, i32 int32 int, f32 float float32, f64 double float64 (NRRD
    /// spellings included; `float32` as `uint8` … `int32` spell the others).
    pub fn parse(name: &str) -> Option<Self> {
        Some(match name.trim().to_ascii_lowercase().as_str() {
            "u8" | "uint8" | "uchar" | "unsigned char" | "uint8_t" => SampleType::U8,
            "i8" | "int8" | "char" | "signed char" | "int8_t" => SampleType::I8,
            "u16" | "uint16" | "ushort" | "unsigned short" | "unsigned short int" | "uint16_t" => {
                SampleType::U16
            }
            "i16" | "int16" | "short" | "short int" | "signed short" | "signed short int"
            | "int16_t" => SampleType::I16,
            "u32" | "uint32" | "uint" | "unsigned int" | "uint32_t" => SampleType::U32,
            "i32" | "int32" | "int" | "signed int" | "int32_t" => SampleType::I32,
            "f32" | "float" | "float32" => SampleType::F32,
            "f64" | "double" | "float64" => SampleType::F64,
            _ => return None,
        })
    }
}

/// `dims` × `kind` as a message says them, e.g. `2x2x2 f32 samples`.
pub(crate) fn samples(dims: [u32; 3], kind: SampleType) -> String {
    format!(
        "{}x{}x{} {} samples",
        dims[0],
        dims[1],
        dims[2],
        kind.name()
    )
}

/// Decode `bytes` (exactly `count` samples) to f32.
pub(crate) fn decode(bytes: &[u8], kind: SampleType, big_endian: bool) -> Vec<f32> {
    macro_rules! conv {
        ($t:ty, $n:expr) => {
            bytes
                .chunks_exact($n)
                .map(|c| {
                    let a: [u8; $n] = c.try_into().expect("chunk size");
                    (if big_endian {
                        <$t>::from_be_bytes(a)
                    } else {
                        <$t>::from_le_bytes(a)
                    }) as f32
                })
                .collect()
        };
    }
    match kind {
        SampleType::U8 => bytes.iter().map(|&b| b as f32).collect(),
        SampleType::I8 => bytes.iter().map(|&b| b as i8 as f32).collect(),
        SampleType::U16 => conv!(u16, 2),
        SampleType::I16 => conv!(i16, 2),
        SampleType::U32 => conv!(u32, 4),
        SampleType::I32 => conv!(i32, 4),
        SampleType::F32 => conv!(f32, 4),
        SampleType::F64 => conv!(f64, 8),
    }
}

/// Bytes of `dims` samples of `kind`, checked for overflow and the voxel limit.
pub(crate) fn data_bytes(dims: [u64; 3], kind: SampleType) -> Result<u64> {
    Ok(check_dims(dims)? * kind.size())
}

/// Normalise decoded samples: 8-bit unsigned by 255 (keeps transfer functions meaningful),
/// everything else by its own min..max.
/// Errors name the file `path`.
pub(crate) fn to_volume(
    path: &Path,
    dims: [u32; 3],
    spacing: [f32; 3],
    samples: Vec<f32>,
    kind: SampleType,
) -> Result<Volume> {
    let range = (kind == SampleType::U8).then_some([0.0, 255.0]);
    Volume::from_samples(dims, spacing, samples, range)
        .map_err(|e| format_error(path, e.to_string()))
}

pub(crate) fn format_error(path: &Path, reason: impl Into<String>) -> Error {
    Error::Volume {
        path: path.to_path_buf(),
        reason: reason.into(),
        advice: None,
    }
}

/// Load a volume file of any format this build reads ([`crate::formats`]: NRRD `.nrrd`/`.nhdr`,
/// VolPack `.den`, MetaImage `.mha`/`.mhd`, NIfTI-1 `.nii`/`.nii.gz` with the `nifti` feature,
/// a DICOM series — a folder or one of its files — with the `dicom` feature, VTK image data
/// `.vti`/`.vtk` with the `vti` feature), told by its first bytes, else its extension. Raw
/// files need their dimensions and sample type ([`load_raw`]); a file of another kind is
/// refused as what it is (`Error::WrongKind`).
pub fn load_any(path: &Path) -> Result<Volume> {
    use crate::formats::{expect, DataKind, Format};
    // A folder is a DICOM series (the only format stored as one).
    #[cfg(feature = "dicom")]
    if path.is_dir() {
        return load_dicom(path);
    }
    match expect(path, DataKind::Volume)? {
        Format::Nrrd => load_nrrd(path),
        Format::Den => load_den(path),
        Format::MetaImage => load_metaimage(path),
        #[cfg(feature = "dicom")]
        Format::Dicom => load_dicom(path),
        #[cfg(feature = "nifti")]
        Format::Nifti => load_nifti(path),
        #[cfg(feature = "vti")]
        Format::Vtk => load_vtk_image(path),
        _ => Err(Error::Volume {
            path: path.to_path_buf(),
            reason: "raw voxels need their dimensions and sample type".into(),
            advice: Some(Advice::text(" (").then(Setting::RawLayout).then_text(")")),
        }),
    }
}

/// A VTK image data file: legacy (`# vtk DataFile` first) or XML, else by its extension.
#[cfg(feature = "vti")]
fn load_vtk_image(path: &Path) -> Result<Volume> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the VTK limit")?;
    let head = &bytes[..bytes.len().min(1024)];
    let legacy = head.starts_with(b"# vtk DataFile")
        || !head.windows(8).any(|w| w == b"<VTKFile")
            && path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("vtk"));
    if legacy {
        parse_vtk(&bytes, path)
    } else {
        parse_vti(&bytes, path)
    }
}
