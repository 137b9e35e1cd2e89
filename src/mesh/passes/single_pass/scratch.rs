//! Scratch resources of the single-pass mesh renderer, sized by the frame and the mesh; each is
//! allocated only for the visibility mode that uses it, after checking the adapter's limits.

use super::pipelines::{Layouts, TRIANGLE_ID_FORMAT};
use super::Visibility;
use crate::advice::{Advice, Setting};
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::gpu::check_size_2d;
use crate::gpu::gpu_buffer::GpuBuffer;
use crate::gpu::texture::{cached_texture_2d, Texture2d};
use crate::mesh::MeshBuffers;
use crate::render::view_layers::DEPTH_FORMAT;
use crate::render::Made;

/// Bytes per triangle of `EyeTriangle` (checked against naga by `src/shader.rs`'s tests) and
/// of a covering rectangle (a `vec4<f32>`, wgsl/mesh/shared/cover_data.wgsl).
pub(crate) const EYE_TRIANGLE_BYTES: u64 = 48;
const RECT_BYTES: u64 = 16;
/// Bytes per subpixel of the atomic nearest-hit keys.
const KEY_BYTES: u64 = 8;
/// Compute visibility: the large triangles' list shares the rectangles' buffer (unused there):
/// a 16-byte header, then 16 bytes per triangle (wgsl/mesh/shared/large_triangles.wgsl).
pub(super) const LARGE_HEADER_BYTES: u64 = 16;
const LARGE_ENTRY_BYTES: u64 = 16;
/// The large triangles' indirect dispatch: x, y, z workgroups (and padding).
pub(super) const LARGE_DISPATCH_BYTES: u64 = 16;

pub(super) struct Scratch {
    eye_triangles: GpuBuffer,
    rects: GpuBuffer,
    depth: Option<Texture2d>,
    triangle_ids: Option<Texture2d>,
    /// Atomic modes only (allocated on first use).
    keys: Option<GpuBuffer>,
    /// Compute visibility only: the large triangles' indirect dispatch.
    large_dispatch: Option<GpuBuffer>,
}

impl Scratch {
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            eye_triangles: GpuBuffer::new(device, "eye triangles", wgpu::BufferUsages::STORAGE),
            rects: GpuBuffer::new(
                device,
                "cover rects",
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            ),
            depth: None,
            triangle_ids: None,
            keys: None,
            large_dispatch: None,
        }
    }
}

/// Bind groups of one frame.
pub(super) struct Groups {
    pub mesh: wgpu::BindGroup,
    pub cover_compute: wgpu::BindGroup,
    /// Atomic mode: keys for the geometry pass (compute: for the large triangles' pass).
    pub keys_write: Option<wgpu::BindGroup>,
    /// Compute visibility: keys and the large triangles' dispatch (the per-triangle pass).
    pub keys_dispatch: Option<wgpu::BindGroup>,
    /// Compute visibility: the mesh, eye triangles and the large triangles' list (their pass).
    pub large: Option<wgpu::BindGroup>,
    /// Exact modes: what the resolve pass reads (triangle ids or keys).
    pub visible: Option<wgpu::BindGroup>,
}

impl Scratch {
    /// Make sure every resource `visibility` needs exists for `frame` and `triangles`.
    pub fn prepare(
        &mut self,
        device: &wgpu::Device,
        visibility: Visibility,
        frame: &Frame,
        triangles: u32,
    ) -> Result<()> {
        let triangles = triangles as u64;
        let what = |buffer| move || format!("single-pass {buffer} bytes ({triangles} triangles)");
        self.eye_triangles.ensure(
            device,
            what("per-triangle buffer"),
            triangles * EYE_TRIANGLE_BYTES,
        )?;
        let rect_bytes =
            (triangles * RECT_BYTES).max(LARGE_HEADER_BYTES + triangles * LARGE_ENTRY_BYTES);
        self.rects
            .ensure(device, what("cover rectangle"), rect_bytes)?;
        let k = frame.display.views_per_pixel();
        let [w, h] = frame.size;
        match visibility {
            Visibility::Fast => {
                cached_texture_2d(
                    &mut self.depth,
                    device,
                    "single-pass depth",
                    frame.size,
                    DEPTH_FORMAT,
                    wgpu::TextureUsages::RENDER_ATTACHMENT,
                )?;
            }
            Visibility::Exact => {
                // K·W subpixel columns: a wide frame can pass the size check and fail here,
                // said in the frame's pixels (the caller's), not in the columns.
                Error::check_subpixel_width(
                    device,
                    frame.size,
                    k,
                    Setting::Visibility(Visibility::Exact),
                    Advice::from(Setting::Visibility(Visibility::Fast))
                        .then_text(", or ")
                        .then(Setting::Visibility(Visibility::Compute))
                        .then_text(" where the adapter has 64-bit atomics"),
                )?;
                let wide = [w.saturating_mul(k), h];
                check_size_2d(device, wide[0], wide[1])?;
                cached_texture_2d(
                    &mut self.depth,
                    device,
                    "subpixel depth",
                    wide,
                    DEPTH_FORMAT,
                    wgpu::TextureUsages::RENDER_ATTACHMENT,
                )?;
                cached_texture_2d(
                    &mut self.triangle_ids,
                    device,
                    "subpixel triangle ids",
                    wide,
                    TRIANGLE_ID_FORMAT,
                    wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
                )?;
            }
            Visibility::Atomic | Visibility::Compute => {
                let bytes = w as u64 * h as u64 * k as u64 * KEY_BYTES;
                let usage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
                self.keys
                    .get_or_insert_with(|| GpuBuffer::new(device, "nearest keys", usage))
                    .ensure(
                        device,
                        || format!("nearest-hit key bytes for {w}x{h}"),
                        bytes,
                    )?;
                if visibility == Visibility::Compute {
                    let usage = wgpu::BufferUsages::STORAGE
                        | wgpu::BufferUsages::INDIRECT
                        | wgpu::BufferUsages::COPY_DST;
                    self.large_dispatch
                        .get_or_insert_with(|| {
                            GpuBuffer::new(device, "large triangles' dispatch", usage)
                        })
                        .ensure(
                            device,
                            || "the large triangles' dispatch".to_string(),
                            LARGE_DISPATCH_BYTES,
                        )?;
                }
            }
        }
        Ok(())
    }

