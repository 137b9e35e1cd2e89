//! `autostereo volume`: render a volume (a built-in data set when no file is given).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use autostereo::render::Method;
use autostereo::volume::load::{RawSpec, SampleType};
use autostereo::volume::VolumeScene;
use autostereo::volume::{generate, Transfer, TransferFunction, Volume};
use autostereo::{AnyData, DataKind, LoadOptions, VolumeData, VolumeLoad};
use glam::Mat4;

use crate::args::{gpu, RenderArgs};
use crate::run::{render_and_save, report, run_summary, Rendered};
use crate::volume_box_args::{parse_clip, parse_crop, ClipArg};
pub use crate::volume_render_args::{PathArg, VolumeRenderArgs};
use autostereo::volume::VolumeSettings;
use autostereo::RendererOptions;

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Builtin {
    /// A contrast CT of a head and neck: face, skull, teeth, spine, arteries, folded brain
    /// (anisotropic z).
    Head,
    /// The Marschner–Lobb test signal.
    Ml,
}

#[derive(clap::Args)]
pub struct VolumeArgs {
    /// Volume file or DICOM series folder (NRRD, NIfTI .nii/.nii.gz, MetaImage .mha/.mhd,
    /// VTK image data .vti/.vtk, DICOM, .den, or raw with --raw-dims/--raw-type); a built-in
    /// data set when omitted.
    file: Option<PathBuf>,
    #[command(flatten, next_help_heading = "Input")]
    data: VolumeDataArgs,
    #[command(flatten)]
    common: RenderArgs,
    #[command(flatten)]
    warp: crate::warp_cmd::WarpArgs,
    #[command(flatten, next_help_heading = "Method")]
    render: VolumeRenderArgs,
    /// Retired: `--output anaglyph --out F.png` writes the red/cyan anaglyph.
    #[arg(long, hide = true)]
    anaglyph: Option<PathBuf>,
}

/// How a volume is loaded and placed: the flags `volume` and `view` share.
#[derive(clap::Args, Clone, Debug, PartialEq)]
pub struct VolumeDataArgs {
    /// Built-in data set used when no file is given [default: head].
    #[arg(long, value_enum)]
    builtin: Option<Builtin>,
    /// Voxels per axis of the built-in data set (4 to 1024) [default: 96].
    #[arg(long, value_parser = clap::value_parser!(u32).range(4..=1024))]
    builtin_size: Option<u32>,
    /// Transfer function: a preset (ct-skin, ct-bone, mri, ml; the CT presets are in HU where
    /// the scan is) or a file of `s r g b a` lines on the normalised scalar, or — after a line
    /// `units` — `value r g b a` lines in the scan's units (HU for a CT).
    #[arg(long, conflicts_with = "window")]
    tf: Option<String>,
    /// A radiologist's window WIDTH,LEVEL in the scan's units (HU for a CT): grey and opacity
    /// ramp from level − width/2 to level + width/2. Alone: the file's own window (DICOM's
    /// WindowWidth/WindowCenter).
    #[arg(long, value_name = "WIDTH,LEVEL", num_args = 0..=1, default_missing_value = "file", value_parser = parse_window)]
    window: Option<WindowArg>,
    /// Rotate the volume by AX,AY,AZ degrees (about x, then y, then z); negative angles as
    /// they are (`--rotate -90,0,0`).
    #[arg(
        long,
        value_name = "AX,AY,AZ",
        value_parser = parse_f32_triple,
        default_value = "0,0,0",
        allow_hyphen_values = true
    )]
    rotate: [f32; 3],
    /// Raw files: dimensions X,Y,Z.
    #[arg(long, value_parser = parse_u32_triple)]
    raw_dims: Option<[u32; 3]>,
    /// Raw files: sample type (u8, i8, u16, i16, u32, i32, f32, f64).
    #[arg(long)]
    raw_type: Option<String>,
    /// Raw files: samples are big-endian.
    #[arg(long)]
    raw_big_endian: bool,
    /// Raw files: bytes to skip before the samples.
    #[arg(long, default_value_t = 0)]
    raw_header: u64,
    /// Voxel spacing X,Y,Z (overrides the file's; each 1e-6 to 1e6).
    #[arg(long, value_parser = parse_spacing)]
    spacing: Option<[f32; 3]>,
    /// Keep only a box of the volume: voxels X0,Y0,Z0,X1,Y1,Z1 (inclusive), or with `mm` after
    /// the last number the same in the spacing's units from the first voxel's corner
    /// (`--crop 0,0,40,511,511,80` or `--crop 20,20,0,180,180,60mm`).
    #[arg(long, value_name = "X0,Y0,Z0,X1,Y1,Z1[mm]", value_parser = parse_crop)]
    crop: Option<autostereo::volume::Crop>,
    /// Clip the volume by a plane, keeping one side (repeat for up to 6, every method):
    /// `x<40` keeps voxels below x = 40, `z>12.5mm` the part beyond 12.5 mm, `NX,NY,NZ,D` the
    /// points with NX·x + NY·y + NZ·z ≤ D — in voxels, or with `mm` after it in the spacing's
    /// units, from the first voxel's corner of the volume as rendered (after --crop).
    #[arg(long, value_name = "AXIS<V|AXIS>V|NX,NY,NZ,D[mm]", value_parser = parse_clip, allow_hyphen_values = true)]
    clip: Vec<ClipArg>,
    /// Average blocks of F³ voxels first (for volumes over the adapter's 3D texture limit).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=256))]
    downsample: u32,
}

