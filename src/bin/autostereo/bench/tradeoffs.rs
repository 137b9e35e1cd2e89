//! Speed/accuracy trade-offs against the N-pass high-quality render, and what a scene that does
//! without a feature saves.

use anyhow::Result;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::points::{GroupCount, SplatScene};
use autostereo::render::{
    AlphaMode, CoverBounds, MeshBaseline, MeshBaselineMethod, MeshSinglePass,
    MeshSinglePassOptions, PointSplatter, SplatDepth, SplatMethod, SplatOptions, Visibility,
    VolumeMethod, VolumeRaycaster, VolumeSlicer,
};
use autostereo::target::SpatialTarget;
use autostereo::timing::FrameTimer;
use serde::{Deserialize, Serialize};

use super::scenes::{self, AnyRenderer, BenchScene, SceneData};
use super::{time_frame, Plan};

/// One setting of one study: its speed and its distance from the reference.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Tradeoff {
    pub study: String,
    pub scene: String,
    pub setting: String,
    pub ms: f64,
    pub psnr_db: f64,
    pub frac_off_2: f64,
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

fn image(ctx: &Ctx, scene: &BenchScene, r: &mut AnyRenderer, frame: &Frame) -> Result<RgbImage> {
    let target = SpatialTarget::new(&ctx.device, frame.size)?;
    r.render(ctx, &scene.data, frame, &target)?;
    Ok(target.read(&ctx.device, &ctx.queue)?)
}

/// Time `r` and compare its image with `reference`.
#[allow(clippy::too_many_arguments)]
fn point(
    ctx: &Ctx,
    timer: &FrameTimer,
    scene: &BenchScene,
    r: &mut AnyRenderer,
    frame: &Frame,
    frames: u32,
    reference: &RgbImage,
    study: &'static str,
    setting: String,
) -> Result<Tradeoff> {
    let ms = time_frame(ctx, timer, scene, r, frame, frames)?;
    let d = compare(&image(ctx, scene, r, frame)?, reference)?;
    eprintln!(
        "  {study} / {}: {setting}: {ms:.1} ms, {:.1} dB",
        scene.name, d.psnr_db
    );
    Ok(Tradeoff {
        study: study.into(),
        scene: scene.name.clone(),
        setting,
        ms,
        psnr_db: d.psnr_db,
        frac_off_2: d.frac_off_2,
    })
}

