//! Shared test helpers: one GPU context per test process (docs/DESIGN.md §7: one device per adapter).
//! No adapter is a test failure, never a skip: CI installs lavapipe.
#![allow(dead_code)]

/// The CPU reference of the 3D Gaussian splatting rules (the GPU renderers' oracle).
pub mod gaussians_reference;

/// A deterministic generator and graphdeco's PLY writer (3D Gaussian test data).
pub mod graphdeco;

use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard, OnceLock};

use autostereo::gpu::{GpuContext, GpuOptions};
use autostereo::image_io::{compare, ImageDiff, RgbImage};

/// The process-wide GPU context, locked so that tests in one binary take turns on it.
pub fn gpu() -> MutexGuard<'static, GpuContext> {
    static CONTEXT: OnceLock<Mutex<GpuContext>> = OnceLock::new();
    CONTEXT
        .get_or_init(|| {
            let ctx = GpuContext::new(&GpuOptions::default())
                .expect("a GPU adapter is required (CI installs lavapipe)");
            eprintln!("adapter: {}", ctx.adapter_label());
            Mutex::new(ctx)
        })
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Where tests write diagnostic images (git-ignored).
pub fn out_dir() -> PathBuf {
    // CARGO_TARGET_TMPDIR is target/tmp of the workspace, for the library's and the CLI's tests.
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("../test-output");
    std::fs::create_dir_all(&dir).expect("create target/test-output");
    dir
}

/// `name` in [`out_dir`].
pub fn out(name: &str) -> PathBuf {
    out_dir().join(name)
}

