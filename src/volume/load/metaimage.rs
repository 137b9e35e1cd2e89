//! MetaImage volumes (ITK's `.mha` with its voxels after the header, `.mhd` with them in
//! `ElementDataFile` beside it): scalar 2D or 3D images of the common element types, either
//! byte order, raw or zlib-compressed (`CompressedData`). A `TransformMatrix` (ITK's LPS+
//! world: each row one voxel axis's direction) places the voxel axes
//! (`crate::volume::orientation`); without one they stay as they are.

use std::io::Read;
use std::path::Path;

use glam::{Mat3, Vec3};

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::orientation::{screen_axes_from_ras, LPS_TO_RAS};
use crate::volume::Volume;

/// Longest header accepted (a guard against reading a binary file as text).
const MAX_HEADER_BYTES: usize = 64 * 1024;

/// Load a `.mha` or `.mhd` file.
pub fn load_metaimage(path: &Path) -> Result<Volume> {
    let bytes =
        crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the MetaImage limit")?;
    parse_metaimage(&bytes, path)
}

struct Header {
    dims: [u32; 3],
    spacing: [f32; 3],
    kind: SampleType,
    big_endian: bool,
    compressed: bool,
    /// `LOCAL` (after the header) or a file name beside it.
    data_file: String,
    axes: Option<Mat3>,
}

/// A MetaImage file's `bytes` (`path` names it in errors; an `.mhd`'s data file is read beside
/// it).
pub fn parse_metaimage(bytes: &[u8], path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let (header, data_start) = parse_header(bytes).map_err(err)?;
    let expected =
        data_bytes(header.dims.map(u64::from), header.kind).map_err(|e| err(e.to_string()))?;
    let external;
    let stored: &[u8] = if header.data_file.eq_ignore_ascii_case("LOCAL") {
        &bytes[data_start..]
    } else {
        let name = &header.data_file;
        let relative = Path::new(name);
        if relative.is_absolute()
            || relative
                .components()
                .any(|c| !matches!(c, std::path::Component::Normal(_)))
        {
            return Err(err(format!(
                "ElementDataFile '{name}': only a file beside the header is read"
            )));
        }
        let data_path = path.parent().unwrap_or(Path::new(".")).join(relative);
        external = crate::file::read_bounded(
            &data_path,
            crate::file::MAX_TEXT_BYTES,
            "the MetaImage limit",
        )
        .map_err(|e| {
            err(format!(
                "ElementDataFile {name}: {e}",
                name = crate::error::quote(name)
            ))
        })?;
        &external
    };
    let mut payload = Vec::new();
    if header.compressed {
        flate2::read::ZlibDecoder::new(stored)
            .take(expected)
            .read_to_end(&mut payload)
            .map_err(|e| err(format!("zlib data: {e}")))?;
    } else {
        payload.extend_from_slice(&stored[..stored.len().min(expected as usize)]);
    }
    if (payload.len() as u64) < expected {
        return Err(err(format!(
            "truncated: {} bytes of voxels, {} need {expected}",
            payload.len(),
            super::samples(header.dims, header.kind)
        )));
    }
    let samples = decode(&payload, header.kind, header.big_endian);
    drop(payload);
    let volume = to_volume(path, header.dims, header.spacing, samples, header.kind)?;
    match header.axes {
        Some(axes) => volume.with_axes(axes),
        None => Ok(volume),
    }
}

