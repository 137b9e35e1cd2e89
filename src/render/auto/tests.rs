//! The census against hand-computed pixels, the choice's rules, and the model's choices against
//! the measurements it was fitted to (docs/auto/measurements.json).

use glam::Vec3;

use super::*;
use crate::camera::{Bounds, CameraSettings};
use crate::display::Display;
use crate::mesh::Mesh;

fn unit_bounds() -> Bounds {
    Bounds {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    }
}

fn frame(spec: &str, size: [u32; 2]) -> Frame {
    let display = Display::parse(spec).unwrap();
    let camera = CameraSettings::default()
        .camera(unit_bounds(), &display, size)
        .unwrap();
    Frame::new(camera, display, size).unwrap()
}

fn lkg16() -> String {
    format!(
        "lkg:{}/data/lkg_sample_16in_landscape_gen3_visual.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// One triangle with eye-space corners `eye` in `frame`.
fn triangle(frame: &Frame, eye: [Vec3; 3]) -> Mesh {
    let world_from_eye = frame.camera.eye_from_world.inverse();
    Mesh {
        positions: eye.map(|p| world_from_eye.transform_point3(p)).to_vec(),
        normals: vec![Vec3::Z; 3],
        colors: vec![[1.0; 4]; 3],
        indices: vec![0, 1, 2],
        tex_coords: Vec::new(),
        texture_ids: Vec::new(),
        textures: Vec::new(),
    }
}

/// A right triangle from the window's centre, legs a quarter of the window, at depth
/// `depth` × the focal distance (scaled so that it projects the same in the centre view).
fn quarter_triangle(frame: &Frame, depth: f32) -> Mesh {
    let (w, fd) = (
        frame.camera.focal_window() * depth,
        frame.camera.focal_distance,
    );
    let z = -fd * depth;
    triangle(
        frame,
        [
            Vec3::new(0.0, 0.0, z),
            Vec3::new(0.25 * w.x, 0.0, z),
            Vec3::new(0.0, 0.25 * w.y, z),
        ],
    )
}

#[test]
fn a_floor_is_a_positive_finite_psnr() {
    assert_eq!(Accuracy::new(None).unwrap(), Accuracy::Exact);
    assert_eq!(Accuracy::new(Some(40.0)).unwrap(), Accuracy::MinPsnr(40.0));
    for bad in [0.0, -3.0, f32::NAN, f32::INFINITY] {
        let e = Accuracy::new(Some(bad)).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidParameter {
                    param: Param::MinPsnr,
                    ..
                }
            ),
            "{e}"
        );
    }
}

#[test]
fn a_triangle_on_the_focal_plane_covers_its_own_pixels() {
    let f = frame("hubner8", [256, 256]);
    let census = MeshCensus::of(&quarter_triangle(&f, 1.0), &f);
    assert_eq!(census.triangles, 1);
    // Legs of 64 pixels: 2048 pixels of triangle in a 64 × 64 rectangle; no disparity.
    assert!((census.triangle_pixels - 2048.0).abs() < 1.0, "{census:?}");
    assert!((census.cover_pixels - 4096.0).abs() <= 65.0, "{census:?}");
}

#[test]
fn off_the_focal_plane_the_cover_widens_by_the_views_disparity() {
    let f = frame("hubner8", [256, 256]);
    let census = MeshCensus::of(&quarter_triangle(&f, 2.0), &f);
    assert!((census.triangle_pixels - 2048.0).abs() < 1.0, "{census:?}");
    // The outermost views' projections of one vertex, apart in pixels (the camera's own
    // projection, not the census's closed form).
    let p = Vec3::new(0.0, 0.0, -2.0 * f.camera.focal_distance);
    let x = |view| f.camera.focal_to_pixel(f.camera.project(view, p), f.size).x;
    let disparity = (x(0) - x(f.camera.views - 1)).abs() as f64;
    assert!(disparity > 4.0, "a visible widening: {disparity}");
    let expected = (64.0 + disparity) * 64.0;
    assert!(
        (census.cover_pixels - expected).abs() <= 2.0 * 64.0 + 66.0,
        "{census:?} vs {expected}"
    );
}

#[test]
fn triangles_behind_the_camera_count_nothing() {
    let f = frame("hubner8", [256, 256]);
    let behind = triangle(
        &f,
        [Vec3::Z, Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 1.0)],
    );
    assert_eq!(MeshCensus::of(&behind, &f), MeshCensus::default());
}

/// The bunny's census on the 16" panel (docs/auto/measurements.json).
fn bunny_16in() -> Workload {
    Workload::Mesh(MeshCensus {
        triangles: 3674,
        triangle_pixels: 2.24e6,
        cover_pixels: 3.93e7,
    })
}

