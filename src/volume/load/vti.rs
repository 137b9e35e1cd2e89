//! VTK XML image data (`.vti`, `<VTKFile type="ImageData">`, feature `vti`): one `Piece`, its
//! `PointData` scalar array (the one `Scalars` names, else the first single-component one) as
//! `ascii`, `binary` (base64) or `appended` (`raw` or `base64`) data, either byte order, UInt32
//! or UInt64 headers, uncompressed or zlib blocks (`vtkZLibDataCompressor`). VTK's world has no
//! patient frame: it is shown as ParaView shows it (x right, y up, z toward the viewer), so the
//! voxel axes point along the `Direction` matrix's columns (docs/VOLUMES.md "Where a volume
//! is"); without a `Direction` they stay as they are.

use std::borrow::Cow;
use std::io::Read;
use std::path::Path;

use base64::engine::{DecodePaddingMode, GeneralPurpose, GeneralPurposeConfig};
use base64::Engine;
use glam::{Mat3, Vec3};
use quick_xml::events::{BytesStart, Event};

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::orientation::check_axes;
use crate::volume::Volume;

type Res<T> = std::result::Result<T, String>;

/// Load a `.vti` file.
pub fn load_vti(path: &Path) -> Result<Volume> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the VTK limit")?;
    parse_vti(&bytes, path)
}

/// A `.vti` file's `bytes` (`path` names it in errors).
pub fn parse_vti(bytes: &[u8], path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let file = parse_xml(bytes).map_err(err)?;
    let expected =
        data_bytes(file.dims.map(u64::from), file.kind).map_err(|e| err(e.to_string()))?;
    let samples = read_samples(&file, expected as usize)
        .map_err(|e| err(format!("DataArray '{}': {e}", file.name)))?;
    let volume = to_volume(path, file.dims, file.spacing, samples, file.kind)?;
    match file.axes {
        Some(axes) => volume.with_axes(axes),
        None => Ok(volume),
    }
}

/// What the XML says: the grid, where it is and where the scalar array's bytes are.
struct Vti<'a> {
    dims: [u32; 3],
    spacing: [f32; 3],
    axes: Option<Mat3>,
    /// The scalar array's name, type and data.
    name: String,
    kind: SampleType,
    data: Stored<'a>,
    layout: Layout,
}

/// How binary data is laid out (the `VTKFile` attributes).
#[derive(Clone, Copy, Default)]
struct Layout {
    big_endian: bool,
    /// UInt64 header words (`header_type`), else UInt32.
    header64: bool,
    /// zlib blocks (`compressor="vtkZLibDataCompressor"`).
    zlib: bool,
}

/// Where a `DataArray`'s values are.
enum Stored<'a> {
    /// Numbers in the element's text.
    Ascii(Cow<'a, [u8]>),
    /// Base64 of header and data in the element's text.
    Binary(Cow<'a, [u8]>),
    /// At this offset into the appended data.
    Appended {
        offset: usize,
        section: Appended<'a>,
    },
}

/// The `AppendedData` section: its bytes after the `_`.
#[derive(Clone, Copy)]
struct Appended<'a> {
    base64: bool,
    data: &'a [u8],
}

/// The scalar `DataArray` while the XML is read.
struct Array {
    name: String,
    kind: SampleType,
    format: Format,
    offset: usize,
}

#[derive(Clone, Copy, PartialEq)]
enum Format {
    Ascii,
    Binary,
    Appended,
}

/// What the XML events have said so far.
#[derive(Default)]
struct State<'a> {
    vtk_file: bool,
    layout: Layout,
    image_data: bool,
    whole_extent: Option<[i64; 6]>,
    spacing: Option<[f64; 3]>,
    direction: Option<[f64; 9]>,
    pieces: usize,
    piece_extent: Option<[i64; 6]>,
    /// PointData's `Scalars` attribute.
    scalars: Option<String>,
    point_arrays: usize,
    cell_arrays: usize,
    /// The first multi-component point array (name, components), for the error.
    first_multi: Option<(String, u64)>,
    chosen: Option<Array>,
    /// The depth of the chosen inline array's element while it is open: its own text (not its
    /// children's, such as VTK's `InformationKey`s) is the data.
    collecting: Option<usize>,
    text: Vec<Cow<'a, [u8]>>,
}

