//! Speed/accuracy trade-offs against the N-pass high-quality render, and what a scene that does
//! without a feature saves.

use anyhow::Result;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{CoverBounds, Visibility};
use autostereo::points::SplatDepth;
use autostereo::points::{GroupCount, SplatScene};
use autostereo::render::Method;
use autostereo::timing::FrameTimer;
use autostereo::volume::AlphaMode;
use autostereo::volume::VolumeSettings;
use autostereo::{AnyRenderer, AnyScene, MeshOptions, PointOptions, RendererOptions};
use autostereo::{VolumeOptions, VolumePath};
use serde::{Deserialize, Serialize};

use super::scenes::{self, BenchScene};
use super::{image, time_frame, Plan};

/// One setting of one study: its speed and its distance from the reference.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tradeoff {
    pub study: String,
    pub scene: String,
    pub setting: String,
    pub ms: f64,
    pub psnr_db: f64,
    pub frac_off_2: f64,
    /// Share of subpixels filled rather than seen (warping only).
    #[serde(default)]
    pub hole_share: Option<f64>,
}

/// A feature a scene can do without, and the time with and without it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Economy {
    pub scene: String,
    pub what: String,
    pub with_ms: f64,
    pub without_ms: f64,
}

type Ctx = autostereo::gpu::GpuContext;

/// One study's fixed parts: where, how long, against what.
struct Probe<'a> {
    ctx: &'a Ctx,
    timer: &'a FrameTimer,
    frame: Frame,
    frames: u32,
    reference: RgbImage,
    study: &'static str,
}

impl Probe<'_> {
    /// Time `r` on `scene` and compare its image with the reference.
    fn run(&self, scene: &BenchScene, mut r: AnyRenderer, setting: String) -> Result<Tradeoff> {
        let (ctx, frame) = (self.ctx, &self.frame);
        let ms = time_frame(ctx, self.timer, scene, &mut r, frame, self.frames)?;
        let d = compare(&image(ctx, scene, &mut r, frame)?, &self.reference)?;
        eprintln!(
            "  {} / {}: {setting}: {ms:.1} ms, {:.1} dB",
            self.study, scene.name, d.psnr_db
        );
        Ok(Tradeoff {
            study: self.study.into(),
            scene: scene.name.clone(),
            setting,
            ms,
            psnr_db: d.psnr_db,
            frac_off_2: d.frac_off_2,
            hole_share: None,
        })
    }
}

/// Every study on the paper's display (8 views, K = 3) at the plan's size, on the first scene
/// of each primitive.
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let mut out = Vec::new();
    let mut done = std::collections::HashSet::new();
    for scene in scenes.iter_mut() {
        if done.insert(scene.primitive) {
            match scene.primitive {
                "volume" => volume_studies(ctx, timer, scene, plan, &mut out)?,
                "points" => splat_studies(ctx, timer, scene, plan, &mut out)?,
                _ => mesh_studies(ctx, timer, scene, plan, &mut out)?,
            }
        }
    }
    Ok(out)
}

/// A probe of `study` on `scene` with the reference rendered by `reference`.
fn probe<'a>(
    ctx: &'a Ctx,
    timer: &'a FrameTimer,
    scene: &BenchScene,
    plan: &Plan,
    study: &'static str,
    mut reference: AnyRenderer,
) -> Result<Probe<'a>> {
    let frame = scenes::frame(scene.bounds, "hubner8", plan.size)?;
    Ok(Probe {
        ctx,
        timer,
        reference: image(ctx, scene, &mut reference, &frame)?,
        frame,
        frames: plan.study_frames(),
        study,
    })
}

/// The volume renderer of `method` on `path` with `settings`.
fn volume_renderer(
    device: &wgpu::Device,
    scene: &BenchScene,
    method: Method,
    path: VolumePath,
    settings: VolumeSettings,
) -> Result<AnyRenderer> {
    let options = RendererOptions {
        volume: VolumeOptions { path, settings },
        ..RendererOptions::new(method)
    };
    Ok(AnyRenderer::new(device, &scene.data, &options)?)
}

/// Sampling step × path (compute, slices with exact and paper α) against N-pass at ¼ voxel.
fn volume_studies(
    ctx: &Ctx,
    timer: &FrameTimer,
    scene: &BenchScene,
    plan: &Plan,
    out: &mut Vec<Tradeoff>,
) -> Result<()> {
    let device = &ctx.device;
    let at_step = |step: f32| VolumeSettings {
        step: Some(step),
        ..VolumeSettings::default()
    };
    let npass = volume_renderer(
        device,
        scene,
        Method::NPass,
        VolumePath::RayMarch,
        at_step(0.25),
    )?;
    let p = probe(ctx, timer, scene, plan, "volume sampling", npass)?;
    let steps: &[f32] = if plan.quick {
        &[0.5, 1.0, 2.0]
    } else {
        &[0.25, 0.5, 1.0, 2.0, 4.0]
    };
    for &step in steps {
        let paths = [
            ("compute", VolumePath::RayMarch),
            ("slices, exact α", VolumePath::Slices(AlphaMode::Exact)),
            ("slices, paper α", VolumePath::Slices(AlphaMode::Paper)),
        ];
        for (name, path) in paths {
            let r = volume_renderer(device, scene, Method::SinglePass, path, at_step(step))?;
            out.push(p.run(scene, r, format!("{name}|{step}"))?);
        }
    }
    Ok(())
}

