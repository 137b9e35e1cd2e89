//! The one set of warp constants both warps' shaders read (`struct Warp` in
//! `wgsl/warp/shared/warp.wgsl`): rendered references and an RGB-D image differ only in what
//! fills it.

use bytemuck::{Pod, Zeroable};

use super::options::{WarpOptions, PARALLAX_PER_DEPTHINESS};
use crate::frame::Frame;

/// The warp's constants. Keep in sync with `struct Warp` in `wgsl/warp/shared/warp.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct WarpUniform {
    size: [u32; 2],
    references: u32,
    fixed_view: u32,
    parallax: f32,
    focus: f32,
    hole_gap: f32,
    hole_mask: u32,
    same_surface: f32,
    _pad0: u32,
    _pad1: [u32; 2],
}
const _: () = assert!(std::mem::size_of::<WarpUniform>() == 48);
crate::shader::gpu_layout!(
    WarpUniform,
    "Warp",
    [
        size,
        references,
        fixed_view,
        parallax,
        focus,
        hole_gap,
        hole_mask,
        same_surface
    ]
);

impl WarpUniform {
    /// Warping `frame`'s views from `options.references` rendered references, into every
    /// subpixel's view (`view` = None) or into view `view` everywhere.
    ///
    /// A point at eye depth d lands at `x_f = p.x·fd/d + vd·(1 − fd/d)` on the focal plane
    /// (`MultiViewCamera::project_offset`), so between cameras at vd_r and vd_v it moves by
    /// `−(vd_v − vd_r)·(n − 1)` with nearness n = fd/d; vd = t·(N−1)/2·e for view position t:
    /// the focus is 1, the focal plane.
    pub(crate) fn for_references(options: &WarpOptions, frame: &Frame, view: Option<u32>) -> Self {
        let camera = &frame.camera;
        let half_span = (camera.views as f32 - 1.0) * 0.5 * camera.separation;
        let pixels_per_unit = frame.size[0] as f32 / camera.focal_window().x;
        Self {
            size: frame.size,
            references: options.references,
            fixed_view: view.unwrap_or(u32::MAX),
            parallax: -half_span * pixels_per_unit,
            focus: 1.0,
            hole_gap: options.hole_gap,
            hole_mask: u32::from(options.hole_mask),
            same_surface: options.same_surface,
            ..Self::zeroed()
        }
    }

    /// Warping an RGB-D image of `size` (one reference, at the centre). Views further right
    /// (higher t) see near points further left: the shift is −t · depthiness · 3 % · width per
    /// unit of nearness − focus.
    pub(crate) fn for_rgbd(options: &WarpOptions, size: [u32; 2]) -> Self {
        Self {
            size,
            references: 1,
            fixed_view: options.view.unwrap_or(u32::MAX),
            parallax: Self::rgbd_parallax(options, size[0]),
            focus: options.focus,
            hole_gap: options.hole_gap,
            hole_mask: u32::from(options.hole_mask),
            same_surface: options.same_surface,
            ..Self::zeroed()
        }
    }

    /// The RGB-D shift (reference pixels) per unit of nearness − focus at view position +1.
    pub(crate) fn rgbd_parallax(options: &WarpOptions, width: u32) -> f32 {
        -options.depthiness * PARALLAX_PER_DEPTHINESS * width as f32
    }
}
