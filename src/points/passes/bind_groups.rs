//! The bind groups a splat frame's passes use (cover, quads, group images, pass constants),
//! made once per frame for the ordinary and the duplicated encode alike.

use super::prepared::PreparedSplats;
use super::PointSplatter;
use crate::error::Result;
use crate::points::SplatScene;

/// The bind groups of one frame's passes.
pub(super) struct FrameGroups {
    pub cover: wgpu::BindGroup,
    pub quad: wgpu::BindGroup,
    pub images: wgpu::BindGroup,
    pub params: wgpu::BindGroup,
}

impl PointSplatter {
    /// This frame's bind groups (after `prepare` made `state` and the frame's `params.write`).
    pub(super) fn frame_groups(
        &self,
        device: &wgpu::Device,
        scene: &SplatScene,
        state: &PreparedSplats,
    ) -> Result<FrameGroups> {
        let scratch = &state.scratch;
        let images = &state.images.layers;
        let group = |label, layout, entries: &[wgpu::BindGroupEntry]| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(label),
                layout,
                entries,
            })
        };
        let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
        let cover_group = group(
            "splat cover",
            &self.layouts.cover,
            &[
                entry(0, scene.buffer.as_entire_binding()),
                entry(1, scratch.eye_splats.binding()),
                entry(2, scratch.rects.binding()),
            ],
        );
        let quad_group = group(
            "splat quads",
            &self.layouts.quad,
            &[
                entry(0, scratch.eye_splats.binding()),
                entry(1, scratch.rects.binding()),
            ],
        );
        let images_group = group(
            "splat group images",
            &self.layouts.groups,
            &[entry(
                0,
                wgpu::BindingResource::TextureView(&images.array_view),
            )],
        );
        let params_group = group(
            "splat pass constants",
            &self.layouts.params,
            &[entry(0, self.params.binding())],
        );
        Ok(FrameGroups {
            cover: cover_group,
            quad: quad_group,
            images: images_group,
            params: params_group,
        })
    }
}
