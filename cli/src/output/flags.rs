//! The flags of what a render command writes: `--out` in `--output`'s format (and its quilt
//! grid, stereo eyes, `--json`), and `--turntable` (numbered frames of the scene turned). Plain
//! flag groups: the writers are cli/src/output/mod.rs and cli/src/turntable.rs.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::render::StereoFormat;

/// The formats of `--output`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputArg {
    /// The display's interleaved image.
    Spatial,
    /// A Looking Glass quilt of every view (view 0 bottom-left), named `…_qs{c}x{r}a{aspect}`.
    Quilt,
    /// One PNG per view: `{stem}_{V}.png`, V zero-padded to the digits of the last view (at
    /// least two), so that the files sort in view order.
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
    pub(crate) fn stereo(self, size: [u32; 2]) -> Option<(StereoFormat, [u32; 2])> {
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

/// What a command writes and where: the flags every command that renders views shares
/// (`mesh`, `points`, `volume`, `gaussians`, `rgbd`), one definition.
#[derive(clap::Args, Clone, Debug)]
#[command(next_help_heading = "Output")]
pub struct OutputArgs {
    /// Output PNG (of the spatial image, or of --output's format). Without it nothing is
    /// written, which only --json, --compare or --frames (a measurement) may ask for.
    #[arg(long, value_name = "F.png")]
    pub out: Option<PathBuf>,
    /// What --out holds: spatial | quilt (named `{stem}_qs{c}x{r}a{aspect}.png`) | views
    /// (`{stem}_00.png`…, zero-padded) | anaglyph | anaglyph-half | anaglyph-dubois |
    /// side-by-side | side-by-side-half | top-bottom | top-bottom-half | rows | columns |
    /// checkerboard (every format but spatial renders each view it needs with the --method).
    #[arg(
        long = "output",
        value_name = "FORMAT",
        value_enum,
        default_value = "spatial"
    )]
    pub format: OutputArg,
    /// With --output quilt: the quilt's grid COLSxROWS (default: a Looking Glass's own grid,
    /// else one chosen for the view count; Looking Glass software also reads e.g. 8x6 for 48
    /// views, the last tiles empty).
    #[arg(long = "quilt", value_name = "COLSxROWS", value_parser = crate::parse::parse_size)]
    pub quilt_grid: Option<[u32; 2]>,
    /// With --output quilt: the quilt image's size WxH (default: a Looking Glass family's own,
    /// e.g. 5999x5999 for the 16" Spatial Display; else the grid of --size views). Tiles are
    /// floor(W/cols) x floor(H/rows), the remainder left black, as Looking Glass does.
    #[arg(long, value_name = "WxH", value_parser = crate::parse::parse_size)]
    pub quilt_size: Option<[u32; 2]>,
    /// With the stereo formats of --output (anaglyph…, side-by-side…, top-bottom…, rows,
    /// columns, checkerboard): the left and right views L,R (default: two views a quarter of
    /// the views apart, about the middle).
    #[arg(long, value_name = "L,R", value_parser = crate::parse::parse_eyes)]
    pub eyes: Option<[u32; 2]>,
    /// Print one JSON object with the run's parameters, timing and the files written
    /// (`written`) on stdout.
    #[arg(long)]
    pub json: bool,
    /// Retired: `--output quilt --out F.png` writes the quilt.
    #[arg(long, hide = true)]
    pub quilt_out: Option<PathBuf>,
    /// Retired: `--output views --out DIR/view.png` writes every view.
    #[arg(long, hide = true)]
    pub views_out: Option<PathBuf>,
}

impl OutputArgs {
    /// Fail early on what can be checked before loading anything; `measuring`: the run was
    /// asked for something besides --out (numbers: --compare, --frames; or another file), so
    /// writing no --out is what was asked.
    pub fn check(&self, measuring: bool) -> Result<()> {
        if let Some(f) = &self.quilt_out {
            bail!(
                "--quilt-out was retired: write the quilt with --output quilt --out {} (one \
                 output per run; the name gets the _qs{{cols}}x{{rows}}a{{aspect}} suffix)",
                f.display()
            );
        }
        if let Some(dir) = &self.views_out {
            bail!(
                "--views-out was retired: write every view with --output views --out {} \
                 (writes view_00.png, view_01.png, … there, as --views-out did)",
                dir.join("view.png").display()
            );
        }
        match &self.out {
            Some(out) => {
                crate::parse::check_output_or_video(out)?;
                if super::video::is_video(out) && self.format == OutputArg::Views {
                    bail!(
                        "--out {}: --output views writes a file per view; a video holds one \
                         image a frame (--output spatial, quilt or a stereo format)",
                        out.display()
                    );
                }
            }
            None if self.format != OutputArg::Spatial => bail!(
                "--output {} writes to --out, which is missing",
                self.format.name()
            ),
            None if !(measuring || self.json) => bail!(
                "nothing to write: give --out F.png (or --json, --compare or --frames N to \
                 measure without writing an image)"
            ),
            None => {}
        }
        if self.quilt_grid.is_some() && self.format != OutputArg::Quilt {
            bail!(
                "--quilt sets the grid of --output quilt, not of --output {}",
                self.format.name()
            );
        }
        if self.quilt_size.is_some() && self.format != OutputArg::Quilt {
            bail!(
                "--quilt-size sets the size of --output quilt, not of --output {}",
                self.format.name()
            );
        }
        if let Some([l, r]) = self.eyes {
            if l == r {
                bail!("--eyes {l},{r}: one view for both eyes has no depth; give two views L,R");
            }
            if self.format.stereo([1, 1]).is_none() {
                bail!(
                    "--eyes {l},{r} chooses the views of a stereo --output (anaglyph, \
                     side-by-side, top-bottom, rows, columns, checkerboard), not of --output {}",
                    self.format.name()
                );
            }
        }
        Ok(())
    }
}

/// The axis the scene turns around (world coordinates, through the centre of its bounds).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Axis {
    X,
    Y,
    Z,
}

/// The turntable's flags.
#[derive(clap::Args, Clone, Debug)]
#[command(next_help_heading = "Output")]
pub struct TurntableArgs {
    /// Render one full turn of the scene as FRAMES numbered files `{--out stem}_{k:04}.png`
    /// (quilts: `{stem}_{k:04}_qs…png`) in --output's format, frame k turned by k/FRAMES·360°;
    /// with --out F.mp4 or F.gif, one video of the frames.
    #[arg(long, value_name = "FRAMES", value_parser = crate::parse::frames_parser())]
    pub turntable: Option<u32>,
    /// The turntable's axis through the scene's centre (y: upright, as on a real turntable).
    #[arg(long, value_enum, default_value = "y", requires = "turntable")]
    pub axis: Axis,
    #[command(flatten)]
    pub video: super::video::VideoArgs,
}

impl TurntableArgs {
    /// Fail early: a turntable writes to numbered files named after `--out`.
    pub fn check(&self, out: Option<&Path>) -> Result<()> {
        if self.turntable.is_some() && out.is_none() {
            bail!("--turntable writes numbered files named after --out, which is missing");
        }
        if let Some(out) = out.filter(|o| super::video::is_video(o)) {
            if self.turntable.is_none() {
                bail!(
                    "--out {}: a video is a turntable's frames: give --turntable FRAMES (one \
                     image is written as .png)",
                    out.display()
                );
            }
        }
        self.video.check(out)
    }
}
