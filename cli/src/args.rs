//! Flag groups shared by several subcommands (display, memory, frames, the render commands'
//! `RenderArgs`); their value parsers are cli/src/parse.rs.

use anyhow::{bail, Context, Result};
use autostereo::render::Method;

use autostereo::display::Display;

pub use crate::camera_args::CameraArgs;
use crate::method_arg::{MethodArg, MethodParser};
use crate::parse::{frames_parser, parse_point, parse_size, parse_view_scale};

/// Display selection flags.
#[derive(clap::Args, Clone, Debug)]
#[command(next_help_heading = "Display")]
pub struct DisplayArgs {
    /// Display: hubner8 | lenticular:N | slanted:N,PITCH,SLANT,PHASE | lkg:PATH.json | lkg (the
    /// attached Looking Glass's calibration) | view:N,V
    /// (view V of N on every pixel: one full-resolution view by any method)
    #[arg(long, default_value = "hubner8")]
    pub display: String,
    /// Number of views (Looking Glass: default the family's, e.g. 49 for a 16" Spatial Display,
    /// 45 where the serial names none; others: must match the display).
    #[arg(long)]
    pub views: Option<u32>,
    /// Window origin on the panel in pixels, X,Y; negative where the window starts left of or
    /// above the panel (`--origin -100,20`). `view` adds the window's position on the monitor
    /// it is on (the panel), wherever that monitor sits on the desktop.
    #[arg(long, value_name = "X,Y", value_parser = parse_point, default_value = "0,0", allow_hyphen_values = true)]
    pub origin: [i32; 2],
    /// Reverse the view order.
    #[arg(long)]
    pub flip_views: bool,
    /// The panel's subpixels are ordered BGR.
    #[arg(long)]
    pub bgr: bool,
}

impl DisplayArgs {
    /// These flags as a command line would repeat them, with the view count `views` the run
    /// used (so that another command sees the same display).
    pub fn flags(&self, views: u32) -> String {
        let mut flags = format!("--display {} --views {views}", self.display);
        if self.origin != [0, 0] {
            flags += &format!(" --origin {},{}", self.origin[0], self.origin[1]);
        }
        if self.flip_views {
            flags += " --flip-views";
        }
        if self.bgr {
            flags += " --bgr";
        }
        flags
    }

    /// Refuse the flags that place the interleaved image on a panel (`--origin`,
    /// `--flip-views`, `--bgr`) with an output that is not interleaved (`--output FORMAT`).
    pub fn check_spatial_only(&self, format: &str) -> Result<()> {
        let given = [
            ("--origin", self.origin != [0, 0]),
            ("--flip-views", self.flip_views),
            ("--bgr", self.bgr),
        ];
        if let Some((flag, _)) = given.iter().find(|(_, set)| *set) {
            bail!(
                "{flag} places the interleaved image on the panel; --output {format} is made of \
                 whole views and does not use it (drop it, or --output spatial)"
            );
        }
        Ok(())
    }

    /// Build the display these flags describe.
    pub fn display(&self) -> Result<Display> {
        // A number in the spec itself that the display cannot use is --display's error (a
        // calibration file's keeps the file's name).
        let from_file = self
            .display
            .trim_start()
            .to_ascii_lowercase()
            .starts_with("lkg");
        let mut display = Display::parse(&self.display).map_err(|e| match e {
            autostereo::Error::InvalidParameter { param, reason, .. } if !from_file => {
                anyhow::anyhow!("--display {}: invalid {param}: {reason}", self.display)
            }
            e => e.into(),
        })?;
        if let Some(n) = self.views {
            display = display.with_views(n)?;
        }
        display.origin = self.origin;
        display.flip_views ^= self.flip_views;
        display.bgr ^= self.bgr;
        Ok(display)
    }
}

/// The image size: `--size`, else the display's panel (a Looking Glass calibration's), else
/// [`DEFAULT_SIZE`].
pub fn image_size(size: Option<[u32; 2]>, display: &Display) -> [u32; 2] {
    size.or(display.panel_size()).unwrap_or(DEFAULT_SIZE)
}

/// The image size of displays that do not say theirs.
pub const DEFAULT_SIZE: [u32; 2] = [512, 512];

/// Create the GPU context (adapter from WGPU_BACKEND / WGPU_ADAPTER_NAME) and log it.
pub fn gpu() -> Result<autostereo::gpu::GpuContext> {
    let ctx =
        autostereo::gpu::GpuContext::new(&Default::default()).context("setting up the GPU")?;
    Ok(ctx)
}

/// The long flags of the group `T` that the command line gave (clap's value source: not a
/// default), in their order there: to name the flag a refusal is about. `matches`: those of
/// the subcommand `T` is flattened into.
pub fn flags_given<T: clap::Args>(matches: &clap::ArgMatches) -> Vec<String> {
    use clap::parser::ValueSource;
    let group = T::augment_args(clap::Command::new("group"));
    let mut given: Vec<(usize, String)> = group
        .get_arguments()
        .filter_map(|arg| {
            let id = arg.get_id().as_str();
            let typed = matches.value_source(id) == Some(ValueSource::CommandLine);
            let at = matches.index_of(id).unwrap_or(usize::MAX);
            typed.then(|| Some((at, format!("--{}", arg.get_long()?))))?
        })
        .collect();
    given.sort();
    given.into_iter().map(|(_, flag)| flag).collect()
}

