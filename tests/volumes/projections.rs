//! MIP, MinIP and the mean along each ray: every method that ray-marches equals the N-pass,
//! and the projections see what compositing hides — a bright blob behind a half-bright slab —
//! against what the volume holds along the ray (the maximum, the minimum, between them).

use autostereo::render::Method;
use autostereo::volume::{Projection, TransferFunction, Volume, VolumeScene, VolumeSettings};
use autostereo::{RendererOptions, VolumeOptions};

use crate::common;

const N: u32 = 32;

/// 0.1 everywhere; a slab of 0.5 over the whole front (z ≥ 24: toward the viewer); a blob of
/// 1.0 of radius 4 voxels at the centre, behind the slab.
fn blob_behind_a_slab() -> Volume {
    let mut data = Vec::with_capacity((N * N * N) as usize);
    for z in 0..N {
        for y in 0..N {
            for x in 0..N {
                let c = |v: u32| v as f32 + 0.5 - N as f32 / 2.0;
                let r2 = c(x) * c(x) + c(y) * c(y) + c(z) * c(z);
                data.push(match () {
                    _ if z >= 24 => 0.5,
                    _ if r2 < 16.0 => 1.0,
                    _ => 0.1,
                });
            }
        }
    }
    Volume::new([N; 3], [1.0; 3], data).unwrap()
}

fn render(
    scene: &VolumeScene,
    method: Method,
    projection: Projection,
    spec: &str,
) -> autostereo::image_io::RgbImage {
    render_at(scene, method, projection, 0.5, spec)
}

/// One frame of `scene` (a 32³ box) by `method`, projecting with `isovalue` for the
/// isosurface.
fn render_at(
    scene: &VolumeScene,
    method: Method,
    projection: Projection,
    isovalue: f32,
    spec: &str,
) -> autostereo::image_io::RgbImage {
    let ctx = common::gpu();
    let options = RendererOptions {
        method,
        volume: VolumeOptions {
            settings: VolumeSettings {
                projection,
                isovalue,
                ..Default::default()
            },
            ..Default::default()
        },
        ..RendererOptions::new(method)
    };
    let mut renderer = options.volume_renderer(&ctx.device).unwrap();
    let frame = common::frame(blob_behind_a_slab().bounds(), spec, 0.02, 1.0, [64, 64]);
    renderer
        .render_image(&ctx.device, &ctx.queue, scene, &frame)
        .unwrap()
}

fn scene(volume: &Volume) -> VolumeScene {
    let ctx = common::gpu();
    // Colour = the scalar, opacity rising with it (the projections show the colour).
    let grey = TransferFunction::new(vec![(0.0, [0.0; 4]), (1.0, [1.0; 4])]).unwrap();
    VolumeScene::new(&ctx.device, &ctx.queue, volume, grey, glam::Mat4::IDENTITY).unwrap()
}

#[test]
fn every_ray_marching_method_projects_as_the_npass() {
    let scene = scene(&blob_behind_a_slab());
    for projection in [
        Projection::Maximum,
        Projection::Minimum,
        Projection::Average,
    ] {
        for spec in ["hubner8", "lenticular:4"] {
            let npass = render(&scene, Method::NPass, projection, spec);
            for method in [Method::SinglePass, Method::Tiled, Method::Layered] {
                let image = render(&scene, method, projection, spec);
                common::assert_matches(
                    &format!("{}-{method}-{spec}", projection.name()),
                    &image,
                    &npass,
                );
            }
        }
    }
}

#[test]
fn projections_see_what_the_volume_holds_along_each_ray() {
    let scene = scene(&blob_behind_a_slab());
    // One view on every pixel: the image is that camera's rays.
    let grey_at = |projection, x: u32, y: u32| {
        let image = render(&scene, Method::SinglePass, projection, "view:8,4");
        image.get(x, y, 1)
    };
    // The centre ray crosses the slab (0.5), the blob (1.0) and the background (0.1).
    let mip = grey_at(Projection::Maximum, 32, 32);
    let minip = grey_at(Projection::Minimum, 32, 32);
    let mean = grey_at(Projection::Average, 32, 32);
    assert!(
        mip >= 250,
        "MIP at the centre sees the blob behind the slab: {mip}"
    );
    assert!(
        (20..=32).contains(&minip),
        "MinIP at the centre: the background's 0.1: {minip}"
    );
    assert!(
        mean > minip && mean < mip,
        "the mean lies between: {minip} < {mean} < {mip}"
    );
    // A ray beside the blob: the slab is its maximum.
    let beside = grey_at(Projection::Maximum, 32, 14);
    assert!(
        (118..=138).contains(&beside),
        "MIP beside the blob: the slab's 0.5: {beside}"
    );
    // Compositing hides the blob behind the slab's opacity where MIP shows it.
    let composite = grey_at(Projection::Composite, 32, 32);
    assert!(
        composite < mip,
        "compositing dims the blob: {composite} vs {mip}"
    );
}

#[test]
fn the_slices_path_and_the_warp_refuse_a_projection_by_name() {
    let ctx = common::gpu();
    let settings = VolumeSettings {
        projection: Projection::Maximum,
        ..Default::default()
    };
    for options in [
        RendererOptions {
            volume: VolumeOptions {
                settings,
                path: autostereo::VolumePath::Slices(autostereo::volume::AlphaMode::Exact),
            },
            ..RendererOptions::new(Method::SinglePass)
        },
        RendererOptions {
            volume: VolumeOptions {
                settings,
                ..Default::default()
            },
            ..RendererOptions::new(Method::Warp)
        },
    ] {
        let error = options
            .volume_renderer(&ctx.device)
            .err()
            .unwrap()
            .to_string();
        assert!(
            error.contains("invalid projection: mip: ray marching only"),
            "{error}"
        );
    }
}

/// The isosurface of a radial ramp (1 at the centre to 0 at 14 voxels) is a sphere of radius
/// 14·(1 − value): lit where the rays meet it, background elsewhere, its area growing as the
/// value falls as the sphere's does (radius 11.2 at 0.2 against 7 at 0.5: about 2.6×).
#[test]
fn an_isosurface_is_the_sphere_of_its_value() {
    let c = |v: u32| v as f32 + 0.5 - N as f32 / 2.0;
    let mut data = Vec::new();
    for z in 0..N {
        for y in 0..N {
            for x in 0..N {
                let r = (c(x) * c(x) + c(y) * c(y) + c(z) * c(z)).sqrt();
                data.push((1.0 - r / 14.0).clamp(0.0, 1.0));
            }
        }
    }
    let ramp = scene(&Volume::new([N; 3], [1.0; 3], data).unwrap());
    let lit = |value: f32| {
        let image = render_at(
            &ramp,
            Method::SinglePass,
            Projection::Isosurface,
            value,
            "view:8,4",
        );
        let background = image.get(0, 0, 0);
        assert!(
            image.get(32, 32, 0) != background,
            "the centre ray meets the surface"
        );
        (0..64 * 64)
            .filter(|i| image.get(i % 64, i / 64, 0) != background)
            .count() as f64
    };
    let (small, large) = (lit(0.5), lit(0.2));
    let ratio = large / small;
    println!("isosurface areas: {small} px at 0.5, {large} px at 0.2 (ratio {ratio:.2})");
    assert!((2.0..=3.2).contains(&ratio), "ratio {ratio:.2}");
}