const APPENDED_TAG: &[u8] = b"<AppendedData";

/// The XML before the appended data (which is not XML when raw) and that data.
fn split_appended(bytes: &[u8]) -> Res<(&[u8], Option<Appended<'_>>)> {
    let Some(start) = bytes
        .windows(APPENDED_TAG.len())
        .position(|w| w == APPENDED_TAG)
    else {
        return Ok((bytes, None));
    };
    let close = bytes[start..]
        .iter()
        .position(|&b| b == b'>')
        .map(|p| start + p)
        .ok_or("AppendedData: its tag has no end")?;
    let mut reader = quick_xml::Reader::from_reader(&bytes[start..=close]);
    let encoding = match reader.read_event() {
        Ok(Event::Start(e) | Event::Empty(e)) => attribute(&e, "encoding")?,
        _ => return Err("AppendedData: a malformed tag".into()),
    };
    let base64 = match encoding.as_deref() {
        Some("raw") => false,
        Some("base64") => true,
        other => {
            return Err(format!(
                "AppendedData encoding {}: raw or base64",
                other.map_or("missing".into(), |e| format!("'{e}'"))
            ))
        }
    };
    let rest = &bytes[close + 1..];
    let data = match rest.iter().position(|b| !b.is_ascii_whitespace()) {
        Some(p) if rest[p] == b'_' => &rest[p + 1..],
        _ => return Err("AppendedData: no '_' before its data".into()),
    };
    Ok((&bytes[..start], Some(Appended { base64, data })))
}

fn parse_xml(bytes: &[u8]) -> Res<Vti<'_>> {
    let (xml, appended) = split_appended(bytes)?;
    let mut reader = quick_xml::Reader::from_reader(xml);
    let mut stack: Vec<Vec<u8>> = Vec::new();
    let mut state = State::default();
    loop {
        let event = reader
            .read_event()
            .map_err(|e| format!("XML near byte {}: {e}", reader.error_position()))?;
        match event {
            Event::Start(e) => {
                let depth = stack.len() + 1;
                state.element(&e, stack.last().map(Vec::as_slice), Some(depth))?;
                stack.push(e.name().as_ref().to_vec());
            }
            Event::Empty(e) => state.element(&e, stack.last().map(Vec::as_slice), None)?,
            Event::End(_) => {
                stack.pop();
                if state.collecting.is_some_and(|depth| stack.len() < depth) {
                    state.collecting = None;
                }
            }
            Event::Text(t) if state.collecting == Some(stack.len()) => {
                state.text.push(t.into_inner())
            }
            Event::CData(t) if state.collecting == Some(stack.len()) => {
                state.text.push(t.into_inner())
            }
            Event::Eof => break,
            _ => {}
        }
    }
    state.finish(appended)
}

impl<'a> State<'a> {
    /// An element's start inside `parent`; `depth` where it has content (not `<…/>`).
    fn element(&mut self, e: &BytesStart, parent: Option<&[u8]>, depth: Option<usize>) -> Res<()> {
        match (e.name().as_ref(), parent) {
            (b"VTKFile", None) => self.vtk_file(e),
            (b"ImageData", Some(b"VTKFile")) => {
                self.image_data = true;
                self.whole_extent = attribute(e, "WholeExtent")?
                    .map(|v| extent("WholeExtent", &v))
                    .transpose()?;
                self.spacing = attribute(e, "Spacing")?
                    .map(|v| numbers::<3>("Spacing", &v))
                    .transpose()?;
                self.direction = attribute(e, "Direction")?
                    .map(|v| numbers::<9>("Direction", &v))
                    .transpose()?;
                Ok(())
            }
            (b"Piece", Some(b"ImageData")) => {
                self.pieces += 1;
                if self.pieces > 1 {
                    return Err("several Pieces: only single-piece files are read".into());
                }
                self.piece_extent = attribute(e, "Extent")?
                    .map(|v| extent("Piece Extent", &v))
                    .transpose()?;
                Ok(())
            }
            (b"PointData", Some(b"Piece")) => {
                self.scalars = attribute(e, "Scalars")?;
                Ok(())
            }
            (b"DataArray", Some(b"CellData")) => {
                self.cell_arrays += 1;
                Ok(())
            }
            (b"DataArray", Some(b"PointData")) => self.point_array(e, depth),
            _ => Ok(()),
        }
    }

