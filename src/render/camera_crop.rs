//! The parallel camera model (`CameraModel::Parallel`): each view is the skewed view shifted
//! and cropped, so every method renders the skewed views and this pass, recorded last, turns
//! the subpixels whose view's shifted image does not reach them into background
//! (`wgsl/render/camera_crop.wgsl`). One fullscreen pass with constant blending; nothing for
//! the other models or when the views coincide.

use crate::camera::CameraModel;
use crate::error::Result;
use crate::frame::{Frame, FrameBinding};
use crate::gpu::pipeline::{begin_pass, fullscreen_pipeline_to, kept};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The crop pass of the parallel model.
pub(crate) struct CameraCrop {
    pipeline: wgpu::RenderPipeline,
    frame: FrameBinding,
}

impl CameraCrop {
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let frame_layout = crate::frame::frame_bind_group_layout(device);
        let module = crate::shader::module(device, "render/camera_crop.wgsl")?;
        // out = src · constant + dst · (1 − src): src is 1 where cropped, the constant the
        // background; alpha is kept.
        let blend = wgpu::BlendState {
            color: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::Constant,
                dst_factor: wgpu::BlendFactor::OneMinusSrc,
                operation: wgpu::BlendOperation::Add,
            },
            alpha: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::Zero,
                dst_factor: wgpu::BlendFactor::One,
                operation: wgpu::BlendOperation::Add,
            },
        };
        let target = wgpu::ColorTargetState {
            format: SPATIAL_FORMAT,
            blend: Some(blend),
            write_mask: wgpu::ColorWrites::ALL,
        };
        let pipeline = fullscreen_pipeline_to(
            device,
            "camera crop",
            &module,
            &[Some(&frame_layout)],
            ("fs_main", &[Some(target)]),
            &[],
        );
        Ok(Self {
            pipeline,
            frame: FrameBinding::new(device, &frame_layout),
        })
    }

    /// Record the crop of `target` (the spatial image of `frame`, full size), if its camera
    /// model has any.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &Frame,
        target: &SpatialTarget,
    ) {
        let camera = &frame.camera;
        if camera.model != CameraModel::Parallel || camera.separation == 0.0 {
            return;
        }
        self.frame.write(device, frame);
        let mut pass = begin_pass(encoder, "camera crop", kept(&target.view), None);
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.frame.bind_group, &[]);
        let [r, g, b, a] = frame.background.map(f64::from);
        pass.set_blend_constant(wgpu::Color { r, g, b, a });
        pass.draw(0..3, 0..1);
    }
}
