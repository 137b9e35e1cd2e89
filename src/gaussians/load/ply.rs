//! graphdeco's 3DGS PLY (what `train.py` saves as `point_cloud.ply`): a binary little-endian
//! `vertex` element of float properties, read by name in any order — `x y z`, `f_dc_0..2`,
//! `f_rest_*` (channel-major: every R coefficient 1.., then G, then B; 0, 9, 24 or 45 of them
//! for SH degree 0 to 3), `opacity` (a logit), `scale_0..2` (logs), `rot_0..3` (an
//! unnormalised w, x, y, z quaternion). Normals and other scalar properties are skipped. The
//! header is the point clouds' PLY header (`crate::io::ply::header`).

use std::path::Path;

use glam::Vec3;

use super::{checked, error, rotation};
use crate::error::Result;
use crate::gaussians::{check_budget, coefficients, sigmoid, Gaussians};
use crate::io::ply::header::{parse_header, Element, Format, Scalar};

/// Which Gaussian attribute a vertex property feeds.
#[derive(Clone, Copy, PartialEq)]
enum Slot {
    Position(usize),
    Dc(usize),
    Rest(usize),
    Opacity,
    Scale(usize),
    Rotation(usize),
    Skipped,
}

fn slot(name: &str) -> Slot {
    let indexed = |prefix: &str, n: usize| {
        name.strip_prefix(prefix)
            .and_then(|i| i.parse::<usize>().ok())
            .filter(|&i| i < n && name.len() == prefix.len() + 1)
    };
    match name {
        "x" => Slot::Position(0),
        "y" => Slot::Position(1),
        "z" => Slot::Position(2),
        "opacity" => Slot::Opacity,
        _ => {
            if let Some(i) = indexed("f_dc_", 3) {
                Slot::Dc(i)
            } else if let Some(i) = indexed("scale_", 3) {
                Slot::Scale(i)
            } else if let Some(i) = indexed("rot_", 4) {
                Slot::Rotation(i)
            } else if let Some(i) = name
                .strip_prefix("f_rest_")
                .filter(|i| i == &"0" || !i.starts_with('0'))
                .and_then(|i| i.parse::<usize>().ok())
            {
                Slot::Rest(i)
            } else {
                Slot::Skipped
            }
        }
    }
}

/// The names every 3DGS vertex needs.
const REQUIRED: [&str; 14] = [
    "x", "y", "z", "f_dc_0", "f_dc_1", "f_dc_2", "opacity", "scale_0", "scale_1", "scale_2",
    "rot_0", "rot_1", "rot_2", "rot_3",
];

