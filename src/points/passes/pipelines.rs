//! Bind group layouts and pipelines of the splat renderer.

use bytemuck::{Pod, Zeroable};

use crate::error::Result;
use crate::frame::frame_bind_group_layout;
use crate::gpu::pass_params::PassParams;
use crate::gpu::pipeline::{
    bind_group_layout, compilation, fullscreen_pipeline_to, multiview_mask, pipeline_layout,
    storage_entry,
};
use crate::render::pipeline_cache::ShaderModules;
use crate::render::specialize::Specialization;
use crate::render::view_layers::nearest_depth_test;
use crate::target::SPATIAL_FORMAT;
use crate::warp::references::REFERENCE_NEARNESS_FORMAT;

/// Invocations per workgroup of `wgsl/points/cover.wgsl`.
pub(super) const COVER_WORKGROUP: u32 = 64;
/// Group image per pixel: packed colour·weight/weight of R, G, B + depth bits.
pub(super) const PIXEL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Uint;
/// Group image per subpixel: packed colour·weight/weight + depth bits.
pub(super) const SUBPIXEL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg32Uint;

/// Per-pass constants. Keep in sync with `struct SplatParams` in `wgsl/points/shared/splat.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct SplatParams {
    /// Smallest camera offset the covering quads must cover.
    pub cover_lo: f32,
    /// Largest camera offset the covering quads must cover.
    pub cover_hi: f32,
    /// Camera offset of every ray when `use_mask` is 0.
    pub fixed_offset: f32,
    /// 1: per-(sub)pixel views from the display mask.
    pub use_mask: u32,
    /// ε of the compositing, eye-depth units.
    pub epsilon: f32,
    /// Group images to composite (the array may hold a spare layer: `ViewLayers`).
    pub groups: u32,
    /// Layer of group g in the group images: `g · group_stride + group_base` (the layered
    /// method keeps N views per group, group-major; everything else 1 and 0).
    pub group_stride: u32,
    /// See `group_stride`.
    pub group_base: u32,
    /// Duplication geometry passes: the view of multiview layer 0 (layered) or of the band's
    /// first tile (tiled).
    pub first_view: u32,
    /// Compositing: the atlas texel row of the group images' row 0 (the tiled method's bands
    /// of tile rows, `duplicate::ViewChunk`; 0 elsewhere).
    pub image_row: u32,
    pub(super) _pad: [u32; 2],
}
const _: () = assert!(std::mem::size_of::<SplatParams>() == 48);
crate::shader::gpu_layout!(
    SplatParams,
    "SplatParams",
    [
        cover_lo,
        cover_hi,
        fixed_offset,
        use_mask,
        epsilon,
        groups,
        group_stride,
        group_base,
        first_view,
        image_row
    ]
);

pub(super) struct Layouts {
    pub frame: wgpu::BindGroupLayout,
    /// splats (read), eye splats and cover rects (write): the cover pass.
    pub cover: wgpu::BindGroupLayout,
    /// eye splats and cover rects (read): the geometry passes.
    pub quad: wgpu::BindGroupLayout,
    /// The group images (compositing).
    pub groups: wgpu::BindGroupLayout,
    /// Per-pass constants (dynamic offset).
    pub params: wgpu::BindGroupLayout,
    /// The quilt layout (tiled geometry pass).
    pub quilt: wgpu::BindGroupLayout,
}

impl Layouts {
    pub fn new(device: &wgpu::Device) -> Self {
        let cs = wgpu::ShaderStages::COMPUTE;
        let vf = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let layout = |label, entries: &[_]| bind_group_layout(device, label, entries);
        Self {
            frame: frame_bind_group_layout(device),
            cover: layout(
                "splat cover",
                &[
                    storage_entry(0, true, cs),
                    storage_entry(1, false, cs),
                    storage_entry(2, false, cs),
                ],
            ),
            quad: layout(
                "splat quads",
                &[storage_entry(0, true, vf), storage_entry(1, true, vf)],
            ),
            groups: layout(
                "splat group images",
                &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Uint,
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                        multisampled: false,
                    },
                    count: None,
                }],
            ),
            params: layout(
                "splat pass constants",
                &[PassParams::<SplatParams>::layout_entry(0, cs | vf)],
            ),
            quilt: layout(
                "splat quilt layout",
                &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: vf,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                }],
            ),
        }
    }
}

