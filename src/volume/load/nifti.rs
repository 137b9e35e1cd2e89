//! NIfTI-1 volumes (`.nii`, `.nii.gz`): the header read by the `nifti` crate, the voxels here —
//! after the header's size passed the voxel limit and the memory budget, inflated no further
//! than the header announces. The first 3D volume of a 4D series; `scl_slope`/`scl_inter`
//! applied; the sform, else the qform, places the voxel axes in RAS+
//! (`crate::volume::orientation`); with neither, the voxel axes stay as they are.

use std::io::Read;
use std::path::Path;

use glam::{Mat3, Quat, Vec3};
use nifti::{Endianness, NiftiHeader};

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::orientation::screen_axes_from_ras;
use crate::volume::Volume;

/// Bytes of a NIfTI-1 header.
const HEADER_BYTES: u64 = 348;

/// Load a `.nii` or `.nii.gz` file (gzip told by its first bytes).
pub fn load_nifti(path: &Path) -> Result<Volume> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the NIfTI limit")?;
    parse_nifti(&bytes, path)
}

/// A NIfTI-1 file's `bytes`, gzip or not (`path` names it in errors).
pub fn parse_nifti(bytes: &[u8], path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let gzip = bytes.starts_with(&[0x1f, 0x8b]);
    let stream = || -> Box<dyn Read + '_> {
        match gzip {
            true => Box::new(flate2::read::GzDecoder::new(bytes)),
            false => Box::new(bytes),
        }
    };
    let mut head = Vec::new();
    stream()
        .take(HEADER_BYTES)
        .read_to_end(&mut head)
        .map_err(|e| err(format!("header: {e}")))?;
    if (head.len() as u64) < HEADER_BYTES {
        return Err(err(format!(
            "{} bytes{}: too short for a NIfTI-1 header ({HEADER_BYTES} bytes); is it a .nii file?",
            head.len(),
            if gzip { " after inflating" } else { "" },
        )));
    }
    let header = NiftiHeader::from_reader(head.as_slice())
        .map_err(|e| err(format!("not a NIfTI-1 header: {e}")))?;
    if &header.magic[..3] == b"ni1" {
        return Err(err(
            "a NIfTI .hdr/.img pair: its voxels are in the .img file (save it as one .nii)".into(),
        ));
    }
    let kind = sample_type(header.datatype).ok_or_else(|| {
        err(format!(
            "datatype {} is not a scalar type read here (u8, i8, u16, i16, u32, i32, f32, f64)",
            header.datatype
        ))
    })?;
    let rank = header.dim[0];
    if !(1..=7).contains(&rank) {
        return Err(err(format!("dim[0] = {rank}: not 1 to 7 dimensions")));
    }
    let dim = |i: usize| if i <= rank as usize { header.dim[i] } else { 1 };
    let dims = [dim(1), dim(2), dim(3)].map(u32::from);
    if dims.contains(&0) {
        return Err(err(format!("dimensions {dims:?}: each must be at least 1")));
    }
    let series: u64 = (4..=7).map(|i| u64::from(dim(i).max(1))).product();
    if series > 1 {
        log::warn!(
            "{}: {series} volumes (a 4D series); the first is shown",
            path.display()
        );
    }
    let expected = data_bytes(dims.map(u64::from), kind).map_err(|e| err(e.to_string()))?;
    let offset = header.vox_offset;
    if !(offset.is_finite() && offset >= HEADER_BYTES as f32) {
        return Err(err(format!(
            "vox_offset {offset}: the voxels must follow the header"
        )));
    }
    let mut payload = Vec::new();
    let mut data = stream();
    std::io::copy(&mut (&mut data).take(offset as u64), &mut std::io::sink())
        .and_then(|_| data.take(expected).read_to_end(&mut payload))
        .map_err(|e| err(format!("voxels: {e}")))?;
    if (payload.len() as u64) < expected {
        return Err(err(format!(
            "truncated: {} bytes of voxels, {dims:?} {kind:?} need {expected}",
            payload.len()
        )));
    }
    let mut samples = decode(&payload, kind, header.endianness == Endianness::Big);
    drop(payload);
    let (slope, inter) = (header.scl_slope, header.scl_inter);
    let scaled =
        slope != 0.0 && slope.is_finite() && inter.is_finite() && (slope, inter) != (1.0, 0.0);
    if scaled {
        samples.iter_mut().for_each(|v| *v = *v * slope + inter);
    }
    let spacing = [1, 2, 3].map(|i| match header.pixdim[i].abs() {
        s if s.is_finite() && s > 0.0 => s,
        _ => 1.0,
    });
    // Scaled 8-bit values are no longer 0…255: normalised by their range as other types are.
    let kind = if scaled { SampleType::F32 } else { kind };
    let volume = to_volume(path, dims, spacing, samples, kind)?;
    match ras_axes(&header) {
        Some(ras) => volume.with_axes(screen_axes_from_ras(ras).map_err(|e| err(e.to_string()))?),
        None => Ok(volume),
    }
}

/// The voxel axes in RAS+ (columns, any length): the sform when its code is set, else the
/// qform's rotation (quaternion b, c, d; qfac = pixdim[0] flips the third axis), else none.
fn ras_axes(h: &NiftiHeader) -> Option<Mat3> {
    if h.sform_code > 0 {
        let [x, y, z] = [h.srow_x, h.srow_y, h.srow_z];
        return Some(Mat3::from_cols(
            Vec3::new(x[0], y[0], z[0]),
            Vec3::new(x[1], y[1], z[1]),
            Vec3::new(x[2], y[2], z[2]),
        ));
    }
    if h.qform_code > 0 {
        let (b, c, d) = (h.quatern_b, h.quatern_c, h.quatern_d);
        let a = (1.0 - (b * b + c * c + d * d)).max(0.0).sqrt();
        let rotation = Mat3::from_quat(Quat::from_xyzw(b, c, d, a).normalize());
        let qfac = if h.pixdim[0] < 0.0 { -1.0 } else { 1.0 };
        return Some(Mat3::from_cols(
            rotation.x_axis,
            rotation.y_axis,
            rotation.z_axis * qfac,
        ));
    }
    None
}

/// NIfTI's datatype codes of the scalar types.
fn sample_type(code: i16) -> Option<SampleType> {
    Some(match code {
        2 => SampleType::U8,
        4 => SampleType::I16,
        8 => SampleType::I32,
        16 => SampleType::F32,
        64 => SampleType::F64,
        256 => SampleType::I8,
        512 => SampleType::U16,
        768 => SampleType::U32,
        _ => return None,
    })
}
