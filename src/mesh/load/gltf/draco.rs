//! `KHR_draco_mesh_compression`: a primitive whose geometry is one Draco stream in a buffer
//! view, decoded by `draco-core` (a pure-Rust decoder, tested by its authors against the C++
//! Draco's files and malformed streams). The stream's attributes are named by the extension's
//! `attributes` map (glTF semantic → Draco unique id); its decoded size is bounded by the
//! memory budget before it is allocated (`DecodeLimits`).

use draco_core::{DataType, DecodeLimits, DecoderBuffer, MeshDecoder, PointAttribute, PointIndex};
use glam::Vec3;

/// The extension of `primitive`, if it has one: its buffer view and its attribute map.
pub(super) struct Compressed {
    view: usize,
    attributes: serde_json::Map<String, serde_json::Value>,
}

impl Compressed {
    pub fn of(primitive: &gltf::Primitive) -> Option<Self> {
        let ext = primitive.extension_value("KHR_draco_mesh_compression")?;
        Some(Self {
            view: ext["bufferView"].as_u64()? as usize,
            attributes: ext["attributes"].as_object()?.clone(),
        })
    }

    /// The decoded primitive: positions, normals, colours, texture coordinate set `set`, and
    /// triangle indices.
    pub fn decode(
        &self,
        root: &gltf::json::Root,
        buffers: &[std::borrow::Cow<'_, [u8]>],
        set: Option<u32>,
    ) -> Result<super::Part, String> {
        let fail =
            |reason: String| format!("its Draco stream (buffer view {}): {reason}", self.view);
        let view = root
            .buffer_views
            .get(self.view)
            .ok_or_else(|| fail("does not exist".into()))?;
        let bytes = super::uri::view_bytes(view, buffers)
            .ok_or_else(|| fail("runs past its buffer".into()))?;
        let budget = crate::budget::Budget::current().max();
        let limits = DecodeLimits::default().with_max_decoded_bytes(budget / 4);
        let mut stream = DecoderBuffer::new(bytes).with_limits(limits);
        let mut mesh = draco_core::Mesh::new();
        MeshDecoder::new()
            .decode(&mut stream, &mut mesh)
            .map_err(|e| fail(e.to_string()))?;
        let n = mesh.num_points();
        let attribute = |semantic: &str| {
            let id = self.attributes.get(semantic)?.as_u64()?;
            mesh.attribute_by_unique_id(u32::try_from(id).ok()?)
        };
        let positions = attribute("POSITION").ok_or_else(|| fail("no POSITION".into()))?;
        let positions: Vec<Vec3> = values::<3>(positions, n)
            .map_err(|e| fail(format!("POSITION: {e}")))?
            .into_iter()
            .map(Vec3::from)
            .collect();
        let normals = attribute("NORMAL")
            .and_then(|a| values::<3>(a, n).ok())
            .map(|v| v.into_iter().map(Vec3::from).collect());
        let colors = attribute("COLOR_0").and_then(|a| match a.num_components() {
            4 => values::<4>(a, n).ok(),
            _ => values::<3>(a, n)
                .ok()
                .map(|v| v.into_iter().map(|[r, g, b]| [r, g, b, 1.0]).collect()),
        });
        let tex_coords = set
            .and_then(|set| attribute(&format!("TEXCOORD_{set}")))
            .and_then(|a| values::<2>(a, n).ok());
        let indices: Vec<u32> = mesh.faces().iter().flatten().map(|p| p.0).collect();
        if let Some(&bad) = indices.iter().find(|&&i| i as usize >= n) {
            return Err(fail(format!("index {bad} beyond its {n} points")));
        }
        Ok(super::Part {
            positions,
            normals,
            colors,
            tex_coords,
            indices,
        })
    }
}

/// The `N`-component values of `attribute` for points `0..n`, as floats (normalised integers
/// to 0..1).
fn values<const N: usize>(attribute: &PointAttribute, n: usize) -> Result<Vec<[f32; N]>, String> {
    let components = attribute.num_components() as usize;
    if components < N {
        return Err(format!("{components} components, {N} wanted"));
    }
    let (size, scale) = match (attribute.data_type(), attribute.normalized()) {
        (DataType::Float32, _) => (4, 1.0),
        (DataType::Uint8, true) => (1, 1.0 / 255.0),
        (DataType::Uint16, true) => (2, 1.0 / 65535.0),
        (other, normalized) => {
            return Err(format!(
                "{other:?} values (normalised: {normalized}) are not read"
            ))
        }
    };
    let data = attribute.buffer().data();
    let stride = attribute.byte_stride().max(0) as usize;
    (0..n)
        .map(|p| {
            let value = attribute.mapped_index(PointIndex(p as u32)).0 as usize;
            let at = value
                .checked_mul(stride)
                .filter(|&at| at + N * size <= data.len())
                .ok_or_else(|| format!("point {p}'s value is outside the decoded data"))?;
            Ok(std::array::from_fn(|c| {
                let b = &data[at + c * size..];
                match size {
                    4 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
                    2 => f32::from(u16::from_le_bytes([b[0], b[1]])) * scale,
                    _ => f32::from(b[0]) * scale,
                }
            }))
        })
        .collect()
}
