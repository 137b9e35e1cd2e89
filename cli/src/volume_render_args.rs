//! How a volume is rendered (`--path`, `--alpha`, `--slices`/`--step`, shading and the compute
//! path's approximations): the flags `volume` and `view` share, their checks against the method
//! and their library options.

use anyhow::{bail, Result};
use autostereo::render::Method;
use autostereo::volume::{AlphaMode, Volume, VolumeScene, VolumeSettings};
use autostereo::{VolumeOptions, VolumePath};

/// `--fit`: what of a volume the camera frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Fit {
    /// The voxels the classification shows (`Volume::visible_bounds`).
    Visible,
    /// The whole box.
    Box,
}

impl Fit {
    /// Its flag value.
    pub fn name(self) -> &'static str {
        match self {
            Self::Visible => "visible",
            Self::Box => "box",
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PathArg {
    /// Compute pass: per-pixel ray marching, exact α per channel.
    Compute,
    /// The paper's view-aligned proxy slices, blended back to front.
    Slices,
}

/// How a volume is rendered: the flags `volume` and `view` share.
#[derive(clap::Args, Clone, Debug, PartialEq)]
pub struct VolumeRenderArgs {
    /// What a ray shows: composite (direct volume rendering), mip (maximum intensity), minip
    /// (minimum intensity) or average, each through the transfer function's colour (e.g.
    /// --projection mip --window 600,300 for contrast-filled vessels in HU).
    #[arg(long, value_enum, default_value = "composite")]
    pub(crate) projection: autostereo::volume::Projection,
    /// With --projection iso: the surface's value in the scan's units (HU for a CT: e.g. 300
    /// for bone, -500 for the skin).
    #[arg(long, value_name = "VALUE", allow_hyphen_values = true)]
    pub(crate) iso: Option<f64>,
    /// What the camera frames: visible (the box around the voxels the transfer function or
    /// isosurface shows, after --clip) or box (the volume's whole box, padding and all).
    #[arg(long, value_enum, default_value = "visible")]
    pub(crate) fit: Fit,
    /// Single-pass path.
    #[arg(long, value_enum, default_value = "compute")]
    pub(crate) path: PathArg,
    /// Slices path: per-channel (exact) or the paper's averaged α.
    #[arg(long, value_enum, default_value = "exact")]
    pub(crate) alpha: AlphaMode,
    /// Samples across the volume's diagonal (3 to 16384).
    #[arg(long, conflicts_with = "step", value_parser = parse_slices)]
    slices: Option<u32>,
    /// Sampling distance in voxels of the smallest spacing (default 0.5).
    #[arg(long)]
    step: Option<f32>,
    /// Emission-absorption only (no gradient shading).
    #[arg(long)]
    no_shading: bool,
    /// Don't jump over space the transfer function makes transparent (compute path; for
    /// measuring what skipping saves: the image is the same).
    #[arg(long)]
    no_skip_empty: bool,
    /// Single pass, compute path: a pixel's K rays share their samples where they lie within
    /// TAU voxels of each other (near the focal plane); 0 = every ray exact. Measured trade-off
    /// in docs/volumes/BENCHMARKS.md.
    #[arg(long, value_name = "TAU", default_value_t = 0.0)]
    share_samples: f32,
    /// Compute path, every method: after a segment that added nothing, probe P sample planes
    /// ahead and take the planes between as transparent where the segment between the two
    /// samples is (1 = exact; an approximation that can miss features thinner than P samples).
    /// Measured trade-off in docs/volumes/BENCHMARKS.md.
    #[arg(long, value_name = "P", default_value_t = 1)]
    empty_stride: u32,
    /// With --empty-stride: probes also step through thin material, where a sample step adds
    /// at most A opacity (0 = transparent material only). Measured in docs/volumes/BENCHMARKS.md.
    #[arg(long, value_name = "A", default_value_t = 0.0)]
    thin_alpha: f32,
}

/// `--slices N`: with fewer than 3 samples across the diagonal
/// ([`VolumeScene::step_for_slices`]: a step of diagonal / N) the image is background only
/// (measured: the built-in head and ml sets, compute and slices paths; 3 is the least that
/// shows the volume), so they are refused with the fix instead of writing a blank image.
fn parse_slices(s: &str) -> Result<u32, String> {
    let n: u32 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a whole number of samples"))?;
    if n < 3 {
        return Err(format!(
            "--slices {n} samples nothing of the volume (the image would be background): \
             give at least 3 samples across its diagonal (e.g. --slices 256), or --step"
        ));
    }
    let most = autostereo::volume::MAX_SAMPLES_PER_RAY as u32;
    if n > most {
        return Err(format!(
            "--slices {n}: at most {most} samples across the volume's diagonal (--slices {most})"
        ));
    }
    Ok(n)
}

impl VolumeRenderArgs {
    /// Refuse what `method` and `--path` would ignore, naming what uses it.
    pub fn check(&self, method: Method) -> Result<()> {
        if self.path == PathArg::Slices && method != Method::SinglePass {
            bail!(
                "--path slices: only the single pass draws proxy slices (the {method} method \
                 ray-marches each view); drop it or use --method single-pass"
            );
        }
        if self.alpha != AlphaMode::Exact && self.path != PathArg::Slices {
            bail!(
                "--alpha: only --path slices blends one α per pixel or per channel (the compute \
                 path's α is always per channel, exact); drop it or add --path slices"
            );
        }
        let compute_only = [
            ("--no-skip-empty", self.no_skip_empty),
            ("--empty-stride", self.empty_stride != 1),
            ("--thin-alpha", self.thin_alpha != 0.0),
            ("--share-samples", self.share_samples != 0.0),
        ];
        for (flag, set) in compute_only {
            if set && self.path != PathArg::Compute {
                bail!(
                    "{flag}: only the compute path (--path compute) ray-marches; the slices \
                     path samples every slice"
                );
            }
        }
        if self.share_samples != 0.0 && method != Method::SinglePass {
            bail!(
                "--share-samples: only the single pass marches a pixel's rays together (the \
                 {method} method marches one view at a time); drop it or use --method \
                 single-pass"
            );
        }
        if self.thin_alpha != 0.0 && self.empty_stride == 1 {
            bail!(
                "--thin-alpha sets how far the probes of --empty-stride P step through thin \
                 material, and there are none with --empty-stride 1: add --empty-stride P > 1"
            );
        }
        Ok(())
    }

    /// The sampling step the flags say (voxels of the smallest spacing; None = the default).
    pub fn step(&self, volume: &Volume) -> Option<f32> {
        match (self.slices, self.step) {
            (Some(n), _) => Some(VolumeScene::step_for_slices(volume, n)),
            (None, step) => step,
        }
    }

    /// `--iso` as the normalised scalar of a volume of `values`, checked against its range.
    /// The box the camera frames for `data` (--fit); the whole box, said, where nothing is
    /// visible.
    pub fn framed(&self, data: &autostereo::VolumeData) -> Result<autostereo::camera::Bounds> {
        let volume = &data.volume;
        if self.fit == Fit::Box {
            return Ok(volume.bounds());
        }
        let isovalue = self.isovalue(&volume.values)?;
        let (bounds, visible) = data.framed_bounds(self.projection, isovalue);
        if !visible {
            eprintln!(
                "note: the transfer function shows none of the volume's voxels (within \
                 --clip): framing its whole box (--fit box); try another --tf or --window"
            );
        }
        Ok(bounds)
    }

    pub fn isovalue(&self, values: &autostereo::volume::Values) -> Result<f32> {
        use autostereo::volume::Projection;
        match (self.projection, self.iso) {
            (Projection::Isosurface, None) => bail!(
                "--projection iso needs --iso VALUE (in the scan's units; its values are {})",
                values.described()
            ),
            (Projection::Isosurface, Some(v)) => {
                let [lo, hi] = values.range;
                if !(lo..=hi).contains(&v) {
                    bail!(
                        "--iso {v}: outside the scan's values {}",
                        values.described()
                    );
                }
                Ok(values.normalise(v))
            }
            (_, Some(_)) => bail!("--iso sets the surface of --projection iso"),
            (_, None) => Ok(0.5),
        }
    }

    /// The volume options the flags say, `step` from [`Self::step`].
    pub fn options(&self, step: Option<f32>) -> VolumeOptions {
        let settings = VolumeSettings {
            step,
            shade: !self.no_shading,
            skip_empty: !self.no_skip_empty,
            share_samples: self.share_samples,
            empty_stride: self.empty_stride,
            thin_alpha: self.thin_alpha,
            projection: self.projection,
            isovalue: 0.5,
        };
        let path = match (self.path, self.alpha) {
            (PathArg::Compute, _) => VolumePath::RayMarch,
            (PathArg::Slices, alpha) => VolumePath::Slices(alpha),
        };
        VolumeOptions { path, settings }
    }
}
