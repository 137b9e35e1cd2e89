//! `autostereo`: command-line front end of the library.

mod args;
mod camera_args;
mod claims;
mod crop_box_arg;
#[cfg(test)]
mod doc_examples;
mod examples;
mod flags;
mod gaussians_cmd;
mod interleave_cmd;
mod mask_cmd;
mod mesh_cmd;
mod method_arg;
mod output;
mod parse;
mod parse_errors;
mod plan;
mod points_cmd;
mod progress;
mod rgbd_cmd;
mod run;
mod turntable;
mod view;
mod views_cmd;
mod volume_box_args;
mod volume_cmd;
mod volume_render_args;
mod warp_cmd;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "autostereo",
    version,
    about = "Multi-view rendering for autostereoscopic displays"
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// In the order a user meets them: the renderers of each kind of data, then the converters
/// and viewers, then the tools.
#[derive(Subcommand)]
enum Command {
    /// Render a triangle mesh (OBJ, PLY, STL, glTF; a generated torus scene when no file is
    /// given).
    #[command(
        after_help = examples::MESH,
        mut_arg("method", |a| method_arg::method_arg(a, "meshes", &autostereo::mesh::METHODS))
    )]
    Mesh(mesh_cmd::MeshArgs),
    /// Render a point cloud as splats (PLY, LAS/LAZ, OBJ vertices; a generated scene when no
    /// file is given).
    #[command(
        after_help = examples::POINTS,
        mut_arg("method", |a| method_arg::method_arg(a, "points", &autostereo::points::METHODS))
    )]
    Points(points_cmd::PointsArgs),
    /// Render a volume (NRRD, NIfTI, MetaImage, VTK, DICOM series, raw; a built-in CT-like
    /// head when no file is given).
    #[command(
        after_help = examples::VOLUME,
        mut_arg("method", |a| method_arg::method_arg(a, "volumes", &autostereo::volume::METHODS))
    )]
    Volume(volume_cmd::VolumeArgs),
    /// Render 3D Gaussian splats (graphdeco PLY, .splat, .spz; a generated scene when no file
    /// is given).
    #[command(
        after_help = examples::GAUSSIANS,
        mut_arg("method", |a| method_arg::method_arg(a, "Gaussian splats", &autostereo::gaussians::METHODS))
    )]
    Gaussians(gaussians_cmd::GaussiansArgs),
    /// An RGB-D image (colour + depth, or side by side) to any display, a quilt or per-view
    /// PNGs.
    #[command(after_help = examples::RGBD)]
    Rgbd(rgbd_cmd::RgbdArgs),
    /// A Looking Glass quilt (views rendered anywhere) to any display's spatial image.
    #[command(after_help = examples::INTERLEAVE)]
    Interleave(interleave_cmd::InterleaveArgs),
    /// Open a window and render live (mouse: orbit, zoom, pan; keys: m method, d display,
    /// p preview, [ ] separation, - = focal plane, r reset, Esc quit).
    #[command(after_help = examples::VIEW)]
    View(view::ViewArgs),
    /// Extract what one view zone sees from a spatial image, or a red/cyan anaglyph.
    #[command(after_help = examples::VIEWS)]
    Views(views_cmd::ViewsArgs),
    /// Write a display mask as a view-index image (each channel = view of that subpixel).
    #[command(after_help = examples::MASK)]
    Mask(mask_cmd::MaskArgs),
}

fn main() -> std::process::ExitCode {
    // wgpu probes EGL displays and logs their failures as errors even when Vulkan is used.
    env_logger::Builder::from_env(
        env_logger::Env::default()
            .default_filter_or("warn,autostereo=info,wgpu_hal::gles::egl=off"),
    )
    .format_timestamp(None)
    .init();
    // args_os: a file name that is not UTF-8 must reach the parser, not panic here.
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let parsed = Cli::command()
        .try_get_matches_from(&args)
        .and_then(|matches| Ok((Cli::from_arg_matches(&matches)?, matches)));
    let (cli, matches) = match parsed {
        Ok(parsed) => parsed,
        Err(e) => match parse_errors::explain(
            &e,
            &args
                .iter()
                .map(|a| a.to_string_lossy().into_owned())
                .collect::<Vec<_>>(),
        ) {
            Some(text) => {
                eprintln!("error: {text}");
                return std::process::ExitCode::from(2);
            }
            None => e.exit(),
        },
    };
    let result = match cli.command {
        Command::Mask(a) => mask_cmd::run(a),
        Command::Mesh(a) => mesh_cmd::run(a),
        Command::Gaussians(a) => gaussians_cmd::run(a),
        Command::Interleave(a) => interleave_cmd::run(a),
        Command::Points(a) => points_cmd::run(a),
        Command::Rgbd(a) => rgbd_cmd::run(a),
        Command::View(a) => view::run(
            a,
            matches
                .subcommand_matches("view")
                .expect("the view command's matches"),
        ),
        Command::Views(a) => views_cmd::run(a),
        Command::Volume(a) => volume_cmd::run(a),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", flags::describe(&e));
            std::process::ExitCode::FAILURE
        }
    }
}
