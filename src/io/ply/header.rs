//! The PLY header: format, elements and their typed properties, and where the body starts.

/// Longest header accepted (real headers are a few hundred bytes).
const MAX_HEADER: usize = 1 << 16;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Format {
    Ascii,
    LittleEndian,
    BigEndian,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Scalar {
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

    pub(crate) fn size(self) -> usize {
        match self {
            Self::I8 | Self::U8 => 1,
            Self::I16 | Self::U16 => 2,
            Self::I32 | Self::U32 | Self::F32 => 4,
            Self::F64 => 8,
        }
    }

    /// Full scale of a colour stored in this type (1 for floats).
    pub(crate) fn color_scale(self) -> f64 {
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

    pub(crate) fn decode(self, bytes: &[u8], format: Format) -> f64 {
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
pub(crate) struct Property {
    pub(crate) name: String,
    pub(crate) value: Scalar,
    /// `Some(count type)` for list properties.
    pub(crate) list: Option<Scalar>,
}

#[derive(Clone, Debug)]
pub(crate) struct Element {
    pub(crate) name: String,
    pub(crate) count: usize,
    pub(crate) properties: Vec<Property>,
}

/// What the header says: the body's format, its elements in order, and where it starts.
pub(crate) struct Header {
    pub(crate) format: Format,
    pub(crate) elements: Vec<Element>,
    pub(crate) body_start: usize,
}

/// Parse the header at the start of `bytes`.
pub(crate) fn parse_header(bytes: &[u8]) -> std::result::Result<Header, String> {
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
                    other => {
                        return Err(format!(
                            "unknown format {other}",
                            other = crate::error::quote(other)
                        ))
                    }
                })
            }
            ["element", name, count] => elements.push(Element {
                name: name.to_string(),
                count: count.parse().map_err(|_| {
                    format!(
                        "element {name} has a bad count {count}",
                        name = crate::error::quote(name),
                        count = crate::error::quote(count)
                    )
                })?,
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
            _ => {
                return Err(format!(
                    "unexpected header line {line}",
                    line = crate::error::quote(line)
                ))
            }
        }
    }
    Ok(Header {
        format: format.ok_or("header has no 'format' line")?,
        elements,
        body_start,
    })
}

fn scalar(name: &str) -> std::result::Result<Scalar, String> {
    Scalar::parse(name).ok_or_else(|| {
        format!(
            "unknown property type {name}",
            name = crate::error::quote(name)
        )
    })
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
