//! The values of a `.vti` file's XML attributes: numbers, extents, array types, and the voxel
//! axes its `Spacing` and `Direction` give.

use std::borrow::Cow;

use glam::{Mat3, Vec3};
use quick_xml::events::BytesStart;

use super::{Res, SampleType};
use crate::volume::orientation::check_axes;

/// An attribute's value, unescaped and its white space normalised.
pub(super) fn attribute(e: &BytesStart, name: &str) -> Res<Option<String>> {
    let element = String::from_utf8_lossy(e.name().as_ref()).into_owned();
    let found = e
        .try_get_attribute(name)
        .map_err(|err| format!("{element}: {err}"))?;
    found
        .map(|a| {
            a.normalized_value(quick_xml::XmlVersion::Implicit1_0)
                .map(Cow::into_owned)
                .map_err(|err| format!("{element} {name}: {err}"))
        })
        .transpose()
}

/// `N` finite numbers.
pub(super) fn numbers<const N: usize>(what: &str, value: &str) -> Res<[f64; N]> {
    let v: Vec<f64> = value
        .split_whitespace()
        .map(str::parse::<f64>)
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| {
            format!(
                "{what} {value}: not numbers",
                value = crate::error::quote(value)
            )
        })?;
    v.try_into()
        .ok()
        .filter(|v: &[f64; N]| v.iter().all(|x| x.is_finite()))
        .ok_or_else(|| {
            format!(
                "{what} {value}: needs {N} finite numbers",
                value = crate::error::quote(value)
            )
        })
}

/// `x0 x1 y0 y1 z0 z1`, each end at or past its start.
pub(super) fn extent(what: &str, value: &str) -> Res<[i64; 6]> {
    let v: Vec<i64> = value
        .split_whitespace()
        .map(str::parse::<i64>)
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| {
            format!(
                "{what} {value}: not whole numbers",
                value = crate::error::quote(value)
            )
        })?;
    let e: [i64; 6] = v.try_into().map_err(|v: Vec<i64>| {
        format!(
            "{what} {value}: {} numbers, 6 needed",
            v.len(),
            value = crate::error::quote(value)
        )
    })?;
    // Bounded, so that end − start + 1 cannot overflow.
    let bound = 1i64 << 40;
    if e.iter().any(|x| x.abs() > bound) || (0..3).any(|a| e[2 * a + 1] < e[2 * a]) {
        return Err(format!(
            "{what} '{value}': each axis's end must be at or past its start"
        ));
    }
    Ok(e)
}

/// A `DataArray` type as a sample type (64-bit integers and others refused by name).
pub(super) fn array_type(name: &str) -> Res<SampleType> {
    Ok(match name {
        "Int8" => SampleType::I8,
        "UInt8" => SampleType::U8,
        "Int16" => SampleType::I16,
        "UInt16" => SampleType::U16,
        "Int32" => SampleType::I32,
        "UInt32" => SampleType::U32,
        "Float32" => SampleType::F32,
        "Float64" => SampleType::F64,
        "Int64" | "UInt64" => {
            return Err(format!(
                "type {name}: 64-bit integers are not read (Int8 … UInt32, Float32, Float64 are)"
            ))
        }
        other => {
            return Err(format!(
                "type '{other}' is not read (Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, \
                 Float64 are)"
            ))
        }
    })
}

/// Spacing and voxel axes on screen from VTK's `Spacing` and `Direction` (row-major: column
/// a is axis a's direction in VTK's world, shown x right, y up, z toward the viewer). A
/// negative spacing turns its axis around. `None`: the axes as they are.
pub(in crate::volume::load) fn place_axes(
    spacing: [f64; 3],
    direction: Option<[f64; 9]>,
) -> Res<([f32; 3], Option<Mat3>)> {
    if spacing.iter().any(|s| *s == 0.0 || !s.is_finite()) {
        return Err(format!("spacing {spacing:?}: needs 3 non-zero numbers"));
    }
    let magnitude = spacing.map(|s| s.abs() as f32);
    if direction.is_none() && spacing.iter().all(|s| *s > 0.0) {
        return Ok((magnitude, None));
    }
    let m = direction.unwrap_or([1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    let mut columns = [Vec3::ZERO; 3];
    for (a, column) in columns.iter_mut().enumerate() {
        let v = Vec3::new(m[a] as f32, m[3 + a] as f32, m[6 + a] as f32);
        let v = v
            .try_normalize()
            .ok_or_else(|| format!("Direction: voxel axis {a} has no direction ({v})"))?;
        *column = if spacing[a] < 0.0 { -v } else { v };
    }
    let axes = Mat3::from_cols(columns[0], columns[1], columns[2]);
    check_axes(axes).map_err(|e| format!("Direction: {e}"))?;
    Ok((magnitude, Some(axes)))
}