#[test]
fn exact_by_default_and_the_quilt_only_above_its_measured_psnr() {
    let f = frame(&lkg16(), [3840, 2160]);
    let all = crate::mesh::METHODS;
    let pick = |accuracy| {
        choose(&f, unit_bounds(), bunny_16in(), accuracy, &all)
            .unwrap()
            .chosen()
            .clone()
    };
    let exact = pick(Accuracy::Exact);
    assert_eq!(exact.psnr_db, None, "{exact:?}");
    let quilt = pick(Accuracy::MinPsnr(40.0));
    assert_eq!((quilt.method, quilt.view_size), (Method::Tiled, [857, 857]));
    assert_eq!(quilt.psnr_db, Some(41.8));
    assert_eq!(pick(Accuracy::MinPsnr(45.0)).psnr_db, None);
    // No measured PSNR, no candidate: the Gaussians' quilt.
    let gaussians = choose(
        &f,
        unit_bounds(),
        Workload::Gaussians,
        Accuracy::MinPsnr(1.0),
        &crate::gaussians::METHODS,
    )
    .unwrap();
    assert!(gaussians
        .candidates
        .iter()
        .all(|c| c.method != Method::Tiled));
    // Not a Looking Glass: no family quilt to weigh.
    let h8 = frame("hubner8", [512, 512]);
    let choice = choose(
        &h8,
        unit_bounds(),
        bunny_16in(),
        Accuracy::MinPsnr(1.0),
        &all,
    )
    .unwrap();
    let weighed: Vec<Method> = choice.candidates.iter().map(|c| c.method).collect();
    assert_eq!(weighed, [Method::SinglePass, Method::NPass]);
    assert!(
        choice.summary().starts_with("auto → "),
        "{}",
        choice.summary()
    );
}

#[test]
fn only_offered_methods_are_weighed_and_none_is_an_error() {
    let f = frame(&lkg16(), [3840, 2160]);
    let only = choose(
        &f,
        unit_bounds(),
        bunny_16in(),
        Accuracy::Exact,
        &[Method::SinglePass],
    );
    let only = only.unwrap();
    assert_eq!(only.candidates.len(), 1);
    assert_eq!(only.chosen().method, Method::SinglePass);
    let none = choose(
        &f,
        unit_bounds(),
        bunny_16in(),
        Accuracy::Exact,
        &[Method::Tiled],
    );
    let e = none.unwrap_err().to_string();
    assert!(e.contains("auto: no method") && e.contains("tiled"), "{e}");
}

/// Every measured case: the method the model predicts fastest is, measured, within 25 % of
/// the fastest (the machine drifts up to 1.5× within a session: docs/AUTO.md), among the
/// exact methods and among all.
#[test]
fn the_model_chooses_what_measured_fastest() {
    let cases: Vec<serde_json::Value> =
        serde_json::from_str(include_str!("../../../docs/auto/measurements.json")).unwrap();
    assert!(cases.len() >= 10);
    for case in &cases {
        let name = case["case"].as_str().unwrap();
        let workload = match case["kind"].as_str().unwrap() {
            "mesh" => Workload::Mesh(serde_json::from_value(case["census"].clone()).unwrap()),
            "points" => Workload::Points,
            "volume" => Workload::Volume,
            "gaussians" => Workload::Gaussians,
            other => panic!("{other}"),
        };
        let size: [u32; 2] = serde_json::from_value(case["size"].clone()).unwrap();
        let counts = Counts {
            pixels: size[0] as f64 * size[1] as f64,
            per_pixel: case["views_per_pixel"].as_f64().unwrap(),
            views: case["views"].as_f64().unwrap(),
            coverage: case["coverage"].as_f64().unwrap(),
        };
        let measured = case["measured_ms"].as_object().unwrap();
        let mut rows = Vec::new();
        for c in case["candidates"].as_array().unwrap() {
            let method: Method = c["method"].as_str().unwrap().parse().unwrap();
            let Some(ms) = measured.get(method.name()).and_then(|v| v.as_f64()) else {
                continue;
            };
            let view_size: [u32; 2] = serde_json::from_value(c["view_size"].clone()).unwrap();
            let predicted = predict(&workload, &counts, method, view_size, size);
            rows.push((method, c["psnr_db"].is_null(), predicted, ms));
        }
        for exact_only in [true, false] {
            let set: Vec<_> = rows.iter().filter(|r| r.1 || !exact_only).collect();
            let fastest = set.iter().map(|r| r.3).fold(f64::INFINITY, f64::min);
            let pick = set
                .iter()
                .min_by(|a, b| a.2.total_cmp(&b.2))
                .unwrap_or_else(|| panic!("{name}: no measured candidate"));
            assert!(
                pick.3 <= 1.25 * fastest,
                "{name} (exact only: {exact_only}): the model picks {} ({:.0} ms measured), the \
                 fastest measured {fastest:.0} ms: {rows:?}",
                pick.0,
                pick.3
            );
        }
    }
}