/// `contents` written as the test input file `name` (target/test-input, git-ignored).
pub fn input_file(name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("../test-input");
    std::fs::create_dir_all(&dir).expect("create target/test-input");
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// Save `image` and an amplified |a − b| diff image under `name` for inspection on failure.
pub fn save_diff(name: &str, a: &RgbImage, b: &RgbImage) -> PathBuf {
    let dir = out_dir();
    let mut diff = RgbImage::new(a.width, a.height);
    for (d, (x, y)) in diff.data.iter_mut().zip(a.data.iter().zip(&b.data)) {
        *d = x.abs_diff(*y).saturating_mul(8);
    }
    a.save_png(&dir.join(format!("{name}.png"))).unwrap();
    b.save_png(&dir.join(format!("{name}.reference.png")))
        .unwrap();
    let path = dir.join(format!("{name}.diff.png"));
    diff.save_png(&path).unwrap();
    path
}

/// `image` matches `reference` on ≥ 99.9 % of subpixels within 2/255 (diff images saved on
/// failure).
pub fn assert_matches(name: &str, image: &RgbImage, reference: &RgbImage) -> ImageDiff {
    let diff = compare(image, reference).unwrap();
    if diff.frac_off_2 > 0.001 {
        let path = save_diff(name, image, reference);
        panic!("{name}: {diff:?} (diff image {})", path.display());
    }
    diff
}

/// The displays the per-view duplication methods are compared on, with an image size each:
/// N = 1, 2, 8 (two masks, one of them per subpixel), 45.
pub const DISPLAYS: &[(&str, [u32; 2])] = &[
    ("lenticular:1", [64, 48]),
    ("slanted:2,2.5,1/3,0.1", [64, 48]),
    ("hubner8", [96, 64]),
    ("lenticular:8", [96, 64]),
    ("slanted:45,7.5,1/6,0.2", [80, 60]),
];

/// A `size` frame looking at `bounds` on display `spec`, with `separation_share` × the bounding
/// radius between views and the focal plane at `focal_scale` × the framing distance.
pub fn frame(
    bounds: autostereo::camera::Bounds,
    spec: &str,
    separation_share: f32,
    focal_scale: f32,
    size: [u32; 2],
) -> autostereo::frame::Frame {
    let display = autostereo::display::Display::parse(spec).unwrap();
    let mut camera = autostereo::camera::MultiViewCamera::framing(
        bounds,
        display.views(),
        Some(separation_share * bounds.radius()),
        0.6,
        size[0] as f32 / size[1] as f32,
    )
    .unwrap();
    camera.focal_distance *= focal_scale;
    autostereo::frame::Frame::new(camera, display, size).unwrap()
}

/// `MeshSinglePass` for `options` where the adapter runs that mode; where it lacks the mode's
/// features, asserts the clear error (adapter named, capability in words, the mode to use
/// instead) and returns `None`.
pub fn mesh_single_pass(
    device: &wgpu::Device,
    options: autostereo::mesh::MeshSinglePassOptions,
) -> Option<autostereo::mesh::MeshSinglePass> {
    let result = autostereo::mesh::MeshSinglePass::new(device, options);
    if device
        .features()
        .contains(options.visibility.required_features())
    {
        return Some(result.unwrap_or_else(|e| panic!("{:?}: {e}", options.visibility)));
    }
    let error = result
        .err()
        .unwrap_or_else(|| panic!("{:?} must fail without its features", options.visibility));
    assert_missing_feature(device, &error, "Visibility::Exact");
    None
}

/// `error` is the clear missing-capability error: it names the adapter and suggests `instead`.
pub fn assert_missing_feature(device: &wgpu::Device, error: &autostereo::Error, instead: &str) {
    let message = error.to_string();
    assert!(
        matches!(error, autostereo::Error::MissingFeature { .. }),
        "{message}"
    );
    assert!(
        message.contains(&device.adapter_info().name),
        "names the adapter: {message}"
    );
    assert!(message.contains(instead), "suggests {instead}: {message}");
    assert!(
        !message.contains("FeaturesWGPU") && !message.contains("this device"),
        "in words: {message}"
    );
}

/// The built-in CT head (24³, ct-skin) on the GPU and its bounds: the small volume the method
/// tests compare on.
pub fn head_scene() -> (autostereo::volume::VolumeScene, autostereo::camera::Bounds) {
    let ctx = gpu();
    let head = autostereo::volume::generate::ct_head(24).unwrap();
    let tf = autostereo::volume::TransferFunction::preset("ct-skin").unwrap();
    let scene = autostereo::volume::VolumeScene::new(
        &ctx.device,
        &ctx.queue,
        &head,
        tf,
        glam::Mat4::IDENTITY,
    )
    .unwrap();
    (scene, head.bounds())
}

/// One frame of `renderer` as an image (prepare, encode, submit, read back).
pub fn render<S: ?Sized>(
    renderer: &mut dyn autostereo::render::Renderer<S>,
    scene: &S,
    frame: &autostereo::frame::Frame,
) -> RgbImage {
    let ctx = gpu();
    renderer
        .render_image(&ctx.device, &ctx.queue, scene, frame)
        .unwrap()
}

/// `volume` on the GPU, classified by the preset `tf` and turned 0.5 rad about y and 0.3 rad
/// about x: the view the volume approximations' tests compare at.
pub fn turned_volume(
    volume: &autostereo::volume::Volume,
    tf: &str,
) -> autostereo::volume::VolumeScene {
    let ctx = gpu();
    let rotate = glam::Mat4::from_rotation_y(0.5) * glam::Mat4::from_rotation_x(0.3);
    let tf = autostereo::volume::TransferFunction::preset(tf).unwrap();
    autostereo::volume::VolumeScene::new(&ctx.device, &ctx.queue, volume, tf, rotate).unwrap()
}

/// One frame of `scene` by the ray caster of `method` with `settings`.
pub fn render_volume(
    scene: &autostereo::volume::VolumeScene,
    frame: &autostereo::frame::Frame,
    method: autostereo::render::Method,
    settings: autostereo::volume::VolumeSettings,
) -> RgbImage {
    let device = gpu().device.clone();
    let mut renderer = autostereo::volume::VolumeRaycaster::new(&device, method, settings).unwrap();
    render(&mut renderer, scene, frame)
}

/// `got` is `want`: dimensions, spacing, voxel axes and voxels (to float rounding); `name`
/// labels the failure.
pub fn assert_same_volume(
    name: &str,
    got: &autostereo::volume::Volume,
    want: &autostereo::volume::Volume,
) {
    assert_eq!(got.dims, want.dims, "{name}: dims");
    assert_eq!(got.spacing, want.spacing, "{name}: spacing");
    assert!(
        got.axes.abs_diff_eq(want.axes, 1e-6),
        "{name}: axes {} vs {}",
        got.axes,
        want.axes
    );
    let off = got
        .data
        .iter()
        .zip(&want.data)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f32::max);
    assert!(off < 1e-6, "{name}: voxels differ by {off}");
}
