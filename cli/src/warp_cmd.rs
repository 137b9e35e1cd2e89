//! `--method warp` in the render commands: its flags, its renderer, and the hole share it
//! reports.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::render::Method;
use autostereo::warp::{WarpOptions, WarpPath};

/// How a warp makes its views: the flags `--method warp` and `rgbd` (always a warp) share.
#[derive(clap::Args, Clone, Debug, Default)]
#[command(next_help_heading = "Warping (--method warp; rgbd)")]
pub struct WarpSynthesisArgs {
    /// Neighbours warped further apart than this many pixels straddle a disocclusion, filled
    /// from the background side (default 2).
    #[arg(long, value_name = "PIXELS")]
    pub hole_gap: Option<f32>,
    /// direct (each subpixel warps its own view straight into the spatial image) or per-view
    /// (N view images first, then the mask compositing).
    #[arg(long, value_enum)]
    pub warp_path: Option<WarpPath>,
    /// Also write the hole mask (255 on subpixels that were filled rather than seen) as PNG
    /// and report its share (--method warp reports the share without it too).
    #[arg(long, value_name = "F.png")]
    pub hole_mask: Option<PathBuf>,
}

impl WarpSynthesisArgs {
    /// The flags given, by name.
    fn given(&self) -> [(&'static str, bool); 3] {
        [
            ("--hole-gap", self.hole_gap.is_some()),
            ("--warp-path", self.warp_path.is_some()),
            ("--hole-mask", self.hole_mask.is_some()),
        ]
    }

    /// Refuse bad values before loading anything.
    pub fn check(&self) -> Result<()> {
        if let Some(path) = &self.hole_mask {
            crate::parse::check_output(path)?;
        }
        Ok(())
    }

    /// `options` with these flags' settings.
    pub fn apply(&self, options: WarpOptions) -> WarpOptions {
        WarpOptions {
            hole_gap: self.hole_gap.unwrap_or(options.hole_gap),
            path: self.warp_path.unwrap_or(options.path),
            ..options
        }
    }
}

/// The warp method's flags (refused with any other method): only the commands whose primitive
/// has the warp method (mesh, points, volume) have them.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct WarpArgs {
    /// With --method warp: reference views R, 1 … N, spread evenly over the views (default 2:
    /// the outermost views; 1: the centre view).
    #[arg(long, help_heading = "Warping (--method warp; rgbd)")]
    pub references: Option<u32>,
    #[command(flatten)]
    pub synthesis: WarpSynthesisArgs,
}

impl WarpArgs {
    /// The first warp flag given, if any.
    pub fn given(&self) -> Option<&'static str> {
        let mut given = vec![("--references", self.references.is_some())];
        given.extend(self.synthesis.given());
        given
            .into_iter()
            .find(|(_, set)| *set)
            .map(|(flag, _)| flag)
    }

    /// Refuse warp flags with another method, and bad values, before loading anything.
    pub fn check(&self, method: Method) -> Result<()> {
        if let Some(flag) = self.given() {
            if method != Method::Warp {
                bail!(
                    "{flag}: only --method warp warps views (the method is {method}); drop it \
                     or add --method warp"
                );
            }
        }
        if self.references == Some(0) {
            bail!("--references 0: at least one reference view");
        }
        self.synthesis.check()?;
        WarpOptions::from(self).check()?;
        Ok(())
    }

    /// The library options these flags say.
    pub fn options(&self) -> WarpOptions {
        WarpOptions::from(self)
    }
}

impl From<&WarpArgs> for WarpOptions {
    fn from(args: &WarpArgs) -> Self {
        let default = WarpOptions::default();
        args.synthesis.apply(WarpOptions {
            references: args.references.unwrap_or(default.references),
            ..default
        })
    }
}

/// The share of subpixels a hole mask marks as filled rather than seen (255 on filled ones).
pub fn hole_share(mask: &autostereo::image_io::RgbImage) -> f64 {
    let filled = mask.data.iter().filter(|&&v| v >= 128).count();
    filled as f64 / mask.data.len().max(1) as f64
}
