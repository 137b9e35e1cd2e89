//! `autostereo view`: the viewer window (the `autostereo-viewer` crate, viewer/) on the scene
//! and settings its flags say; the flags of every primitive as the render commands have them.

mod scene;

use std::path::PathBuf;

use anyhow::Result;
use autostereo::render::Method;
use autostereo_viewer::{Preview, Switch};

use crate::args::{CameraArgs, DisplayArgs};
use crate::parse::{check_output, parse_size};

#[derive(clap::Args)]
pub struct ViewArgs {
    /// A mesh, point cloud, volume or Gaussian splat file or DICOM folder (its kind told by its
    /// first bytes, else its extension; a PLY with faces is a mesh, one with graphdeco's
    /// properties Gaussians); the built-in head volume when omitted.
    file: Option<PathBuf>,
    /// What the file holds, where its extension does not say.
    #[arg(long, value_enum, help_heading = "Input")]
    kind: Option<autostereo::DataKind>,
    #[command(flatten)]
    display: DisplayArgs,
    #[command(flatten)]
    camera: CameraArgs,
    // Mesh flags, as `autostereo mesh` has them (one definition: cli/src/mesh_cmd.rs).
    #[command(flatten, next_help_heading = "Mesh")]
    mesh: crate::mesh_cmd::MeshFlags,
    // Point-cloud flags, as `autostereo points` has them.
    #[command(flatten, next_help_heading = "Points")]
    points: crate::points_cmd::PointFlags,
    // Volume flags, as `autostereo volume` has them.
    #[command(flatten, next_help_heading = "Volume")]
    volume_data: crate::volume_cmd::VolumeDataArgs,
    #[command(flatten, next_help_heading = "Volume")]
    volume_render: crate::volume_cmd::VolumeRenderArgs,
    // Gaussian splat flags, as `autostereo gaussians` has them.
    #[command(flatten, next_help_heading = "Gaussians")]
    gaussians: crate::gaussians_cmd::GaussianFlags,
    #[command(flatten, next_help_heading = "Points and Gaussians")]
    crop: crate::crop_box_arg::CropBoxArgs,
    #[command(flatten)]
    memory: crate::args::MemoryArgs,
    /// Window client-area size WxH in pixels.
    #[arg(long, value_parser = parse_size, default_value = "512x512", help_heading = "Window")]
    size: [u32; 2],
    /// Window position X,Y on the screen (the mask's origin follows it); negative on a
    /// monitor left of or above the primary (`--position -1920,0`).
    #[arg(long, value_name = "X,Y", value_parser = crate::parse::parse_point, allow_hyphen_values = true, help_heading = "Window")]
    position: Option<[i32; 2]>,
    /// Full screen: without a number on the display's panel (the monitor of a Looking Glass
    /// calibration's size, said on stderr; other displays: the first monitor), else on monitor
    /// MONITOR (0 = the first; --list-monitors lists them). The mask follows the window's
    /// place on its monitor: no --origin needed for a panel beside another monitor.
    #[arg(long, value_name = "MONITOR", num_args = 0..=1, default_missing_value = "panel", value_parser = parse_monitor, help_heading = "Window")]
    fullscreen: Option<autostereo_viewer::Monitor>,
    /// List the monitors (number, name, size, position on the desktop, scale) and exit.
    #[arg(long, help_heading = "Window")]
    list_monitors: bool,
    /// Starting method (keys: m cycles through the primitive's methods).
    #[arg(long, value_parser = crate::parse::method_parser(), default_value = "single-pass", help_heading = "Method")]
    method: Method,
    /// What the window shows (key: p).
    #[arg(long, value_enum, default_value = "spatial", help_heading = "Window")]
    preview: Preview,
    /// Save what was presented as PNG (read back from the surface texture) after
    /// --quit-after-frames frames, or after 3, and then exit (for scripts), unless
    /// --keep-open.
    #[arg(long, help_heading = "Scripts")]
    screenshot: Option<PathBuf>,
    /// With --screenshot: keep the window open after the screenshot is saved (until Esc or
    /// the window is closed) instead of exiting.
    #[arg(
        long,
        requires = "screenshot",
        conflicts_with = "quit_after_frames",
        help_heading = "Scripts"
    )]
    keep_open: bool,
    /// Exit after K presented frames.
    #[arg(long, help_heading = "Scripts")]
    quit_after_frames: Option<u32>,
    /// Print one JSON object when the viewer ends: the scene, method, display, window size,
    /// frames presented and the files written (`written`: the screenshot); an --exercise
    /// run's memory report in it.
    #[arg(long, help_heading = "Scripts")]
    json: bool,
    /// Move the window to X,Y after frame K (tests: the mask phase must follow): K:X,Y (X, Y
    /// negative as --position's).
    #[arg(long, value_name = "K:X,Y", value_parser = parse_move, help_heading = "Scripts")]
    move_after: Option<(u32, [i32; 2])>,
    /// Scripted stress run for K frames: switch the method every 10 frames, the display every
    /// 70, the window size every 35; prints (JSON) resident memory every 50 frames, the heap
    /// in use every 10, the live GPU objects at each end of the period after which the run's
    /// state repeats, and that period.
    #[arg(long, help_heading = "Scripts")]
    exercise: Option<u32>,
    /// What the exercise run switches (default all).
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "methods,displays,sizes",
        requires = "exercise",
        help_heading = "Scripts"
    )]
    exercise_switch: Vec<Switch>,
}

