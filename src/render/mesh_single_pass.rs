//! Single-pass triangle meshes (paper §3.2, §3.3.3, §3.5.3): one covering quad per triangle,
//! per-subpixel ray-triangle tests, the spatial image written directly.
//!
//! Visibility:
//! - [`Visibility::Fast`]: the paper's — one depth per fragment (the nearest hit subpixel)
//!   through the hardware depth test; dual-source blending keeps missed subpixels.
//! - [`Visibility::Exact`]: per-subpixel nearest (depth, triangle) with 64-bit atomics in the
//!   geometry pass, then a resolve pass that shades each subpixel once. Matches N-pass.

use std::collections::HashMap;

use super::pipeline::{cleared, fullscreen_pipeline_with};
use super::specialize::Specialization;
use super::view_layers::DEPTH_FORMAT;
use crate::error::{Error, Result};
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::mesh::MeshBuffers;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// How per-subpixel visibility is resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Visibility {
    /// One depth per fragment (min over hit subpixels), hardware depth test. Approximate where
    /// different triangles win different subpixels of one pixel.
    Fast,
    /// One depth per subpixel (64-bit atomics), deferred shading. Needs
    /// `SHADER_INT64_ATOMIC_MIN_MAX` (Vulkan lavapipe has it; GL does not).
    Exact,
}

/// Horizontal extent of the covering quads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CoverBounds {
    /// DESIGN §3: `x ± vd·|1 − fd/d|` per vertex. Always covers.
    Exact,
    /// The paper's printed `(x ∓ vd)·fd/d`: under-covers geometry beyond 2·fd (kept to measure).
    Paper,
}

/// Creation-time options.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshSinglePassOptions {
    /// Visibility mode.
    pub visibility: Visibility,
    /// Covering-quad bounds.
    pub bounds: CoverBounds,
}

impl Default for MeshSinglePassOptions {
    fn default() -> Self {
        Self {
            visibility: Visibility::Exact,
            bounds: CoverBounds::Exact,
        }
    }
}

struct Pipelines {
    cover: wgpu::ComputePipeline,
    geometry: wgpu::RenderPipeline,
    resolve: Option<wgpu::RenderPipeline>,
}

/// The single-pass mesh renderer.
pub struct MeshSinglePass {
    options: MeshSinglePassOptions,
    frame: FrameBinding,
    layouts: Layouts,
    pipelines: HashMap<Specialization, Pipelines>,
    depth: Option<(wgpu::Texture, wgpu::TextureView)>,
    keys: Option<Keys>,
    cover: Option<CoverData>,
}

/// Per-triangle eye-space vertices and covering rectangles (written by `mesh_cover.wgsl`).
struct CoverData {
    eye_triangles: wgpu::Buffer,
    rects: wgpu::Buffer,
}

/// Bytes per triangle of `EyeTriangle` and of a covering rectangle (wgsl/shared/cover_data.wgsl).
const EYE_TRIANGLE_BYTES: u64 = 48;
const RECT_BYTES: u64 = 16;
/// Invocations per workgroup of `mesh_cover.wgsl`.
const COVER_WORKGROUP: u32 = 64;

struct Layouts {
    frame: wgpu::BindGroupLayout,
    mesh: wgpu::BindGroupLayout,
    cover_compute: wgpu::BindGroupLayout,
    keys_write: wgpu::BindGroupLayout,
    keys_read: wgpu::BindGroupLayout,
}

/// The per-subpixel nearest-hit buffer of exact mode and its two bind groups.
struct Keys {
    buffer: wgpu::Buffer,
    write: wgpu::BindGroup,
    read: wgpu::BindGroup,
}

/// Split `groups` workgroups over x and y within the per-dimension limit (the shader
/// linearises `group.y · groups.x + group.x` and skips indices past the end).
fn dispatch_2d(device: &wgpu::Device, groups: u32) -> [u32; 2] {
    let max = device.limits().max_compute_workgroups_per_dimension.max(1);
    let x = groups.clamp(1, max);
    [x, groups.div_ceil(x).max(1)]
}

