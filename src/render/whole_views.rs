//! Images made of whole views, each rendered by any renderer on a `view:N,V` display (one view
//! on every pixel): one view, a Looking Glass quilt of every view, a stereo pair composed into
//! one image. What the `--output` formats other than the spatial image write, and what a
//! library user asks for beside the spatial image.

use crate::display::Display;
use crate::error::Result;
use crate::frame::Frame;
use crate::image_io::RgbImage;
use crate::render::quilt_image::QuiltImage;
use crate::render::{Renderer, StereoCompositor, StereoFormat};
use crate::target::SpatialTarget;

/// View `view` of `frame` alone at `size` pixels. `shown_at`: the aspect the view is shown at,
/// whatever the image's own (a quilt's tile is stretched to the quilt's aspect; the view is
/// rendered at the tile's size, unscaled); `None`: the frame's (the half-size stereo formats are
/// squeezed).
#[allow(clippy::too_many_arguments)]
pub fn render_view<S: ?Sized>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    view: u32,
    size: [u32; 2],
    shown_at: Option<f32>,
) -> Result<SpatialTarget> {
    let views = frame.camera.views;
    let mut eye = Frame {
        display: Display::parse(&format!("view:{views},{view}"))?,
        size,
        ..frame.clone()
    };
    if let Some(aspect) = shown_at {
        eye.camera.aspect = aspect;
        eye.view_scale = [1.0; 2];
    }
    let target = SpatialTarget::new(device, size)?;
    renderer.render(device, queue, scene, &eye, &target)?;
    Ok(target)
}

/// Every view of `frame` in `quilt`'s tiles (view 0 bottom-left; empty tiles and the remainder
/// black), each rendered at the tile's size and shown at the quilt's aspect.
pub fn render_quilt<S: ?Sized>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    quilt: &QuiltImage,
) -> Result<RgbImage> {
    render_quilt_counted(device, queue, renderer, scene, frame, quilt, &mut |_| {})
}

/// [`render_quilt`], calling `done(v)` as each view `v` is in its tile (a progress bar's
/// count: the views are the work).
pub fn render_quilt_counted<S: ?Sized>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    quilt: &QuiltImage,
    done: &mut dyn FnMut(u32),
) -> Result<RgbImage> {
    let layout = &quilt.layout;
    let [w, h] = layout.size();
    RgbImage::check_size(quilt.size[0], quilt.size[1])?;
    let mut tiles = RgbImage::new(w, h);
    let shown = Some(quilt.aspect);
    for v in 0..frame.camera.views.min(layout.views) {
        let tile = render_view(device, queue, renderer, scene, frame, v, layout.tile, shown)?
            .read(device, queue)?;
        let [tx, ty] = layout.tile_origin(v);
        let row = (tile.width * 3) as usize;
        for y in 0..tile.height {
            let src = (y * tile.width * 3) as usize;
            let dst = (((ty + y) * w + tx) * 3) as usize;
            tiles.data[dst..dst + row].copy_from_slice(&tile.data[src..src + row]);
        }
        done(v);
    }
    quilt.image(&tiles)
}

/// Views `eyes` = [left, right] of `frame`, each rendered at `eye` pixels, composed as
/// `format` (an image of `format.output_size(eye)`).
#[allow(clippy::too_many_arguments)]
pub fn render_stereo<S: ?Sized>(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    format: StereoFormat,
    eye: [u32; 2],
    eyes: [u32; 2],
) -> Result<RgbImage> {
    let [l, r] = eyes;
    let left = render_view(device, queue, renderer, scene, frame, l, eye, None)?;
    let right = render_view(device, queue, renderer, scene, frame, r, eye, None)?;
    let target = SpatialTarget::new(device, format.output_size(eye))?;
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("stereo output"),
    });
    StereoCompositor::new(device)?.encode(device, &mut encoder, format, &left, &right, &target)?;
    queue.submit([encoder.finish()]);
    target.read(device, queue)
}