/// A graphdeco 3DGS PLY file's `bytes` (`path` names it in errors).
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<Gaussians> {
    let fail = |reason: String| error(path, reason);
    let header = parse_header(bytes).map_err(fail)?;
    if header.format != Format::LittleEndian {
        let name = match header.format {
            Format::Ascii => "ascii",
            _ => "binary_big_endian",
        };
        return Err(fail(format!(
            "a {name} PLY: 3DGS PLYs are binary_little_endian (as graphdeco's trainer writes them)"
        )));
    }
    let position = header
        .elements
        .iter()
        .position(|e| e.name == "vertex")
        .ok_or_else(|| fail("no 'vertex' element".into()))?;
    // Elements before the vertices are skipped by their fixed size.
    let mut offset = 0usize;
    for element in &header.elements[..position] {
        let size = record_size(element)
            .and_then(|s| s.checked_mul(element.count))
            .ok_or_else(|| {
                fail(format!(
                    "element '{}' before 'vertex' has list properties or an impossible size",
                    element.name
                ))
            })?;
        offset = offset.saturating_add(size);
    }
    let vertex = &header.elements[position];
    let layout = Layout::of(vertex).map_err(fail)?;
    let n = vertex.count;
    let body = bytes.get(header.body_start..).unwrap_or_default();
    let have = body.len().saturating_sub(offset);
    let need = n
        .checked_mul(layout.stride)
        .filter(|&need| need <= have && offset <= body.len());
    let Some(need) = need else {
        return Err(fail(format!(
            "truncated: the header declares {n} Gaussians of {} bytes, but {have} bytes are left \
             for them",
            layout.stride
        )));
    };
    check_budget(n as u64, layout.degree, 0).map_err(|e| fail(e.to_string()))?;
    let k = coefficients(layout.degree);
    let mut g = Gaussians {
        positions: Vec::with_capacity(n),
        scales: Vec::with_capacity(n),
        rotations: Vec::with_capacity(n),
        opacities: Vec::with_capacity(n),
        sh_degree: layout.degree,
        sh: Vec::with_capacity(n * k),
    };
    let records = body[offset..offset + need].chunks_exact(layout.stride.max(1));
    for (i, record) in records.enumerate() {
        let f = |at: usize| f32::from_le_bytes(record[at..at + 4].try_into().expect("4 bytes"));
        let v3 = |at: [usize; 3]| Vec3::new(f(at[0]), f(at[1]), f(at[2]));
        g.positions.push(v3(layout.position));
        g.scales.push(v3(layout.scale).map(f32::exp));
        let [w, x, y, z] = layout.rotation.map(f);
        g.rotations.push(rotation(i, w, x, y, z).map_err(fail)?);
        g.opacities.push(sigmoid(f(layout.opacity)));
        g.sh.push(layout.dc.map(f));
        // f_rest_j is channel j / (k − 1), coefficient 1 + j % (k − 1).
        for coefficient in 0..k - 1 {
            g.sh.push([0, 1, 2].map(|c| f(layout.rest[c * (k - 1) + coefficient])));
        }
    }
    if g.positions.len() != n {
        // Only a zero stride (no properties) gets here: `Layout::of` needs x, y and z.
        return Err(fail("the vertex element has no properties".into()));
    }
    checked(g, path)
}

/// Byte offsets of the properties a 3DGS record holds.
struct Layout {
    stride: usize,
    degree: u32,
    position: [usize; 3],
    dc: [usize; 3],
    rest: Vec<usize>,
    opacity: usize,
    scale: [usize; 3],
    rotation: [usize; 4],
}

impl Layout {
    fn of(vertex: &Element) -> std::result::Result<Self, String> {
        let (mut position, mut dc, mut scale, mut rotation) =
            ([None; 3], [None; 3], [None; 3], [None; 4]);
        let mut opacity = None;
        let mut rest: Vec<(usize, usize)> = Vec::new();
        let mut at = 0usize;
        for (i, p) in vertex.properties.iter().enumerate() {
            if vertex.properties[..i].iter().any(|q| q.name == p.name) {
                return Err(format!("vertex property '{}' appears twice", p.name));
            }
            if p.list.is_some() {
                return Err(format!(
                    "vertex property '{}' is a list: a 3DGS PLY's properties are scalars",
                    p.name
                ));
            }
            let s = slot(&p.name);
            if s != Slot::Skipped && p.value != Scalar::F32 {
                return Err(format!(
                    "vertex property '{}' is not float ({:?}): a 3DGS PLY's properties are f32",
                    p.name, p.value
                ));
            }
            match s {
                Slot::Position(a) => position[a] = Some(at),
                Slot::Dc(a) => dc[a] = Some(at),
                Slot::Scale(a) => scale[a] = Some(at),
                Slot::Rotation(a) => rotation[a] = Some(at),
                Slot::Opacity => opacity = Some(at),
                Slot::Rest(j) => rest.push((j, at)),
                Slot::Skipped => {}
            }
            at += p.value.size();
        }
        let located = [
            &position[..],
            &dc[..],
            &[opacity],
            &scale[..],
            &rotation[..],
        ]
        .concat();
        let missing: Vec<&str> = REQUIRED
            .iter()
            .zip(&located)
            .filter(|(_, at)| at.is_none())
            .map(|(name, _)| *name)
            .collect();
        if !missing.is_empty() {
            return Err(format!(
                "not a 3DGS PLY: the vertex element lacks {} (a point cloud's PLY is read as \
                 points)",
                missing.join(", ")
            ));
        }
        rest.sort_unstable();
        let degree = match rest.len() {
            0 => 0,
            9 => 1,
            24 => 2,
            45 => 3,
            other => {
                return Err(format!(
                    "{other} f_rest properties: SH degree 0, 1, 2 or 3 has 0, 9, 24 or 45"
                ))
            }
        };
        if let Some(j) = rest.iter().enumerate().position(|(i, (j, _))| i != *j) {
            return Err(format!(
                "f_rest_{j} is missing: f_rest_0 to f_rest_{} must all be there",
                rest.len() - 1
            ));
        }
        let found = |at: Option<usize>| at.expect("checked above");
        Ok(Layout {
            stride: at,
            degree,
            position: position.map(found),
            dc: dc.map(found),
            rest: rest.into_iter().map(|(_, at)| at).collect(),
            opacity: found(opacity),
            scale: scale.map(found),
            rotation: rotation.map(found),
        })
    }
}

