//! Legacy VTK `.vtk` image data (feature `vti`): `DATASET STRUCTURED_POINTS` with
//! `DIMENSIONS`, `SPACING` (or `ASPECT_RATIO`), `ORIGIN` and one `POINT_DATA` `SCALARS` array,
//! ASCII or BINARY (big-endian, as VTK writes it). The format has no directions: the voxel
//! axes stay as they are (a negative spacing turns its axis around), as for `.vti` files
//! without a `Direction`. Other datasets (meshes, grids) are refused by name.

use std::path::Path;

use super::vti::{ascii_values, place_axes};
use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::Volume;

type Res<T> = std::result::Result<T, String>;

/// Longest header accepted before the samples (a guard against reading a binary file as text).
const MAX_HEADER_BYTES: usize = 64 * 1024;

/// Load a legacy `.vtk` file.
pub fn load_vtk(path: &Path) -> Result<Volume> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the VTK limit")?;
    parse_vtk(&bytes, path)
}

/// A legacy `.vtk` file's `bytes` (`path` names it in errors).
pub fn parse_vtk(bytes: &[u8], path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let header = parse_header(bytes).map_err(err)?;
    let expected =
        data_bytes(header.dims.map(u64::from), header.kind).map_err(|e| err(e.to_string()))?;
    let (spacing, axes) = place_axes(header.spacing, None).map_err(err)?;
    let data = &bytes[header.data_start..];
    let samples = if header.binary {
        if (data.len() as u64) < expected {
            return Err(err(format!(
                "truncated: {} bytes of SCALARS {}, {} need {expected}",
                data.len(),
                header.name,
                super::samples(header.dims, header.kind)
            )));
        }
        decode(&data[..expected as usize], header.kind, true)
    } else {
        let count = (expected / header.kind.size()) as usize;
        ascii_values(data, count).map_err(|e| err(format!("SCALARS {}: {e}", header.name)))?
    };
    let volume = to_volume(path, header.dims, spacing, samples, header.kind)?;
    match axes {
        Some(axes) => volume.with_axes(axes),
        None => Ok(volume),
    }
}

struct Header {
    dims: [u32; 3],
    spacing: [f64; 3],
    kind: SampleType,
    binary: bool,
    /// The SCALARS array's name.
    name: String,
    /// Where the samples start.
    data_start: usize,
}

/// Words and lines of the header.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Cursor<'a> {
    /// The rest of the current line (without its line end), moving past it.
    fn line(&mut self) -> &'a [u8] {
        let rest = &self.bytes[self.at..];
        let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        self.at += (end + 1).min(rest.len());
        let line = &rest[..end];
        line.strip_suffix(b"\r").unwrap_or(line)
    }

    /// The next whitespace-separated word ("" at the end).
    fn word(&mut self) -> Res<String> {
        let rest = &self.bytes[self.at..];
        let start = rest
            .iter()
            .position(|b| !b.is_ascii_whitespace())
            .unwrap_or(rest.len());
        let len = rest[start..]
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len() - start);
        self.at += start + len;
        if self.at > MAX_HEADER_BYTES {
            return Err(
                "no POINT_DATA SCALARS in the first 64 KiB (not a legacy VTK file?)".into(),
            );
        }
        Ok(String::from_utf8_lossy(&rest[start..start + len]).into_owned())
    }

    /// `N` numbers after a keyword.
    fn numbers<const N: usize>(&mut self, keyword: &str) -> Res<[f64; N]> {
        let mut v = [0.0; N];
        for x in &mut v {
            let word = self.word()?;
            *x = word
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    format!(
                        "{keyword}: {word} is not a number ({N} needed)",
                        word = crate::error::quote(word)
                    )
                })?;
        }
        Ok(v)
    }
}

