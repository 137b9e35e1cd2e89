//! The embeddable API: prepare, then record several frames into one encoder before one submit;
//! the spatial image into a caller-made texture of any 8-bit format, subpixels unchanged;
//! clear errors for what a caller can get wrong.

use crate::common;

use autostereo::camera::Bounds;
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{MeshNPass, MeshSinglePass, MeshSinglePassOptions, Visibility};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatOptions};
use autostereo::readback::read_texture_rgba8;
use autostereo::render::{Method, OutputBlit, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeSettings;
use autostereo::volume::{generate, TransferFunction};
use autostereo::volume::{VolumeRaycaster, VolumeScene};
use autostereo::Error;
use autostereo::{AnyRenderer, AnyScene, RendererOptions};
use glam::{Mat4, Vec3};

const SIZE: [u32; 2] = [96, 80];

/// Two frames of the same display and size whose cameras differ (the second orbits 0.6 rad).
fn two_frames(bounds: Bounds) -> [Frame; 2] {
    let a = common::frame(bounds, "hubner8", 0.06, 1.0, SIZE);
    let mut b = a.clone();
    b.camera.eye_from_world *= Mat4::from_rotation_y(0.6);
    [a, b]
}

/// Frame `a` then frame `b` encoded into one encoder, one submit; each must equal the image
/// the same renderer makes for it alone.
fn assert_two_frames_in_one_encoder<S>(
    name: &str,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    bounds: Bounds,
) {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let frames = two_frames(bounds);
    let alone: Vec<RgbImage> = frames
        .iter()
        .map(|frame| {
            let target = SpatialTarget::new(device, SIZE).unwrap();
            renderer
                .render(device, queue, scene, frame, &target)
                .unwrap();
            target.read(device, queue).unwrap()
        })
        .collect();
    assert_ne!(
        alone[0], alone[1],
        "{name}: the two cameras must see different images"
    );
    // Prepared once: the two frames share display and size.
    renderer.prepare(device, queue, scene, &frames[0]).unwrap();
    let targets = [
        SpatialTarget::new(device, SIZE).unwrap(),
        SpatialTarget::new(device, SIZE).unwrap(),
    ];
    let mut encoder = device.create_command_encoder(&Default::default());
    for (frame, target) in frames.iter().zip(&targets) {
        renderer
            .encode(device, &mut encoder, scene, frame, target)
            .unwrap();
    }
    queue.submit([encoder.finish()]);
    for (i, target) in targets.iter().enumerate() {
        let together = target.read(device, queue).unwrap();
        if together != alone[i] {
            panic!(
                "{name}: frame {i} encoded beside the other differs: {}",
                common::save_diff(&format!("two-frames-{name}-{i}"), &together, &alone[i])
                    .display()
            );
        }
    }
}

#[test]
fn two_frames_with_different_cameras_in_one_encoder_before_one_submit() {
    let mesh = Mesh::torus_scene();
    let bounds = mesh.bounds().unwrap();
    let (buffers, visibility) = {
        let ctx = common::gpu();
        let buffers = MeshBuffers::new(&ctx.device, &mesh).unwrap();
        (buffers, Visibility::best_exact(&ctx.device))
    };
    let options = MeshSinglePassOptions {
        visibility,
        ..Default::default()
    };
    let mut single = MeshSinglePass::new(&common::gpu().device, options).unwrap();
    assert_two_frames_in_one_encoder("mesh-single-pass", &mut single, &buffers, bounds);
    let mut npass = MeshNPass::new(&common::gpu().device, Method::NPass).unwrap();
    assert_two_frames_in_one_encoder("mesh-n-pass", &mut npass, &buffers, bounds);

    let head = generate::ct_head(24).unwrap();
    let scene = {
        let ctx = common::gpu();
        let tf = TransferFunction::preset("ct-skin").unwrap();
        VolumeScene::new(&ctx.device, &ctx.queue, &head, tf, Mat4::IDENTITY).unwrap()
    };
    for method in [Method::SinglePass, Method::NPass] {
        let mut raycaster =
            VolumeRaycaster::new(&common::gpu().device, method, VolumeSettings::default()).unwrap();
        let name = format!("volume-{method}");
        assert_two_frames_in_one_encoder(&name, &mut raycaster, &scene, head.bounds());
    }

    let cloud = PointCloud::sphere(800, Vec3::ZERO, 1.0, Some(0.8));
    let (splats, _) = cloud.complete(1.0).unwrap();
    let scene = SplatScene::new(&common::gpu().device, &splats, GroupCount::Auto).unwrap();
    let options = SplatOptions::for_scene(&scene, 0.01);
    let mut splatter =
        PointSplatter::new(&common::gpu().device, Method::SinglePass, options).unwrap();
    assert_two_frames_in_one_encoder("points", &mut splatter, &scene, splats.bounds().unwrap());
}

/// A caller-made texture of each 8-bit format (BGRA8 sRGB is what most surfaces are) gets
/// exactly the subpixel values of the RGBA8 spatial image: no filtering, no colour re-encoding.
#[test]
fn caller_textures_of_every_8_bit_format_get_the_exact_subpixels() {
    let mesh = Mesh::torus_scene();
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.06, 1.0, SIZE);
    let buffers = MeshBuffers::new(device, &mesh).unwrap();
    let spatial = SpatialTarget::new(device, SIZE).unwrap();
    MeshNPass::new(device, Method::NPass)
        .unwrap()
        .render(device, queue, &buffers, &frame, &spatial)
        .unwrap();
    let expected = read_texture_rgba8(device, queue, &spatial.texture, 0).unwrap();
    // Subpixel values across the whole range, so that an sRGB round trip that is off shows.
    let distinct: std::collections::HashSet<u8> = expected.iter().copied().collect();
    assert!(distinct.len() > 100, "{} distinct values", distinct.len());
    for format in [
        wgpu::TextureFormat::Bgra8UnormSrgb,
        wgpu::TextureFormat::Bgra8Unorm,
        wgpu::TextureFormat::Rgba8UnormSrgb,
        wgpu::TextureFormat::Rgba8Unorm,
    ] {
        let texture = caller_texture(device, format, SIZE, wgpu::TextureUsages::RENDER_ATTACHMENT);
        let output = OutputBlit::new(device, format).unwrap();
        let mut encoder = device.create_command_encoder(&Default::default());
        output
            .encode(device, &mut encoder, &spatial, &texture)
            .unwrap();
        queue.submit([encoder.finish()]);
        let mut bytes = read_texture_rgba8(device, queue, &texture, 0).unwrap();
        if matches!(
            format,
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        ) {
            bytes.chunks_mut(4).for_each(|texel| texel.swap(0, 2));
        }
        let off = bytes.iter().zip(&expected).filter(|(a, b)| a != b).count();
        assert_eq!(off, 0, "{format:?}: {off} channel values changed");
    }
}

