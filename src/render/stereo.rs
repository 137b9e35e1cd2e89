//! Two eyes' views into one stereo image (`wgsl/render/stereo.wgsl`): the formats stereo
//! displays and glasses take — anaglyphs, side by side, top and bottom, and the row-, column-
//! and checkerboard-interlaced formats. Render each eye with any method on a `view:N,V`
//! display (one view on every pixel), then compose.

use bytemuck::{Pod, Zeroable};

use crate::error::{Error, Result};
use crate::gpu::pass_params::constants_buffer;
use crate::gpu::pipeline::{
    bind_group_layout, draw_fullscreen, fullscreen_pipeline, uniform_entry,
};
use crate::gpu::texture::texture_2d_layout_entry;
use crate::param::Param;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The default stereo pair of `views` views: two views a quarter of the cone apart (at least
/// adjacent ones) around the middle, so that the pair has real disparity for any N (45 views:
/// 16 and 27); `[0, 0]` for one view.
pub fn default_eyes(views: u32) -> [u32; 2] {
    if views < 2 {
        return [0, 0];
    }
    let apart = ((views - 1) / 4).max(1);
    let left = (views - 1 - apart) / 2;
    [left, left + apart]
}

/// A stereo image format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StereoFormat {
    /// Red-cyan: red from the left eye, green and blue from the right.
    AnaglyphColor,
    /// Red-cyan with the left eye's luma in red (less retinal rivalry on saturated colours).
    AnaglyphHalfColor,
    /// Red-cyan by Dubois's least-squares projection (the least ghosting with common glasses).
    AnaglyphDubois,
    /// Left | right: the output is twice an eye's width (render each eye at half the panel's
    /// width for the "half" form).
    SideBySide,
    /// Left over right: twice an eye's height.
    TopBottom,
    /// Even rows left, odd rows right (line-interleaved monitors).
    Rows,
    /// Even columns left, odd columns right.
    Columns,
    /// (x + y) even left, odd right.
    Checkerboard,
}

impl StereoFormat {
    /// Every format, in the order the tools list them.
    pub const ALL: [StereoFormat; 8] = [
        StereoFormat::AnaglyphColor,
        StereoFormat::AnaglyphHalfColor,
        StereoFormat::AnaglyphDubois,
        StereoFormat::SideBySide,
        StereoFormat::TopBottom,
        StereoFormat::Rows,
        StereoFormat::Columns,
        StereoFormat::Checkerboard,
    ];

    /// The CLI's name.
    pub fn name(self) -> &'static str {
        match self {
            StereoFormat::AnaglyphColor => "anaglyph",
            StereoFormat::AnaglyphHalfColor => "anaglyph-half-color",
            StereoFormat::AnaglyphDubois => "anaglyph-dubois",
            StereoFormat::SideBySide => "side-by-side",
            StereoFormat::TopBottom => "top-bottom",
            StereoFormat::Rows => "rows",
            StereoFormat::Columns => "columns",
            StereoFormat::Checkerboard => "checkerboard",
        }
    }

    /// The output size for eyes of `eye` pixels.
    pub fn output_size(self, eye: [u32; 2]) -> [u32; 2] {
        match self {
            StereoFormat::SideBySide => [eye[0].saturating_mul(2), eye[1]],
            StereoFormat::TopBottom => [eye[0], eye[1].saturating_mul(2)],
            _ => eye,
        }
    }

    fn code(self) -> u32 {
        Self::ALL.iter().position(|&f| f == self).expect("listed") as u32
    }
}

/// The compositor's constants. Keep in sync with `struct Stereo` in `wgsl/render/stereo.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct StereoUniform {
    format: u32,
    _pad: [u32; 3],
}
crate::shader::gpu_layout!(StereoUniform, "Stereo", [format]);

/// Composes a left and a right eye's images into a stereo image.
pub struct StereoCompositor {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
}

impl StereoCompositor {
    /// Build the pass.
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = bind_group_layout(
            device,
            "stereo eyes",
            &[
                texture_2d_layout_entry(0, fragment),
                texture_2d_layout_entry(1, fragment),
                uniform_entry(2, fragment),
            ],
        );
        let module = crate::shader::module(device, "render/stereo.wgsl")?;
        let pipeline =
            fullscreen_pipeline(device, "stereo", &module, &[Some(&layout)], SPATIAL_FORMAT);
        Ok(Self { layout, pipeline })
    }

    /// Record `format` of `left` and `right` (equal sizes) into `output`, of
    /// [`StereoFormat::output_size`] of the eyes' size (or one pixel more per axis, left
    /// black: an odd panel's width halved for side by side).
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        format: StereoFormat,
        left: &SpatialTarget,
        right: &SpatialTarget,
        output: &SpatialTarget,
    ) -> Result<()> {
        if left.size() != right.size() {
            return Err(Error::invalid(
                Param::StereoEyes,
                format!(
                    "left {:?} and right {:?} differ in size",
                    left.size(),
                    right.size()
                ),
            ));
        }
        // One spare column or row is allowed (an odd panel halved for side by side); it stays
        // black.
        let wanted = format.output_size(left.size());
        let fits = |i: usize| output.size()[i] >= wanted[i] && output.size()[i] <= wanted[i] + 1;
        if !(fits(0) && fits(1)) {
            return Err(Error::invalid(
                Param::StereoOutput,
                format!(
                    "{:?} for {} of {:?} eyes: needs {wanted:?}",
                    output.size(),
                    format.name(),
                    left.size()
                ),
            ));
        }
        let uniform = StereoUniform {
            format: format.code(),
            _pad: [0; 3],
        };
        let constants = constants_buffer(
            device,
            "stereo constants",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(&uniform),
        );
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("stereo eyes"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&left.view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&right.view),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: constants.as_entire_binding(),
                },
            ],
        });
        draw_fullscreen(encoder, "stereo", &self.pipeline, &[&group], &output.view);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn default_eyes_are_a_quarter_of_the_cone_apart() {
        use super::default_eyes;
        assert_eq!(default_eyes(45), [16, 27]);
        assert_eq!(default_eyes(49), [18, 30]);
        assert_eq!(default_eyes(8), [3, 4]);
        assert_eq!(default_eyes(2), [0, 1]);
        assert_eq!(default_eyes(1), [0, 0]);
        for n in 2..=256 {
            let [l, r] = default_eyes(n);
            assert!(l < r && r < n, "{n}: {l},{r}");
        }
    }
}
