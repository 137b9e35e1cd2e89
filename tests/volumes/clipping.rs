//! Clipping planes (`VolumeScene::clip`): every method cuts as the N-pass does, in every
//! projection; a plane past the box changes nothing and one before it leaves the background;
//! a half cut off by a plane is the half a crop keeps, placed where it was.

use crate::common;

use autostereo::image_io::{compare, RgbImage};
use autostereo::render::{Method, Renderer};
use autostereo::volume::{generate, ClipPlane, Crop, Projection, TransferFunction, Volume};
use autostereo::volume::{AlphaMode, VolumeScene, VolumeSettings, VolumeSlicer};
use glam::{Mat4, Vec3};

const SIZE: [u32; 2] = [80, 64];

fn scene(volume: &Volume, model: Mat4, clip: Vec<ClipPlane>) -> VolumeScene {
    let ctx = common::gpu();
    let tf = TransferFunction::preset("ct-skin").unwrap();
    let mut scene = VolumeScene::new(&ctx.device, &ctx.queue, volume, tf, model).unwrap();
    scene.clip = clip;
    scene
}

fn frame(volume: &Volume, spec: &str) -> autostereo::frame::Frame {
    common::frame(volume.bounds(), spec, 0.06, 1.0, SIZE)
}

fn settings(projection: Projection) -> VolumeSettings {
    VolumeSettings {
        projection,
        isovalue: 0.4,
        ..Default::default()
    }
}

fn slices(scene: &VolumeScene, frame: &autostereo::frame::Frame) -> RgbImage {
    let device = common::gpu().device.clone();
    let mut slicer =
        VolumeSlicer::new(&device, AlphaMode::Exact, VolumeSettings::default()).unwrap();
    common::render(&mut slicer, scene, frame)
}

/// Two oblique planes through the turned head: a wedge cut out of it.
fn wedge(head: &Volume) -> Vec<ClipPlane> {
    let e = head.extent();
    vec![
        ClipPlane::new(Vec3::new(1.0, 0.3, 0.0), 0.6 * e.x),
        ClipPlane::new(Vec3::new(0.0, -0.4, 1.0), 0.7 * e.z),
    ]
}

#[test]
fn every_method_clips_as_the_npass_in_every_projection() {
    let head = generate::ct_head(32).unwrap();
    let turned = Mat4::from_rotation_y(0.7) * Mat4::from_rotation_x(0.3);
    let whole = scene(&head, turned, Vec::new());
    let clipped = scene(&head, turned, wedge(&head));
    for spec in ["hubner8", "lenticular:4"] {
        let frame = frame(&head, spec);
        for projection in [
            Projection::Composite,
            Projection::Maximum,
            Projection::Isosurface,
        ] {
            let s = settings(projection);
            let npass = common::render_volume(&clipped, &frame, Method::NPass, s);
            let uncut = common::render_volume(&whole, &frame, Method::NPass, s);
            let cut = compare(&npass, &uncut).unwrap();
            assert!(
                cut.frac_off_2 > 0.02,
                "{spec} {}: the planes cut something away: {cut:?}",
                projection.name()
            );
            for method in [Method::SinglePass, Method::Tiled, Method::Layered] {
                let image = common::render_volume(&clipped, &frame, method, s);
                common::assert_matches(
                    &format!("clip-{method}-{}-{spec}", projection.name()),
                    &image,
                    &npass,
                );
            }
        }
        let npass =
            common::render_volume(&clipped, &frame, Method::NPass, VolumeSettings::default());
        let diff = compare(&slices(&clipped, &frame), &npass).unwrap();
        assert!(diff.psnr_db >= 45.0, "slices exact {spec}: {diff:?}");
    }
}

#[test]
fn planes_past_the_box_keep_everything_and_planes_before_it_nothing() {
    let head = generate::ct_head(24).unwrap();
    let e = head.extent();
    let frame = frame(&head, "hubner8");
    let render = |clip| {
        let s = scene(&head, Mat4::from_rotation_y(0.4), clip);
        common::render_volume(&s, &frame, Method::SinglePass, VolumeSettings::default())
    };
    let whole = render(Vec::new());
    let past = render(vec![
        ClipPlane::new(Vec3::X, e.x + 1.0),
        ClipPlane::new(-Vec3::Z, 1.0),
    ]);
    assert_eq!(past.data, whole.data, "planes outside the box cut nothing");
    let before = render(vec![ClipPlane::new(Vec3::Y, -1.0)]);
    let background = before.data[..3].to_vec();
    assert!(
        before.data.chunks(3).all(|p| p == background),
        "a plane with the box on its far side leaves only the background"
    );
    assert!(whole.data.chunks(3).any(|p| p != background));
}

/// Cutting the head at x = half its box keeps what cropping the voxels below that keeps: the
/// same samples but within half a voxel of the cut, where the crop's sampler clamps to its last
/// voxel and the clipped one still blends in the next (measured 58 dB).
#[test]
fn a_plane_through_the_middle_keeps_the_half_a_crop_keeps() {
    let n = 32;
    let head = generate::ct_head(n).unwrap();
    let half = head
        .cropped(Crop::Voxels {
            min: [0; 3],
            max: [n / 2 - 1, head.dims[1] - 1, head.dims[2] - 1],
        })
        .unwrap();
    let frame = frame(&head, "hubner8");
    let spin = Mat4::from_rotation_y(0.5);
    // The crop is centred where every volume is: move it back to where its half was.
    let shift = Mat4::from_translation(Vec3::new(-head.extent().x / 4.0, 0.0, 0.0));
    let plane = ClipPlane::from_voxels(Vec3::X, (n / 2) as f32, head.spacing.into());
    let clipped = scene(&head, spin, vec![plane]);
    let cropped = scene(&half, spin * shift, Vec::new());
    let a = common::render_volume(
        &clipped,
        &frame,
        Method::SinglePass,
        VolumeSettings::default(),
    );
    let b = common::render_volume(
        &cropped,
        &frame,
        Method::SinglePass,
        VolumeSettings::default(),
    );
    let diff = compare(&a, &b).unwrap();
    println!("clip vs crop: {diff:?}");
    if diff.psnr_db < 45.0 {
        common::save_diff("clip-vs-crop", &a, &b);
    }
    assert!(diff.psnr_db >= 45.0, "{diff:?}");
}

#[test]
fn impossible_planes_are_refused_naming_the_clipping_planes() {
    let head = generate::ct_head(16).unwrap();
    let frame = frame(&head, "hubner8");
    let s = scene(&head, Mat4::IDENTITY, vec![ClipPlane::new(Vec3::ZERO, 1.0)]);
    let ctx = common::gpu();
    let mut renderer = autostereo::volume::VolumeRaycaster::new(
        &ctx.device,
        Method::SinglePass,
        VolumeSettings::default(),
    )
    .unwrap();
    let error = renderer
        .render_image(&ctx.device, &ctx.queue, &s, &frame)
        .err()
        .unwrap()
        .to_string();
    assert!(
        error.contains("clipping planes") && error.contains("nonzero"),
        "{error}"
    );
}
