//! Volumes as a warp's reference views (src/warp): the N-pass rays of every reference view in
//! one dispatch (`wgsl/volume/raycast_reference.wgsl`), writing colour and the nearness of
//! each ray's representative depth (where its opacity crosses ½; see `wgsl/volume/shared/
//! march.wgsl`).

use super::{PreparedFor, RaycastPipelineKey, VolumeEncode, VolumeRaycaster};
use crate::error::Result;
use crate::frame::Frame;
use crate::render::begin_prepare;
use crate::render::Method;
use crate::volume::passes::resources::VolumeResources;
use crate::volume::VolumeScene;
use crate::warp::references::{check_reference_method, ReferenceImages, ReferenceRenderer};

impl ReferenceRenderer<VolumeScene> for VolumeRaycaster {
    fn prepare_references(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &VolumeScene,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        check_reference_method("VolumeRaycaster", self.method)?;
        let key = PreparedFor::of(&self.settings, frame, Method::Warp);
        self.resources
            .upload(device, queue, scene, &self.settings, key.skip_empty)?;
        self.finish_prepare(device, key, None)
    }

    fn encode_references(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &VolumeScene,
        frame: &Frame,
        images: &ReferenceImages,
    ) -> Result<()> {
        scene.validate()?;
        self.settings.validate_for(scene)?;
        let encode = VolumeEncode {
            renderer: "VolumeRaycaster",
            prepared: self.prepared.as_ref().map(|p| p.key),
            resources: &self.resources,
            settings: &self.settings,
            wanted: PreparedFor::of(&self.settings, frame, Method::Warp),
        };
        encode.check_current(scene)?;
        let params = VolumeResources::params(scene, &self.settings, frame, false, 0.0);
        let volume_group = self.resources.bind(device, scene, frame, &[params])?;
        let output_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("volume reference views"),
            layout: &self.output_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&images.color.array_view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&images.nearness.array_view),
                },
            ],
        });
        let key = RaycastPipelineKey::from(PreparedFor::of(&self.settings, frame, Method::Warp));
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("volume reference views"),
            timestamp_writes: None,
        });
        pass.set_pipeline(self.pipelines.get(&key)?);
        pass.set_bind_group(0, &self.resources.frame.bind_group, &[]);
        pass.set_bind_group(1, &volume_group, &[self.resources.params.offset(0)]);
        pass.set_bind_group(2, &output_group, &[]);
        let [w, h] = frame.size;
        pass.dispatch_workgroups(w.div_ceil(8), h.div_ceil(8), frame.camera.views);
        Ok(())
    }

    fn depth_meaning(&self) -> &'static str {
        "where the ray's opacity crosses ½, else its opacity-weighted mean depth"
    }
}
