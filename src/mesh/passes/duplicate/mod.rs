//! The mesh duplication methods: every view's copy of the mesh in one draw, the way engines
//! without this crate's single pass render multi-view images (the baselines it must beat).
//!
//! - [`MeshTiled`] (de Sorbier et al.): instanced per view into the tiles of one quilt atlas
//!   with one depth buffer (`wgsl/mesh/tiled.wgsl`, `tiled_discard.wgsl`).
//! - [`MeshLayered`] (Beck et al.): multiview into texture-array layers with per-layer depth
//!   (`wgsl/mesh/layered.wgsl`); one pass per layer where the adapter has no multiview.
//! - [`MeshMrt`] (de Sorbier, Nozick & Biri): ≤ 8 views per draw into multiple render targets
//!   sharing one depth buffer (`wgsl/mesh/mrt.wgsl`).
//!
//! All of them transform and shade with `wgsl/mesh/shared/view_vertex.wgsl`, the N-pass's
//! code, and take their cameras from [`MultiViewCamera::view_uniform`].

mod layered;
mod mrt;
mod tiled;

pub use layered::MeshLayered;
pub use mrt::MeshMrt;
pub use tiled::MeshTiled;

use std::num::NonZeroU32;
use std::ops::Range;

pub use crate::render::batches::batches;

use bytemuck::Zeroable;

use crate::camera::{MultiViewCamera, ViewUniform};
use crate::display::MAX_VIEWS;
use crate::error::Result;
use crate::gpu::pass_params::{constants_buffer, PassParams};
use crate::mesh::MeshBuffers;
use crate::render::view_layers::nearest_depth_test;

/// The views one pass of the layered and MRT methods draws.
/// Keep in sync with `ViewBatch` in wgsl/mesh/shared/view_vertex.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct ViewBatch {
    /// First view of the pass.
    pub first: u32,
    /// Views in the pass.
    pub count: u32,
    _pad: [u32; 2],
}
const _: () = assert!(std::mem::size_of::<ViewBatch>() == 16);
crate::shader::gpu_layout!(ViewBatch, "ViewBatch", [first, count]);

impl ViewBatch {
    fn of(range: &Range<u32>) -> Self {
        Self {
            first: range.start,
            count: range.len() as u32,
            _pad: [0; 2],
        }
    }
}

/// Bytes of the per-view camera array (`array<View, MAX_VIEWS>` in the shaders).
const VIEWS_BYTES: u64 = MAX_VIEWS as u64 * std::mem::size_of::<ViewUniform>() as u64;

/// Every view's camera of `camera`, in a uniform buffer of this frame's own
/// (`src/gpu/pass_params.rs` says why not a queue write).
pub(crate) fn views_buffer(device: &wgpu::Device, camera: &MultiViewCamera) -> wgpu::Buffer {
    let mut views = vec![ViewUniform::zeroed(); MAX_VIEWS as usize];
    for (i, view) in views.iter_mut().enumerate().take(camera.views as usize) {
        *view = camera.view_uniform(camera.view_offset(i as u32));
    }
    constants_buffer(
        device,
        "duplicated views",
        wgpu::BufferUsages::UNIFORM,
        bytemuck::cast_slice(&views),
    )
}

/// The group-layout entry of [`views_buffer`] at `binding`.
pub(crate) fn views_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: wgpu::BufferSize::new(VIEWS_BYTES),
        },
        count: None,
    }
}

/// The layered and MRT methods' group 1: every view's camera and, per pass, its batch of
/// views (dynamic offset), for passes of at most `max_per_pass` views.
pub(crate) struct BatchedViews {
    pub max_per_pass: u32,
    pub layout: wgpu::BindGroupLayout,
    batch: PassParams<ViewBatch>,
    label: &'static str,
}

/// One frame's batches and the group that binds them.
pub(crate) struct BoundBatches {
    pub passes: Vec<Range<u32>>,
    pub group: wgpu::BindGroup,
}

impl BatchedViews {
    pub fn new(device: &wgpu::Device, label: &'static str, max_per_pass: u32) -> Self {
        let stages = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = crate::gpu::pipeline::bind_group_layout(
            device,
            label,
            &[
                views_entry(0),
                PassParams::<ViewBatch>::layout_entry(1, stages),
            ],
        );
        Self {
            max_per_pass,
            layout,
            batch: PassParams::new(device, label),
            label,
        }
    }

    /// This frame's passes over `camera`'s views and their group (new buffers of the frame's
    /// own, no queue writes).
    pub fn bind(&mut self, device: &wgpu::Device, camera: &MultiViewCamera) -> BoundBatches {
        let passes = batches(camera.views, self.max_per_pass);
        let params: Vec<ViewBatch> = passes.iter().map(ViewBatch::of).collect();
        self.batch.write(device, &params);
        let views = views_buffer(device, camera);
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(self.label),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: views.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: self.batch.binding(),
                },
            ],
        });
        BoundBatches { passes, group }
    }

    /// The dynamic offset of pass `i`'s batch.
    pub fn offset(&self, i: usize) -> u32 {
        self.batch.offset(i)
    }
}

/// The shading a mesh pipeline is built for: its fragment entry point and whether the mesh
/// is textured (the `TEXTURED` override of wgsl/mesh/shared/texture.wgsl: off, a software
/// rasteriser pays nothing for the untaken texture fetches).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Shading {
    pub fragment: &'static str,
    pub textured: bool,
}

impl Shading {
    /// `fs_main` for `mesh` (textured as it is).
    pub fn of(mesh: &MeshBuffers) -> Self {
        Self {
            fragment: "fs_main",
            textured: mesh.textured,
        }
    }
}

/// A pipeline drawing `MeshBuffers` with `module`'s `vs_main` and `shading`'s fragment entry
/// into `targets`, with the nearest-depth test every mesh pass uses (and `multiview` layers, if
/// any). The N-pass and the duplication methods all build theirs here.
pub(crate) fn mesh_pipeline(
    device: &wgpu::Device,
    label: &str,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    targets: &[Option<wgpu::ColorTargetState>],
    multiview_mask: Option<NonZeroU32>,
    shading: Shading,
) -> Result<wgpu::RenderPipeline> {
    let constants = [("TEXTURED", shading.textured as u32 as f64)];
    crate::gpu::checked(device, &format!("building the {label} pipeline"), || {
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(label),
            layout: Some(layout),
            vertex: wgpu::VertexState {
                module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(MeshBuffers::vertex_layout())],
            },
            // No culling: OBJ winding is not reliable; shading is two-sided.
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: Some(nearest_depth_test()),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module,
                entry_point: Some(shading.fragment),
                compilation_options: crate::gpu::pipeline::compilation(&constants),
                targets,
            }),
            multiview_mask,
            cache: None,
        })
    })
}

/// Record the mesh's vertex and index buffers and draw `instances` copies of it.
pub(crate) fn draw_mesh(pass: &mut wgpu::RenderPass<'_>, mesh: &MeshBuffers, instances: u32) {
    pass.set_vertex_buffer(0, mesh.vertices.slice(..));
    pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
    pass.draw_indexed(0..mesh.index_count, 0, 0..instances);
}
