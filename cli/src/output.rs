//! `--output`: what a render command writes to `--out`. The spatial image is the run's own
//! frame; every other format is made of views, each rendered by the run's renderer (any
//! method) with the run's camera on a one-view display (`view:N,V`), then tiled into a quilt,
//! written one PNG per view, or composited as a stereo pair (`StereoCompositor`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::RgbImage;
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::{Renderer, StereoCompositor, StereoFormat};
use autostereo::target::SpatialTarget;

/// The formats of `--output`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputArg {
    /// The display's interleaved image.
    Spatial,
    /// A Looking Glass quilt of every view (view 0 bottom-left), named `…_qs{c}x{r}a{aspect}`.
    Quilt,
    /// One PNG per view: `{stem}_view{V}.png`.
    Views,
    /// Red-cyan anaglyph of the --eyes pair, full colour.
    Anaglyph,
    /// Red-cyan anaglyph, half colour (the left eye's luminance in red).
    AnaglyphHalf,
    /// Red-cyan anaglyph, Dubois' least-squares matrices.
    AnaglyphDubois,
    /// Left and right eye side by side, each the full --size (output twice as wide).
    SideBySide,
    /// Side by side in the --size: each eye half as wide (what 3D TVs expect).
    SideBySideHalf,
    /// Left eye above the right, each the full --size (output twice as tall).
    TopBottom,
    /// Top and bottom in the --size: each eye half as tall.
    TopBottomHalf,
    /// Row-interlaced (left eye on even rows), for line-polarised monitors.
    Rows,
    /// Column-interlaced (left eye on even columns).
    Columns,
    /// Checkerboard (left eye where x + y is even), for DLP 3D projectors.
    Checkerboard,
}

impl OutputArg {
    /// The flag value, as the user wrote it.
    pub fn name(self) -> String {
        clap::ValueEnum::to_possible_value(&self)
            .map_or_else(|| format!("{self:?}"), |v| v.get_name().to_string())
    }

    /// The compositor's format and each eye's size for an output of `size`, for the stereo
    /// formats; `None` for the others.
    fn stereo(self, size: [u32; 2]) -> Option<(StereoFormat, [u32; 2])> {
        let half_w = [(size[0] / 2).max(1), size[1]];
        let half_h = [size[0], (size[1] / 2).max(1)];
        Some(match self {
            Self::Spatial | Self::Quilt | Self::Views => return None,
            Self::Anaglyph => (StereoFormat::AnaglyphColor, size),
            Self::AnaglyphHalf => (StereoFormat::AnaglyphHalfColor, size),
            Self::AnaglyphDubois => (StereoFormat::AnaglyphDubois, size),
            Self::SideBySide => (StereoFormat::SideBySide, size),
            Self::SideBySideHalf => (StereoFormat::SideBySide, half_w),
            Self::TopBottom => (StereoFormat::TopBottom, size),
            Self::TopBottomHalf => (StereoFormat::TopBottom, half_h),
            Self::Rows => (StereoFormat::Rows, size),
            Self::Columns => (StereoFormat::Columns, size),
            Self::Checkerboard => (StereoFormat::Checkerboard, size),
        })
    }
}

/// The two views of the stereo formats: `eyes`, or [`default_eyes`].
pub fn eye_views(eyes: Option<[u32; 2]>, views: u32) -> Result<[u32; 2]> {
    let [l, r] = eyes.unwrap_or(default_eyes(views));
    for v in [l, r] {
        if v >= views {
            bail!(
                "--eyes {l},{r}: view {v} does not exist (the display has views 0..{})",
                views - 1
            );
        }
    }
    Ok([l, r])
}

/// The default stereo pair: two views a quarter of the cone apart (at least adjacent ones)
/// around the middle, so that the pair has real disparity for any N (45 views: 16 and 27).
pub fn default_eyes(views: u32) -> [u32; 2] {
    if views < 2 {
        return [0, 0];
    }
    let apart = ((views - 1) / 4).max(1);
    let left = (views - 1 - apart) / 2;
    [left, left + apart]
}

