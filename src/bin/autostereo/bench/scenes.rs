//! The benchmark's scenes (one per primitive and data set) and the renderers measured on them.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use autostereo::camera::{Bounds, MultiViewCamera};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::render::Renderer;
use autostereo::render::{
    AlphaMode, MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled,
    Method, PointSplatter, SplatDepth, SplatOptions, TileClip, Visibility, VolumeRaycaster,
    VolumeScene, VolumeSlicer,
};
pub use autostereo::render::{AnyRenderer, AnyScene};
use autostereo::volume::{load, phantom, TransferFunction, Volume};
use autostereo::warp::{ReferenceRenderer, SceneWarp, SceneWarpOptions, WarpPath};
use glam::Mat4;

pub struct BenchScene {
    /// volume | points | mesh
    pub primitive: &'static str,
    pub name: String,
    pub detail: String,
    pub bounds: Bounds,
    pub data: AnyScene,
    /// The splats of a point scene (regrouped by the trade-off studies).
    pub splats: Option<autostereo::points::Splats>,
}

/// Which family a measured method belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    SinglePass,
    NPass,
    SingleView,
    /// Per-view duplication in one draw (tiled, layered, MRT): the competition.
    Duplication,
    /// Depth-image warping of R reference views (approximate; accuracy in `bench --warp`).
    Warp,
}

pub struct MethodEntry {
    pub name: String,
    pub kind: Kind,
    pub renderer: AnyRenderer,
}

fn fetched(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("data/fetched")
        .join(name)
}

/// The scenes of a run: real data where `data/fetch` got it, generated stand-ins otherwise.
pub fn scenes(ctx: &autostereo::gpu::GpuContext, plan: &super::Plan) -> Result<Vec<BenchScene>> {
    let quick = plan.quick;
    let (device, queue) = (&ctx.device, &ctx.queue);
    let mut out = Vec::new();
    let rotation = Mat4::from_rotation_x(-90f32.to_radians());
    let mut volumes = vec![(
        "head (built-in)".to_string(),
        phantom::ct_head(if quick { 48 } else { 96 })?,
        "ct-skin",
    )];
    let brain = fetched("brainsmall.den");
    if ((plan.studies() && !quick) || plan.volumes) && brain.is_file() {
        let v = load::load_den(&brain)?;
        volumes.push((
            "brainsmall.den".into(),
            Volume::new(v.dims, [1.0, 1.0, 1.5], v.data)?,
            "mri",
        ));
    }
    for (name, volume, tf) in volumes {
        let tf = TransferFunction::preset(tf)?;
        let scene = VolumeScene::new(device, queue, &volume, tf, None, rotation)?;
        out.push(BenchScene {
            primitive: "volume",
            detail: format!("{:?} voxels", volume.dims),
            name,
            bounds: volume.bounds(),
            data: AnyScene::Volume(Box::new(scene)),
            splats: None,
        });
    }
    if plan.volumes {
        return Ok(out);
    }
    // The sweep's duplication and N-pass grow with N to 64: the smaller dragon keeps it short.
    let dragon = if quick || plan.sweep || plan.warp || plan.view_scale {
        "dragon_vrip_res3.ply"
    } else {
        "dragon_vrip.ply"
    };
    // Generated stand-ins only where data/fetch did not run; a broken file is an error.
    let (name, cloud) = if fetched(dragon).is_file() {
        (
            format!("{dragon} vertices"),
            PointCloud::load(&fetched(dragon))?,
        )
    } else {
        (
            "torus scene (generated)".to_string(),
            PointCloud::torus_scene(),
        )
    };
    let (splats, completion) = cloud.complete(1.0)?;
    let scene = SplatScene::new(device, &splats, GroupCount::Auto)?;
    out.push(BenchScene {
        primitive: "points",
        detail: format!(
            "{} points, {} groups (normals/radii estimated: {}/{})",
            splats.len(),
            scene.groups(),
            completion.normals_estimated,
            completion.radii_estimated
        ),
        name,
        bounds: splats.bounds().context("empty cloud")?,
        data: AnyScene::Points(scene),
        splats: Some(splats),
    });
    let meshes: &[&str] = if quick || !plan.studies() {
        &["dragon_vrip_res2.obj"]
    } else {
        &["dragon_vrip_res2.obj", "dragon_vrip.obj"]
    };
    let mut any_mesh = false;
    for file in meshes {
        if fetched(file).is_file() {
            let mesh = Mesh::load_obj(&fetched(file))?;
            out.push(mesh_scene(device, file.to_string(), &mesh)?);
            any_mesh = true;
        }
    }
    if !any_mesh {
        out.push(mesh_scene(
            device,
            "torus scene (generated)".into(),
            &Mesh::torus_scene(),
        )?);
    }
    Ok(out)
}

