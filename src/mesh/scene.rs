//! Mesh data on the GPU: one vertex buffer and one index buffer, usable both as vertex/index
//! input (N-pass, single view) and as storage for vertex pulling (single pass), and the
//! textures' bind group (src/mesh/texture_buffers.rs).

use bytemuck::{Pod, Zeroable};
use wgpu::util::DeviceExt;

use super::Mesh;
use crate::error::Result;
use crate::gpu::gpu_buffer::check_storage_bytes;

/// One vertex. Keep in sync with `VertexIn` in `wgsl/mesh/shared/view_vertex.wgsl` (and
/// `MeshVertex`, checked by src/shader.rs's tests).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuVertex {
    /// Position (w unused).
    pub position: [f32; 4],
    /// Normal (w unused).
    pub normal: [f32; 4],
    /// Linear RGBA colour.
    pub color: [f32; 4],
    /// Texture coordinate.
    pub tex_coord: [f32; 2],
    /// Index into the mesh's textures, or [`super::NO_TEXTURE`].
    pub texture: u32,
    /// Keeps the 16-byte alignment of the storage array.
    pub _pad: u32,
}
const _: () = assert!(std::mem::size_of::<GpuVertex>() == 64);
crate::shader::gpu_layout!(
    GpuVertex,
    "MeshVertex",
    [position, normal, color, tex_coord, texture]
);

/// A mesh uploaded to the GPU.
pub struct MeshBuffers {
    /// Vertices ([`GpuVertex`]).
    pub vertices: wgpu::Buffer,
    /// u32 triangle indices.
    pub indices: wgpu::Buffer,
    /// Number of indices.
    pub index_count: u32,
    /// Number of vertices.
    pub vertex_count: u32,
    /// Whether any vertex samples a texture: the `TEXTURED` constant of the shading stages.
    pub textured: bool,
    /// The textures, bound as group 3 by every mesh stage that shades.
    pub textures: super::texture_buffers::TextureBuffers,
    /// The buffers' share of the memory budget.
    _charge: crate::budget::GpuCharge,
}

impl MeshBuffers {
    /// Validate `mesh`, check the buffer sizes against the device limits, upload.
    pub fn new(device: &wgpu::Device, mesh: &Mesh) -> Result<Self> {
        mesh.validate()?;
        let textures = super::texture_buffers::TextureBuffers::new(device, &mesh.textures)?;
        let vertex_bytes = mesh.positions.len() as u64 * std::mem::size_of::<GpuVertex>() as u64;
        let index_bytes = mesh.indices.len() as u64 * 4;
        // The single pass reads both as storage buffers.
        check_storage_bytes(device, "vertex buffer bytes", vertex_bytes)?;
        check_storage_bytes(device, "index buffer bytes", index_bytes)?;
        let textured = !mesh.tex_coords.is_empty();
        let vertices: Vec<GpuVertex> = (0..mesh.positions.len())
            .map(|i| GpuVertex {
                position: mesh.positions[i].extend(1.0).to_array(),
                normal: mesh.normals[i].extend(0.0).to_array(),
                color: mesh.colors[i],
                tex_coord: match textured {
                    true => mesh.tex_coords[i].to_array(),
                    false => [0.0; 2],
                },
                texture: match textured {
                    true => mesh.texture_ids[i],
                    false => super::NO_TEXTURE,
                },
                _pad: 0,
            })
            .collect();
        let storage = wgpu::BufferUsages::STORAGE;
        let charge = crate::budget::charge_gpu(
            || format!("the mesh buffers ({} triangles)", mesh.indices.len() / 3),
            vertex_bytes + index_bytes,
        )?;
        Ok(Self {
            vertices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh vertices"),
                contents: bytemuck::cast_slice(&vertices),
                usage: wgpu::BufferUsages::VERTEX | storage,
            }),
            indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("mesh indices"),
                contents: bytemuck::cast_slice(&mesh.indices),
                usage: wgpu::BufferUsages::INDEX | storage,
            }),
            index_count: mesh.indices.len() as u32,
            vertex_count: mesh.positions.len() as u32,
            textured: mesh.is_textured(),
            textures,
            _charge: charge,
        })
    }

    /// Vertex layout matching [`GpuVertex`] (locations 0 to 4).
    pub fn vertex_layout() -> wgpu::VertexBufferLayout<'static> {
        const ATTRIBUTES: [wgpu::VertexAttribute; 5] = wgpu::vertex_attr_array![
            0 => Float32x4, 1 => Float32x4, 2 => Float32x4, 3 => Float32x2, 4 => Uint32
        ];
        wgpu::VertexBufferLayout {
            array_stride: std::mem::size_of::<GpuVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRIBUTES,
        }
    }
}