/// What a render command writes after its timed run: `--quilt-out` (the tiled method's atlas,
/// first, since `--output` renders more frames with the same renderer), then `--out`, or with
/// `--turntable` its numbered frames (scene turned around the centre of `bounds`).
pub fn save_all<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    bounds: autostereo::camera::Bounds,
    common: &crate::args::RenderArgs,
    spatial: &RgbImage,
) -> Result<Option<crate::turntable::Summary>> {
    if let Some(quilt) = &common.quilt_out {
        crate::run::save_quilt(ctx, &*renderer, quilt)?;
    }
    let turntable = crate::turntable::render(ctx, renderer, scene, frame, bounds, common)?;
    if let Some(summary) = &turntable {
        if !common.json {
            eprintln!("{}", summary.line());
        }
    } else if let Some(out) = &common.out {
        write(ctx, renderer, scene, frame, common, Some(spatial), out)?;
        if common.output == OutputArg::Spatial {
            crate::run::how_to_look(out, common, frame);
        }
    }
    Ok(turntable)
}

/// Write `--out` in `--output`'s format; `spatial` is the frame's image if already rendered
/// (else the spatial format renders it). Returns what was written.
pub fn write<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    common: &crate::args::RenderArgs,
    spatial: Option<&RgbImage>,
    out: &Path,
) -> Result<Vec<PathBuf>> {
    let views = frame.camera.views;
    // `own_aspect`: seen at the image's own aspect (a quilt's tiles: a Looking Glass's are
    // the panel's); else at the frame's (the half-size stereo formats are squeezed).
    let mut one = |view: u32, size: [u32; 2], own_aspect: bool| -> Result<SpatialTarget> {
        let display = Display::parse(&format!("view:{views},{view}"))?;
        let mut eye = Frame {
            display,
            size,
            ..frame.clone()
        };
        if own_aspect {
            eye.camera.aspect = size[0] as f32 / size[1] as f32;
        }
        let target = SpatialTarget::new(&ctx.device, size)?;
        renderer
            .render(&ctx.device, &ctx.queue, scene, &eye, &target)
            .with_context(|| format!("--output {}: rendering view {view}", common.output.name()))?;
        Ok(target)
    };
    if let Some((format, eye)) = common.output.stereo(frame.size) {
        let [l, r] = eye_views(common.eyes, views)?;
        let (left, right) = (one(l, eye, false)?, one(r, eye, false)?);
        let output = SpatialTarget::new(&ctx.device, format.output_size(eye))?;
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("stereo output"),
            });
        StereoCompositor::new(&ctx.device)?.encode(
            &ctx.device,
            &mut encoder,
            format,
            &left,
            &right,
            &output,
        )?;
        ctx.queue.submit([encoder.finish()]);
        output.read(&ctx.device, &ctx.queue)?.save_png(out)?;
        return Ok(vec![out.to_path_buf()]);
    }
    match common.output {
        OutputArg::Views => {
            let stem = out.with_extension("");
            let mut written = Vec::new();
            for v in 0..views {
                let path = PathBuf::from(format!("{}_view{v}.png", stem.display()));
                one(v, frame.size, false)?
                    .read(&ctx.device, &ctx.queue)?
                    .save_png(&path)?;
                written.push(path);
            }
            Ok(written)
        }
        OutputArg::Quilt => {
            // A Looking Glass's own quilt unless --quilt says otherwise: the family's grid,
            // tiles of the panel's aspect within the family's quilt size.
            let layout = match (common.quilt_grid, frame.display.default_quilt(views)) {
                (Some([cols, rows]), _) => {
                    QuiltLayout::with_grid(cols, rows, frame.size, views).context("--quilt")?
                }
                (None, Some(lkg)) => lkg,
                (None, None) => QuiltLayout::for_views(views, frame.size),
            };
            let [w, h] = layout.size();
            RgbImage::check_size(w, h).context("--output quilt")?;
            let mut quilt = RgbImage::new(w, h);
            for v in 0..views {
                let tile = one(v, layout.tile, true)?.read(&ctx.device, &ctx.queue)?;
                let [tx, ty] = layout.tile_origin(v);
                for y in 0..tile.height {
                    let src = (y * tile.width * 3) as usize;
                    let dst = (((ty + y) * w + tx) * 3) as usize;
                    let row = (tile.width * 3) as usize;
                    quilt.data[dst..dst + row].copy_from_slice(&tile.data[src..src + row]);
                }
            }
            let named = layout.file_name(out);
            quilt.save_png(&named)?;
            Ok(vec![named])
        }
        _ => {
            match spatial {
                Some(image) => image.save_png(out)?,
                None => {
                    let target = SpatialTarget::new(&ctx.device, frame.size)?;
                    renderer.render(&ctx.device, &ctx.queue, scene, frame, &target)?;
                    target.read(&ctx.device, &ctx.queue)?.save_png(out)?;
                }
            }
            Ok(vec![out.to_path_buf()])
        }
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
