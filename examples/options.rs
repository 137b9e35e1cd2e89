//! The facade in brief: any scene, one `RendererOptions`, one `AnyRenderer`. The built-in head
//! sampled every voxel with probes 3 planes ahead through air (the head's fastest setting
//! ≥ 40 dB in `bench --volumes`, 41.9 dB on the paper's display: docs/VOLUMES.md) and a mesh
//! with the paper's one depth per pixel, each on a 45-view slanted lens, measured against its
//! exact N-pass, through the library's public API only.
//!
//! `cargo run --release --example options -- [OUT_DIR]`

use anyhow::Result;
use autostereo::camera::{Bounds, MultiViewCamera};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeScene;
use autostereo::volume::{generate, TransferFunction, VolumeSettings};
use autostereo::{AnyRenderer, AnyScene, MeshOptions, RendererOptions, VolumeOptions};
use glam::Mat4;

/// One frame of `scene` rendered as `options` say.
fn render(
    ctx: &GpuContext,
    scene: &AnyScene,
    options: &RendererOptions,
    frame: &Frame,
) -> Result<RgbImage> {
    let mut renderer = AnyRenderer::new(&ctx.device, scene, options)?;
    let target = SpatialTarget::new(&ctx.device, frame.size)?;
    renderer.render(&ctx.device, &ctx.queue, scene, frame, &target)?;
    Ok(target.read(&ctx.device, &ctx.queue)?)
}

/// The frame of a 45-view slanted lens at 512² around `bounds`.
fn frame(bounds: Bounds) -> Result<Frame> {
    let display = Display::parse("slanted:45,7.5,1/6,0.2")?;
    let camera = MultiViewCamera::framing(bounds, display.views(), None, 0.5, 1.0)?;
    Ok(Frame::new(camera, display, [512, 512])?)
}

fn main() -> Result<()> {
    let out_dir = std::env::args().nth(1).unwrap_or_else(|| ".".into());
    let ctx = GpuContext::new(&Default::default())?;
    println!("adapter: {}", ctx.adapter_label());

    let head = generate::ct_head(96)?;
    let rotation = Mat4::from_rotation_x(-90f32.to_radians());
    let tf = TransferFunction::preset("ct-skin")?;
    let volume = VolumeScene::new(&ctx.device, &ctx.queue, &head, tf, rotation)?;
    let volume = AnyScene::Volume(Box::new(volume));
    let coarse = RendererOptions {
        volume: VolumeOptions {
            settings: VolumeSettings {
                step: Some(1.0),
                empty_stride: 3,
                ..Default::default()
            },
            ..Default::default()
        },
        ..RendererOptions::new(Method::SinglePass)
    };

    let torus = Mesh::torus_scene();
    let bounds = torus.bounds().expect("the torus scene has vertices");
    let mesh = AnyScene::Mesh(MeshBuffers::new(&ctx.device, &torus)?);
    let paper_depth = RendererOptions {
        mesh: MeshOptions {
            visibility: Some(autostereo::mesh::Visibility::Fast),
            ..Default::default()
        },
        ..RendererOptions::new(Method::SinglePass)
    };

    for (name, scene, bounds, options, what) in [
        (
            "volume",
            &volume,
            head.bounds(),
            coarse,
            format!("{:?}", coarse.volume.settings),
        ),
        (
            "mesh",
            &mesh,
            bounds,
            paper_depth,
            format!("{:?}", paper_depth.mesh),
        ),
    ] {
        let frame = frame(bounds)?;
        let image = render(&ctx, scene, &options, &frame)?;
        let oracle = render(&ctx, scene, &RendererOptions::new(Method::NPass), &frame)?;
        let path = std::path::Path::new(&out_dir).join(format!("options_{name}.png"));
        image.save_png(&path)?;
        let d = compare(&image, &oracle)?;
        println!(
            "{name}: {what}\n  wrote {}; against the exact N-pass: {:.1} dB PSNR, {:.2} % of \
             subpixels off by more than 2/255",
            path.display(),
            d.psnr_db,
            100.0 * d.frac_off_2
        );
    }
    Ok(())
}