    fn vtk_file(&mut self, e: &BytesStart) -> Res<()> {
        self.vtk_file = true;
        let kind = attribute(e, "type")?.unwrap_or_default();
        if kind != "ImageData" {
            let what = match kind.as_str() {
                "PolyData" | "UnstructuredGrid" | "PPolyData" | "PUnstructuredGrid" => {
                    "a mesh, not image data"
                }
                "StructuredGrid" | "PStructuredGrid" => "a curvilinear grid, not image data",
                "RectilinearGrid" | "PRectilinearGrid" => {
                    "a rectilinear grid (spacing per line), not image data"
                }
                "PImageData" => "a parallel index of pieces: give one piece's .vti",
                _ => "not image data",
            };
            return Err(format!(
                "VTKFile type '{kind}': {what} (type=\"ImageData\" is read)"
            ));
        }
        self.layout.big_endian = match attribute(e, "byte_order")?.as_deref() {
            None | Some("LittleEndian") => false,
            Some("BigEndian") => true,
            Some(other) => {
                return Err(format!(
                    "byte_order {other}: LittleEndian or BigEndian",
                    other = crate::error::quote(other)
                ))
            }
        };
        self.layout.header64 = match attribute(e, "header_type")?.as_deref() {
            None | Some("UInt32") => false,
            Some("UInt64") => true,
            Some(other) => {
                return Err(format!(
                    "header_type {other}: UInt32 or UInt64",
                    other = crate::error::quote(other)
                ))
            }
        };
        self.layout.zlib = match attribute(e, "compressor")?.as_deref() {
            None | Some("") => false,
            Some("vtkZLibDataCompressor") => true,
            Some(other) => {
                return Err(format!(
                    "compressor {other} is not read (vtkZLibDataCompressor is)"
                ))
            }
        };
        Ok(())
    }

    /// A `DataArray` of the `PointData`: the scalar array when it is the one `Scalars` names
    /// (else the first single-component one).
    fn point_array(&mut self, e: &BytesStart, depth: Option<usize>) -> Res<()> {
        self.point_arrays += 1;
        let name = attribute(e, "Name")?.unwrap_or_default();
        let components = match attribute(e, "NumberOfComponents")? {
            None => 1,
            Some(v) => v.trim().parse::<u64>().map_err(|_| {
                format!(
                    "DataArray {name}: NumberOfComponents {v}",
                    name = crate::error::quote(&name),
                    v = crate::error::quote(v)
                )
            })?,
        };
        let chosen = self.chosen.is_none()
            && match &self.scalars {
                Some(scalars) => *scalars == name,
                None => components == 1,
            };
        if !chosen {
            if components != 1 && self.first_multi.is_none() {
                self.first_multi = Some((name, components));
            }
            return Ok(());
        }
        if components != 1 {
            return Err(multi_component(&name, components));
        }
        let kind = array_type(&attribute(e, "type")?.unwrap_or_default())
            .map_err(|m| format!("DataArray {name}: {m}", name = crate::error::quote(&name)))?;
        let format = match attribute(e, "format")?.as_deref() {
            None | Some("ascii") => Format::Ascii,
            Some("binary") => Format::Binary,
            Some("appended") => Format::Appended,
            Some(other) => {
                return Err(format!(
                    "DataArray '{name}': format '{other}' (ascii, binary or appended)"
                ))
            }
        };
        let offset = match (format, attribute(e, "offset")?) {
            (Format::Appended, Some(v)) => v.trim().parse::<usize>().map_err(|_| {
                format!(
                    "DataArray {name}: offset {v}",
                    name = crate::error::quote(&name),
                    v = crate::error::quote(v)
                )
            })?,
            (Format::Appended, None) => {
                return Err(format!(
                    "DataArray {name}: appended without an offset",
                    name = crate::error::quote(&name)
                ))
            }
            _ => 0,
        };
        self.collecting = depth.filter(|_| format != Format::Appended);
        self.chosen = Some(Array {
            name,
            kind,
            format,
            offset,
        });
        Ok(())
    }

