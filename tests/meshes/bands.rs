//! Frames rendered in bands (src/render/bands.rs) equal the same frames rendered whole, for
//! every primitive and the methods that render view images too; the parallel camera, whose
//! crop needs the whole image, is refused clearly; and a frame whose exact-visibility keys
//! exceed the adapter's storage binding falls back to bands by itself.

use crate::common;

use autostereo::camera::CameraModel;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::render::Method;
use autostereo::{RendererOptions, VolumeOptions, VolumePath};
use glam::Vec3;

/// 161 columns: the second band of each row overlaps the first by one column.
const SIZE: [u32; 2] = [161, 130];
/// Bands of at most 81×65 pixels: four.
const BAND_PIXELS: u64 = 81 * 65;

fn banded(options: RendererOptions) -> RendererOptions {
    RendererOptions {
        max_band_pixels: Some(BAND_PIXELS),
        ..options
    }
}

/// `whole` and `bands` agree on ≥ 99.9 % of subpixels within 2/255.
fn assert_same(name: &str, bands: &RgbImage, whole: &RgbImage) {
    let lit = whole.data.iter().filter(|&&v| v > 0).count();
    assert!(
        lit > whole.data.len() / 20,
        "{name}: the scene must be visible"
    );
    let diff = compare(bands, whole).unwrap();
    if diff.frac_off_2 > 0.001 {
        common::save_diff(&format!("bands-{name}"), bands, whole);
    }
    assert!(diff.frac_off_2 <= 0.001, "{name}: {diff:?}");
}

fn mesh_frame(mesh: &Mesh, spec: &str, model: CameraModel) -> Frame {
    let mut frame = common::frame(mesh.bounds().unwrap(), spec, 0.06, 1.1, SIZE);
    frame.camera.model = model;
    frame
}

#[test]
fn banded_meshes_equal_whole_ones() {
    let device = common::gpu().device.clone();
    let mesh = Mesh::torus_scene();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    for (method, spec, model) in [
        (Method::SinglePass, "hubner8", CameraModel::Skewed),
        (
            Method::SinglePass,
            "slanted:45,7.5,-1,0.3",
            CameraModel::ToeIn,
        ),
        (Method::NPass, "hubner8", CameraModel::Skewed),
        (Method::Tiled, "lenticular:8", CameraModel::Skewed),
        (Method::SingleView, "hubner8", CameraModel::Skewed),
    ] {
        let frame = mesh_frame(&mesh, spec, model);
        let options = RendererOptions::new(method);
        let whole = common::render(
            options.mesh_renderer(&device).unwrap().as_mut(),
            &buffers,
            &frame,
        );
        let mut renderer = banded(options).mesh_renderer(&device).unwrap();
        let bands = common::render(renderer.as_mut(), &buffers, &frame);
        let said = renderer.describe().unwrap_or_default();
        assert!(said.contains("4 bands of 81x65"), "{method}: {said}");
        assert_same(&format!("mesh-{method}-{model}"), &bands, &whole);
    }
}

#[test]
fn banded_points_and_volumes_equal_whole_ones() {
    let device = common::gpu().device.clone();
    let splats = PointCloud::torus_scene().complete(1.0).unwrap().0;
    let scene = {
        let ctx = common::gpu();
        SplatScene::new(&ctx.device, &splats, GroupCount::Auto).unwrap()
    };
    let frame = common::frame(splats.bounds().unwrap(), "hubner8", 0.06, 1.1, SIZE);
    for method in [Method::SinglePass, Method::NPass] {
        let options = RendererOptions::new(method);
        let whole = common::render(
            options.points_renderer(&device, &scene).unwrap().as_mut(),
            &scene,
            &frame,
        );
        let bands = common::render(
            banded(options)
                .points_renderer(&device, &scene)
                .unwrap()
                .as_mut(),
            &scene,
            &frame,
        );
        assert_same(&format!("points-{method}"), &bands, &whole);
    }
    let (volume, bounds) = common::head_scene();
    let frame = common::frame(bounds, "hubner8", 0.06, 1.0, SIZE);
    for (name, path) in [
        ("raycast", VolumePath::RayMarch),
        (
            "slices",
            VolumePath::Slices(autostereo::volume::AlphaMode::Paper),
        ),
    ] {
        let options = RendererOptions {
            volume: VolumeOptions {
                path,
                ..Default::default()
            },
            ..Default::default()
        };
        let whole = common::render(
            options.volume_renderer(&device).unwrap().as_mut(),
            &volume,
            &frame,
        );
        let bands = common::render(
            banded(options).volume_renderer(&device).unwrap().as_mut(),
            &volume,
            &frame,
        );
        assert_same(&format!("volume-{name}"), &bands, &whole);
    }
}

#[test]
fn the_parallel_camera_is_not_banded_and_says_why() {
    let ctx = common::gpu();
    let mesh = Mesh::torus_scene();
    let buffers = MeshBuffers::new(&ctx.device, &mesh).unwrap();
    let frame = mesh_frame(&mesh, "hubner8", CameraModel::Parallel);
    let mut renderer = banded(RendererOptions::default())
        .mesh_renderer(&ctx.device)
        .unwrap();
    let error = renderer
        .prepare(&ctx.device, &ctx.queue, &buffers, &frame)
        .unwrap_err()
        .to_string();
    assert!(error.contains("parallel camera"), "{error}");
}

/// 2400×2400 with K = 3: 138 MB of nearest-hit keys, beyond a 128 MiB storage binding (the
/// default limit, lavapipe's): where the adapter's visibility mode keeps keys and its binding is
/// that small, the single pass renders in bands by itself, and equals the N-pass either way.
#[test]
fn a_frame_beyond_the_storage_binding_falls_back_to_bands() {
    let device = common::gpu().device.clone();
    let mesh = Mesh::sphere(Vec3::ZERO, 1.0, 24, 48, [0.8, 0.5, 0.3, 1.0]);
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let size = [2400, 2400];
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.06, 1.1, size);
    let mut single = RendererOptions::default().mesh_renderer(&device).unwrap();
    let image = common::render(single.as_mut(), &buffers, &frame);
    let options = RendererOptions::default().mesh_single_pass(&device);
    let keys = 2400 * 2400 * 3 * 8;
    let keeps_keys = options.visibility.name() != "exact" && options.visibility.name() != "fast";
    let binding = device.limits().max_storage_buffer_binding_size;
    let said = single.describe().unwrap_or_default();
    assert_eq!(
        said.contains("bands"),
        keeps_keys && keys > binding,
        "{:?}, binding {binding}: {said}",
        options.visibility
    );
    let npass = common::render(
        RendererOptions::new(Method::NPass)
            .mesh_renderer(&device)
            .unwrap()
            .as_mut(),
        &buffers,
        &frame,
    );
    assert_same("mesh-2400", &image, &npass);
}
