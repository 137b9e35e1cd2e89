//! PLY point clouds (Stanford polygon format): ASCII and binary little/big endian. The `vertex`
//! element gives the points (x y z; optional nx ny nz, red green blue, radius); other elements
//! (faces…) are skipped. Every count is checked against the bytes present before allocating.

use std::path::Path;

use glam::Vec3;

use super::PointCloud;
use crate::error::{Error, Result};

/// Longest header accepted (real headers are a few hundred bytes).
const MAX_HEADER: usize = 1 << 16;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Format {
    Ascii,
    LittleEndian,
    BigEndian,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Self> {
        Some(match name {
            "char" | "int8" => Self::I8,
            "uchar" | "uint8" => Self::U8,
            "short" | "int16" => Self::I16,
            "ushort" | "uint16" => Self::U16,
            "int" | "int32" => Self::I32,
            "uint" | "uint32" => Self::U32,
            "float" | "float32" => Self::F32,
            "double" | "float64" => Self::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::I32 | Self::U32 | Self::F32 => 4,
            Self::F64 => 8,
        }
    }

    /// Full scale of a colour stored in this type (1 for floats).
    fn color_scale(self) -> f64 {
        match self {
            Self::U8 => 255.0,
            Self::I8 => 127.0,
            Self::U16 => 65535.0,
            Self::I16 => 32767.0,
            Self::U32 => u32::MAX as f64,
            Self::I32 => i32::MAX as f64,
            Self::F32 | Self::F64 => 1.0,
        }
    }

    fn decode(self, bytes: &[u8], format: Format) -> f64 {
        macro_rules! read {
            ($t:ty) => {{
                let a = bytes[..std::mem::size_of::<$t>()]
                    .try_into()
                    .expect("sized");
                (if format == Format::BigEndian {
                    <$t>::from_be_bytes(a)
                } else {
                    <$t>::from_le_bytes(a)
                }) as f64
            }};
        }
        match self {
            Self::I8 => read!(i8),
            Self::U8 => read!(u8),
            Self::I16 => read!(i16),
            Self::U16 => read!(u16),
            Self::I32 => read!(i32),
            Self::U32 => read!(u32),
            Self::F32 => read!(f32),
            Self::F64 => read!(f64),
        }
    }
}

#[derive(Clone, Debug)]
struct Property {
    name: String,
    value: Scalar,
    /// `Some(count type)` for list properties.
    list: Option<Scalar>,
}

#[derive(Clone, Debug)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
}

struct Header {
    format: Format,
    elements: Vec<Element>,
    body_start: usize,
}

/// Load the `vertex` element of a PLY file.
pub fn load(path: &Path) -> Result<PointCloud> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the PLY limit")?;
    parse(&bytes).map_err(|reason| Error::Points {
        path: path.into(),
        reason,
    })
}

/// Parse PLY `bytes` (errors are plain reasons; [`load`] adds the path).
pub fn parse(bytes: &[u8]) -> std::result::Result<PointCloud, String> {
    let header = parse_header(bytes)?;
    let vertex_index = header
        .elements
        .iter()
        .position(|e| e.name == "vertex")
        .ok_or("no 'vertex' element")?;
    let body = &bytes[header.body_start..];
    let mut reader: Box<dyn ValueReader> = match header.format {
        Format::Ascii => Box::new(AsciiReader::new(body)?),
        f => Box::new(BinaryReader {
            bytes: body,
            at: 0,
            format: f,
        }),
    };
    for element in &header.elements[..vertex_index] {
        skip_element(reader.as_mut(), element)?;
    }
    read_vertices(reader.as_mut(), &header.elements[vertex_index])
}