/// Rendering straight into a caller-made RGBA8 texture equals rendering into the library's own;
/// a resize is one call on the target and a prepare for the new size.
#[test]
fn caller_made_spatial_targets_and_resizing() {
    let mesh = Mesh::torus_scene();
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let buffers = MeshBuffers::new(device, &mesh).unwrap();
    let mut renderer = MeshSinglePass::new(
        device,
        MeshSinglePassOptions {
            visibility: Visibility::best_exact(device),
            ..Default::default()
        },
    )
    .unwrap();
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.06, 1.0, SIZE);
    let own = SpatialTarget::new(device, SIZE).unwrap();
    renderer
        .render(device, queue, &buffers, &frame, &own)
        .unwrap();
    let usage = SpatialTarget::REQUIRED_USAGES | wgpu::TextureUsages::COPY_SRC;
    let texture = caller_texture(device, wgpu::TextureFormat::Rgba8Unorm, SIZE, usage);
    let theirs = SpatialTarget::from_texture(texture).unwrap();
    renderer
        .render(device, queue, &buffers, &frame, &theirs)
        .unwrap();
    assert_eq!(
        theirs.read(device, queue).unwrap(),
        own.read(device, queue).unwrap()
    );

    let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
    let bgra = caller_texture(device, wgpu::TextureFormat::Bgra8Unorm, SIZE, attachment);
    let e = SpatialTarget::from_texture(bgra).err().unwrap().to_string();
    assert!(e.contains("Bgra8Unorm") && e.contains("OutputBlit"), "{e}");
    let no_storage = caller_texture(device, wgpu::TextureFormat::Rgba8Unorm, SIZE, attachment);
    let e = SpatialTarget::from_texture(no_storage)
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("STORAGE_BINDING"), "{e}");

    // Resize: the target, then the frame; the next render prepares for the new size.
    let mut target = own;
    let bigger = [SIZE[0] + 17, SIZE[1] + 9];
    target.resize(device, bigger).unwrap();
    assert_eq!(target.size(), bigger);
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.06, 1.0, bigger);
    let mut encoder = device.create_command_encoder(&Default::default());
    let stale = renderer.encode(device, &mut encoder, &buffers, &frame, &target);
    assert!(matches!(stale, Err(Error::NotPrepared { .. })));
    renderer
        .render(device, queue, &buffers, &frame, &target)
        .unwrap();
    let image = target.read(device, queue).unwrap();
    assert!(image.data.iter().filter(|&&v| v > 0).count() > image.data.len() / 20);
}

fn caller_texture(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    size: [u32; 2],
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    caller_texture_exact(device, format, size, usage | wgpu::TextureUsages::COPY_SRC)
}