fn parse_move(s: &str) -> Result<(u32, [i32; 2]), String> {
    let (frame, at) = s
        .split_once(':')
        .ok_or_else(|| format!("'{s}' is not K:X,Y"))?;
    let frame = frame
        .trim()
        .parse()
        .map_err(|_| format!("'{s}': K is not a whole number"))?;
    Ok((frame, crate::parse::parse_point(at)?))
}

impl ViewArgs {
    /// What to load, with every primitive's flags.
    fn scene_flags(&self) -> scene::SceneFlags<'_> {
        scene::SceneFlags {
            file: self.file.as_deref(),
            kind: self.kind,
            mesh: &self.mesh,
            points: &self.points,
            volume_data: &self.volume_data,
            volume_render: &self.volume_render,
            gaussians: &self.gaussians,
            crop: self.crop,
        }
    }
}

/// `--fullscreen` `panel` (no number given) or a monitor's number.
fn parse_monitor(value: &str) -> Result<autostereo_viewer::Monitor, String> {
    match value {
        "panel" => Ok(autostereo_viewer::Monitor::Panel),
        number => number
            .parse()
            .map(autostereo_viewer::Monitor::Index)
            .map_err(|_| format!("'{number}' is not a monitor number (0 = the first)")),
    }
}

/// `--list-monitors`: one line each on stdout (with `--json`, one object).
fn list_monitors(json: bool) -> Result<()> {
    let monitors = autostereo_viewer::monitors().map_err(in_flag_words)?;
    match json {
        true => println!("{}", serde_json::json!({ "monitors": monitors })),
        false if monitors.is_empty() => println!("no monitors found"),
        false => monitors.iter().for_each(|m| println!("{}", m.line())),
    }
    Ok(())
}

/// `given`: the `view` command's matches (which flags were typed, not defaulted).
pub fn run(args: ViewArgs, given: &clap::ArgMatches) -> Result<()> {
    if args.list_monitors {
        return list_monitors(args.json);
    }
    if let Some(path) = &args.screenshot {
        check_output(path)?;
    }
    if args.quit_after_frames == Some(0) {
        anyhow::bail!("--quit-after-frames 0: at least one frame");
    }
    let _budget = args.memory.apply();
    // Fail on a bad display or flags of another primitive before opening a window.
    let display = args.display.display()?;
    args.scene_flags().check(given)?;
    let scene = scene::load(&args.scene_flags())?;
    let options = autostereo_viewer::Options {
        display,
        display_name: args.display.display.clone(),
        camera: args.camera.settings(),
        orbit: Default::default(),
        size: args.size,
        position: args.position,
        fullscreen: args.fullscreen,
        method: args.method,
        preview: args.preview,
        screenshot: args.screenshot.clone(),
        keep_open: args.keep_open,
        quit_after_frames: args.quit_after_frames,
        move_after: args.move_after,
        exercise: args.exercise,
        exercise_switch: args.exercise_switch.clone(),
    };
    let report = autostereo_viewer::run(scene, options).map_err(in_flag_words)?;
    print_report(&report, args.json);
    Ok(())
}

/// A viewer error in the command line's words: the setting it is about named by its flag; the
/// library's errors as they are (`flags::describe` names their flags).
fn in_flag_words(error: autostereo_viewer::Error) -> anyhow::Error {
    use autostereo_viewer::Error;
    match error {
        Error::Library(e) => e.into(),
        Error::NoMonitor { index, found } => {
            anyhow::anyhow!("--fullscreen {index}: {found} monitor(s) found, numbered from 0")
        }
        e @ Error::NoPanelMonitor { .. } => anyhow::anyhow!(
            "--fullscreen: {e} (give --fullscreen MONITOR to choose one; --list-monitors lists \
             them)"
        ),
        Error::WindowTooLarge {
            size: [w, h],
            fullscreen,
            limit,
            adapter,
        } => anyhow::anyhow!(
            "{} {w}x{h}: larger than this adapter's largest surface ({limit} per side on \
             {adapter})",
            match fullscreen {
                true => "--fullscreen: the monitor's size",
                false => "--size",
            }
        ),
        Error::MethodUnavailable {
            method,
            primitive,
            available,
        } => anyhow::anyhow!(
            "--method {method}: {primitive} scenes have {}",
            available
                .iter()
                .map(|m| m.name())
                .collect::<Vec<_>>()
                .join(", ")
        ),
        other => other.into(),
    }
}

/// With `--json`, one object saying what the viewer showed and the files it wrote (`written`),
/// as every command's `--json` does, an exercise run's memory report in it; without, the
/// exercise report alone (cli/tests/viewer reads it).
fn print_report(report: &autostereo_viewer::Report, json: bool) {
    match (json, &report.exercise) {
        (false, exercise) => {
            if let Some(exercise) = exercise {
                println!("{exercise}");
            }
            crate::output::say_written(false, &report.written);
        }
        (true, exercise) => {
            let mut fields = exercise.clone().unwrap_or_else(|| serde_json::json!({}));
            let own = serde_json::to_value(report).expect("a report is plain data");
            crate::run::merge(&mut fields, own);
            println!("{fields}");
        }
    }
}
