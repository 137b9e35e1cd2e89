//! The benchmark's scenes (one per primitive and data set) and the renderers measured on them.

use std::path::PathBuf;

use anyhow::{Context, Result};
use autostereo::camera::{Bounds, MultiViewCamera};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{MeshLayered, TileClip, Visibility};
use autostereo::points::SplatDepth;
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::render::Method;
use autostereo::volume::AlphaMode;
use autostereo::volume::VolumeScene;
use autostereo::volume::{generate, load, TransferFunction, Volume};
use autostereo::warp::{WarpOptions, WarpPath};
use autostereo::{AnyRenderer, AnyScene, MeshOptions, PointOptions, RendererOptions};
use autostereo::{VolumeOptions, VolumePath};
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
    /// Depth-image warping of R reference views (approximate; accuracy in `autostereo-bench --warp`).
    Warp,
}

pub struct MethodEntry {
    pub name: String,
    pub kind: Kind,
    pub renderer: AnyRenderer,
}

/// The scenes of a run: real data where `data/fetch` got it, generated stand-ins otherwise.
pub fn scenes(ctx: &autostereo::gpu::GpuContext, plan: &super::Plan) -> Result<Vec<BenchScene>> {
    let quick = plan.quick;
    let fetched = |name: &str| -> PathBuf { plan.data.join(name) };
    let (device, queue) = (&ctx.device, &ctx.queue);
    let mut out = Vec::new();
    let rotation = Mat4::from_rotation_x(-90f32.to_radians());
    let mut volumes = vec![(
        "head (built-in)".to_string(),
        generate::ct_head(if quick { 48 } else { 96 })?,
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
        let scene = VolumeScene::new(device, queue, &volume, tf, rotation)?;
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

/// [`Method::Warp`] on `path`, R = 2.
fn on_path(path: WarpPath) -> RendererOptions {
    RendererOptions {
        warp: WarpOptions {
            path,
            ..Default::default()
        },
        ..RendererOptions::new(Method::Warp)
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
    let build = |options: RendererOptions| AnyRenderer::new(device, &scene.data, &options);
    let of = |method| build(RendererOptions::new(method));
    let warps = || -> Result<Vec<MethodEntry>> {
        Ok(vec![
            entry(WARP_DIRECT, Kind::Warp, build(on_path(WarpPath::Direct))?),
            entry(
                WARP_PER_VIEW,
                Kind::Warp,
                build(on_path(WarpPath::PerView))?,
            ),
        ])
    };
    let mut v = Vec::new();
    match &scene.data {
        AnyScene::Volume(_) => {
            let slices = |alpha| {
                build(RendererOptions {
                    volume: VolumeOptions {
                        path: VolumePath::Slices(alpha),
                        ..Default::default()
                    },
                    ..Default::default()
                })
            };
            v.extend([
                entry(
                    "single-pass (compute)",
                    Kind::SinglePass,
                    of(Method::SinglePass)?,
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
                entry("n-pass", Kind::NPass, of(Method::NPass)?),
                entry("single-view", Kind::SingleView, of(Method::SingleView)?),
                entry("tiled", Kind::Duplication, of(Method::Tiled)?),
                entry("layered", Kind::Duplication, of(Method::Layered)?),
            ]);
        }
        AnyScene::Gaussians(_) => {
            let cpu_sort = RendererOptions {
                gaussians: autostereo::gaussians::GaussianOptions {
                    sort: autostereo::gaussians::SortOn::Cpu,
                    ..Default::default()
                },
                ..Default::default()
            };
            v.extend([
                entry(
                    "single-pass (GPU sort)",
                    Kind::SinglePass,
                    of(Method::SinglePass)?,
                ),
                entry("single-pass (CPU sort)", Kind::SinglePass, build(cpu_sort)?),
                entry("n-pass", Kind::NPass, of(Method::NPass)?),
                entry("single-view", Kind::SingleView, of(Method::SingleView)?),
            ]);
        }
        AnyScene::Points(_) => {
            let paper = RendererOptions {
                points: PointOptions {
                    depth: SplatDepth::Paper,
                    ..Default::default()
                },
                ..Default::default()
            };
            v.extend([
                entry(
                    "single-pass (exact depth)",
                    Kind::SinglePass,
                    of(Method::SinglePass)?,
                ),
                entry("single-pass (paper depth)", Kind::SinglePass, build(paper)?),
                entry("n-pass", Kind::NPass, of(Method::NPass)?),
                entry("single-view", Kind::SingleView, of(Method::SingleView)?),
                entry("tiled", Kind::Duplication, of(Method::Tiled)?),
                entry("layered", Kind::Duplication, of(Method::Layered)?),
            ]);
        }
        AnyScene::Mesh(_) => {
            for visibility in [
                Visibility::Compute,
                Visibility::Atomic,
                Visibility::Exact,
                Visibility::Fast,
            ] {
                if !device.features().contains(visibility.required_features()) {
                    continue;
                }
                let options = RendererOptions {
                    mesh: MeshOptions {
                        visibility: Some(visibility),
                        ..Default::default()
                    },
                    ..Default::default()
                };
                v.push(entry(
                    &format!("single-pass ({})", visibility.name()),
                    Kind::SinglePass,
                    build(options)?,
                ));
            }
            v.push(entry("n-pass", Kind::NPass, of(Method::NPass)?));
            v.push(entry(
                "single-view",
                Kind::SingleView,
                of(Method::SingleView)?,
            ));
            for clip in [TileClip::ClipDistances, TileClip::Discard] {
                if clip.resolve(device).is_ok() {
                    let options = RendererOptions {
                        mesh: MeshOptions {
                            tile_clip: clip,
                            ..Default::default()
                        },
                        ..RendererOptions::new(Method::Tiled)
                    };
                    v.push(entry(
                        &format!("tiled ({})", clip.name()),
                        Kind::Duplication,
                        build(options)?,
                    ));
                }
            }
            let name = match MeshLayered::views_per_pass_on(device) {
                1 => "layered (pass per layer)".to_string(),
                n => format!("layered (multiview ≤ {n})"),
            };
            v.push(entry(&name, Kind::Duplication, of(Method::Layered)?));
            v.push(entry(
                "mrt (shared depth, approximate)",
                Kind::Duplication,
                of(Method::Mrt)?,
            ));
        }
        AnyScene::Rgbd(_) => {}
    }
    v.extend(warps()?);
    Ok(v)
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