pub(super) struct Pipelines {
    pub cover: wgpu::ComputePipeline,
    pub geometry: wgpu::RenderPipeline,
    pub composite: wgpu::RenderPipeline,
}

/// Which geometry pass draws the splats into the group images.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Geometry {
    /// One fragment per pixel, the pass's cover rectangles (`points/pixel.wgsl`).
    Pixel,
    /// Exact depth at subpixel resolution (K = 3 displays; `points/subpixel.wgsl`).
    Subpixel,
    /// Instanced per view into the tiles of an atlas (`points/tiled.wgsl`).
    Tiled,
    /// Multiview into `layers` layers at once (`points/layered.wgsl`).
    Layered { layers: u32 },
    /// A warp's reference views: the pixel geometry, composited with the nearness.
    Reference,
}

/// What the splat pipelines are specialised for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct SplatPipelineKey {
    /// The display's K and N.
    pub spec: Specialization,
    pub geometry: Geometry,
}

pub(super) fn build(
    device: &wgpu::Device,
    modules: &mut ShaderModules,
    layouts: &Layouts,
    key: SplatPipelineKey,
) -> Result<Pipelines> {
    let SplatPipelineKey { spec, geometry } = key;
    let subpixel = geometry == Geometry::Subpixel;
    let padding = if subpixel { 0.5 } else { 1.0 / 16.0 };
    let cover_constants = spec.constants(&[("COVER_PADDING_PX", padding)]);
    // The duplicated quads are computed in the vertex stage, with the cover pass's padding.
    let constants = match geometry {
        Geometry::Tiled | Geometry::Layered { .. } => cover_constants.clone(),
        _ => spec.constants(&[]),
    };
    let layered = matches!(geometry, Geometry::Layered { .. });
    let composite_constants = spec.constants(&[
        ("SUBPIXEL_DEPTH", subpixel as u32 as f64),
        ("LAYERED_GROUPS", layered as u32 as f64),
    ]);

    let layout_of =
        |label, groups: &[Option<&wgpu::BindGroupLayout>]| pipeline_layout(device, label, groups);
    let cover_module = modules.get(device, "points/cover.wgsl")?;
    let cover = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("splat cover"),
        layout: Some(&layout_of(
            "splat cover",
            &[
                Some(&layouts.frame),
                Some(&layouts.cover),
                Some(&layouts.params),
            ],
        )),
        module: &cover_module,
        entry_point: Some("cs_main"),
        compilation_options: compilation(&cover_constants),
        cache: None,
    });
    let (stage, format) = match geometry {
        Geometry::Pixel | Geometry::Reference => ("points/pixel.wgsl", PIXEL_FORMAT),
        Geometry::Subpixel => ("points/subpixel.wgsl", SUBPIXEL_FORMAT),
        Geometry::Tiled => ("points/tiled.wgsl", PIXEL_FORMAT),
        Geometry::Layered { .. } => ("points/layered.wgsl", PIXEL_FORMAT),
    };
    let multiview_mask = match geometry {
        Geometry::Layered { layers } => multiview_mask(layers),
        _ => None,
    };
    let mut groups = vec![
        Some(&layouts.frame),
        Some(&layouts.quad),
        Some(&layouts.params),
    ];
    if geometry == Geometry::Tiled {
        groups.push(Some(&layouts.quilt));
    }
    let module = modules.get(device, stage)?;
    let geometry = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(stage),
        layout: Some(&layout_of(stage, &groups)),
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs_splat"),
            compilation_options: compilation(&constants),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(nearest_depth_test()),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs_main"),
            compilation_options: compilation(&constants),
            targets: &[Some(format.into())],
        }),
        multiview_mask,
        cache: None,
    });
    let composite_module = modules.get(device, "points/composite.wgsl")?;
    let reference_targets = [
        Some(SPATIAL_FORMAT.into()),
        Some(REFERENCE_NEARNESS_FORMAT.into()),
    ];
    let fragment: (_, &[_]) = match key.geometry {
        Geometry::Reference => ("fs_reference", &reference_targets),
        _ => ("fs_main", &[Some(SPATIAL_FORMAT.into())]),
    };
    let composite = fullscreen_pipeline_to(
        device,
        "splat composite",
        &composite_module,
        &[
            Some(&layouts.frame),
            Some(&layouts.groups),
            Some(&layouts.params),
        ],
        fragment,
        &composite_constants,
    );
    Ok(Pipelines {
        cover,
        geometry,
        composite,
    })
}