    fn finish(self, appended: Option<Appended<'a>>) -> Res<Vti<'a>> {
        if !self.vtk_file {
            return Err("no VTKFile element (not a VTK XML file)".into());
        }
        if !self.image_data {
            return Err("no ImageData element".into());
        }
        let whole = self.whole_extent.ok_or("ImageData: missing WholeExtent")?;
        if self.pieces == 0 {
            return Err("no Piece".into());
        }
        let Some(array) = self.chosen else {
            return Err(if self.point_arrays == 0 && self.cell_arrays > 0 {
                "CellData only: cell values are not read (a volume's values are PointData)".into()
            } else if let Some(scalars) = &self.scalars {
                format!(
                    "PointData Scalars {scalars} names no DataArray",
                    scalars = crate::error::quote(scalars)
                )
            } else if let Some((name, components)) = &self.first_multi {
                multi_component(name, *components)
            } else {
                "no PointData DataArray (no voxel values)".into()
            });
        };
        let e = self.piece_extent.unwrap_or(whole);
        let mut dims = [0u32; 3];
        for (a, d) in dims.iter_mut().enumerate() {
            *d = u32::try_from(e[2 * a + 1] - e[2 * a] + 1)
                .map_err(|_| format!("Extent {e:?}: more than 2³² points along an axis"))?;
        }
        let (spacing, axes) = place_axes(self.spacing.unwrap_or([1.0; 3]), self.direction)?;
        let data = match array.format {
            Format::Ascii => Stored::Ascii(join(self.text)),
            Format::Binary => Stored::Binary(join(self.text)),
            Format::Appended => Stored::Appended {
                offset: array.offset,
                section: appended.ok_or_else(|| {
                    format!(
                        "DataArray '{}' is appended, but there is no AppendedData",
                        array.name
                    )
                })?,
            },
        };
        Ok(Vti {
            dims,
            spacing,
            axes,
            name: array.name,
            kind: array.kind,
            data,
            layout: self.layout,
        })
    }
}

fn multi_component(name: &str, components: u64) -> String {
    format!(
        "PointData array {name} has {components} components: scalar volumes only",
        name = crate::error::quote(name)
    )
}

fn join(pieces: Vec<Cow<'_, [u8]>>) -> Cow<'_, [u8]> {
    match pieces.len() {
        0 => Cow::Borrowed(&[]),
        1 => pieces.into_iter().next().expect("one piece"),
        _ => Cow::Owned(pieces.concat()),
    }
}

/// An attribute's value, unescaped and its white space normalised.
fn attribute(e: &BytesStart, name: &str) -> Res<Option<String>> {
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
fn numbers<const N: usize>(what: &str, value: &str) -> Res<[f64; N]> {
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
fn extent(what: &str, value: &str) -> Res<[i64; 6]> {
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
fn array_type(name: &str) -> Res<SampleType> {
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
pub(super) fn place_axes(
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

/// `n` whitespace-separated numbers from `text` (further ones are ignored).
pub(super) fn ascii_values(text: &[u8], n: usize) -> Res<Vec<f32>> {
    // Each number takes at least two bytes but the last: a short text is refused before
    // anything is allocated for it.
    let mut values = Vec::with_capacity(n.min(text.len() / 2 + 1));
    for token in text
        .split(|b| b.is_ascii_whitespace())
        .filter(|t| !t.is_empty())
    {
        if values.len() == n {
            break;
        }
        let value = std::str::from_utf8(token)
            .ok()
            .and_then(|s| s.parse::<f64>().ok())
            .ok_or_else(|| {
                let shown = crate::error::quote(String::from_utf8_lossy(token));
                format!("{shown} is not a number")
            })?;
        values.push(value as f32);
    }
    if values.len() < n {
        return Err(format!("too few values: {} of {n}", values.len()));
    }
    Ok(values)
}

fn read_samples(file: &Vti, expected: usize) -> Res<Vec<f32>> {
    let count = expected / file.kind.size() as usize;
    let mut blob = match &file.data {
        Stored::Ascii(text) => return ascii_values(text, count),
        Stored::Binary(text) => {
            let clean: Vec<u8> = text
                .iter()
                .copied()
                .filter(|b| !b.is_ascii_whitespace())
                .collect();
            let mut blob = Blob::Base64(Base64::new(&clean));
            let bytes = read_blob(&mut blob, file.layout, expected)?;
            return Ok(decode(&bytes, file.kind, file.layout.big_endian));
        }
        Stored::Appended { offset, section } => {
            let data = section.data.get(*offset..).ok_or_else(|| {
                format!(
                    "offset {offset} is past the appended data's {} bytes",
                    section.data.len()
                )
            })?;
            if section.base64 {
                Blob::Base64(Base64::new(data))
            } else {
                Blob::Raw(data)
            }
        }
    };
    let bytes = read_blob(&mut blob, file.layout, expected)?;
    Ok(decode(&bytes, file.kind, file.layout.big_endian))
}

/// Binary data: raw bytes, or base64 text decoded as far as it is read.
enum Blob<'a> {
    Raw(&'a [u8]),
    Base64(Base64<'a>),
}

impl Blob<'_> {
    /// The most bytes it can hold.
    fn capacity(&self) -> usize {
        match self {
            Blob::Raw(b) => b.len(),
            Blob::Base64(b) => b.text.len() / 4 * 3 + 3,
        }
    }

    /// Its first `n` bytes, or all it has when it holds fewer.
    fn get(&mut self, n: usize) -> Res<&[u8]> {
        match self {
            Blob::Raw(b) => Ok(&b[..n.min(b.len())]),
            Blob::Base64(b) => {
                b.fill(n)?;
                Ok(&b.out[..n.min(b.out.len())])
            }
        }
    }
}

/// Base64 text that may be several encodings one after another (VTK encodes a header and its
/// data separately: `…==` in the middle), decoded on demand.
struct Base64<'a> {
    text: &'a [u8],
    at: usize,
    out: Vec<u8>,
}

const BASE64: GeneralPurpose = GeneralPurpose::new(
    &base64::alphabet::STANDARD,
    GeneralPurposeConfig::new()
        .with_decode_padding_mode(DecodePaddingMode::Indifferent)
        .with_decode_allow_trailing_bits(true),
);

impl<'a> Base64<'a> {
    /// Text up to the first byte that is not base64 (the appended data's end).
    fn new(text: &'a [u8]) -> Self {
        let end = text
            .iter()
            .position(|&b| !(b.is_ascii_alphanumeric() || matches!(b, b'+' | b'/' | b'=')))
            .unwrap_or(text.len());
        Self {
            text: &text[..end],
            at: 0,
            out: Vec::new(),
        }
    }

    /// Decode until `n` bytes are out (or the text ends), in whole groups of 4, each encoding
    /// ended by its padding decoded on its own.
    fn fill(&mut self, n: usize) -> Res<()> {
        while self.out.len() < n && self.at < self.text.len() {
            let groups = (n - self.out.len()).div_ceil(3);
            let mut end = self
                .at
                .saturating_add(groups.saturating_mul(4))
                .min(self.text.len());
            if let Some(p) = self.text[self.at..end].iter().position(|&c| c == b'=') {
                end = (self.at + (p / 4 + 1) * 4).min(self.text.len());
            }
            BASE64
                .decode_vec(&self.text[self.at..end], &mut self.out)
                .map_err(|e| format!("base64 at character {}: {e}", self.at))?;
            self.at = end;
        }
        Ok(())
    }
}

/// The `expected` data bytes of a binary array: after its byte count, or inflated from its zlib
/// blocks (header: block count, block size, last block's size, each block's compressed size).
fn read_blob<'b>(blob: &'b mut Blob, layout: Layout, expected: usize) -> Res<Cow<'b, [u8]>> {
    let w = if layout.header64 { 8 } else { 4 };
    let word = |b: &[u8], i: usize| -> u64 {
        let b = &b[i * w..(i + 1) * w];
        match (w, layout.big_endian) {
            (8, false) => u64::from_le_bytes(b.try_into().expect("8 bytes")),
            (8, true) => u64::from_be_bytes(b.try_into().expect("8 bytes")),
            (_, false) => u32::from_le_bytes(b.try_into().expect("4 bytes")).into(),
            (_, true) => u32::from_be_bytes(b.try_into().expect("4 bytes")).into(),
        }
    };
    let capacity = blob.capacity() as u64;
    if !layout.zlib {
        let head = blob.get(w)?;
        if head.len() < w {
            return Err("truncated: no byte count before the data".into());
        }
        let count = word(head, 0);
        if count < expected as u64 {
            return Err(format!(
                "{count} bytes of data, the extent and type need {expected}"
            ));
        }
        let all = blob.get(w + expected)?;
        if all.len() < w + expected {
            return Err(format!(
                "truncated: {} bytes of data, {expected} needed",
                all.len() - w
            ));
        }
        return Ok(Cow::Borrowed(&all[w..]));
    }
    let head = blob.get(3 * w)?;
    if head.len() < 3 * w {
        return Err("truncated: no compression header".into());
    }
    let (blocks, size, last) = (word(head, 0), word(head, 1), word(head, 2));
    let header_len = blocks
        .checked_add(3)
        .and_then(|b| b.checked_mul(w as u64))
        .filter(|&l| l <= capacity)
        .ok_or_else(|| format!("{blocks} compressed blocks: more than the file holds"))?
        as usize;
    let head = blob.get(header_len)?;
    if head.len() < header_len {
        return Err(format!("truncated: a header of {blocks} compressed blocks"));
    }
    let compressed: Vec<u64> = (3..3 + blocks as usize).map(|i| word(head, i)).collect();
    let stored = compressed
        .iter()
        .try_fold(0u64, |sum, &c| sum.checked_add(c))
        .filter(|&s| s <= capacity)
        .ok_or("compressed block sizes: more than the file holds")? as usize;
    let total = match blocks {
        0 => Some(0),
        n => (n - 1)
            .checked_mul(size)
            .and_then(|t| t.checked_add(if last == 0 { size } else { last })),
    };
    if total.is_none_or(|t| t < expected as u64) {
        return Err(format!(
            "{blocks} compressed blocks of {size} bytes (last {last}): fewer than the {expected} \
             bytes the extent and type need"
        ));
    }
    let data = blob.get(header_len + stored)?;
    // zlib inflates at most 1032:1: a small file cannot reserve much more than it holds.
    let mut out = Vec::with_capacity(expected.min(stored.saturating_mul(1032)));
    let mut at = header_len;
    for (i, &c) in compressed.iter().enumerate() {
        if out.len() >= expected {
            break;
        }
        let Some(block) = data.get(at..at + c as usize) else {
            return Err(format!(
                "truncated: compressed block {i} of {blocks} ends past the data"
            ));
        };
        let block_size = if i + 1 == compressed.len() && last != 0 {
            last
        } else {
            size
        };
        let want = block_size.min((expected - out.len()) as u64);
        let before = out.len();
        flate2::read::ZlibDecoder::new(block)
            .take(want)
            .read_to_end(&mut out)
            .map_err(|e| format!("zlib block {i}: {e}"))?;
        if ((out.len() - before) as u64) < want {
            return Err(format!(
                "zlib block {i}: {} of {want} bytes (truncated)",
                out.len() - before
            ));
        }
        at += c as usize;
    }
    Ok(Cow::Owned(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn xml(image: &str, array: &str) -> String {
        format!(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" \
             byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<ImageData {image}>\n\
             <Piece Extent=\"0 1 0 1 0 0\"><PointData Scalars=\"s\">{array}</PointData>\
             </Piece></ImageData></VTKFile>\n"
        )
    }

    // With a child VTK 9 writes (its text is not data).
    const ASCII: &str = "<DataArray type=\"UInt8\" Name=\"s\" format=\"ascii\">1 2\n\
        <InformationKey name=\"L2_NORM_RANGE\"><Value index=\"0\">9</Value></InformationKey>\n\
        3 4</DataArray>";

    #[test]
    fn the_header_gives_the_grid_spacing_and_axes() {
        let file = xml(
            "WholeExtent=\"0 1 0 1 0 0\" Origin=\"5 5 5\" Spacing=\"0.5 -2 1\" \
             Direction=\"0 1 0 1 0 0 0 0 1\"",
            ASCII,
        );
        let vti = parse_xml(file.as_bytes()).unwrap();
        assert_eq!(vti.dims, [2, 2, 1]);
        assert_eq!(vti.spacing, [0.5, 2.0, 1.0]);
        assert_eq!(vti.kind, SampleType::U8);
        assert_eq!(vti.name, "s");
        // Column 0 of the row-major Direction is (0, 1, 0); axis 1 is (1, 0, 0) turned
        // around by its negative spacing.
        let axes = vti.axes.unwrap();
        assert_eq!(axes.x_axis, Vec3::Y);
        assert_eq!(axes.y_axis, -Vec3::X);
        assert_eq!(axes.z_axis, Vec3::Z);
        assert_eq!(read_samples(&vti, 4).unwrap(), [1.0, 2.0, 3.0, 4.0]);
        // No Direction, positive spacing: the axes as they are.
        let plain = xml("WholeExtent=\"0 1 0 1 0 0\"", ASCII);
        let plain = parse_xml(plain.as_bytes()).unwrap();
        assert!(plain.axes.is_none());
        assert_eq!(plain.spacing, [1.0; 3]);
    }

    #[test]
    fn broken_headers_say_what_is_wrong() {
        let refused = |image: &str, array: &str, expected: &str| {
            let e = match parse_xml(xml(image, array).as_bytes()) {
                Ok(_) => panic!("{image} {array}: accepted"),
                Err(e) => e,
            };
            assert!(e.contains(expected), "'{e}' lacks '{expected}'");
        };
        let whole = "WholeExtent=\"0 1 0 1 0 0\"";
        refused("", ASCII, "missing WholeExtent");
        refused("WholeExtent=\"0 1 0 1\"", ASCII, "4 numbers, 6 needed");
        refused("WholeExtent=\"0 1 1 0 0 0\"", ASCII, "at or past its start");
        refused(
            &format!("{whole} Direction=\"1 0.3 0 0 1 0 0 0 1\""),
            ASCII,
            "right angles",
        );
        refused(&format!("{whole} Spacing=\"1 0 1\""), ASCII, "non-zero");
        refused(
            whole,
            &ASCII.replace("UInt8", "Int64"),
            "type Int64: 64-bit integers are not read",
        );
        refused(
            whole,
            &ASCII.replace("UInt8", "Bit"),
            "type 'Bit' is not read",
        );
        refused(
            whole,
            &ASCII.replace("format", "NumberOfComponents=\"3\" format"),
            "'s' has 3 components",
        );
        refused(
            whole,
            &ASCII.replace("\"s\"", "\"t\""),
            "Scalars 's' names no",
        );
        refused(
            whole,
            &ASCII.replace("\"ascii\"", "\"appended\" offset=\"0\""),
            "no AppendedData",
        );
        let e = parse_xml(b"<VTKFile type=\"PolyData\"><PolyData/></VTKFile>")
            .err()
            .unwrap();
        assert!(e.contains("'PolyData': a mesh"), "{e}");
        let e = parse_xml(b"<a/>").err().unwrap();
        assert!(e.contains("no VTKFile"), "{e}");
        let cells = xml(whole, "").replace(
            "<PointData Scalars=\"s\"></PointData>",
            "<CellData>\n<DataArray type=\"UInt8\" Name=\"c\" format=\"ascii\">1</DataArray>\
             </CellData>",
        );
        let e = parse_xml(cells.as_bytes()).err().unwrap();
        assert!(e.contains("CellData only"), "{e}");
        let two = xml(whole, ASCII).replace("</Piece>", "</Piece><Piece/>");
        assert!(parse_xml(two.as_bytes())
            .err()
            .unwrap()
            .contains("several Pieces"));
    }

    #[test]
    fn appended_data_is_split_from_the_xml() {
        let mut file = b"<VTKFile type=\"ImageData\"><ImageData WholeExtent=\"0 0 0 0 0 1\">\
            <Piece><PointData><DataArray type=\"Int16\" Name=\"a\" format=\"appended\" \
            offset=\"6\"/></PointData></Piece></ImageData>\n<AppendedData encoding=\"raw\">\n  _"
            .to_vec();
        // Another array first (count 2: 2 bytes), then ours: count 4, values 7 and −2.
        file.extend_from_slice(&[2, 0, 0, 0, 9, 9, 4, 0, 0, 0, 7, 0, 0xfe, 0xff]);
        file.extend_from_slice(b"\n</AppendedData></VTKFile>");
        let vti = parse_xml(&file).unwrap();
        assert!(matches!(vti.data, Stored::Appended { offset: 6, .. }));
        assert_eq!(read_samples(&vti, 4).unwrap(), [7.0, -2.0]);
    }

    #[test]
    fn base64_of_a_header_and_its_data_encoded_apart_or_together() {
        let header = 4u32.to_le_bytes();
        let data = [1u8, 2, 3, 4];
        let apart = format!("{}{}", BASE64.encode(header), BASE64.encode(data));
        let together = BASE64.encode([header, data].concat());
        assert!(apart.contains("==") && apart != together);
        for text in [apart, together] {
            let mut blob = Blob::Base64(Base64::new(text.as_bytes()));
            let bytes = read_blob(&mut blob, Layout::default(), 4).unwrap();
            assert_eq!(&*bytes, &data, "{text}");
        }
    }

    #[test]
    fn zlib_blocks_are_inflated_no_further_than_needed() {
        use std::io::Write;
        let zlib = |b: &[u8]| {
            let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::fast());
            e.write_all(b).unwrap();
            e.finish().unwrap()
        };
        let data: Vec<u8> = (0..10).collect();
        let (a, b) = (zlib(&data[..6]), zlib(&data[6..]));
        let layout = Layout {
            header64: true,
            zlib: true,
            ..Layout::default()
        };
        let mut bytes = Vec::new();
        for w in [2u64, 6, 4, a.len() as u64, b.len() as u64] {
            bytes.extend_from_slice(&w.to_le_bytes());
        }
        bytes.extend_from_slice(&a);
        bytes.extend_from_slice(&b);
        let mut blob = Blob::Raw(&bytes);
        let got = read_blob(&mut blob, layout, 10).unwrap();
        assert_eq!(&*got, &data);
        // A block count past the file, and a cut block, are errors.
        let mut huge = bytes.clone();
        huge[..8].copy_from_slice(&u64::MAX.to_le_bytes());
        let e = read_blob(&mut Blob::Raw(&huge), layout, 10).unwrap_err();
        assert!(e.contains("more than the file holds"), "{e}");
        let cut = &bytes[..bytes.len() - 3];
        let e = read_blob(&mut Blob::Raw(cut), layout, 10).unwrap_err();
        assert!(e.contains("truncated"), "{e}");
    }
}
