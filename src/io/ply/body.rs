//! The PLY body: values read in the header's order, ASCII or binary, the elements before
//! `vertex` skipped and the vertex properties decoded into points, every count checked against
//! the bytes present before anything is allocated.

use glam::Vec3;

use super::header::{Element, Format, Property, Scalar};
use super::Vertices;

/// Sequential values of the body, ASCII or binary.
pub(super) trait ValueReader {
    fn next(&mut self, ty: Scalar) -> std::result::Result<f64, String>;
    /// Upper bound on how many values remain (the allocation guard).
    fn remaining_values(&self, smallest: Scalar) -> usize;
}

pub(super) struct BinaryReader<'a> {
    pub(super) bytes: &'a [u8],
    pub(super) at: usize,
    pub(super) format: Format,
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

pub(super) struct AsciiReader<'a> {
    tokens: std::str::SplitAsciiWhitespace<'a>,
    len: usize,
}

impl<'a> AsciiReader<'a> {
    pub(super) fn new(body: &'a [u8]) -> std::result::Result<Self, String> {
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
        token.parse::<f64>().map_err(|_| {
            format!(
                "{token} is not a number",
                token = crate::error::quote(token)
            )
        })
    }

    fn remaining_values(&self, _smallest: Scalar) -> usize {
        // Every value takes at least one character and one separator.
        self.len / 2 + 1
    }
}

/// Read past every entry of `element`.
pub(super) fn skip_element(
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

/// The points of the `vertex` element.
pub(super) fn read_vertices(
    reader: &mut dyn ValueReader,
    element: &Element,
) -> std::result::Result<Vertices, String> {
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
    crate::budget::check_points(n as u64).map_err(|e| e.to_string())?;
    let mut cloud = Vertices {
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

/// The triangles of the `face` element: each polygon's `vertex_indices` (or `vertex_index`)
/// list as a fan from its first corner, every index checked against `vertices`.
pub(super) fn read_faces(
    reader: &mut dyn ValueReader,
    element: &Element,
    vertices: usize,
) -> std::result::Result<Vec<u32>, String> {
    let corners = element
        .properties
        .iter()
        .position(|p| {
            p.list.is_some() && matches!(p.name.as_str(), "vertex_indices" | "vertex_index")
        })
        .ok_or("the face element has no 'vertex_indices' list")?;
    check_count(reader, element)?;
    // A polygon of n corners is 3(n − 2) indices: at most three per corner value the data
    // holds, four bytes each, against the memory budget before any is kept.
    let corner_type = element.properties[corners].value;
    let most = (reader.remaining_values(corner_type) as u64).saturating_mul(3);
    crate::budget::check(
        || format!("a PLY face element of up to {most} triangle corners"),
        most.saturating_mul(4),
    )
    .map_err(|e| e.to_string())?;
    let mut triangles = Vec::new();
    let mut polygon = Vec::new();
    for i in 0..element.count {
        for (j, p) in element.properties.iter().enumerate() {
            if j != corners {
                read_property(reader, p, |_| {}).map_err(|e| format!("face {i}: {e}"))?;
                continue;
            }
            let count_type = p.list.unwrap_or(Scalar::U8);
            let n = reader.next(count_type)?;
            if !(0.0..=1e9).contains(&n) || n.fract() != 0.0 {
                return Err(format!("face {i} has a bad corner count {n}"));
            }
            polygon.clear();
            for _ in 0..n as usize {
                let index = reader.next(p.value)?;
                if !(0.0..vertices as f64).contains(&index) || index.fract() != 0.0 {
                    return Err(format!(
                        "face {i}: corner {index} is not one of the {vertices} vertices"
                    ));
                }
                polygon.push(index as u32);
            }
        }
        // A polygon of n corners is n − 2 triangles; points and lines have none.
        for k in 1..polygon.len().saturating_sub(1) {
            triangles.extend([polygon[0], polygon[k], polygon[k + 1]]);
        }
    }
    Ok(triangles)
}