    /// The rectangles' buffer (compute visibility: the large triangles' list).
    pub fn rects_buffer(&self) -> &wgpu::Buffer {
        self.rects.buffer()
    }

    pub fn large_dispatch_buffer(&self) -> Option<&GpuBuffer> {
        self.large_dispatch.as_ref()
    }

    pub fn depth_view(&self) -> Option<&wgpu::TextureView> {
        self.depth.as_ref().map(|t| &t.view)
    }

    pub fn triangle_ids_view(&self) -> Result<&wgpu::TextureView> {
        Ok(&self
            .triangle_ids
            .made("the exact visibility's triangle ids")?
            .view)
    }

    /// The buffers the cover pass writes and the later passes read.
    pub fn cover_buffers(&self) -> [&wgpu::Buffer; 2] {
        [self.eye_triangles.buffer(), self.rects.buffer()]
    }

    pub fn keys_buffer(&self) -> Option<&GpuBuffer> {
        self.keys.as_ref()
    }

    /// Bind groups for this frame (cheap to create; the buffers behind them are cached).
    pub fn bind_groups(
        &self,
        device: &wgpu::Device,
        layouts: &Layouts,
        visibility: Visibility,
        mesh: &MeshBuffers,
    ) -> Result<Groups> {
        let mesh_resources = || {
            vec![
                mesh.vertices.as_entire_binding(),
                mesh.indices.as_entire_binding(),
                self.eye_triangles.binding(),
                self.rects.binding(),
            ]
        };
        let group =
            |label, layout: &wgpu::BindGroupLayout, resources: Vec<wgpu::BindingResource>| {
                let entries: Vec<wgpu::BindGroupEntry> = resources
                    .into_iter()
                    .enumerate()
                    .map(|(i, resource)| wgpu::BindGroupEntry {
                        binding: i as u32,
                        resource,
                    })
                    .collect();
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some(label),
                    layout,
                    entries: &entries,
                })
            };
        let keys = || -> Result<_> {
            Ok(self
                .keys
                .made("the atomic visibility's nearest keys")?
                .binding())
        };
        let (keys_write, visible) = match visibility {
            Visibility::Fast => (None, None),
            Visibility::Exact => {
                let view = wgpu::BindingResource::TextureView(self.triangle_ids_view()?);
                (
                    None,
                    Some(group("triangle ids", &layouts.triangle_ids, vec![view])),
                )
            }
            Visibility::Atomic | Visibility::Compute => (
                Some(group("nearest keys", &layouts.keys_write, vec![keys()?])),
                Some(group("nearest keys", &layouts.keys_read, vec![keys()?])),
            ),
        };
        let (keys_dispatch, large) = match (visibility, &self.large_dispatch) {
            (Visibility::Compute, Some(dispatch)) => (
                Some(group(
                    "nearest keys + large dispatch",
                    &layouts.keys_dispatch,
                    vec![keys()?, dispatch.binding()],
                )),
                Some(group("large triangles", &layouts.large, mesh_resources())),
            ),
            _ => (None, None),
        };
        Ok(Groups {
            keys_dispatch,
            large,
            mesh: group("mesh + cover data", &layouts.mesh, mesh_resources()),
            cover_compute: group(
                "mesh cover compute",
                &layouts.cover_compute,
                mesh_resources(),
            ),
            keys_write,
            visible,
        })
    }
}