fn parse_header(bytes: &[u8]) -> Res<Header> {
    let mut c = Cursor { bytes, at: 0 };
    let first = c.line();
    if !first.starts_with(b"# vtk DataFile") {
        let shown = crate::error::quote(String::from_utf8_lossy(first));
        return Err(format!(
            "not a legacy VTK file (its first line is {shown}, not '# vtk DataFile Version …')"
        ));
    }
    c.line(); // the title
    let binary = match c.word()?.to_ascii_uppercase().as_str() {
        "ASCII" => false,
        "BINARY" => true,
        other => {
            return Err(format!(
                "{other} on the third line: ASCII or BINARY",
                other = crate::error::quote(other)
            ))
        }
    };
    let keyword = c.word()?;
    if !keyword.eq_ignore_ascii_case("DATASET") {
        return Err(format!(
            "{keyword} where DATASET belongs",
            keyword = crate::error::quote(keyword)
        ));
    }
    let dataset = c.word()?.to_ascii_uppercase();
    let what = match dataset.as_str() {
        "STRUCTURED_POINTS" => None,
        "POLYDATA" | "UNSTRUCTURED_GRID" => Some("a mesh/polydata, not image data"),
        "STRUCTURED_GRID" => Some("a curvilinear grid, not image data"),
        "RECTILINEAR_GRID" => Some("a rectilinear grid (spacing per line), not image data"),
        _ => Some("not image data"),
    };
    if let Some(what) = what {
        return Err(format!(
            "DATASET {dataset}: {what} (STRUCTURED_POINTS is read)"
        ));
    }
    let (mut dims, mut spacing) = (None, None);
    let points = loop {
        let keyword = c.word()?.to_ascii_uppercase();
        match keyword.as_str() {
            "DIMENSIONS" => {
                let d = c.numbers::<3>("DIMENSIONS")?;
                if d.iter()
                    .any(|&x| x < 1.0 || x.fract() != 0.0 || x > u32::MAX as f64)
                {
                    return Err(format!("DIMENSIONS {d:?}: whole numbers of at least 1"));
                }
                dims = Some(d.map(|x| x as u32));
            }
            "SPACING" | "ASPECT_RATIO" => spacing = Some(c.numbers::<3>(&keyword)?),
            "ORIGIN" => {
                c.numbers::<3>("ORIGIN")?;
            }
            "POINT_DATA" => break c.numbers::<1>("POINT_DATA")?[0],
            "CELL_DATA" => {
                return Err("CELL_DATA: cell values are not read (POINT_DATA SCALARS are)".into())
            }
            "" => return Err("no POINT_DATA (no voxel values)".into()),
            other => {
                return Err(format!(
                    "{other} in STRUCTURED_POINTS is not read",
                    other = crate::error::quote(other)
                ))
            }
        }
    };
    let dims = dims.ok_or("missing DIMENSIONS")?;
    let count = dims.iter().map(|&d| u64::from(d)).product::<u64>();
    if points != count as f64 {
        return Err(format!(
            "POINT_DATA {points}, but DIMENSIONS {dims:?} have {count} points"
        ));
    }
    let attribute = c.word()?.to_ascii_uppercase();
    if attribute != "SCALARS" {
        return Err(format!(
            "POINT_DATA {attribute}: only SCALARS are read (a scalar volume)"
        ));
    }
    // SCALARS name type [components], on one line.
    let line = String::from_utf8_lossy(c.line()).into_owned();
    let fields: Vec<&str> = line.split_whitespace().collect();
    let (name, kind) = match fields[..] {
        [name, kind] | [name, kind, _] => (name.to_string(), scalar_type(kind)?),
        _ => return Err(format!("SCALARS '{}': name type [components]", line.trim())),
    };
    if let Some(&n) = fields.get(2) {
        if n != "1" {
            return Err(format!(
                "SCALARS {name} has {n} components: scalar volumes only"
            ));
        }
    }
    // An optional `LOOKUP_TABLE name` line; binary samples start on the next line.
    // (Binary samples are not read as words: they may hold any byte.)
    let table = if binary {
        bytes[c.at..]
            .get(..12)
            .is_some_and(|w| w.eq_ignore_ascii_case(b"LOOKUP_TABLE"))
    } else {
        let line_start = c.at;
        let next = c.word()?;
        c.at = line_start;
        next.eq_ignore_ascii_case("LOOKUP_TABLE")
    };
    if table {
        c.word()?;
        c.word()?;
        if binary {
            c.line();
        }
    }
    Ok(Header {
        dims,
        spacing: spacing.unwrap_or([1.0; 3]),
        kind,
        binary,
        name,
        data_start: c.at,
    })
}

