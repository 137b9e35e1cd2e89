//! What the viewer renders each frame: the camera's frame on a display, and the frames of
//! each preview (the spatial image, one view, the quilt's tiles, a stereo pair).

use crate::error::Result;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::render::quilt_image::{QuiltChoice, QuiltImage};
use autostereo::render::StereoFormat;

use super::State;
use crate::options::{Options, Preview};

impl State {
    /// The frame of the current camera settings on `display`, `size` pixels. The display's
    /// origin is where the window sits, plus --origin (a panel not at the screen's top-left).
    pub(super) fn frame_on(
        &self,
        options: &Options,
        mut display: Display,
        size: [u32; 2],
    ) -> Result<Frame> {
        // Wrapping, as the mask's own sums: it uses the origin only modulo 2³².
        display.origin = [
            self.position[0].wrapping_add(options.display.origin[0]),
            self.position[1].wrapping_add(options.display.origin[1]),
        ];
        let base = options.camera.camera(self.scene.bounds, &display, size)?;
        // The orbit starts from the command line's camera and turns about what it looks at.
        let mut camera = self
            .orbit
            .apply(&base, options.camera.pivot(self.scene.bounds));
        camera.separation *= self.separation_scale;
        camera.focal_distance *= self.focal_scale;
        Ok(Frame::new(camera, display, size)?)
    }

    /// What to render this frame: (frame, which target: 0 the window's, 1 and 2 the eyes' or
    /// the quilt's tile, and where in the window's to copy the tile, for the quilt preview).
    #[allow(clippy::type_complexity)]
    pub(super) fn frames(
        &self,
        options: &Options,
    ) -> Result<Vec<(Frame, usize, Option<[u32; 2]>)>> {
        let size = [self.config.width, self.config.height];
        let panel = self.displays[self.display].1.clone();
        let n = panel.views();
        let centre = self.preview_view.unwrap_or((n - 1) / 2).min(n - 1);
        let one = |v: u32| Display::parse(&format!("view:{n},{v}"));
        Ok(match (self.preview, self.preview.stereo()) {
            (Preview::Spatial, _) => vec![(self.frame_on(options, panel, size)?, 0, None)],
            (Preview::View, _) => vec![(self.frame_on(options, one(centre)?, size)?, 0, None)],
            (Preview::Quilt, _) => {
                // Looking Glass order: view 0 bottom-left, left to right, bottom to top. The
                // grid `--output quilt` writes for this display (a Looking Glass's own), in a
                // quilt the window's size: whole-pixel tiles from the bottom-left, each view
                // shown at the quilt's aspect (squeezed into its tile, as the file holds it).
                let written = panel.quilt(n, size, &QuiltChoice::default())?;
                let grid = [written.layout.cols, written.layout.rows];
                let window = QuiltImage::in_size(grid, size, n, written.aspect)?;
                let top = size[1] - window.layout.size()[1];
                (0..n)
                    .map(|v| {
                        let mut frame = self.frame_on(options, one(v)?, window.layout.tile)?;
                        frame.camera.aspect = window.aspect;
                        let [x, y] = window.layout.tile_origin(v);
                        Ok((frame, 1, Some([x, y + top])))
                    })
                    .collect::<Result<_>>()?
            }
            (_, Some(format)) => {
                // Side by side: each eye half the window's width (the "half" form).
                let eye = match format {
                    StereoFormat::SideBySide => [(size[0] / 2).max(1), size[1]],
                    _ => size,
                };
                // The command line's default pair (a quarter of the cone apart), or from the
                // chosen view on.
                let [l, r] = autostereo::render::default_eyes(n);
                let left = self.preview_view.map_or(l, |v| v.min(n - 1));
                let right = (left + r - l).min(n - 1);
                vec![
                    (self.frame_on(options, one(left)?, eye)?, 1, None),
                    (self.frame_on(options, one(right)?, eye)?, 2, None),
                ]
            }
            (_, None) => unreachable!("every other preview is stereo"),
        })
    }
}