fn parse_header(bytes: &[u8]) -> std::result::Result<Header, String> {
    let window = &bytes[..bytes.len().min(MAX_HEADER)];
    // `end_header` on a line of its own (a comment may contain the words).
    let end = find_line(window, b"end_header").ok_or(if bytes.starts_with(b"ply") {
        "header has no 'end_header' within 64 KiB"
    } else {
        "not a PLY file (does not start with 'ply')"
    })?;
    let text = std::str::from_utf8(&window[..end]).map_err(|_| "header is not text")?;
    let mut body_start = end + b"end_header".len();
    // The body starts after the line break that ends the header (LF or CR LF).
    if bytes.get(body_start) == Some(&b'\r') {
        body_start += 1;
    }
    if bytes.get(body_start) == Some(&b'\n') {
        body_start += 1;
    }
    let mut lines = text.lines().map(str::trim);
    if lines.next() != Some("ply") {
        return Err("not a PLY file (does not start with 'ply')".into());
    }
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    for line in lines {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            [] | ["comment", ..] | ["obj_info", ..] => {}
            ["format", f, _version] => {
                format = Some(match *f {
                    "ascii" => Format::Ascii,
                    "binary_little_endian" => Format::LittleEndian,
                    "binary_big_endian" => Format::BigEndian,
                    other => return Err(format!("unknown format '{other}'")),
                })
            }
            ["element", name, count] => elements.push(Element {
                name: name.to_string(),
                count: count
                    .parse()
                    .map_err(|_| format!("element '{name}' has a bad count '{count}'"))?,
                properties: Vec::new(),
            }),
            ["property", "list", count, value, name] => {
                let element = elements.last_mut().ok_or("property before any element")?;
                element.properties.push(Property {
                    name: name.to_string(),
                    value: scalar(value)?,
                    list: Some(scalar(count)?),
                });
            }
            ["property", value, name] => {
                let element = elements.last_mut().ok_or("property before any element")?;
                element.properties.push(Property {
                    name: name.to_string(),
                    value: scalar(value)?,
                    list: None,
                });
            }
            _ => return Err(format!("unexpected header line '{line}'")),
        }
    }
    Ok(Header {
        format: format.ok_or("header has no 'format' line")?,
        elements,
        body_start,
    })
}

fn scalar(name: &str) -> std::result::Result<Scalar, String> {
    Scalar::parse(name).ok_or_else(|| format!("unknown property type '{name}'"))
}

/// Offset of the line that is exactly `line` (allowing CR LF and surrounding blanks).
fn find_line(haystack: &[u8], line: &[u8]) -> Option<usize> {
    let mut start = 0;
    for text in haystack.split(|&b| b == b'\n') {
        if text.trim_ascii() == line {
            return Some(start + (text.len() - text.trim_ascii_start().len()));
        }
        start += text.len() + 1;
    }
    None
}

/// Sequential values of the body, ASCII or binary.
trait ValueReader {
    fn next(&mut self, ty: Scalar) -> std::result::Result<f64, String>;
    /// Upper bound on how many values remain (the allocation guard).
    fn remaining_values(&self, smallest: Scalar) -> usize;
}

struct BinaryReader<'a> {
    bytes: &'a [u8],
    at: usize,
    format: Format,
}

impl ValueReader for BinaryReader<'_> {
    fn next(&mut self, ty: Scalar) -> std::result::Result<f64, String> {
        let end = self.at + ty.size();
        let slice = self
            .bytes
            .get(self.at..end)
            .ok_or("truncated: the data ends early")?;
        self.at = end;
        Ok(ty.decode(slice, self.format))
    }

    fn remaining_values(&self, smallest: Scalar) -> usize {
        (self.bytes.len() - self.at) / smallest.size()
    }
}

struct AsciiReader<'a> {
    tokens: std::str::SplitAsciiWhitespace<'a>,
    len: usize,
}

impl<'a> AsciiReader<'a> {
    fn new(body: &'a [u8]) -> std::result::Result<Self, String> {
        let text = std::str::from_utf8(body).map_err(|_| "ASCII body is not text")?;
        Ok(Self {
            tokens: text.split_ascii_whitespace(),
            len: text.len(),
        })
    }
}

impl ValueReader for AsciiReader<'_> {
    fn next(&mut self, _ty: Scalar) -> std::result::Result<f64, String> {
        let token = self.tokens.next().ok_or("truncated: the data ends early")?;
        token
            .parse::<f64>()
            .map_err(|_| format!("'{token}' is not a number"))
    }

    fn remaining_values(&self, _smallest: Scalar) -> usize {
        // Every value takes at least one character and one separator.
        self.len / 2 + 1
    }
}

