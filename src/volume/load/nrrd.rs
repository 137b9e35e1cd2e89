//! NRRD (teem) volumes: 3D, raw or gzip encoding, attached or detached (`data file:`) data,
//! the common sample types, `spacings` or `space directions`; with a patient `space` (RAS, LAS,
//! LPS), the directions place the voxel axes (`crate::volume::orientation`).

use std::io::Read;
use std::path::Path;

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::{Error, Result};
use crate::volume::Volume;

/// Longest header accepted (a guard against reading a binary file as text).
const MAX_HEADER_BYTES: usize = 64 * 1024;

struct Header {
    kind: SampleType,
    dims: [u32; 3],
    big_endian: bool,
    gzip: bool,
    spacing: [f32; 3],
    data_file: Option<String>,
    byte_skip: u64,
    /// The voxel axes on screen, from `space` and `space directions` (None: as they are).
    axes: Option<glam::Mat3>,
}

/// A patient `space` as the matrix from it to RAS+ (NRRD's names, long and short).
fn space_to_ras(space: &str) -> Option<glam::Mat3> {
    use glam::{Mat3, Vec3};
    let flip = |x: f32, y: f32| Mat3::from_diagonal(Vec3::new(x, y, 1.0));
    Some(match space.to_ascii_lowercase().as_str() {
        "right-anterior-superior" | "ras" => Mat3::IDENTITY,
        "left-anterior-superior" | "las" => flip(-1.0, 1.0),
        "left-posterior-superior" | "lps" => flip(-1.0, -1.0),
        _ => return None,
    })
}

fn parse_header(path: &Path, text: &str) -> Result<Header> {
    let err = |m: String| format_error(path, m);
    let mut lines = text.lines();
    let magic = lines.next().unwrap_or("");
    if !magic.starts_with("NRRD000") {
        return Err(err(format!(
            "not a NRRD file (its first line is {}, not 'NRRD0001' … 'NRRD0005')",
            crate::error::quote(magic)
        )));
    }
    let (mut kind, mut dims, mut dimension) = (None, None, None);
    let (mut endian, mut encoding, mut spacing, mut data_file, mut byte_skip) =
        (None, None, None, None, 0u64);
    let (mut space, mut directions) = (None, None);
    for line in lines {
        if line.is_empty() {
            break;
        }
        if line.starts_with('#') {
            continue;
        }
        let Some((key, value)) = line.split_once(':') else {
            continue;
        };
        let value = value.trim_start_matches('=').trim();
        match key.trim().to_ascii_lowercase().as_str() {
            "type" => {
                kind = Some(SampleType::parse(value).ok_or_else(|| {
                    err(format!(
                        "unsupported type {value}",
                        value = crate::error::quote(value)
                    ))
                })?)
            }
            "dimension" => {
                dimension = Some(value.parse::<u32>().map_err(|_| {
                    err(format!(
                        "bad dimension {value}",
                        value = crate::error::quote(value)
                    ))
                })?)
            }
            "sizes" => {
                let v: Vec<u32> = value
                    .split_whitespace()
                    .map(|s| {
                        s.parse().map_err(|_| {
                            err(format!(
                                "bad sizes {value}",
                                value = crate::error::quote(value)
                            ))
                        })
                    })
                    .collect::<Result<_>>()?;
                dims = Some(v);
            }
            "endian" => endian = Some(value.to_ascii_lowercase()),
            "encoding" => encoding = Some(value.to_ascii_lowercase()),
            "spacings" => {
                let v: Vec<f32> = value
                    .split_whitespace()
                    .map(|s| {
                        s.parse().map_err(|_| {
                            err(format!(
                                "bad spacings {value}",
                                value = crate::error::quote(value)
                            ))
                        })
                    })
                    .collect::<Result<_>>()?;
                spacing = Some(v);
            }
            "space directions" => {
                // "(dx,0,0) (0,dy,0) (0,0,dz)": the spacing of each axis is its vector's length.
                let v: Vec<Vec<f32>> = value
                    .split(')')
                    .filter(|s| s.contains('('))
                    .map(|s| {
                        let comps: Vec<f32> = s
                            .trim()
                            .trim_start_matches('(')
                            .split(',')
                            .map(|c| {
                                c.trim().parse::<f32>().map_err(|_| {
                                    err(format!(
                                        "bad space directions {value}",
                                        value = crate::error::quote(value)
                                    ))
                                })
                            })
                            .collect::<Result<_>>()?;
                        Ok(comps)
                    })
                    .collect::<Result<_>>()?;
                spacing = Some(
                    v.iter()
                        .map(|c| c.iter().map(|c| c * c).sum::<f32>().sqrt())
                        .collect(),
                );
                directions = Some(v);
            }
            "space" => space = Some(value.to_string()),
            "data file" | "datafile" => data_file = Some(value.to_string()),
            "byte skip" | "byteskip" => {
                byte_skip = value.parse().map_err(|_| {
                    err(format!(
                        "unsupported byte skip {value}",
                        value = crate::error::quote(value)
                    ))
                })?
            }
            _ => {}
        }
    }
    let kind = kind.ok_or_else(|| err("missing field 'type'".into()))?;
    if dimension.ok_or_else(|| err("missing field 'dimension'".into()))? != 3 {
        return Err(err(format!(
            "dimension {} is not 3 (only scalar 3D volumes)",
            dimension.unwrap_or(0)
        )));
    }
    let dims = dims.ok_or_else(|| err("missing field 'sizes'".into()))?;
    let dims: [u32; 3] = dims
        .try_into()
        .map_err(|d: Vec<u32>| err(format!("sizes has {} values, expected 3", d.len())))?;
    let encoding = encoding.ok_or_else(|| err("missing field 'encoding'".into()))?;
    let gzip = match encoding.as_str() {
        "raw" => false,
        "gzip" | "gz" => true,
        other => {
            return Err(err(format!(
                "unsupported encoding '{other}' (raw and gzip are)"
            )))
        }
    };
    let big_endian = match endian.as_deref() {
        Some("big") => true,
        Some("little") | None if kind.size() == 1 || endian.is_some() => false,
        None => return Err(err("missing field 'endian' for multi-byte samples".into())),
        Some(other) => {
            return Err(err(format!(
                "unknown endian {other}",
                other = crate::error::quote(other)
            )))
        }
    };
    let spacing = match spacing {
        None => [1.0; 3],
        Some(v) if v.len() == 3 && v.iter().all(|s| s.is_finite() && *s > 0.0) => {
            [v[0], v[1], v[2]]
        }
        Some(v) => return Err(err(format!("spacings {v:?}: need 3 positive values"))),
    };
    let axes = match (space.as_deref().and_then(space_to_ras), &directions) {
        (Some(to_ras), Some(d)) if d.len() == 3 && d.iter().all(|c| c.len() == 3) => {
            let column = |c: &Vec<f32>| to_ras * glam::Vec3::new(c[0], c[1], c[2]);
            let ras = glam::Mat3::from_cols(column(&d[0]), column(&d[1]), column(&d[2]));
            Some(
                crate::volume::orientation::screen_axes_from_ras(ras)
                    .map_err(|e| err(format!("space directions: {e}")))?,
            )
        }
        (Some(_), Some(_)) => {
            return Err(err("space directions: need three 3D vectors".into()));
        }
        _ => None,
    };
    Ok(Header {
        kind,
        dims,
        big_endian,
        gzip,
        spacing,
        data_file,
        byte_skip,
        axes,
    })
}