/// A legacy type name as a sample type.
fn scalar_type(name: &str) -> Res<SampleType> {
    Ok(match name.to_ascii_lowercase().as_str() {
        "unsigned_char" => SampleType::U8,
        "char" | "signed_char" => SampleType::I8,
        "unsigned_short" => SampleType::U16,
        "short" => SampleType::I16,
        "unsigned_int" => SampleType::U32,
        "int" => SampleType::I32,
        "float" => SampleType::F32,
        "double" => SampleType::F64,
        "long" | "unsigned_long" | "vtktypeint64" | "vtktypeuint64" | "vtkidtype" => {
            return Err(format!(
                "SCALARS type {name}: 64-bit integers are not read (unsigned_char … int, float, \
                 double are)"
            ))
        }
        _ => {
            return Err(format!(
                "SCALARS type '{name}' is not read (unsigned_char, char, unsigned_short, short, \
                 unsigned_int, int, float, double are)"
            ))
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &str = "# vtk DataFile Version 3.0\nCT\nBINARY\nDATASET STRUCTURED_POINTS\n\
        DIMENSIONS 2 1 1\nSPACING 0.5 1 -2\nORIGIN 0 0 0\nPOINT_DATA 2\n\
        SCALARS density short 1\nLOOKUP_TABLE default\n";

    #[test]
    fn the_header_gives_the_grid_and_where_samples_start() {
        let mut file = HEAD.as_bytes().to_vec();
        // Binary samples may start with bytes that look like whitespace.
        file.extend_from_slice(&[0x20, 0x0a, 0, 1]);
        let h = parse_header(&file).unwrap();
        assert_eq!(h.dims, [2, 1, 1]);
        assert_eq!(h.spacing, [0.5, 1.0, -2.0]);
        assert_eq!(h.kind, SampleType::I16);
        assert_eq!(h.name, "density");
        assert!(h.binary);
        assert_eq!(h.data_start, HEAD.len());
        let v = parse_vtk(&file, Path::new("t.vtk")).unwrap();
        assert_eq!(v.spacing, [0.5, 1.0, 2.0]);
        assert_eq!(
            v.axes.z_axis,
            -glam::Vec3::Z,
            "negative spacing turns z around"
        );
        // ASCII without a LOOKUP_TABLE line, ASPECT_RATIO for SPACING.
        let ascii = HEAD
            .replace("BINARY", "ASCII")
            .replace("LOOKUP_TABLE default\n", "")
            .replace("SPACING", "ASPECT_RATIO")
            + "7 9\n";
        let h = parse_header(ascii.as_bytes()).unwrap();
        assert!(!h.binary);
        assert_eq!(&ascii.as_bytes()[h.data_start..], b"7 9\n");
        let v = parse_vtk(ascii.as_bytes(), Path::new("t.vtk")).unwrap();
        assert_eq!(v.data, [0.0, 1.0]);
    }

    #[test]
    fn other_datasets_and_broken_headers_are_refused_by_name() {
        let refused = |text: String, expected: &str| {
            let e = match parse_header(text.as_bytes()) {
                Ok(_) => panic!("accepted: {text}"),
                Err(e) => e,
            };
            assert!(e.contains(expected), "'{e}' lacks '{expected}'");
        };
        refused(
            HEAD.replace("STRUCTURED_POINTS", "POLYDATA"),
            "DATASET POLYDATA: a mesh/polydata, not image data",
        );
        refused(HEAD.replace("DataFile", "Data"), "not a legacy VTK file");
        refused(HEAD.replace("BINARY", "XML"), "ASCII or BINARY");
        refused(
            HEAD.replace("POINT_DATA 2", "POINT_DATA 3"),
            "have 2 points",
        );
        refused(HEAD.replace("DIMENSIONS 2", "DIMENSIONS 0"), "at least 1");
        refused(HEAD.replace("short 1", "float 3"), "has 3 components");
        refused(HEAD.replace("short", "long"), "64-bit integers");
        refused(HEAD.replace("short", "bit"), "type 'bit' is not read");
        refused(HEAD.replace("SCALARS", "VECTORS"), "only SCALARS");
        refused(HEAD.replace("POINT_DATA", "CELL_DATA"), "CELL_DATA");
        refused(
            HEAD.split("POINT_DATA").next().unwrap().to_string(),
            "no POINT_DATA",
        );
    }
}
