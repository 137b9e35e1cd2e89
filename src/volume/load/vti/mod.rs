//! VTK XML image data (`.vti`, `<VTKFile type="ImageData">`, feature `vti`): one `Piece`, its
//! `PointData` scalar array (the one `Scalars` names, else the first single-component one) as
//! `ascii`, `binary` (base64) or `appended` (`raw` or `base64`) data, either byte order, UInt32
//! or UInt64 headers, uncompressed or zlib blocks (`vtkZLibDataCompressor`). VTK's world has no
//! patient frame: it is shown as ParaView shows it (x right, y up, z toward the viewer), so the
//! voxel axes point along the `Direction` matrix's columns (docs/VOLUMES.md "Where a volume
//! is"); without a `Direction` they stay as they are.

use std::borrow::Cow;
use std::path::Path;

use glam::Mat3;
use quick_xml::events::{BytesStart, Event};

mod data;
mod values;

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::Volume;
pub(in crate::volume::load) use data::ascii_values;
use data::read_samples;
pub(in crate::volume::load) use values::place_axes;
use values::{array_type, attribute, extent, numbers};

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

#[cfg(test)]
mod tests;