/// Load a `.nrrd` (attached data) or `.nhdr` (detached, `data file:` relative to it).
pub fn load_nrrd(path: &Path) -> Result<Volume> {
    crate::file::check_regular(path)?;
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_nrrd(&bytes, path)
}

/// A NRRD file's `bytes` (`path` names it in errors; a detached `data file:` is read relative
/// to it).
pub fn parse_nrrd(bytes: &[u8], path: &Path) -> Result<Volume> {
    // The header ends at the first blank line, with LF or CRLF line ends.
    let end = |mark: &[u8]| {
        bytes
            .windows(mark.len())
            .take(MAX_HEADER_BYTES)
            .position(|w| w == mark)
            .map(|p| p + mark.len())
    };
    let head_len = match (end(b"\n\n"), end(b"\r\n\r\n")) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    let header_text = match head_len {
        Some(n) => String::from_utf8_lossy(&bytes[..n]).into_owned(),
        // A detached header may end without a blank line.
        None if bytes.len() <= MAX_HEADER_BYTES => String::from_utf8_lossy(bytes).into_owned(),
        None => {
            return Err(format_error(
                path,
                "no end of header (blank line) in the first 64 KiB",
            ))
        }
    };
    let header = parse_header(path, &header_text)?;
    let expected = data_bytes(header.dims.map(u64::from), header.kind)
        .map_err(|e| format_error(path, e.to_string()))?;
    // Never read or inflate past what the header announces (+1 byte to detect excess).
    let wanted = expected.saturating_add(header.byte_skip);
    let mut payload = Vec::new();
    let read = match &header.data_file {
        Some(name) => {
            let data_path = path.parent().unwrap_or(Path::new(".")).join(name);
            let named = |e: Error| format_error(path, format!("`data file: {name}`: {e}"));
            crate::file::check_regular(&data_path).map_err(named)?;
            let file =
                std::fs::File::open(&data_path).map_err(|e| named(Error::io(&data_path, e)))?;
            let reader = std::io::BufReader::new(file);
            if header.gzip {
                flate2::read::GzDecoder::new(reader)
                    .take(wanted.saturating_add(1))
                    .read_to_end(&mut payload)
            } else {
                reader
                    .take(wanted.saturating_add(1))
                    .read_to_end(&mut payload)
            }
        }
        None => {
            let attached = &bytes[head_len.unwrap_or(bytes.len())..];
            if header.gzip {
                flate2::read::GzDecoder::new(attached)
                    .take(wanted.saturating_add(1))
                    .read_to_end(&mut payload)
            } else {
                payload = attached.to_vec();
                Ok(payload.len())
            }
        }
    };
    read.map_err(|e| {
        let what = if header.gzip { "gzip data" } else { "data" };
        format_error(path, format!("{what}: {e}"))
    })?;
    let available = (payload.len() as u64).saturating_sub(header.byte_skip);
    if available < expected {
        return Err(format_error(
            path,
            format!(
                "truncated data: {available} bytes, {} need {expected}",
                super::samples(header.dims, header.kind)
            ),
        ));
    }
    let start = header.byte_skip as usize;
    let samples = decode(
        &payload[start..start + expected as usize],
        header.kind,
        header.big_endian,
    );
    let volume = to_volume(path, header.dims, header.spacing, samples, header.kind)?;
    match header.axes {
        Some(axes) => volume.with_axes(axes),
        None => Ok(volume),
    }
}