fn parse_triple<T: std::str::FromStr>(s: &str) -> Result<[T; 3], String> {
    let parts: Vec<&str> = s.split(',').collect();
    let bad = || format!("'{s}' is not three comma-separated numbers");
    if parts.len() != 3 {
        return Err(bad());
    }
    let mut out = Vec::with_capacity(3);
    for p in parts {
        out.push(p.trim().parse::<T>().map_err(|_| bad())?);
    }
    out.try_into().map_err(|_| bad())
}

fn parse_u32_triple(s: &str) -> Result<[u32; 3], String> {
    parse_triple(s)
}

/// `--spacing`'s range: each axis 1e-6 to 1e6 world units per voxel. Outside it the volume's
/// box (up to 1024 voxels a side times the spacing) leaves f32 cameras nothing usable: a
/// 1e30 spacing overflowed the framing ("the scene's bounds Vec3(-8e30, …)"), and 0 or a
/// negative spacing is no box at all.
const SPACING_RANGE: (f32, f32) = (1e-6, 1e6);

fn parse_spacing(s: &str) -> Result<[f32; 3], String> {
    let v = parse_f32_triple(s)?;
    let (min, max) = SPACING_RANGE;
    if v.iter().all(|x| (min..=max).contains(x)) {
        Ok(v)
    } else {
        Err(format!(
            "each voxel spacing must be from {min:e} to {max:e} world units per voxel \
             (e.g. --spacing 1,1,2)"
        ))
    }
}

fn parse_f32_triple(s: &str) -> Result<[f32; 3], String> {
    let v: [f32; 3] = parse_triple(s)?;
    if v.iter().all(|x| x.is_finite()) {
        Ok(v)
    } else {
        Err(format!("'{s}' has a non-finite value"))
    }
}

impl VolumeDataArgs {
    /// The volume in `file` (the built-in data set without one), resampled, classified by
    /// --tf (else the preset of its format) and placed by --rotate: by the library's
    /// [`autostereo::load`] for a file.
    pub fn load(&self, file: Option<&Path>) -> Result<VolumeData> {
        let mut data = self.load_unclipped(file)?;
        data.clip = self.clip_planes(&data.volume);
        Ok(data)
    }

    fn load_unclipped(&self, file: Option<&Path>) -> Result<VolumeData> {
        let raw = self.raw_dims.is_some()
            || self.raw_type.is_some()
            || self.raw_big_endian
            || self.raw_header != 0;
        let Some(path) = file else {
            if raw {
                bail!(
                    "--raw-dims, --raw-type, --raw-big-endian and --raw-header describe a raw \
                     FILE, and none is given"
                );
            }
            let size = self.builtin_size.unwrap_or(96);
            let (volume, preset) = match self.builtin.unwrap_or(Builtin::Head) {
                Builtin::Head => (generate::ct_head(size)?, "ct-skin"),
                Builtin::Ml => (generate::marschner_lobb(size)?, "ml"),
            };
            let volume = match self.spacing {
                Some(spacing) => Volume::new(volume.dims, spacing, volume.data)?,
                None => volume,
            };
            let volume = match self.crop {
                Some(crop) => volume.cropped(crop)?,
                None => volume,
            };
            let volume = autostereo::resampled(volume, self.downsample)?;
            let mut data = VolumeData::with_preset(volume, preset, self.model())?;
            if let Some(choice) = self.transfer()? {
                let (transfer, preset) = choice.resolve(&data.volume.values)?;
                data.transfer = transfer;
                data.preset = preset;
            }
            return Ok(data);
        };
        if self.builtin.is_some() || self.builtin_size.is_some() {
            bail!(
                "--builtin and --builtin-size choose the data set used without a FILE, and {} is \
                 given",
                path.display()
            );
        }
        let options = LoadOptions {
            kind: Some(DataKind::Volume),
            volume: self.volume_load()?,
            ..LoadOptions::default()
        };
        match crate::progress::during(&crate::progress::loading(path), || {
            autostereo::load(path, &options)
        })? {
            AnyData::Volume(data) => Ok(*data),
            _ => unreachable!("a volume was asked for"),
        }
    }