/// `--max-memory`: the loading budget, one definition for every command that loads data.
#[derive(clap::Args, Clone, Debug)]
pub struct MemoryArgs {
    /// CPU memory budget for loading (bytes, or with K/M/G/T, KB…TB or KiB…TiB, all binary:
    /// 1K = 1KB = 1KiB = 1024 bytes; default 8G): inputs that would
    /// need more are refused before anything is allocated.
    #[arg(long, value_parser = autostereo::budget::parse_bytes, help_heading = "Input")]
    pub max_memory: Option<u64>,
}

impl MemoryArgs {
    /// The command's budget (the flag's figure, else the default), current on this thread
    /// while the guard lives: hold it for the whole command.
    #[must_use = "the budget applies only while the guard lives"]
    pub fn apply(&self) -> autostereo::budget::Entered {
        let bytes = self
            .max_memory
            .unwrap_or(autostereo::budget::DEFAULT_MAX_MEMORY);
        autostereo::budget::Budget::new(bytes).enter()
    }
}

/// `--frames N`: timing, one definition for every command that renders frames.
#[derive(clap::Args, Clone, Debug)]
pub struct FramesArgs {
    /// Time N frames after two warm-up frames and report the median (without it: one frame,
    /// no warm-up).
    #[arg(long, value_name = "N", value_parser = frames_parser(), help_heading = "Measuring")]
    pub frames: Option<u32>,
}

impl FramesArgs {
    /// Frames rendered before timing: two when timing is asked for (lavapipe compiles shaders
    /// on first use), none for one image.
    pub fn warm_up(&self) -> u32 {
        if self.frames.is_some() {
            2
        } else {
            0
        }
    }

    /// Frames timed (and rendered after the warm-up).
    pub fn timed(&self) -> u32 {
        self.frames.unwrap_or(1)
    }

    /// What the reported time is, for the console: "one frame" or "median of N frames".
    pub fn described(&self) -> String {
        match self.frames {
            None => "one frame".into(),
            Some(1) => "1 frame after 2 warm-up frames".into(),
            Some(n) => format!("median of {n} frames"),
        }
    }

    /// The `--json` fields: frames timed and warm-up frames before them.
    pub fn fields(&self) -> serde_json::Value {
        serde_json::json!({ "frames": self.timed(), "warm_up_frames": self.warm_up() })
    }
}

/// Flags every render command shares (extend, don't break: tools and benchmarks use them).
#[derive(clap::Args)]
pub struct RenderArgs {
    #[command(flatten)]
    pub memory: MemoryArgs,
    #[command(flatten)]
    pub display: DisplayArgs,
    #[command(flatten)]
    pub camera: CameraArgs,
    /// Image size WxH in pixels (default: a Looking Glass calibration's panel, else 512x512).
    #[arg(long, value_parser = parse_size, help_heading = "Display")]
    pub size: Option<[u32; 2]>,
    /// Rendering method (each command offers its primitive's: cli/src/method_arg.rs).
    #[arg(long, value_parser = MethodParser::new("scenes", &Method::ALL), default_value = "auto", help_heading = "Method")]
    pub method: MethodArg,
    /// With --method auto: also choose approximations whose PSNR against the N-pass, as
    /// measured in docs/quilt_pipeline.md, is at least DB (the quilt pipeline, the lower of two
    /// panels: 41.8 dB for meshes, 36 for points, 47.6 for volumes); without it auto chooses
    /// exact methods only.
    #[arg(long, value_name = "DB", help_heading = "Method")]
    pub min_psnr: Option<f32>,
    /// Per-view resolution: the n-pass, tiled, layered and mrt methods render their view
    /// images at S × --size (each side rounded up) and up-sample them bilinearly when
    /// compositing; 1 = full size. In (0, 1].
    #[arg(long, value_name = "S", default_value_t = 1.0, value_parser = parse_view_scale, help_heading = "Method")]
    pub view_scale: f32,
    /// The view images' size instead of --view-scale (each side at most --size's; the views
    /// keep the camera's aspect, so tiles of another aspect stretch as Looking Glass's quilts
    /// do: e.g. --method tiled --view-size 857x857 renders a 16" panel's 7x7 quilt of 857x857);
    /// with --output quilt also the size of the quilt's tiles.
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with = "view_scale", help_heading = "Method")]
    pub view_size: Option<[u32; 2]>,
    #[command(flatten)]
    pub output: crate::output::flags::OutputArgs,
    #[command(flatten)]
    pub turntable: crate::output::flags::TurntableArgs,
    /// Also render N-pass and report psnr_db, max_abs_err, frac_off_2 against it.
    #[arg(long, help_heading = "Measuring")]
    pub compare: bool,
    #[command(flatten)]
    pub timing: FramesArgs,
}
