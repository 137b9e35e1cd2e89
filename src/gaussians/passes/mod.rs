//! The Gaussian renderers (docs/GAUSSIANS.md): the single pass, the N-pass (the oracle) and the
//! single view, all from one splat stage (`wgsl/gaussians/splat.wgsl`) over one depth sort
//! ([`sort`]). Each blends back to front with dual-source blending into an RGBA16F target
//! cleared to the background: per channel exactly graphdeco's front-to-back sum, except that
//! blending cannot stop where transmittance falls below 1e-4 (what it would have dropped
//! weighs less than 1e-4).

mod renderer;
mod sort;

pub use sort::{cpu_order, SortOn};

use bytemuck::{Pod, Zeroable};

use super::scene::GaussianScene;
use super::GaussianOptions;
use crate::camera::CameraModel;
use crate::error::{Error, Result};
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::gpu_buffer::GpuBuffer;
use crate::gpu::pass_params::PassParams;
use crate::gpu::pipeline::{
    begin_pass, bind_group_layout, cleared, compilation, over_per_channel_pipeline,
    pipeline_layout, storage_entry,
};
use crate::gpu::texture::{texture_2d_reusing, Texture2d};
use crate::param::Param;
use crate::render::accumulation::AccumulationResolve;
use crate::render::atlas::{Atlas, AtlasCompositor, TileSampling};
use crate::render::composite::Compositor;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::quilt::QuiltLayout;
use crate::render::specialize::Specialization;
use crate::render::view_layers::ViewLayers;
use crate::render::{begin_prepare, prepared_state, Made as _, Method, Prepared, Renderer};
use crate::target::SpatialTarget;

/// Threads per workgroup of the colour table's fill.
const COLORS_WORKGROUP: u32 = 64;

/// Bytes of the single pass's colour table: two words per Gaussian and view.
fn color_table_bytes(scene: &GaussianScene, frame: &Frame) -> u64 {
    u64::from(scene.count) * u64::from(frame.camera.views) * 8
}

/// Accumulation format: float, so thousands of blended Gaussians don't quantise.
const ACCUMULATION_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// Per-pass constants. Keep in sync with `struct GaussianParams` in
/// `wgsl/gaussians/shared/gaussian.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct GaussianParams {
    camera_world: [f32; 4],
    right_world: [f32; 4],
    offsets: [f32; 4],
    tile: [f32; 4],
    count: u32,
    coefficients: u32,
    fixed_view: u32,
    color_table: u32,
}
const _: () = assert!(std::mem::size_of::<GaussianParams>() == 80);
crate::shader::gpu_layout!(
    GaussianParams,
    "GaussianParams",
    [
        camera_world,
        right_world,
        offsets,
        tile,
        count,
        coefficients,
        fixed_view,
        color_table
    ]
);

#[cfg(test)]
pub(crate) const GAUSSIAN_PARAMS_LAYOUT: crate::shader::GpuLayout = GaussianParams::GPU_LAYOUT;
#[cfg(test)]
pub(crate) const SORT_STEP_LAYOUT: crate::shader::GpuLayout = sort::SortStep::GPU_LAYOUT;

impl GaussianParams {
    /// The constants of a pass over `frame` covering the offsets `lo..=hi`; `fixed`: every
    /// channel shows the view at that offset.
    fn new(scene: &GaussianScene, frame: &Frame, lo: f32, hi: f32, fixed: Option<f32>) -> Self {
        let world_from_eye = frame.camera.eye_from_world.inverse();
        let camera = world_from_eye.transform_point3(glam::Vec3::ZERO);
        let right = world_from_eye.transform_vector3(glam::Vec3::X).normalize();
        Self {
            camera_world: camera.extend(1.0).to_array(),
            right_world: right.extend(0.0).to_array(),
            offsets: [lo, hi, fixed.unwrap_or(0.0), 0.0],
            tile: [0.0; 4],
            count: scene.count,
            coefficients: scene.coefficients(),
            fixed_view: fixed.is_some() as u32,
            color_table: 0,
        }
    }
}

/// What a frame needs prepared.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PreparedFor {
    spec: Specialization,
    size: [u32; 2],
    view_size: [u32; 2],
    count: u32,
    /// The single pass reads its colours from a table per Gaussian and view (it fits a
    /// storage binding), else evaluates the SH per subpixel.
    color_table: bool,
}

/// What `prepare` made: the accumulation target (single pass, single view; the tiled method's
/// is quilt-sized), the view layers (N-pass) or the quilt atlas (tiled).
struct Made {
    accumulation: Option<Texture2d>,
    layers: Option<ViewLayers>,
    atlas: Option<Atlas>,
}