fn storage_entry(binding: u32, read_only: bool, stages: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

impl MeshSinglePass {
    /// Check the device can run `options` and prepare the layouts; pipelines are built lazily
    /// per display specialisation (K, N).
    pub fn new(device: &wgpu::Device, options: MeshSinglePassOptions) -> Result<Self> {
        let needed = match options.visibility {
            Visibility::Fast => (wgpu::Features::DUAL_SOURCE_BLENDING, "fast visibility (dual-source blending)"),
            Visibility::Exact => (
                wgpu::Features::SHADER_INT64 | wgpu::Features::SHADER_INT64_ATOMIC_MIN_MAX,
                "exact visibility (64-bit atomics)",
            ),
        };
        if !device.features().contains(needed.0) {
            return Err(Error::MissingFeature {
                adapter: String::new(),
                feature: format!("{:?}", needed.0 - device.features()),
                purpose: needed.1.into(),
            });
        }
        let vf = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let cs = wgpu::ShaderStages::COMPUTE;
        let layouts = Layouts {
            frame: frame_bind_group_layout(device),
            mesh: device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("mesh + cover data"),
                entries: &[
                    storage_entry(0, true, vf),
                    storage_entry(1, true, vf),
                    storage_entry(2, true, vf),
                    storage_entry(3, true, vf),
                ],
            }),
            cover_compute: device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("mesh cover compute"),
                entries: &[
                    storage_entry(0, true, cs),
                    storage_entry(1, true, cs),
                    storage_entry(2, false, cs),
                    storage_entry(3, false, cs),
                ],
            }),
            keys_write: device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("nearest keys (write)"),
                entries: &[storage_entry(0, false, wgpu::ShaderStages::FRAGMENT)],
            }),
            keys_read: device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("nearest keys (read)"),
                entries: &[storage_entry(0, true, wgpu::ShaderStages::FRAGMENT)],
            }),
        };
        Ok(Self {
            options,
            frame: FrameBinding::new(device, &layouts.frame),
            layouts,
            pipelines: HashMap::new(),
            depth: None,
            keys: None,
            cover: None,
        })
    }

    /// The options this renderer was made with.
    pub fn options(&self) -> MeshSinglePassOptions {
        self.options
    }

    fn ensure_pipelines(&mut self, device: &wgpu::Device, spec: Specialization) -> Result<()> {
        if !self.pipelines.contains_key(&spec) {
            let built = crate::gpu::checked(device, "building the single-pass mesh pipelines", || {
                self.build(device, spec)
            })??;
            self.pipelines.insert(spec, built);
        }
        Ok(())
    }

    fn build(&self, device: &wgpu::Device, spec: Specialization) -> Result<Pipelines> {
        let paper = (self.options.bounds == CoverBounds::Paper) as u32 as f64;
        let cover_constants = spec.constants(&[("PAPER_BOUNDS", paper)]);
        let constants = spec.constants(&[]);
        let exact = self.options.visibility == Visibility::Exact;
        let (stage, mut groups) = if exact {
            ("mesh_single_pass_depth.wgsl", vec![Some(&self.layouts.frame), Some(&self.layouts.mesh)])
        } else {
            ("mesh_single_pass_fast.wgsl", vec![Some(&self.layouts.frame), Some(&self.layouts.mesh)])
        };
        if exact {
            groups.push(Some(&self.layouts.keys_write));
        }
        let module = crate::shader::module(device, stage)?;
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(stage),
            bind_group_layouts: &groups,
            immediate_size: 0,
        });
        let options = wgpu::PipelineCompilationOptions {
            constants: &constants,
            zero_initialize_workgroup_memory: true,
        };
        let target = if exact {
            // The geometry pass writes only storage; the attachment just gives the pass its size.
            wgpu::ColorTargetState {
                format: SPATIAL_FORMAT,
                blend: None,
                write_mask: wgpu::ColorWrites::empty(),
            }
        } else {
            let keep_missed = wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::Src1,
                dst_factor: wgpu::BlendFactor::OneMinusSrc1,
                operation: wgpu::BlendOperation::Add,
            };
            wgpu::ColorTargetState {
                format: SPATIAL_FORMAT,
                blend: Some(wgpu::BlendState {
                    color: keep_missed,
                    alpha: wgpu::BlendComponent::REPLACE,
                }),
                write_mask: wgpu::ColorWrites::ALL,
            }
        };
        let geometry = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(stage),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_cover"),
                compilation_options: options.clone(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: (!exact).then(|| wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: options,
                targets: &[Some(target)],
            }),
            multiview_mask: None,
            cache: None,
        });
        let cover_module = crate::shader::module(device, "mesh_cover.wgsl")?;
        let cover_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh cover"),
            bind_group_layouts: &[Some(&self.layouts.frame), Some(&self.layouts.cover_compute)],
            immediate_size: 0,
        });
        let cover = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("mesh cover"),
            layout: Some(&cover_layout),
            module: &cover_module,
            entry_point: Some("cs_main"),
            compilation_options: wgpu::PipelineCompilationOptions {
                constants: &cover_constants,
                zero_initialize_workgroup_memory: true,
            },
            cache: None,
        });
        let resolve = if exact {
            let module = crate::shader::module(device, "mesh_single_pass_resolve.wgsl")?;
            Some(fullscreen_pipeline_with(
                device,
                "mesh single-pass resolve",
                &module,
                &[Some(&self.layouts.frame), Some(&self.layouts.mesh), Some(&self.layouts.keys_read)],
                SPATIAL_FORMAT,
                &constants,
            ))
        } else {
            None
        };
        Ok(Pipelines {
            cover,
            geometry,
            resolve,
        })
    }

    fn depth_view(&mut self, device: &wgpu::Device, size: [u32; 2]) -> wgpu::TextureView {
        if self.depth.as_ref().is_none_or(|(t, _)| [t.width(), t.height()] != size) {
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("single-pass depth"),
                size: wgpu::Extent3d {
                    width: size[0],
                    height: size[1],
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: DEPTH_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            });
            let view = texture.create_view(&Default::default());
            self.depth = Some((texture, view));
        }
        self.depth.as_ref().expect("set above").1.clone()
    }

    /// The nearest-key buffer for `frame`: 8 bytes per ray (K per pixel), checked against the
    /// storage binding limit before allocating.
    fn ensure_keys(&mut self, device: &wgpu::Device, frame: &Frame) -> Result<()> {
        let rays = frame.size[0] as u64 * frame.size[1] as u64 * frame.display.views_per_pixel() as u64;
        let bytes = rays * 8;
        let limit = device.limits().max_storage_buffer_binding_size.min(device.limits().max_buffer_size);
        if bytes > limit {
            return Err(Error::LimitExceeded {
                what: format!("exact-visibility depth buffer bytes for {}x{}", frame.size[0], frame.size[1]),
                value: bytes,
                limit,
            });
        }
        if self.keys.as_ref().is_none_or(|k| k.buffer.size() != bytes) {
            self.keys = None;
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("nearest keys"),
                size: bytes,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let group = |layout: &wgpu::BindGroupLayout| {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("nearest keys"),
                    layout,
                    entries: &[wgpu::BindGroupEntry {
                        binding: 0,
                        resource: buffer.as_entire_binding(),
                    }],
                })
            };
            let (write, read) = (group(&self.layouts.keys_write), group(&self.layouts.keys_read));
            self.keys = Some(Keys { buffer, write, read });
        }
        Ok(())
    }

    /// Per-triangle buffers for `triangles` triangles, checked against the storage limits.
    fn ensure_cover(&mut self, device: &wgpu::Device, triangles: u64) -> Result<()> {
        let limit = device.limits().max_storage_buffer_binding_size.min(device.limits().max_buffer_size);
        let bytes = triangles * EYE_TRIANGLE_BYTES;
        if bytes > limit {
            return Err(Error::LimitExceeded {
                what: format!("single-pass per-triangle buffer bytes for {triangles} triangles"),
                value: bytes,
                limit,
            });
        }
        if self.cover.as_ref().is_none_or(|c| c.rects.size() != triangles * RECT_BYTES) {
            self.cover = None;
            let buffer = |label, size| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size,
                    usage: wgpu::BufferUsages::STORAGE,
                    mapped_at_creation: false,
                })
            };
            self.cover = Some(CoverData {
                eye_triangles: buffer("eye triangles", bytes),
                rects: buffer("cover rects", triangles * RECT_BYTES),
            });
        }
        Ok(())
    }

    /// Record the frame into `encoder`.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        frame.validate()?;
        if target.size() != frame.size {
            return Err(Error::invalid("target", format!("size {:?} differs from the frame's {:?}", target.size(), frame.size)));
        }
        self.frame.write(queue, frame);
        let triangles = mesh.index_count / 3;
        self.ensure_cover(device, triangles as u64)?;
        let spec = Specialization::of(frame);
        self.ensure_pipelines(device, spec)?;
        let cover = self.cover.as_ref().expect("ensured above");
        let group = |layout: &wgpu::BindGroupLayout| {
            let buffers = [&mesh.vertices, &mesh.indices, &cover.eye_triangles, &cover.rects];
            let entries: Vec<wgpu::BindGroupEntry> = buffers
                .iter()
                .enumerate()
                .map(|(i, b)| wgpu::BindGroupEntry {
                    binding: i as u32,
                    resource: b.as_entire_binding(),
                })
                .collect();
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("mesh + cover data"),
                layout,
                entries: &entries,
            })
        };
        let mesh_group = group(&self.layouts.mesh);
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("mesh cover"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipelines[&spec].cover);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &group(&self.layouts.cover_compute), &[]);
            let [x, y] = dispatch_2d(device, triangles.div_ceil(COVER_WORKGROUP));
            pass.dispatch_workgroups(x, y, 1);
        }
        let quad_vertices = triangles * 6;
        match self.options.visibility {
            Visibility::Fast => {
                let depth = self.depth_view(device, frame.size);
                let pipelines = &self.pipelines[&spec];
                let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("mesh single pass (fast)"),
                    color_attachments: &[Some(cleared(&target.view, frame.background))],
                    depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                        view: &depth,
                        depth_ops: Some(wgpu::Operations {
                            load: wgpu::LoadOp::Clear(1.0),
                            store: wgpu::StoreOp::Discard,
                        }),
                        stencil_ops: None,
                    }),
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                pass.set_pipeline(&pipelines.geometry);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &mesh_group, &[]);
                pass.draw(0..quad_vertices, 0..1);
            }
            Visibility::Exact => {
                self.ensure_keys(device, frame)?;
                let keys = self.keys.as_ref().expect("ensured above");
                encoder.clear_buffer(&keys.buffer, 0, None);
                let pipelines = &self.pipelines[&spec];
                {
                    let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                        label: Some("mesh single pass (exact depth)"),
                        color_attachments: &[Some(cleared(&target.view, frame.background))],
                        depth_stencil_attachment: None,
                        timestamp_writes: None,
                        occlusion_query_set: None,
                        multiview_mask: None,
                    });
                    pass.set_pipeline(&pipelines.geometry);
                    pass.set_bind_group(0, &self.frame.bind_group, &[]);
                    pass.set_bind_group(1, &mesh_group, &[]);
                    pass.set_bind_group(2, &keys.write, &[]);
                    pass.draw(0..quad_vertices, 0..1);
                }
                let resolve = pipelines.resolve.as_ref().expect("exact pipelines resolve");
                super::pipeline::draw_fullscreen(
                    encoder,
                    "mesh single pass (resolve)",
                    resolve,
                    &[&self.frame.bind_group, &mesh_group, &keys.read],
                    &target.view,
                );
            }
        }
        Ok(())
    }

    /// Encode, submit and wait.
    pub fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("mesh single pass"),
        });
        self.encode(device, queue, &mut encoder, mesh, frame, target)?;
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)
    }
}