fn skip_element(
    reader: &mut dyn ValueReader,
    element: &Element,
) -> std::result::Result<(), String> {
    check_count(reader, element)?;
    for _ in 0..element.count {
        for p in &element.properties {
            read_property(reader, p, |_| {})?;
        }
    }
    Ok(())
}

/// Reject counts the remaining data cannot hold (before anything is allocated).
fn check_count(reader: &dyn ValueReader, element: &Element) -> std::result::Result<(), String> {
    let per_entry = element.properties.len().max(1);
    let smallest = element
        .properties
        .iter()
        .map(|p| p.list.unwrap_or(p.value))
        .min_by_key(|s| s.size())
        .unwrap_or(Scalar::U8);
    let possible = reader.remaining_values(smallest) / per_entry;
    if element.count > possible {
        return Err(format!(
            "truncated: element '{}' declares {} entries but the data holds at most {possible}",
            element.name, element.count
        ));
    }
    Ok(())
}

fn read_property(
    reader: &mut dyn ValueReader,
    p: &Property,
    mut value: impl FnMut(f64),
) -> std::result::Result<(), String> {
    match p.list {
        None => value(reader.next(p.value)?),
        Some(count_type) => {
            let n = reader.next(count_type)?;
            if !(0.0..=1e9).contains(&n) || n.fract() != 0.0 {
                return Err(format!("list '{}' has a bad length {n}", p.name));
            }
            for _ in 0..n as usize {
                reader.next(p.value)?;
            }
        }
    }
    Ok(())
}

/// Which vertex property feeds which point attribute.
#[derive(Clone, Copy)]
enum Slot {
    Position(usize),
    Normal(usize),
    Color(usize),
    Radius,
    Ignored,
}

fn slot(name: &str) -> Slot {
    match name {
        "x" => Slot::Position(0),
        "y" => Slot::Position(1),
        "z" => Slot::Position(2),
        "nx" => Slot::Normal(0),
        "ny" => Slot::Normal(1),
        "nz" => Slot::Normal(2),
        "red" | "r" | "diffuse_red" => Slot::Color(0),
        "green" | "g" | "diffuse_green" => Slot::Color(1),
        "blue" | "b" | "diffuse_blue" => Slot::Color(2),
        "radius" => Slot::Radius,
        _ => Slot::Ignored,
    }
}

fn read_vertices(
    reader: &mut dyn ValueReader,
    element: &Element,
) -> std::result::Result<PointCloud, String> {
    let slots: Vec<Slot> = element.properties.iter().map(|p| slot(&p.name)).collect();
    for (i, p) in element.properties.iter().enumerate() {
        if element.properties[..i].iter().any(|q| q.name == p.name) {
            return Err(format!("vertex property '{}' appears twice", p.name));
        }
    }
    let has = |f: fn(&Slot) -> bool, n: usize| slots.iter().filter(|s| f(s)).count() == n;
    if !has(|s| matches!(s, Slot::Position(_)), 3) {
        return Err("the vertex element needs properties x, y and z".into());
    }
    if element
        .properties
        .iter()
        .any(|p| p.list.is_some() && !matches!(slot(&p.name), Slot::Ignored))
    {
        return Err("x/y/z, normals, colours and radius must be scalar properties".into());
    }
    let normals = has(|s| matches!(s, Slot::Normal(_)), 3);
    let colors = has(|s| matches!(s, Slot::Color(_)), 3);
    let radii = has(|s| matches!(s, Slot::Radius), 1);
    check_count(reader, element)?;
    let n = element.count;
    super::check_point_budget(n as u64).map_err(|e| e.to_string())?;
    let mut cloud = PointCloud {
        positions: Vec::with_capacity(n),
        normals: normals.then(|| Vec::with_capacity(n)),
        colors: colors.then(|| Vec::with_capacity(n)),
        radii: radii.then(|| Vec::with_capacity(n)),
    };
    for i in 0..n {
        let (mut p, mut nrm, mut col, mut r) = ([0.0f64; 3], [0.0f64; 3], [0.0f32; 3], 0.0);
        for (prop, s) in element.properties.iter().zip(&slots) {
            read_property(reader, prop, |v| match *s {
                Slot::Position(a) => p[a] = v,
                Slot::Normal(a) => nrm[a] = v,
                Slot::Color(a) => col[a] = (v / prop.value.color_scale()).clamp(0.0, 1.0) as f32,
                Slot::Radius => r = v,
                Slot::Ignored => {}
            })
            .map_err(|e| format!("vertex {i}: {e}"))?;
        }
        let position = Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32);
        if !position.is_finite() {
            return Err(format!("vertex {i} has a non-finite position {p:?}"));
        }
        cloud.positions.push(position);
        if let Some(v) = &mut cloud.normals {
            v.push(Vec3::new(nrm[0] as f32, nrm[1] as f32, nrm[2] as f32));
        }
        if let Some(v) = &mut cloud.colors {
            v.push(col);
        }
        if let Some(v) = &mut cloud.radii {
            v.push(r as f32);
        }
    }
    Ok(cloud)
}

