//! Bind group layouts and pipelines of the single-pass mesh renderer.

use super::{CoverBounds, MeshSinglePassOptions, Visibility};
use crate::error::Result;
use crate::frame::frame_bind_group_layout;
use crate::gpu::pipeline::{
    bind_group_layout, compilation, fullscreen_pipeline_with, pipeline_layout, storage_entry,
};
use crate::render::pipeline_cache::ShaderModules;
use crate::render::specialize::Specialization;
use crate::render::view_layers::nearest_depth_test;
use crate::target::SPATIAL_FORMAT;

/// Invocations per workgroup of `wgsl/mesh/single_pass_cover.wgsl`.
pub(super) const COVER_WORKGROUP: u32 = 64;
/// Format of the per-subpixel triangle-id target of `Visibility::Exact`.
pub(super) const TRIANGLE_ID_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;

pub(super) struct Layouts {
    pub frame: wgpu::BindGroupLayout,
    /// vertices, indices, eye triangles, cover rects — read-only (geometry and resolve passes).
    pub mesh: wgpu::BindGroupLayout,
    /// The same four, the last two writable (cover compute pass).
    pub cover_compute: wgpu::BindGroupLayout,
    /// Nearest-hit keys, read-write (atomic geometry pass, the large triangles' pass).
    pub keys_write: wgpu::BindGroupLayout,
    /// Nearest-hit keys and the large triangles' dispatch, read-write (compute visibility).
    pub keys_dispatch: wgpu::BindGroupLayout,
    /// The mesh, eye triangles and the large triangles' list, read-only (compute visibility's large pass).
    pub large: wgpu::BindGroupLayout,
    /// Nearest-hit keys, read-only (atomic resolve).
    pub keys_read: wgpu::BindGroupLayout,
    /// Subpixel triangle ids (subpixel resolve).
    pub triangle_ids: wgpu::BindGroupLayout,
    /// The mesh's textures (group 3 of the stages that shade: fast geometry, resolves).
    pub textures: wgpu::BindGroupLayout,
}

impl Layouts {
    pub fn new(device: &wgpu::Device) -> Self {
        let vf = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let cs = wgpu::ShaderStages::COMPUTE;
        let fs = wgpu::ShaderStages::FRAGMENT;
        let layout = |label, entries: &[_]| bind_group_layout(device, label, entries);
        Self {
            frame: frame_bind_group_layout(device),
            mesh: layout(
                "mesh + cover data",
                &[
                    storage_entry(0, true, vf),
                    storage_entry(1, true, vf),
                    storage_entry(2, true, vf),
                    storage_entry(3, true, vf),
                ],
            ),
            cover_compute: layout(
                "mesh cover compute",
                &[
                    storage_entry(0, true, cs),
                    storage_entry(1, true, cs),
                    storage_entry(2, false, cs),
                    storage_entry(3, false, cs),
                ],
            ),
            keys_write: layout(
                "nearest keys (write)",
                &[storage_entry(0, false, fs | wgpu::ShaderStages::COMPUTE)],
            ),
            keys_dispatch: layout(
                "nearest keys + large dispatch",
                &[storage_entry(0, false, cs), storage_entry(1, false, cs)],
            ),
            large: layout(
                "large triangles",
                &[
                    storage_entry(0, true, cs),
                    storage_entry(1, true, cs),
                    storage_entry(2, true, cs),
                    storage_entry(3, true, cs),
                ],
            ),
            keys_read: layout("nearest keys (read)", &[storage_entry(0, true, fs)]),
            triangle_ids: layout(
                "subpixel triangle ids",
                &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: fs,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Uint,
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                }],
            ),
            textures: crate::mesh::texture_buffers::texture_bind_group_layout(device),
        }
    }
}

pub(super) struct Pipelines {
    /// The per-triangle compute pass: covering rectangles, or (compute visibility) the whole
    /// software rasterisation.
    pub compute: wgpu::ComputePipeline,
    pub compute_label: &'static str,
    /// Compute visibility: the large triangles' pass.
    pub large: Option<wgpu::ComputePipeline>,
    /// The hardware geometry pass (none for compute visibility).
    pub geometry: Option<wgpu::RenderPipeline>,
    pub resolve: Option<wgpu::RenderPipeline>,
}

/// The stage files and the colour target of each visibility mode's geometry pass.
fn geometry_stage(visibility: Visibility) -> Option<(&'static str, wgpu::ColorTargetState, bool)> {
    Some(match visibility {
        Visibility::Compute => return None,
        Visibility::Exact => (
            "mesh/single_pass_exact.wgsl",
            TRIANGLE_ID_FORMAT.into(),
            true,
        ),
        // The atomic pass writes only storage; the attachment just gives the pass its size.
        Visibility::Atomic => (
            "mesh/single_pass_atomic.wgsl",
            wgpu::ColorTargetState {
                format: SPATIAL_FORMAT,
                blend: None,
                write_mask: wgpu::ColorWrites::empty(),
            },
            false,
        ),
        // colour · coverage + destination · (1 − coverage): missed subpixels keep their value.
        Visibility::Fast => (
            "mesh/single_pass_fast.wgsl",
            wgpu::ColorTargetState {
                format: SPATIAL_FORMAT,
                blend: Some(wgpu::BlendState {
                    color: wgpu::BlendComponent {
                        src_factor: wgpu::BlendFactor::Src1,
                        dst_factor: wgpu::BlendFactor::OneMinusSrc1,
                        operation: wgpu::BlendOperation::Add,
                    },
                    alpha: wgpu::BlendComponent::REPLACE,
                }),
                write_mask: wgpu::ColorWrites::ALL,
            },
            true,
        ),
    })
}