/// Every study on the paper's display (8 views, K = 3) at the plan's size.
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let frames = if plan.quick { 3 } else { 5 };
    let device = &ctx.device;
    let mut out = Vec::new();
    let mut done = std::collections::HashSet::new();
    for scene in scenes.iter_mut() {
        // One study set per primitive (the first scene of each).
        if !done.insert(scene.primitive) {
            continue;
        }
        let frame = scenes::frame(scene.bounds, "hubner8", plan.size)?;
        match scene.primitive {
            "volume" => {
                let SceneData::Volume(v) = &mut scene.data else {
                    unreachable!()
                };
                let voxel = v.voxel;
                let default_step = v.step;
                v.step = 0.25 * voxel;
                let mut npass = AnyRenderer::Volume(Box::new(VolumeRaycaster::new(
                    device,
                    VolumeMethod::NPass,
                )?));
                let reference = image(ctx, scene, &mut npass, &frame)?;
                let steps: &[f32] = if plan.quick {
                    &[0.5, 1.0, 2.0]
                } else {
                    &[0.25, 0.5, 1.0, 2.0, 4.0]
                };
                for &step in steps {
                    if let SceneData::Volume(v) = &mut scene.data {
                        v.step = step * voxel;
                    }
                    let paths: [(&str, AnyRenderer); 3] = [
                        (
                            "compute",
                            AnyRenderer::Volume(Box::new(VolumeRaycaster::new(
                                device,
                                VolumeMethod::SinglePass,
                            )?)),
                        ),
                        (
                            "slices, exact α",
                            AnyRenderer::Volume(Box::new(VolumeSlicer::new(
                                device,
                                AlphaMode::Exact,
                            )?)),
                        ),
                        (
                            "slices, paper α",
                            AnyRenderer::Volume(Box::new(VolumeSlicer::new(
                                device,
                                AlphaMode::Paper,
                            )?)),
                        ),
                    ];
                    for (path, mut r) in paths {
                        out.push(
                            point(
                                ctx,
                                timer,
                                scene,
                                &mut r,
                                &frame,
                                frames,
                                &reference,
                                "volume sampling",
                                format!("{path}, step {step} voxel"),
                            )
                            .map(|mut t| {
                                t.setting = format!("{path}|{step}");
                                t
                            })?,
                        );
                    }
                }
                if let SceneData::Volume(v) = &mut scene.data {
                    v.step = default_step;
                }
            }
            "points" => {
                let SceneData::Points(s) = &scene.data else {
                    unreachable!()
                };
                let depth_extent = SplatOptions::epsilon_for(s, 1.0);
                let auto_groups = s.groups();
                let options = move |depth, f: f32| SplatOptions {
                    depth,
                    epsilon: f * depth_extent,
                };
                let mut npass = AnyRenderer::points(PointSplatter::new(
                    device,
                    SplatMethod::NPass,
                    options(SplatDepth::Exact, 0.01),
                )?);
                let reference = image(ctx, scene, &mut npass, &frame)?;
                for depth in [SplatDepth::Exact, SplatDepth::Paper] {
                    let mut r = AnyRenderer::points(PointSplatter::new(
                        device,
                        SplatMethod::SinglePass,
                        options(depth, 0.01),
                    )?);
                    out.push(point(
                        ctx,
                        timer,
                        scene,
                        &mut r,
                        &frame,
                        frames,
                        &reference,
                        "splat depth",
                        depth.name().into(),
                    )?);
                }
                let epsilons: &[f32] = if plan.quick {
                    &[0.001, 0.01, 0.1]
                } else {
                    &[0.001, 0.003, 0.01, 0.03, 0.1]
                };
                for &f in epsilons {
                    let mut r = AnyRenderer::points(PointSplatter::new(
                        device,
                        SplatMethod::SinglePass,
                        options(SplatDepth::Exact, f),
                    )?);
                    out.push(point(
                        ctx,
                        timer,
                        scene,
                        &mut r,
                        &frame,
                        frames,
                        &reference,
                        "splat epsilon",
                        format!("{f}"),
                    )?);
                }
                let splats = scene.splats.take().expect("point scenes keep their splats");
                let counts: &[u32] = if plan.quick { &[1, 4] } else { &[1, 2, 4, 8] };
                let original = std::mem::replace(
                    &mut scene.data,
                    SceneData::Points(SplatScene::new(device, &splats, GroupCount::Fixed(1))?),
                );
                for &k in counts {
                    scene.data =
                        SceneData::Points(SplatScene::new(device, &splats, GroupCount::Fixed(k))?);
                    let mut r = AnyRenderer::points(PointSplatter::new(
                        device,
                        SplatMethod::SinglePass,
                        options(SplatDepth::Exact, 0.01),
                    )?);
                    out.push(point(
                        ctx,
                        timer,
                        scene,
                        &mut r,
                        &frame,
                        frames,
                        &reference,
                        "splat groups",
                        format!("{k}"),
                    )?);
                }
                scene.data = original;
                let mut r = AnyRenderer::points(PointSplatter::new(
                    device,
                    SplatMethod::SinglePass,
                    options(SplatDepth::Exact, 0.01),
                )?);
                out.push(point(
                    ctx,
                    timer,
                    scene,
                    &mut r,
                    &frame,
                    frames,
                    &reference,
                    "splat groups",
                    format!("auto ({auto_groups})"),
                )?);
                scene.splats = Some(splats);
            }
            _ => {
                let mut npass = AnyRenderer::Mesh(Box::new(MeshBaseline::new(
                    device,
                    MeshBaselineMethod::NPass,
                )?));
                let reference = image(ctx, scene, &mut npass, &frame)?;
                let modes = [
                    (Visibility::Compute, CoverBounds::Exact),
                    (Visibility::ExactAtomic, CoverBounds::Exact),
                    (Visibility::Exact, CoverBounds::Exact),
                    (Visibility::Fast, CoverBounds::Exact),
                    (Visibility::Compute, CoverBounds::Paper),
                ];
                for (visibility, bounds) in modes {
                    if !device.features().contains(visibility.required_features()) {
                        continue;
                    }
                    let options = MeshSinglePassOptions { visibility, bounds };
                    let mut r = AnyRenderer::Mesh(Box::new(MeshSinglePass::new(device, options)?));
                    let bounds = if bounds == CoverBounds::Paper {
                        ", paper bounds"
                    } else {
                        ""
                    };
                    out.push(point(
                        ctx,
                        timer,
                        scene,
                        &mut r,
                        &frame,
                        frames,
                        &reference,
                        "mesh visibility",
                        format!("{}{bounds}", visibility.name()),
                    )?);
                }
            }
        }
    }
    Ok(out)
}

/// What a scene saves by not using a feature: volume shading (the K = 3 → 1 saving comes from
/// the measured rows, in the report).
pub fn economy(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Economy>> {
    let mut out = Vec::new();
    let frames = if plan.quick { 3 } else { 5 };
    for scene in scenes.iter_mut() {
        if let SceneData::Volume(_) = &scene.data {
            let frame = scenes::frame(scene.bounds, "hubner8", plan.size)?;
            let mut r = AnyRenderer::Volume(Box::new(VolumeRaycaster::new(
                &ctx.device,
                VolumeMethod::SinglePass,
            )?));
            let with_ms = time_frame(ctx, timer, scene, &mut r, &frame, frames)?;
            if let SceneData::Volume(v) = &mut scene.data {
                v.shade = false;
            }
            let without_ms = time_frame(ctx, timer, scene, &mut r, &frame, frames)?;
            if let SceneData::Volume(v) = &mut scene.data {
                v.shade = true;
            }
            out.push(Economy {
                scene: scene.name.clone(),
                what: "lighting (gradient shading), single pass (compute)".into(),
                with_ms,
                without_ms,
            });
        }
    }
    Ok(out)
}