/// Bytes per entry of an element of scalar properties (`None` with a list property).
fn record_size(element: &Element) -> Option<usize> {
    element
        .properties
        .iter()
        .map(|p| p.list.is_none().then(|| p.value.size()))
        .sum()
}

#[cfg(test)]
mod tests {
    use glam::Quat;

    use super::*;

    use crate::io::ply::{gaussian_properties, GAUSSIAN_PROPERTIES};
    fn header(properties: &[&str], count: usize) -> Vec<u8> {
        let mut h = format!("ply\nformat binary_little_endian 1.0\nelement vertex {count}\n");
        for p in properties {
            h += &format!("property float {p}\n");
        }
        h += "end_header\n";
        h.into_bytes()
    }

    const BASIC: [&str; 14] = [
        "x", "y", "z", "f_dc_0", "f_dc_1", "f_dc_2", "opacity", "scale_0", "scale_1", "scale_2",
        "rot_0", "rot_1", "rot_2", "rot_3",
    ];

    #[test]
    fn properties_in_any_order() {
        let mut names = BASIC.to_vec();
        names.reverse();
        names.insert(3, "nx");
        let mut bytes = header(&names, 1);
        let value = |name: &str| match name {
            "x" => 1.0f32,
            "y" => 2.0,
            "z" => 3.0,
            "f_dc_1" => 0.5,
            "opacity" => 0.0,
            "scale_1" => 1.0,
            "rot_0" => 2.0,
            _ => 0.0,
        };
        for n in &names {
            bytes.extend(value(n).to_le_bytes());
        }
        let g = parse_ply(&bytes, Path::new("g.ply")).unwrap();
        assert_eq!(g.positions, vec![Vec3::new(1.0, 2.0, 3.0)]);
        assert_eq!(g.sh, vec![[0.0, 0.5, 0.0]]);
        assert_eq!(g.opacities, vec![0.5]);
        assert_eq!(g.scales, vec![Vec3::new(1.0, 1.0f32.exp(), 1.0)]);
        assert_eq!(g.rotations, vec![Quat::IDENTITY]);
    }

    #[test]
    fn the_tell_tale_properties() {
        let head = header(&BASIC, 0);
        assert_eq!(gaussian_properties(&head).unwrap(), GAUSSIAN_PROPERTIES);
        let cloud = header(&["x", "y", "z"], 0);
        assert!(gaussian_properties(&cloud).unwrap().is_empty());
        assert!(gaussian_properties(b"hello").is_err());
    }

    #[test]
    fn slots_by_name() {
        assert!(slot("f_rest_44") == Slot::Rest(44));
        assert!(slot("f_rest_07") == Slot::Skipped);
        assert!(slot("scale_3") == Slot::Skipped);
        assert!(slot("rot_3") == Slot::Rotation(3));
        assert!(slot("f_dc_00") == Slot::Skipped);
    }
}