    /// How the library reads a FILE: raw as --raw-* describe, --spacing, --downsample, --tf,
    /// --rotate.
    pub fn volume_load(&self) -> Result<VolumeLoad> {
        let raw = match (self.raw_dims, &self.raw_type) {
            (Some(dims), Some(kind)) => {
                let kind = SampleType::parse(kind).with_context(|| {
                    format!("unknown --raw-type '{kind}' (u8, i8, u16, i16, u32, i32, f32, f64)")
                })?;
                Some(RawSpec {
                    dims,
                    kind,
                    big_endian: self.raw_big_endian,
                    spacing: self.spacing.unwrap_or([1.0; 3]),
                    header_bytes: self.raw_header,
                })
            }
            (None, None) if self.raw_big_endian || self.raw_header != 0 => bail!(
                "--raw-big-endian and --raw-header describe a raw file, given with --raw-dims and \
                 --raw-type"
            ),
            (None, None) => None,
            _ => bail!("raw volumes need both --raw-dims and --raw-type"),
        };
        Ok(VolumeLoad {
            raw,
            spacing: self.spacing,
            crop: self.crop,
            downsample: self.downsample,
            transfer: self.transfer()?,
            model: self.model(),
        })
    }

    /// The classification --tf or --window asks for, if either.
    pub fn transfer(&self) -> Result<Option<Transfer>> {
        if let Some(window) = self.window {
            return Ok(Some(Transfer::Window(match window {
                WindowArg::File => None,
                WindowArg::Given(w) => Some(w),
            })));
        }
        let Some(name) = self.tf.as_deref() else {
            return Ok(None);
        };
        let path = Path::new(name);
        // A name with a path separator or an extension is a file, even when it is missing:
        // "no such file" is the error then, not "unknown preset".
        let looks_like_file =
            name.contains(std::path::MAIN_SEPARATOR) || path.extension().is_some();
        if path.exists() || looks_like_file {
            Ok(Some(
                Transfer::load(path).with_context(|| format!("--tf {name}"))?,
            ))
        } else {
            // Checked here, before loading: a misspelt preset fails at once.
            TransferFunction::preset(name).with_context(|| format!("--tf {name}"))?;
            Ok(Some(Transfer::Preset(name.to_string())))
        }
    }

    /// The --clip planes for `volume` (the volume as rendered).
    pub fn clip_planes(&self, volume: &Volume) -> Vec<autostereo::volume::ClipPlane> {
        self.clip.iter().map(|c| c.plane(volume)).collect()
    }

    /// The model matrix of --rotate.
    pub fn model(&self) -> Mat4 {
        let [ax, ay, az] = self.rotate.map(f32::to_radians);
        Mat4::from_rotation_z(az) * Mat4::from_rotation_y(ay) * Mat4::from_rotation_x(ax)
    }
}

