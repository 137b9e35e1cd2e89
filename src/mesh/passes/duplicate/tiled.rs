//! Tiled duplication (de Sorbier et al.): one instanced draw, instance i = view i's copy of the
//! mesh in view i's tile of a quilt atlas with one depth buffer; then the mask composites from
//! the atlas. The atlas is a Looking Glass quilt as it stands ([`MeshTiled::atlas`]).

use super::{draw_mesh, mesh_pipeline, views_buffer, views_entry, Shading};
use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::pipeline::{
    begin_pass_to, bind_group_layout, cleared, pipeline_layout, uniform_entry, PassTargets,
};
use crate::mesh::options::TileClip;
use crate::mesh::passes::npass::PreparedFor;
use crate::mesh::texture_buffers::{texture_bind_group_layout, TEXTURE_GROUP};
use crate::mesh::MeshBuffers;
use crate::render::atlas::{Atlas, AtlasCompositor, TileSampling};
use crate::render::quilt::QuiltLayout;
use crate::render::{begin_prepare, check_target, prepared_state, Made, Prepared, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

impl TileClip {
    /// What `self` is on `device`: `Auto` resolved; `ClipDistances` fails with
    /// `Error::MissingFeature` where the adapter has none.
    pub fn resolve(self, device: &wgpu::Device) -> Result<Self> {
        let has = device.features().contains(wgpu::Features::CLIP_DISTANCES);
        match self {
            Self::Auto if has => Ok(Self::ClipDistances),
            Self::Auto => Ok(Self::Discard),
            Self::ClipDistances => {
                crate::gpu::require_features(
                    device,
                    wgpu::Features::CLIP_DISTANCES,
                    "tiled rendering clipped by clip distances",
                    crate::advice::Advice::text("use ")
                        .then(crate::advice::Setting::TileClip(Self::Discard)),
                )?;
                Ok(self)
            }
            Self::Discard => Ok(self),
        }
    }
}

/// The tiled mesh renderer.
pub struct MeshTiled {
    clip: TileClip,
    /// Without textures and with (`MeshBuffers::textured`).
    pipelines: [wgpu::RenderPipeline; 2],
    views_layout: wgpu::BindGroupLayout,
    frame: FrameBinding,
    compositor: AtlasCompositor,
    /// The quilt atlas (with depth) of the prepared frame.
    prepared: Option<Prepared<PreparedFor, Atlas>>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

impl MeshTiled {
    /// Build the pipeline for `clip` (resolved on `device`).
    pub fn new(device: &wgpu::Device, clip: TileClip) -> Result<Self> {
        let clip = clip.resolve(device)?;
        let frame_layout = frame_bind_group_layout(device);
        let quilt_entry = uniform_entry(1, wgpu::ShaderStages::VERTEX_FRAGMENT);
        let views_layout = bind_group_layout(device, "tiled views", &[views_entry(0), quilt_entry]);
        let stage = match clip {
            TileClip::ClipDistances => "mesh/tiled.wgsl",
            _ => "mesh/tiled_discard.wgsl",
        };
        let module = crate::shader::module(device, stage)?;
        let layout = pipeline_layout(
            device,
            "mesh tiled",
            &[
                Some(&frame_layout),
                Some(&views_layout),
                None,
                Some(&texture_bind_group_layout(device)),
            ],
        );
        let targets = [Some(SPATIAL_FORMAT.into())];
        let pipeline = |textured| {
            let shading = Shading {
                fragment: "fs_main",
                textured,
            };
            mesh_pipeline(
                device,
                "mesh tiled",
                &module,
                &layout,
                &targets,
                None,
                shading,
            )
        };
        let pipelines = [pipeline(false)?, pipeline(true)?];
        Ok(Self {
            clip,
            pipelines,
            views_layout,
            compositor: AtlasCompositor::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    /// How copies are clipped to their tiles on this adapter.
    pub fn clip(&self) -> TileClip {
        self.clip
    }
}

impl Renderer<MeshBuffers> for MeshTiled {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        _mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        let last = self.prepared.take().map(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        let layout = QuiltLayout::for_views(frame.camera.views, frame.view_size());
        let atlas = match last {
            Some(atlas) if atlas.fits(&layout, true) => atlas,
            last => {
                drop(last); // free before allocating the replacement
                Atlas::new(device, layout, true)?
            }
        };
        self.prepared = Some(Prepared {
            key: PreparedFor::of(frame),
            made: atlas,
        });
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        check_target(frame, target)?;
        let atlas = &prepared_state("MeshTiled", &self.prepared, &PreparedFor::of(frame))?.made;
        self.frame.write(device, &frame.for_view_images());
        let views = views_buffer(device, &frame.camera);
        let quilt = atlas.layout.uniform_buffer(device, atlas.layout.uniform());
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("tiled views"),
            layout: &self.views_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: views.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: quilt.as_entire_binding(),
                },
            ],
        });
        {
            let depth = &atlas.depth.made("MeshTiled atlas depth")?.view;
            // The depth is kept: it is each view's depth map (the MRT test's oracle).
            let mut pass = begin_pass_to(
                encoder,
                "mesh tiled",
                PassTargets {
                    colors: &[Some(cleared(&atlas.color.view, frame.background))],
                    depth: Some(depth),
                    keep_depth: true,
                    multiview_mask: None,
                },
            );
            pass.set_pipeline(&self.pipelines[mesh.textured as usize]);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &group, &[]);
            pass.set_bind_group(TEXTURE_GROUP, &mesh.textures.bind_group, &[]);
            draw_mesh(&mut pass, mesh, frame.camera.views);
        }
        self.compositor.encode(
            device,
            encoder,
            &self.frame,
            atlas,
            target,
            TileSampling::Bilinear,
        );
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }

    fn atlas(&self) -> Option<&Atlas> {
        self.prepared.as_ref().map(|p| &p.made)
    }
}