/// The header and where the voxels start (after the `ElementDataFile` line, which ends it).
fn parse_header(bytes: &[u8]) -> std::result::Result<(Header, usize), String> {
    let (mut ndims, mut dims, mut spacing, mut kind) = (None, None, None, None);
    let (mut big_endian, mut compressed, mut matrix) = (false, false, None);
    let mut at = 0;
    loop {
        if at >= MAX_HEADER_BYTES.min(bytes.len()) {
            return Err(
                "no ElementDataFile line in the first 64 KiB (not a MetaImage header?)".into(),
            );
        }
        let end = bytes[at..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |p| at + p + 1);
        let line = String::from_utf8_lossy(&bytes[at..end]);
        at = end;
        let line = line.trim_end_matches(['\r', '\n']);
        let Some((key, value)) = line.split_once('=') else {
            continue;
        };
        let (key, value) = (key.trim(), value.trim());
        let numbers = |n: usize| -> std::result::Result<Vec<f64>, String> {
            let v: Vec<f64> = value
                .split_whitespace()
                .map(|s| {
                    s.parse::<f64>().map_err(|_| {
                        format!(
                            "{key}: {value} is not numbers",
                            value = crate::error::quote(value)
                        )
                    })
                })
                .collect::<std::result::Result<_, _>>()?;
            if v.len() < n || v.iter().any(|x| !x.is_finite()) {
                return Err(format!(
                    "{key}: {value} needs {n} finite numbers",
                    value = crate::error::quote(value)
                ));
            }
            Ok(v)
        };
        let boolean = || value.eq_ignore_ascii_case("true") || value == "1";
        match key {
            "ObjectType" if !value.eq_ignore_ascii_case("Image") => {
                return Err(format!(
                    "ObjectType {}: only images are volumes",
                    crate::error::quote(value)
                ));
            }
            "NDims" => {
                ndims =
                    Some(value.parse::<usize>().map_err(|_| {
                        format!("NDims {value}", value = crate::error::quote(value))
                    })?)
            }
            "DimSize" => dims = Some(numbers(ndims.unwrap_or(3).min(3))?),
            "ElementSpacing" | "ElementSize" if spacing.is_none() || key == "ElementSpacing" => {
                spacing = Some(numbers(ndims.unwrap_or(3).min(3))?)
            }
            "ElementType" => kind = Some(element_type(value)?),
            "ElementByteOrderMSB" | "BinaryDataByteOrderMSB" => big_endian = boolean(),
            "CompressedData" => compressed = boolean(),
            "ElementNumberOfChannels" if value != "1" => {
                return Err(format!(
                    "{} channels per voxel: scalar volumes only",
                    crate::error::quote(value)
                ));
            }
            "HeaderSize" if value != "0" => {
                return Err(format!(
                    "HeaderSize {}: a header skip is not read",
                    crate::error::quote(value)
                ));
            }
            // 2D images carry 4 numbers: used only as 3D's 9.
            "TransformMatrix" | "Rotation" | "Orientation" => {
                matrix = Some(numbers(1)?).filter(|m| m.len() == 9)
            }
            "BinaryData" if !boolean() => {
                return Err("BinaryData = False: voxels as text are not read".into());
            }
            "ElementDataFile" => {
                let ndims = ndims.ok_or("missing NDims")?;
                if !(2..=3).contains(&ndims) {
                    return Err(format!("NDims {ndims}: only 2D and 3D images"));
                }
                let dims = dims.ok_or("missing DimSize")?;
                let dim = |i: usize| dims.get(i).copied().unwrap_or(1.0);
                let dims = [0, 1, 2].map(|i| dim(i).min(u32::MAX as f64) as u32);
                if (0..ndims).any(|i| dim(i) < 1.0 || dim(i).fract() != 0.0) {
                    return Err(format!("DimSize {dims:?}: whole numbers of at least 1"));
                }
                let spacing = spacing.unwrap_or_else(|| vec![1.0; 3]);
                let spacing = [0, 1, 2].map(|i| spacing.get(i).copied().unwrap_or(1.0) as f32);
                let axes = match matrix {
                    Some(m) if ndims == 3 => {
                        // Row a is voxel axis a's direction in LPS+ (ITK's MetaImageIO).
                        let axis = |a: usize| {
                            LPS_TO_RAS
                                * Vec3::new(
                                    m[3 * a] as f32,
                                    m[3 * a + 1] as f32,
                                    m[3 * a + 2] as f32,
                                )
                        };
                        Some(
                            screen_axes_from_ras(Mat3::from_cols(axis(0), axis(1), axis(2)))
                                .map_err(|e| format!("TransformMatrix: {e}"))?,
                        )
                    }
                    _ => None,
                };
                let header = Header {
                    dims,
                    spacing,
                    kind: kind.ok_or("missing ElementType")?,
                    big_endian,
                    compressed,
                    data_file: value.to_string(),
                    axes,
                };
                return Ok((header, at));
            }
            _ => {}
        }
    }
}

/// MetaImage's element types (MET_LONG is 32-bit in MetaIO).
fn element_type(name: &str) -> std::result::Result<SampleType, String> {
    Ok(match name {
        "MET_UCHAR" => SampleType::U8,
        "MET_CHAR" => SampleType::I8,
        "MET_USHORT" => SampleType::U16,
        "MET_SHORT" => SampleType::I16,
        "MET_UINT" | "MET_ULONG" => SampleType::U32,
        "MET_INT" | "MET_LONG" => SampleType::I32,
        "MET_FLOAT" => SampleType::F32,
        "MET_DOUBLE" => SampleType::F64,
        other => {
            return Err(format!(
                "ElementType {} is not read (MET_UCHAR, MET_CHAR, MET_USHORT, MET_SHORT, \
                 MET_UINT, MET_INT, MET_FLOAT, MET_DOUBLE are)",
                crate::error::quote(other)
            ))
        }
    })
}