pub(super) fn build(
    device: &wgpu::Device,
    modules: &mut ShaderModules,
    layouts: &Layouts,
    options: MeshSinglePassOptions,
    spec: Specialization,
    textured: bool,
) -> Result<Pipelines> {
    let paper = (options.bounds == CoverBounds::Paper) as u32 as f64;
    let subpixel_samples = options.visibility == Visibility::Exact && spec.views_per_pixel > 1;
    let padding = if subpixel_samples { 0.5 } else { 1.0 / 16.0 };
    let cover_constants = spec.constants(&[("PAPER_BOUNDS", paper), ("COVER_PADDING_PX", padding)]);
    let clusters = options.clusters.override_value(spec.view_count) as f64;
    let compute_constants = spec.constants(&[("PAPER_BOUNDS", paper), ("VIEW_CLUSTERS", clusters)]);
    let constants = spec.constants(&[]);
    // The stages that shade (fast geometry, resolves) declare TEXTURED; the others do not.
    let shading = spec.constants(&[("TEXTURED", textured as u32 as f64)]);
    let geometry_constants = match options.visibility {
        Visibility::Fast => &shading,
        _ => &constants,
    };

    let layout_of =
        |label, groups: &[Option<&wgpu::BindGroupLayout>]| pipeline_layout(device, label, groups);

    let compute_stage = if options.visibility == Visibility::Compute {
        "mesh/single_pass_compute.wgsl"
    } else {
        "mesh/single_pass_cover.wgsl"
    };
    let keys_write = matches!(options.visibility, Visibility::Atomic | Visibility::Compute)
        .then_some(&layouts.keys_write);
    let compute_keys =
        (options.visibility == Visibility::Compute).then_some(&layouts.keys_dispatch);
    let compute_pipeline = |modules: &mut ShaderModules,
                            stage: &'static str,
                            groups: &[Option<&wgpu::BindGroupLayout>],
                            constants: &[(&str, f64)]|
     -> Result<wgpu::ComputePipeline> {
        Ok(
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(stage),
                layout: Some(&layout_of(stage, groups)),
                module: &modules.get(device, stage)?,
                entry_point: Some("cs_main"),
                compilation_options: compilation(constants),
                cache: None,
            }),
        )
    };
    let compute = compute_pipeline(
        modules,
        compute_stage,
        &[
            Some(&layouts.frame),
            Some(&layouts.cover_compute),
            compute_keys,
        ],
        if options.visibility == Visibility::Compute {
            &compute_constants
        } else {
            &cover_constants
        },
    )?;
    let large = match options.visibility {
        Visibility::Compute => Some(compute_pipeline(
            modules,
            "mesh/single_pass_compute_large.wgsl",
            &[
                Some(&layouts.frame),
                Some(&layouts.large),
                Some(&layouts.keys_write),
            ],
            &compute_constants,
        )?),
        _ => None,
    };

    let geometry = match geometry_stage(options.visibility) {
        None => None,
        Some((stage, target, depth_test)) => {
            let module = modules.get(device, stage)?;
            Some(
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some(stage),
                    layout: Some(&layout_of(
                        stage,
                        &[
                            Some(&layouts.frame),
                            Some(&layouts.mesh),
                            keys_write,
                            // Only the fast pass shades as it rasterises.
                            (options.visibility == Visibility::Fast).then_some(&layouts.textures),
                        ],
                    )),
                    vertex: wgpu::VertexState {
                        module: &module,
                        // Subpixel fragments are many per triangle: flat varyings beat loads there.
                        entry_point: Some(if options.visibility == Visibility::Exact {
                            "vs_cover_flat"
                        } else {
                            "vs_cover"
                        }),
                        compilation_options: compilation(&constants),
                        buffers: &[],
                    },
                    primitive: wgpu::PrimitiveState::default(),
                    depth_stencil: depth_test.then(nearest_depth_test),
                    multisample: Default::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some("fs_main"),
                        compilation_options: compilation(geometry_constants),
                        targets: &[Some(target)],
                    }),
                    multiview_mask: None,
                    cache: None,
                }),
            )
        }
    };

    let resolve_stage = match options.visibility {
        Visibility::Exact => Some(("mesh/single_pass_exact_resolve.wgsl", &layouts.triangle_ids)),
        Visibility::Atomic | Visibility::Compute => {
            Some(("mesh/single_pass_atomic_resolve.wgsl", &layouts.keys_read))
        }
        Visibility::Fast => None,
    };
    let resolve = match resolve_stage {
        Some((stage, visible)) => Some(fullscreen_pipeline_with(
            device,
            stage,
            &modules.get(device, stage)?,
            &[
                Some(&layouts.frame),
                Some(&layouts.mesh),
                Some(visible),
                Some(&layouts.textures),
            ],
            SPATIAL_FORMAT,
            &shading,
        )),
        None => None,
    };
    Ok(Pipelines {
        compute,
        compute_label: compute_stage,
        large,
        geometry,
        resolve,
    })
}