/// A caller's texture with exactly `usage`.
fn caller_texture_exact(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    size: [u32; 2],
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("caller texture"),
        size: wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

#[test]
fn what_a_caller_can_get_wrong_is_a_clear_error() {
    let ctx = common::gpu();
    let device = &ctx.device;
    let message = |e: Error| e.to_string();
    // A format whose values would not reach the panel unchanged.
    let e = OutputBlit::new(device, wgpu::TextureFormat::Rgba16Float)
        .err()
        .unwrap();
    assert!(message(e).contains("Rgba16Float"));
    let spatial = SpatialTarget::new(device, SIZE).unwrap();
    let output = OutputBlit::new(device, wgpu::TextureFormat::Bgra8Unorm).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    let mut try_into = |format, size, usage| {
        let texture = caller_texture(device, format, size, usage);
        message(
            output
                .encode(device, &mut encoder, &spatial, &texture)
                .err()
                .unwrap(),
        )
    };
    let attachment = wgpu::TextureUsages::RENDER_ATTACHMENT;
    assert!(
        try_into(wgpu::TextureFormat::Rgba8Unorm, SIZE, attachment).contains("format Rgba8Unorm")
    );
    assert!(try_into(wgpu::TextureFormat::Bgra8Unorm, [8, 8], attachment).contains("size 8x8"));
    let sampled = wgpu::TextureUsages::TEXTURE_BINDING;
    assert!(try_into(wgpu::TextureFormat::Bgra8Unorm, SIZE, sampled).contains("RENDER_ATTACHMENT"));
    drop(encoder);

    // Encoding a frame the renderer was not prepared for.
    let mesh = Mesh::torus_scene();
    let buffers = MeshBuffers::new(device, &mesh).unwrap();
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.06, 1.0, SIZE);
    let mut renderer = MeshNPass::new(device, Method::NPass).unwrap();
    let mut encoder = device.create_command_encoder(&Default::default());
    let e = renderer
        .encode(device, &mut encoder, &buffers, &frame, &spatial)
        .err()
        .unwrap();
    assert!(matches!(e, Error::NotPrepared { .. }), "{e}");
    assert!(e.to_string().contains("prepare"), "{e}");
    // Prepared for another display: still an error, not a silent pipeline build.
    let other = common::frame(mesh.bounds().unwrap(), "lenticular:4", 0.06, 1.0, SIZE);
    renderer
        .prepare(device, &ctx.queue, &buffers, &other)
        .unwrap();
    assert!(renderer
        .encode(device, &mut encoder, &buffers, &frame, &spatial)
        .is_err());
    // The single pass has no N-pass of its own.
    assert!(MeshNPass::new(device, Method::SinglePass).is_err());
    drop(encoder);

    // AnyRenderer hides the primitive but renders only its own.
    let cloud = PointCloud::sphere(200, Vec3::ZERO, 1.0, Some(0.8));
    let (splats, _) = cloud.complete(1.0).unwrap();
    let points = AnyScene::Points(SplatScene::new(device, &splats, GroupCount::Auto).unwrap());
    let mesh_scene = AnyScene::Mesh(buffers);
    let mut any = AnyRenderer::new(
        device,
        &mesh_scene,
        &RendererOptions::new(Method::SinglePass),
    )
    .unwrap();
    any.render(device, &ctx.queue, &mesh_scene, &frame, &spatial)
        .unwrap();
    let e = any
        .render(device, &ctx.queue, &points, &frame, &spatial)
        .err()
        .unwrap();
    assert!(
        e.to_string().contains("a points scene for a mesh renderer"),
        "{e}"
    );
}

/// Each primitive's `METHODS` (what the CLI offers per command) is exactly what its renderer
/// builds: every other method is refused naming it, never built and ignored.
#[test]
fn each_primitive_lists_exactly_the_methods_its_renderer_takes() {
    use autostereo::gaussians::{GaussianOptions, GaussianSplatter};
    let ctx = common::gpu();
    let device = &ctx.device;
    let cloud = PointCloud::sphere(50, Vec3::ZERO, 1.0, Some(0.8));
    let (splats, _) = cloud.complete(1.0).unwrap();
    let points = SplatScene::new(device, &splats, GroupCount::Auto).unwrap();
    let dual_source = device
        .features()
        .contains(wgpu::Features::DUAL_SOURCE_BLENDING);
    for method in Method::ALL {
        let options = RendererOptions::new(method);
        let built: [(&str, &[Method], Result<(), Error>); 4] = [
            (
                "mesh",
                &autostereo::mesh::METHODS,
                options.mesh_renderer(device).map(drop),
            ),
            (
                "points",
                &autostereo::points::METHODS,
                options.points_renderer(device, &points).map(drop),
            ),
            (
                "volume",
                &autostereo::volume::METHODS,
                options.volume_renderer(device).map(drop),
            ),
            (
                "gaussians",
                &autostereo::gaussians::METHODS,
                GaussianSplatter::new(device, method, GaussianOptions::default()).map(drop),
            ),
        ];
        for (primitive, methods, result) in built {
            match result {
                Ok(()) => assert!(methods.contains(&method), "{primitive} built {method}"),
                Err(e) if methods.contains(&method) => {
                    // Listed but not buildable here: only the Gaussians' missing dual-source
                    // blending may explain it, as the clear capability error.
                    assert!(
                        primitive == "gaussians" && !dual_source,
                        "{primitive} {method}: {e}"
                    );
                    common::assert_missing_feature(device, &e, "");
                }
                Err(e) => assert!(
                    e.to_string().contains(method.name()),
                    "{primitive} refuses {method} naming it: {e}"
                ),
            }
        }
    }
}