#[cfg(test)]
mod tests {
    use super::*;

    const ASCII: &str = "ply\nformat ascii 1.0\ncomment test\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 255 0 0\n1 2 3 0 255 0\n3 0 1 1\n";

    #[test]
    fn ascii_with_colours() {
        let c = parse(ASCII.as_bytes()).unwrap();
        assert_eq!(c.positions, vec![Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0)]);
        assert_eq!(c.colors.unwrap()[1], [0.0, 1.0, 0.0]);
        assert!(c.normals.is_none() && c.radii.is_none());
    }

    fn binary(big: bool) -> Vec<u8> {
        let format = if big { "big" } else { "little" };
        let mut b = format!("ply\nformat binary_{format}_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 1\nproperty double x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float radius\nend_header\n").into_bytes();
        let f = |v: f32| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        b.push(2);
        for i in [7i32, 8] {
            b.extend(if big {
                i.to_be_bytes()
            } else {
                i.to_le_bytes()
            });
        }
        b.extend(if big {
            1.5f64.to_be_bytes()
        } else {
            1.5f64.to_le_bytes()
        });
        for v in [2.0, 3.0, 0.0, 0.0, 1.0, 0.25] {
            b.extend(f(v));
        }
        b
    }

    #[test]
    fn binary_both_endians_after_a_list_element() {
        for big in [false, true] {
            let c = parse(&binary(big)).unwrap();
            assert_eq!(c.positions, vec![Vec3::new(1.5, 2.0, 3.0)]);
            assert_eq!(c.normals.unwrap(), vec![Vec3::Z]);
            assert_eq!(c.radii.unwrap(), vec![0.25]);
        }
    }

    #[test]
    fn malformed_inputs_are_errors() {
        let mut truncated = binary(false);
        truncated.truncate(truncated.len() - 3);
        let huge = ASCII.replace("vertex 2", "vertex 999999999999");
        let no_z = ASCII.replace("property float z\n", "");
        let nan = ASCII.replace("1 2 3", "1 nan 3");
        let cases: Vec<(Vec<u8>, &str)> = vec![
            (b"hello".to_vec(), "not a PLY"),
            (truncated, "truncated"),
            (huge.into_bytes(), "truncated"),
            (no_z.into_bytes(), "x, y and z"),
            (nan.into_bytes(), "non-finite"),
            (
                ASCII.replace("ascii", "utf9").into_bytes(),
                "unknown format",
            ),
            (
                ASCII.replace("uchar red", "quad red").into_bytes(),
                "unknown property type",
            ),
            (
                ASCII.replace("255 0 0", "255 x 0").into_bytes(),
                "not a number",
            ),
            (
                ASCII.replace("end_header", "end_headr").into_bytes(),
                "end_header",
            ),
            (
                ASCII
                    .replace("comment test", "comment no end_header here")
                    .replace("end_header\n0", "end_headr\n0")
                    .into_bytes(),
                "end_header",
            ),
            (
                ASCII
                    .replace("property float z", "property float x")
                    .into_bytes(),
                "twice",
            ),
        ];
        for (bytes, expected) in cases {
            let err = parse(&bytes).unwrap_err();
            assert!(err.contains(expected), "{err} lacks '{expected}'");
        }
    }
}