pub fn run(args: VolumeArgs) -> Result<()> {
    if let Some(path) = &args.anaglyph {
        bail!(
            "--anaglyph was retired: write the red/cyan anaglyph with --output anaglyph --out {} \
             (--eyes L,R picks the views)",
            path.display()
        );
    }
    let mut plan = args.common.plan(
        args.file.as_deref(),
        autostereo::DataKind::Volume,
        args.warp,
    )?;
    plan.check_flags(&autostereo::volume::METHODS, |m| args.render.check(m))?;
    let data = args.data.load(args.file.as_deref())?;
    let bounds = args.render.framed(&data)?;
    let VolumeData {
        volume,
        transfer,
        model,
        clip,
        ..
    } = data;
    let step = args.render.step(&volume);
    let frame = plan.decide(
        plan.frame(bounds)?,
        bounds,
        |_| autostereo::render::auto::Workload::Volume,
        &autostereo::volume::METHODS,
        |m| args.render.check(m),
    )?;
    let ctx = gpu()?;
    let mut scene = VolumeScene::new(&ctx.device, &ctx.queue, &volume, transfer, model)?;
    scene.clip = clip;
    // The settings are checked where the renderer is built (src/volume/options.rs, the
    // renderers' constructors); cli/src/flags.rs names the flags in their errors.
    let mut volume_options = args.render.options(step);
    volume_options.settings.isovalue = args.render.isovalue(&volume.values)?;
    let options = RendererOptions {
        volume: volume_options,
        ..plan.options
    };
    let settings = options.volume.settings;
    settings.validate_for(&scene)?;
    let mut renderer = options.volume_renderer(&ctx.device)?;
    let step = settings.step_length(&scene);
    // Against the exact N-pass: the probes would otherwise thin out the oracle's samples too,
    // and a coarser step than the default is an approximation of the default's image.
    // (A step no coarser than the default is kept as given: an exact N-pass run then has the
    // oracle's very options, which --compare refuses as a comparison with itself.)
    let oracle = VolumeSettings {
        step: match step <= scene.default_step_length() {
            true => settings.step,
            false => Some(scene.default_step_length() / scene.voxel),
        },
        ..settings.exact()
    };
    let method = plan.method.name();
    let extra = serde_json::json!({
        "path": match args.render.path { PathArg::Compute => "compute", PathArg::Slices => "slices" },
        "alpha": match (args.render.path, args.render.alpha) {
            (PathArg::Compute, _) => "exact",
            (PathArg::Slices, alpha) => alpha.name(),
        },
        "projection": settings.projection.name(),
        "framed": {
            "fit": args.render.fit.name(),
            "min": bounds.min.to_array(),
            "max": bounds.max.to_array(),
            "clip_planes": scene.clip.len(),
        },
        "volume_dims": volume.dims,
        "values": volume.values,
        "spacing": volume.spacing,
        "step": step,
        "compare_step": plan.compare.then(|| oracle.step_length(&scene)),
        "samples_per_ray_max": (scene.extent.length() / step).ceil(),
        "skip_empty": settings.skip_empty && matches!(args.render.path, PathArg::Compute),
        // Sharing needs K = 3 rays per pixel (subpixel displays).
        "share_samples": settings.share_samples,
        "share_samples_active": settings.share_samples > 0.0
            && frame.display.views_per_pixel() == 3,
        "empty_stride": settings.empty_stride,
        "thin_alpha": settings.thin_alpha,
        "transparent_cells": scene.cells().transparent_share(&scene.transfer),
    });
    let Rendered { run, fields, diff } = render_and_save(
        &ctx,
        &mut plan,
        &options,
        renderer.as_mut(),
        |o| o.volume_renderer(&ctx.device),
        RendererOptions {
            method: Method::NPass,
            volume: autostereo::VolumeOptions {
                settings: oracle,
                path: autostereo::VolumePath::RayMarch,
            },
            ..options
        },
        &scene,
        &frame,
        bounds,
        extra,
    )?;
    let summary = format!(
        "{method}: volume {:?}, values {}, {}",
        volume.dims,
        volume.values.described(),
        run_summary(&ctx, &plan, &frame, &run)
    );
    report(plan.output.json, fields, diff, &summary);
    Ok(())
}

/// `--window`: the file's own, or WIDTH,LEVEL.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WindowArg {
    File,
    Given([f64; 2]),
}

fn parse_window(value: &str) -> std::result::Result<WindowArg, String> {
    if value == "file" {
        return Ok(WindowArg::File);
    }
    let parts: Vec<f64> = value
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect::<std::result::Result<_, _>>()
        .map_err(|_| format!("'{value}' is not WIDTH,LEVEL (e.g. 400,40 for soft tissue in HU)"))?;
    match parts[..] {
        [width, level] if width > 0.0 && width.is_finite() && level.is_finite() => {
            Ok(WindowArg::Given([width, level]))
        }
        _ => Err(format!(
            "'{value}' is not WIDTH,LEVEL with a positive width (e.g. 400,40 for soft tissue in HU)"
        )),
    }
}