/// 3D Gaussian splats by [`Method::SinglePass`], [`Method::NPass`], [`Method::SingleView`] or
/// [`Method::Tiled`] (every view into its tile of a quilt, as Looking Glass's splat tools do,
/// then interleaved).
pub struct GaussianSplatter {
    method: Method,
    color_table: bool,
    frame: FrameBinding,
    views_frame: FrameBinding,
    scene_layout: wgpu::BindGroupLayout,
    splat_layout: wgpu::BindGroupLayout,
    pipelines: PipelineCache<Specialization, wgpu::RenderPipeline>,
    resolve: AccumulationResolve,
    compositor: Compositor,
    atlas_compositor: AtlasCompositor,
    sort: sort::DepthSort,
    /// The single pass's colours per Gaussian and view, and the stage that fills them.
    colors: GpuBuffer,
    colors_pipeline: wgpu::ComputePipeline,
    colors_layout: wgpu::BindGroupLayout,
    params: PassParams<GaussianParams>,
    prepared: Option<Prepared<PreparedFor, Made>>,
    crop: crate::render::camera_crop::CameraCrop,
}

impl GaussianSplatter {
    /// Needs `DUAL_SOURCE_BLENDING` (one α per channel). The duplication methods and the warp
    /// are not Gaussian methods (refused with the reason).
    pub fn new(device: &wgpu::Device, method: Method, options: GaussianOptions) -> Result<Self> {
        if !crate::gaussians::METHODS.contains(&method) {
            return Err(Error::invalid(
                Param::Method,
                format!(
                    "{method}: Gaussian splats render by single-pass, n-pass, single-view or \
                     tiled (a quilt)"
                ),
            ));
        }
        crate::gpu::require_features(
            device,
            wgpu::Features::DUAL_SOURCE_BLENDING,
            "Gaussian splats (one α per subpixel)",
            crate::advice::Advice::text("use an adapter with dual-source blending"),
        )?;
        let frame_layout = frame_bind_group_layout(device);
        let fragment = wgpu::ShaderStages::VERTEX_FRAGMENT | wgpu::ShaderStages::COMPUTE;
        let scene_entries = [
            storage_entry(0, true, fragment),
            storage_entry(1, true, fragment),
            PassParams::<GaussianParams>::layout_entry(2, fragment),
        ];
        let scene_layout = bind_group_layout(device, "gaussian scene", &scene_entries);
        let mut splat_entries = scene_entries.to_vec();
        splat_entries.push(storage_entry(3, true, wgpu::ShaderStages::VERTEX));
        splat_entries.push(storage_entry(4, true, wgpu::ShaderStages::FRAGMENT));
        let splat_layout = bind_group_layout(device, "gaussian splats", &splat_entries);
        let resolve = AccumulationResolve::new(device, &frame_layout)?;
        let colors_layout = bind_group_layout(
            device,
            "gaussian colours",
            &[storage_entry(0, false, wgpu::ShaderStages::COMPUTE)],
        );
        let colors_pipeline = {
            let module = crate::shader::module(device, "gaussians/colors.wgsl")?;
            let layout = pipeline_layout(
                device,
                "gaussian colours",
                &[
                    Some(&frame_layout),
                    Some(&scene_layout),
                    Some(&colors_layout),
                ],
            );
            let constants = [("WORKGROUP", COLORS_WORKGROUP as f64)];
            crate::gpu::checked(device, "building the Gaussian colour table", || {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("gaussian colours"),
                    layout: Some(&layout),
                    module: &module,
                    entry_point: Some("cs_main"),
                    compilation_options: compilation(&constants),
                    cache: None,
                })
            })?
        };
        Ok(Self {
            method,
            color_table: options.color_table,
            colors: GpuBuffer::new(device, "gaussian colours", wgpu::BufferUsages::STORAGE),
            colors_pipeline,
            colors_layout,
            frame: FrameBinding::new(device, &frame_layout),
            views_frame: FrameBinding::new(device, &frame_layout),
            compositor: Compositor::new(device, &frame_layout)?,
            atlas_compositor: AtlasCompositor::new(device, &frame_layout)?,
            sort: sort::DepthSort::new(device, options.sort, &frame_layout, &scene_layout)?,
            scene_layout,
            splat_layout,
            pipelines: PipelineCache::new("Gaussian splat"),
            resolve,
            params: PassParams::new(device, "gaussian params"),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    fn ensure_pipeline(&mut self, device: &wgpu::Device, spec: Specialization) -> Result<()> {
        let frame_layout = frame_bind_group_layout(device);
        let splat_layout = &self.splat_layout;
        let constants = spec.constants(&[]);
        self.pipelines.prepare(device, spec, |modules| {
            let layout = pipeline_layout(
                device,
                "gaussian splats",
                &[Some(&frame_layout), Some(splat_layout)],
            );
            let module = modules.get(device, "gaussians/splat.wgsl")?;
            Ok(over_per_channel_pipeline(
                device,
                "gaussian splats",
                &layout,
                &module,
                &constants,
                ACCUMULATION_FORMAT,
            ))
        })?;
        Ok(())
    }

    fn key(&self, device: &wgpu::Device, scene: &GaussianScene, frame: &Frame) -> PreparedFor {
        let table_bytes = color_table_bytes(scene, frame);
        PreparedFor {
            spec: Specialization::of(frame),
            size: frame.size,
            view_size: frame.view_size(),
            count: scene.count,
            color_table: self.method == Method::SinglePass
                && self.color_table
                && table_bytes <= crate::gpu::gpu_buffer::storage_binding_limit(device),
        }
    }

    /// The per-view layers of the last N-pass frame (for per-view outputs and tests).
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.prepared.as_ref().and_then(|p| p.made.layers.as_ref())
    }

    /// Record only `frame`'s depth sort (benchmarks time it alone; `prepare` first).
    pub fn encode_sort(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &GaussianScene,
        frame: &Frame,
    ) -> Result<()> {
        let params = GaussianParams::new(scene, frame, 0.0, 0.0, None);
        self.params.write(device, &[params]);
        self.frame.write(device, frame);
        let group = self.scene_group(device, scene, None);
        self.sort
            .encode(device, encoder, scene, frame, &self.frame, &group)?;
        Ok(())
    }

    /// Record the colour table's fill (`gaussians/colors.wgsl`).
    fn encode_colors(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &GaussianScene,
        scene_group: &wgpu::BindGroup,
    ) {
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaussian colours"),
            layout: &self.colors_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: self.colors.binding(),
            }],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("gaussian colours"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.colors_pipeline);
        pass.set_bind_group(0, &self.frame.bind_group, &[]);
        pass.set_bind_group(1, scene_group, &[0]);
        pass.set_bind_group(2, &group, &[]);
        let groups = scene.count.div_ceil(COLORS_WORKGROUP);
        let max = device.limits().max_compute_workgroups_per_dimension;
        pass.dispatch_workgroups(groups.min(max), groups.div_ceil(max), 1);
    }

    /// The scene's bind group (with the draw order for the splat pass).
    fn scene_group(
        &self,
        device: &wgpu::Device,
        scene: &GaussianScene,
        order: Option<&wgpu::Buffer>,
    ) -> wgpu::BindGroup {
        let mut entries = vec![
            wgpu::BindGroupEntry {
                binding: 0,
                resource: scene.geometry.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: scene.sh.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: self.params.binding(),
            },
        ];
        if let Some(order) = order {
            entries.push(wgpu::BindGroupEntry {
                binding: 3,
                resource: order.as_entire_binding(),
            });
            entries.push(wgpu::BindGroupEntry {
                binding: 4,
                resource: self.colors.binding(),
            });
        }
        let layout = match order {
            Some(_) => &self.splat_layout,
            None => &self.scene_layout,
        };
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaussians"),
            layout,
            entries: &entries,
        })
    }

    /// The depth order of the last frame's sort read back (tests: the order the views share).
    pub fn last_order(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &GaussianScene,
    ) -> Result<Vec<u32>> {
        self.sort.read_order(device, queue, scene.count)
    }

    /// Every view into its tile of the quilt-sized `accumulation` (cleared once to the
    /// background), each tile its own viewport and scissor and its pass's constants (`draw`'s
    /// offset is not used).
    fn draw_tiles(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        draw: &Draw,
        atlas: &Atlas,
        accumulation: &Texture2d,
    ) -> Result<()> {
        let clear = cleared(&accumulation.view, draw.background);
        let mut pass = begin_pass(encoder, "gaussian quilt", clear, None);
        pass.set_pipeline(self.pipelines.get(&draw.spec)?);
        pass.set_bind_group(0, &draw.frame.bind_group, &[]);
        let layout = &atlas.layout;
        for v in 0..layout.views {
            let [x, y] = layout.tile_origin(v);
            let [w, h] = layout.tile;
            pass.set_viewport(x as f32, y as f32, w as f32, h as f32, 0.0, 1.0);
            pass.set_scissor_rect(x, y, w, h);
            pass.set_bind_group(1, draw.group, &[self.params.offset(v as usize)]);
            pass.draw(0..6, 0..draw.count);
        }
        Ok(())
    }

    /// Draw every Gaussian, in the sorted order, into `target` (cleared to the background).
    fn draw(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        draw: &Draw,
        target: &wgpu::TextureView,
    ) -> Result<()> {
        let clear = cleared(target, draw.background);
        let mut pass = begin_pass(encoder, "gaussian splats", clear, None);
        pass.set_pipeline(self.pipelines.get(&draw.spec)?);
        pass.set_bind_group(0, &draw.frame.bind_group, &[]);
        pass.set_bind_group(1, draw.group, &[draw.offset]);
        pass.draw(0..6, 0..draw.count);
        Ok(())
    }
}

/// One draw of every Gaussian: the frame's constants, the scene's bind group at a pass's
/// constants, the pipelines' key.
struct Draw<'a> {
    frame: &'a FrameBinding,
    background: [f32; 4],
    group: &'a wgpu::BindGroup,
    offset: u32,
    spec: Specialization,
    count: u32,
}