/// Depth mode, ε and group count against N-pass with automatic groups and ε = 0.01.
fn splat_studies(
    ctx: &Ctx,
    timer: &FrameTimer,
    scene: &mut BenchScene,
    plan: &Plan,
    out: &mut Vec<Tradeoff>,
) -> Result<()> {
    let device = &ctx.device;
    let AnyScene::Points(s) = &scene.data else {
        unreachable!()
    };
    let auto_groups = s.groups();
    // ε is a share of the scene's size; regrouped scenes keep the same splats, so the same ε.
    let splatter = |scene: &BenchScene, method, depth, epsilon_fraction| -> Result<AnyRenderer> {
        let options = RendererOptions {
            points: PointOptions {
                depth,
                epsilon_fraction,
            },
            ..RendererOptions::new(method)
        };
        Ok(AnyRenderer::new(device, &scene.data, &options)?)
    };
    let exact = |scene: &BenchScene, fraction| {
        splatter(scene, Method::SinglePass, SplatDepth::Exact, fraction)
    };
    let reference = splatter(scene, Method::NPass, SplatDepth::Exact, 0.01)?;
    let mut p = probe(ctx, timer, scene, plan, "splat depth", reference)?;
    for depth in [SplatDepth::Exact, SplatDepth::Paper] {
        out.push(p.run(
            scene,
            splatter(scene, Method::SinglePass, depth, 0.01)?,
            depth.name().into(),
        )?);
    }
    p.study = "splat epsilon";
    let epsilons: &[f32] = if plan.quick {
        &[0.001, 0.01, 0.1]
    } else {
        &[0.001, 0.003, 0.01, 0.03, 0.1]
    };
    for &f in epsilons {
        out.push(p.run(scene, exact(scene, f)?, format!("{f}"))?);
    }
    p.study = "splat groups";
    let splats = scene.splats.take().expect("point scenes keep their splats");
    let counts: &[u32] = if plan.quick { &[1, 4] } else { &[1, 2, 4, 8] };
    let mut original = None;
    for &k in counts {
        let regrouped = AnyScene::Points(SplatScene::new(device, &splats, GroupCount::Fixed(k))?);
        let previous = std::mem::replace(&mut scene.data, regrouped);
        original.get_or_insert(previous);
        out.push(p.run(scene, exact(scene, 0.01)?, format!("{k}"))?);
    }
    if let Some(original) = original {
        scene.data = original;
    }
    scene.splats = Some(splats);
    out.push(p.run(scene, exact(scene, 0.01)?, format!("auto ({auto_groups})"))?);
    Ok(())
}

/// Every visibility mode (and the paper's bounds) against N-pass.
fn mesh_studies(
    ctx: &Ctx,
    timer: &FrameTimer,
    scene: &BenchScene,
    plan: &Plan,
    out: &mut Vec<Tradeoff>,
) -> Result<()> {
    let device = &ctx.device;
    let npass = AnyRenderer::new(device, &scene.data, &RendererOptions::new(Method::NPass))?;
    let p = probe(ctx, timer, scene, plan, "mesh visibility", npass)?;
    let modes = [
        (Visibility::Compute, CoverBounds::Exact),
        (Visibility::Atomic, CoverBounds::Exact),
        (Visibility::Exact, CoverBounds::Exact),
        (Visibility::Fast, CoverBounds::Exact),
        (Visibility::Compute, CoverBounds::Paper),
    ];
    for (visibility, bounds) in modes {
        if !device.features().contains(visibility.required_features()) {
            continue;
        }
        let options = RendererOptions {
            mesh: MeshOptions {
                visibility: Some(visibility),
                bounds,
                ..Default::default()
            },
            ..RendererOptions::new(Method::SinglePass)
        };
        let r = AnyRenderer::new(device, &scene.data, &options)?;
        let note = if bounds == CoverBounds::Paper {
            ", paper bounds"
        } else {
            ""
        };
        out.push(p.run(scene, r, format!("{}{note}", visibility.name()))?);
    }
    Ok(())
}

/// What a scene saves by not using a feature: volume shading, and work in empty space (marching
/// through transparent space vs skipping it). The K = 3 → 1 saving comes from the measured
/// rows, in the report.
pub fn economy(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Economy>> {
    let mut out = Vec::new();
    let frames = plan.study_frames();
    for scene in scenes.iter_mut() {
        if let AnyScene::Volume(_) = &scene.data {
            let frame = scenes::frame(scene.bounds, "hubner8", plan.size)?;
            let exact = VolumeSettings::default();
            // (what, the settings with the feature used, without it)
            let features = [
                (
                    "lighting (gradient shading), single pass (compute)",
                    exact,
                    VolumeSettings {
                        shade: false,
                        ..exact
                    },
                ),
                (
                    "marching through transparent space (no empty-space skipping), single pass \
                     (compute)",
                    VolumeSettings {
                        skip_empty: false,
                        ..exact
                    },
                    exact,
                ),
            ];
            for (what, with, without) in features {
                let ray = |settings| {
                    let path = VolumePath::RayMarch;
                    volume_renderer(&ctx.device, scene, Method::SinglePass, path, settings)
                };
                let with_ms = time_frame(ctx, timer, scene, &mut ray(with)?, &frame, frames)?;
                let without_ms = time_frame(ctx, timer, scene, &mut ray(without)?, &frame, frames)?;
                out.push(Economy {
                    scene: scene.name.clone(),
                    what: what.into(),
                    with_ms,
                    without_ms,
                });
            }
        }
    }
    Ok(out)
}