fn mesh_scene(device: &wgpu::Device, name: String, mesh: &Mesh) -> Result<BenchScene> {
    Ok(BenchScene {
        primitive: "mesh",
        detail: format!("{} triangles", mesh.triangle_count()),
        name,
        bounds: mesh.bounds().context("empty mesh")?,
        data: AnyScene::Mesh(MeshBuffers::new(device, mesh)?),
        splats: None,
    })
}

/// The warp rows of every run: R = 2 references, straight into the spatial image and Beck's
/// way through N view images.
pub const WARP_DIRECT: &str = "warp (R = 2, direct, approximate)";
pub const WARP_PER_VIEW: &str = "warp (R = 2, per-view, approximate)";

/// [`Method::Warp`] from `references` (a renderer built for it) with `options`.
pub fn warp_renderer<S: ?Sized + 'static>(
    device: &wgpu::Device,
    references: impl ReferenceRenderer<S> + 'static,
    options: SceneWarpOptions,
) -> Result<Box<dyn Renderer<S>>> {
    Ok(Box::new(SceneWarp::new(
        device,
        Box::new(references),
        options,
    )?))
}

fn on_path(path: WarpPath) -> SceneWarpOptions {
    SceneWarpOptions {
        path,
        ..Default::default()
    }
}

/// Every method measured on `scene`: each single-pass path/mode, N-pass, single view, the
/// duplication methods.
pub fn methods(device: &wgpu::Device, scene: &BenchScene) -> Result<Vec<MethodEntry>> {
    let entry = |name: &str, kind, renderer| MethodEntry {
        name: name.to_string(),
        kind,
        renderer,
    };
    Ok(match &scene.data {
        AnyScene::Volume(_) => {
            let ray = |m| -> Result<AnyRenderer> {
                Ok(AnyRenderer::Volume(Box::new(VolumeRaycaster::new(
                    device, m,
                )?)))
            };
            let warp = |path| -> Result<AnyRenderer> {
                let references = VolumeRaycaster::new(device, Method::Warp)?;
                let r = warp_renderer(device, references, on_path(path))?;
                Ok(AnyRenderer::Volume(r))
            };
            let slices = |a| -> Result<AnyRenderer> {
                Ok(AnyRenderer::Volume(Box::new(VolumeSlicer::new(device, a)?)))
            };
            vec![
                entry(
                    "single-pass (compute)",
                    Kind::SinglePass,
                    ray(Method::SinglePass)?,
                ),
                entry(
                    "single-pass (slices, exact α)",
                    Kind::SinglePass,
                    slices(AlphaMode::Exact)?,
                ),
                entry(
                    "single-pass (slices, paper α)",
                    Kind::SinglePass,
                    slices(AlphaMode::Paper)?,
                ),
                entry("n-pass", Kind::NPass, ray(Method::NPass)?),
                entry("single-view", Kind::SingleView, ray(Method::SingleView)?),
                entry("tiled", Kind::Duplication, ray(Method::Tiled)?),
                entry("layered", Kind::Duplication, ray(Method::Layered)?),
                entry(WARP_DIRECT, Kind::Warp, warp(WarpPath::Direct)?),
                entry(WARP_PER_VIEW, Kind::Warp, warp(WarpPath::PerView)?),
            ]
        }
        AnyScene::Points(s) => {
            let splat = |m, depth| -> Result<AnyRenderer> {
                let options = SplatOptions {
                    depth,
                    ..SplatOptions::for_scene(s, 0.01)
                };
                Ok(AnyRenderer::Points(Box::new(PointSplatter::new(
                    device, m, options,
                )?)))
            };
            let warp = |path| -> Result<AnyRenderer> {
                let options = SplatOptions::for_scene(s, 0.01);
                let references = PointSplatter::new(device, Method::Warp, options)?;
                let r = warp_renderer(device, references, on_path(path))?;
                Ok(AnyRenderer::Points(r))
            };
            vec![
                entry(
                    "single-pass (exact depth)",
                    Kind::SinglePass,
                    splat(Method::SinglePass, SplatDepth::Exact)?,
                ),
                entry(
                    "single-pass (paper depth)",
                    Kind::SinglePass,
                    splat(Method::SinglePass, SplatDepth::Paper)?,
                ),
                entry(
                    "n-pass",
                    Kind::NPass,
                    splat(Method::NPass, SplatDepth::Exact)?,
                ),
                entry(
                    "single-view",
                    Kind::SingleView,
                    splat(Method::SingleView, SplatDepth::Exact)?,
                ),
                entry(
                    "tiled",
                    Kind::Duplication,
                    splat(Method::Tiled, SplatDepth::Exact)?,
                ),
                entry(
                    "layered",
                    Kind::Duplication,
                    splat(Method::Layered, SplatDepth::Exact)?,
                ),
                entry(WARP_DIRECT, Kind::Warp, warp(WarpPath::Direct)?),
                entry(WARP_PER_VIEW, Kind::Warp, warp(WarpPath::PerView)?),
            ]
        }
        AnyScene::Mesh(_) => {
            let mut v = Vec::new();
            for visibility in [
                Visibility::Compute,
                Visibility::Atomic,
                Visibility::Exact,
                Visibility::Fast,
            ] {
                if !device.features().contains(visibility.required_features()) {
                    continue;
                }
                let options = MeshSinglePassOptions {
                    visibility,
                    ..Default::default()
                };
                v.push(entry(
                    &format!("single-pass ({})", visibility.name()),
                    Kind::SinglePass,
                    AnyRenderer::Mesh(Box::new(MeshSinglePass::new(device, options)?)),
                ));
            }
            let base = |m| -> Result<AnyRenderer> {
                Ok(AnyRenderer::Mesh(Box::new(MeshNPass::new(device, m)?)))
            };
            v.push(entry("n-pass", Kind::NPass, base(Method::NPass)?));
            v.push(entry(
                "single-view",
                Kind::SingleView,
                base(Method::SingleView)?,
            ));
            for clip in [TileClip::ClipDistances, TileClip::Discard] {
                if clip.resolve(device).is_ok() {
                    v.push(entry(
                        &format!("tiled ({})", clip.name()),
                        Kind::Duplication,
                        AnyRenderer::Mesh(Box::new(MeshTiled::new(device, clip)?)),
                    ));
                }
            }
            let layered = MeshLayered::new(device)?;
            let name = match layered.views_per_pass() {
                1 => "layered (pass per layer)".to_string(),
                n => format!("layered (multiview ≤ {n})"),
            };
            v.push(entry(
                &name,
                Kind::Duplication,
                AnyRenderer::Mesh(Box::new(layered)),
            ));
            v.push(entry(
                "mrt (shared depth, approximate)",
                Kind::Duplication,
                AnyRenderer::Mesh(Box::new(MeshMrt::new(device)?)),
            ));
            for (name, path) in [
                (WARP_DIRECT, WarpPath::Direct),
                (WARP_PER_VIEW, WarpPath::PerView),
            ] {
                let references = MeshNPass::new(device, Method::Warp)?;
                let r = warp_renderer(device, references, on_path(path))?;
                v.push(entry(name, Kind::Warp, AnyRenderer::Mesh(r)));
            }
            v
        }
    })
}

/// The frame of a measurement: `display` with N views over the fixed baseline of the default
/// 8-view camera (a display's views share one viewing cone: more views are denser, not wider).
pub fn frame(bounds: Bounds, display: &str, size: [u32; 2]) -> Result<Frame> {
    let display = Display::parse(display)?;
    let views = display.views();
    let aspect = size[0] as f32 / size[1] as f32;
    let mut camera = MultiViewCamera::framing(bounds, views, None, 30f32.to_radians(), aspect)?;
    if views > 1 {
        camera.separation *= 7.0 / (views - 1) as f32;
    }
    Ok(Frame::new(camera, display, size)?)
}
