//! Bad input is a clear error, never a panic: library calls and the CLI.

use crate::common;

use std::path::PathBuf;

use autostereo::camera::Bounds;
use autostereo::camera::MultiViewCamera;
use autostereo::display::{Calibration, Display};
use autostereo::frame::Frame;
use autostereo::mesh::Mesh;
use autostereo::Error;

fn temp_file(name: &str, contents: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-input");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

/// The sample Looking Glass calibration, as text and as JSON.
fn sample_calibration() -> (String, serde_json::Value) {
    let full = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/lkg_sample_visual.json"
    ))
    .unwrap();
    let json = serde_json::from_str(&full).unwrap();
    (full, json)
}

#[test]
fn malformed_obj_files_are_mesh_errors() {
    for (name, text, expect) in [
        (
            "bad_number.obj",
            "v 1 2 x\nv 0 0 0\nv 1 0 0\nf 1 2 3\n",
            "malformed",
        ),
        (
            "bad_index.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
            "index out of bounds",
        ),
        ("no_faces.obj", "v 0 0 0\nv 1 0 0\n", "no triangles"),
        ("empty.obj", "", "no triangles"),
        (
            "nan.obj",
            "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "non-finite",
        ),
    ] {
        let path = temp_file(name, text);
        match Mesh::load_obj(&path) {
            Err(Error::Mesh { reason, .. }) => {
                assert!(reason.contains(expect), "{name}: {reason}")
            }
            other => panic!("{name}: expected a mesh error, got {other:?}"),
        }
    }
    assert!(matches!(
        Mesh::load_obj("does/not/exist.obj".as_ref()),
        Err(Error::Mesh { .. })
    ));
}

#[test]
fn unknown_display_spec_and_bad_view_counts_are_errors() {
    assert!(matches!(
        Display::parse("hologram:3"),
        Err(Error::DisplaySpec { .. })
    ));
    assert!(matches!(
        Display::parse("lenticular:0"),
        Err(Error::InvalidParameter {
            param: autostereo::Param::Views,
            ..
        })
    ));
    assert!(matches!(
        Display::parse("slanted:0,8,1,0"),
        Err(Error::InvalidParameter {
            param: autostereo::Param::Views,
            ..
        })
    ));
    assert!(matches!(
        Display::parse("slanted:8,0,1,0"),
        Err(Error::InvalidParameter {
            param: autostereo::Param::Pitch,
            ..
        })
    ));
    assert!(matches!(
        Display::parse("lenticular:257"),
        Err(Error::InvalidParameter { .. })
    ));
    assert!(Display::parse("hubner8").unwrap().with_views(9).is_err());
    // Subnormal, huge or non-finite lens parameters would make the fixed-point phase
    // meaningless: errors naming the parameter.
    for (spec, name) in [
        ("slanted:8,1e-320,1,0", "pitch"),
        ("slanted:8,8,1e300,0", "slant"),
        ("slanted:8,8,1,1e300", "phase"),
    ] {
        match Display::parse(spec) {
            Err(Error::InvalidParameter { param, .. }) => assert_eq!(param.name(), name, "{spec}"),
            other => panic!("{spec}: expected an error on {name}, got {other:?}"),
        }
    }
}

#[test]
fn looking_glass_calibration_giving_an_unusable_lens_is_an_error() {
    let (full, json) = sample_calibration();
    for (i, (field, value)) in [("slope", 1e-300), ("slope", -1e-300), ("center", 1e300)]
        .into_iter()
        .enumerate()
    {
        let mut bad = json.clone();
        bad[field]["value"] = value.into();
        let path = temp_file(&format!("lkg_bad_{i}.json"), &bad.to_string());
        let err = Display::parse(&format!("lkg:{}", path.display())).unwrap_err();
        assert!(
            err.to_string().contains("calibration"),
            "{field} = {value}: {err}"
        );
    }
    let calibration = Calibration::from_json(&full, "v.json".as_ref()).unwrap();
    assert_eq!(
        calibration.holoplay_view(0, 3, 4, 1),
        0,
        "no views: no panic"
    );
}

#[test]
fn volumes_and_transfer_functions_with_inconsistent_fields_are_errors() {
    use autostereo::volume::VolumeScene;
    use autostereo::volume::{generate, PreintegrationTable, TransferFunction};
    use glam::Mat4;
    let empty_tf = TransferFunction { points: vec![] };
    assert_eq!(empty_tf.eval(0.5), [0.0; 4]);
    assert!(PreintegrationTable::new(&empty_tf, 1.0).is_err());
    let unsorted = TransferFunction {
        points: vec![(0.8, [1.0; 4]), (0.2, [0.0; 4])],
    };
    assert!(PreintegrationTable::new(&unsorted, 1.0).is_err());
    // Scalars outside 0..1 (the GPU holds them as f16: 1e6 would be inf there).
    let err = autostereo::volume::Volume::new([2, 1, 1], [1.0; 3], vec![0.5, 1e6]).unwrap_err();
    assert!(err.to_string().contains("voxel 1 is 1000000"), "{err}");
    let mut volume = generate::ct_head(8).unwrap();
    volume.data.truncate(10);
    assert!(volume.validate().is_err());
    let ctx = common::gpu();
    let ct_skin = TransferFunction::preset("ct-skin").unwrap();
    let head = generate::ct_head(8).unwrap();
    for (volume, tf, expect) in [
        (&volume, ct_skin, "values for dimensions"),
        (&head, empty_tf, "control point"),
    ] {
        let scene = VolumeScene::new(&ctx.device, &ctx.queue, volume, tf, Mat4::IDENTITY);
        let err = scene.err().unwrap().to_string();
        assert!(err.contains(expect), "{err}");
    }
    // A step of nothing is refused when the renderer is built; one too fine for this volume's
    // box (more than MAX_SAMPLES_PER_RAY samples along its diagonal) before the frame.
    use autostereo::render::{Method, Renderer};
    use autostereo::volume::VolumeRaycaster;
    let scene = VolumeScene::new(
        &ctx.device,
        &ctx.queue,
        &head,
        TransferFunction::preset("ct-skin").unwrap(),
        Mat4::IDENTITY,
    )
    .unwrap();
    let at = |step| VolumeSettings {
        step: Some(step),
        ..VolumeSettings::default()
    };
    let err = VolumeRaycaster::new(&ctx.device, Method::SinglePass, at(0.0)).err();
    assert!(err.unwrap().to_string().contains("sampling step"));
    let frame = common::frame(head.bounds(), "hubner8", 0.05, 1.0, [16, 16]);
    let target = autostereo::target::SpatialTarget::new(&ctx.device, [16, 16]).unwrap();
    let mut renderer = VolumeRaycaster::new(&ctx.device, Method::SinglePass, at(1e-4)).unwrap();
    let err = renderer.render(&ctx.device, &ctx.queue, &scene, &frame, &target);
    assert!(err.unwrap_err().to_string().contains("sampling step"));
}

#[test]
fn a_target_of_another_size_than_the_frame_is_an_error_for_every_mesh_renderer() {
    use autostereo::mesh::MeshBuffers;
    use autostereo::mesh::{MeshNPass, MeshSinglePass, MeshSinglePassOptions};
    use autostereo::render::{Method, Renderer};
    use autostereo::target::SpatialTarget;
    let ctx = common::gpu();
    let mesh = Mesh::torus_scene();
    let buffers = MeshBuffers::new(&ctx.device, &mesh).unwrap();
    let frame = common::frame(mesh.bounds().unwrap(), "hubner8", 0.05, 1.0, [32, 32]);
    let target = SpatialTarget::new(&ctx.device, [48, 32]).unwrap();
    let mut renderers: Vec<Box<dyn Renderer<MeshBuffers>>> = vec![
        Box::new(MeshNPass::new(&ctx.device, Method::NPass).unwrap()),
        Box::new(MeshNPass::new(&ctx.device, Method::SingleView).unwrap()),
        Box::new(MeshSinglePass::new(&ctx.device, MeshSinglePassOptions::default()).unwrap()),
    ];
    for renderer in &mut renderers {
        let err = renderer
            .render(&ctx.device, &ctx.queue, &buffers, &frame, &target)
            .unwrap_err();
        assert!(err.to_string().contains("differs from the frame"), "{err}");
    }
}

#[test]
fn zero_size_and_zero_views_are_errors() {
    let bounds = Bounds {
        min: glam::Vec3::splat(-1.0),
        max: glam::Vec3::splat(1.0),
    };
    let camera = MultiViewCamera::framing(bounds, 8, None, 0.5, 1.0).unwrap();
    let display = Display::parse("hubner8").unwrap();
    assert!(matches!(
        Frame::new(camera.clone(), display.clone(), [0, 0]),
        Err(Error::InvalidParameter {
            param: autostereo::Param::Size,
            ..
        })
    ));
    assert!(MultiViewCamera::framing(bounds, 0, None, 0.5, 1.0).is_err());
    assert!(
        Frame::new(camera.with_views(4), display, [64, 64]).is_err(),
        "camera/display N mismatch"
    );
}

#[test]
fn calibration_with_missing_or_bad_fields_is_an_error() {
    let (_, json) = sample_calibration();
    for field in [
        "pitch",
        "slope",
        "center",
        "DPI",
        "screenW",
        "screenH",
        "flipImageX",
        "invView",
    ] {
        let mut partial = json.clone();
        partial.as_object_mut().unwrap().remove(field);
        let err = Calibration::from_json(&partial.to_string(), "visual.json".as_ref()).unwrap_err();
        assert!(
            err.to_string()
                .contains(&format!("missing field '{field}'")),
            "{err}"
        );
    }
    for bad in ["{", "[]", r#"{"pitch": "x"}"#] {
        assert!(matches!(
            Calibration::from_json(bad, "visual.json".as_ref()),
            Err(Error::Calibration { .. })
        ));
    }
    let mut zero = json.clone();
    zero["slope"]["value"] = 0.0.into();
    assert!(Calibration::from_json(&zero.to_string(), "v.json".as_ref()).is_err());
}

/// What the interleaving does not model is refused by name, never ignored: the vertical and
/// subpixel-order flips, and a cell table that is incomplete (configVersion 3's subpixel cells
/// themselves are read: tests/display/mask/).
#[test]
fn looking_glass_calibrations_the_model_does_not_cover_are_refused_clearly() {
    let (_, json) = sample_calibration();
    let refused = |edit: &dyn Fn(&mut serde_json::Value), expect: &str| {
        let mut v = json.clone();
        edit(&mut v);
        let err = Calibration::from_json(&v.to_string(), "visual.json".as_ref()).unwrap_err();
        let text = err.to_string();
        assert!(
            text.contains("visual.json") && text.contains(expect),
            "{text}"
        );
    };
    refused(
        &|v| {
            v["configVersion"] = "3.0".into();
            v["subpixelCells"] = serde_json::json!([{ "ROffsetX": 0.0 }]);
            v["CellPatternMode"] = 2.0.into();
        },
        "subpixelCells[0]: missing field 'ROffsetY'",
    );
    refused(
        &|v| v["subpixelCells"] = serde_json::json!([{ "ROffsetX": 0.0 }]),
        "'subpixelCells' needs 'CellPatternMode'",
    );
    refused(
        &|v| v["flipImageY"]["value"] = 1.0.into(),
        "'flipImageY' = 1",
    );
    refused(&|v| v["flipSubp"]["value"] = 1.0.into(), "'flipSubp' = 1");
    // 0 or absent is the model's own orientation.
    for name in ["flipImageY", "flipSubp"] {
        let mut v = json.clone();
        v.as_object_mut().unwrap().remove(name);
        assert!(Calibration::from_json(&v.to_string(), "v.json".as_ref()).is_ok());
    }
    assert!(Calibration::from_json(&json.to_string(), "v.json".as_ref()).is_ok());
}

use autostereo::volume::VolumeSettings;
use common::cli;

#[test]
fn cli_reports_bad_input_without_panicking() {
    let bad_obj = temp_file("cli_bad.obj", "v 1 2 x\nf 1 2 3\n");
    let bad_ply = temp_file(
        "cli_bad.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1\n",
    );
    let calibration = temp_file("cli_calibration.json", r#"{"pitch": {"value": 50}}"#);
    let tiny_raw = temp_file("cli_tiny.raw", "ab");
    let xyz = temp_file("cli_cloud.xyz", "1 2 3\n");
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-input/cli_out.png");
    let out = out.to_str().unwrap();
    let lkg = format!("lkg:{}", calibration.display());
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["mesh", bad_obj.to_str().unwrap(), "--out", out],
            "malformed OBJ",
        ),
        (
            vec!["mesh", "--display", "hologram", "--out", out],
            "unknown display",
        ),
        (
            vec!["mesh", "--display", "lenticular:0", "--out", out],
            "views",
        ),
        (vec!["mesh", "--size", "0x0", "--out", out], "at least 1"),
        (
            vec!["mask", "--display", &lkg, "--size", "8x8", "--out", out],
            "missing field",
        ),
        (
            vec![
                "mask",
                "--display",
                "hubner8",
                "--size",
                "8x8",
                "--views",
                "0",
                "--out",
                out,
            ],
            "views",
        ),
        (vec!["mesh", "--frames", "0"], "1..=100000"),
        (vec!["volume", "--frames", "4294967295"], "1..=100000"),
        (
            vec!["mask", "--size", "100000x100000", "--out", out],
            "more than 268435456",
        ),
        (vec!["volume", "--builtin-size", "2000"], "4..=1024"),
        (
            vec![
                "volume",
                tiny_raw.to_str().unwrap(),
                "--raw-dims",
                "2,1,1",
                "--raw-type",
                "u8",
                "--raw-header",
                "18446744073709551615",
            ],
            "overflow",
        ),
        (vec!["volume", "missing.nrrd"], "missing.nrrd"),
        (vec!["points", "missing.ply"], "missing.ply"),
        (vec!["points", bad_ply.to_str().unwrap()], "truncated"),
        (
            vec!["points", xyz.to_str().unwrap()],
            "unknown format; read here: meshes .obj .ply",
        ),
        (
            vec!["points", "--groups", "0", "--size", "8x8"],
            "group count",
        ),
        (vec!["points", "--epsilon=-1", "--size", "8x8"], "--epsilon"),
        (
            vec!["points", "--radius-scale", "NaN", "--size", "8x8"],
            "radius scale",
        ),
        (
            vec!["volume", "--tf", "nope", "--size", "8x8"],
            "unknown preset",
        ),
        (
            vec!["volume", "--step", "0", "--size", "8x8"],
            "sampling step",
        ),
        (vec!["volume", "x.raw", "--raw-dims", "4,4,4"], "--raw-type"),
        (vec!["volume", "--rotate", "1,2"], "three comma-separated"),
        (
            vec![
                "volume",
                "--builtin-size",
                "8",
                "--path",
                "slices",
                "--method",
                "n-pass",
            ],
            "single-pass",
        ),
        (vec!["mesh", "--visibility", "bogus"], "invalid value"),
        (
            vec!["views", "nonexistent.png", "--view", "0", "--out", out],
            "nonexistent.png",
        ),
        (
            vec!["mesh", "--out", "/no/such/dir/x.png"],
            "does not exist",
        ),
    ];
    for (args, expect) in cases {
        let (ok, stderr) = cli(&common::measuring(&args));
        assert!(!ok, "{args:?} should fail");
        assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
        assert!(
            stderr.contains(expect),
            "{args:?}: stderr lacks '{expect}': {stderr}"
        );
    }
}

#[test]
fn bad_point_clouds_and_splat_settings_are_errors() {
    use autostereo::points::PointCloud;
    use autostereo::points::{PointSplatter, SplatDepth, SplatOptions};
    use autostereo::render::Method;
    let missing = PointCloud::load("no/such/cloud.ply".as_ref()).unwrap_err();
    assert!(matches!(missing, Error::Io { .. }), "{missing}");
    let ply = temp_file("not_ply.ply", "hello\n");
    let err = PointCloud::load(&ply).unwrap_err();
    assert!(
        matches!(err, Error::Points { .. }) && err.to_string().contains("not a PLY"),
        "{err}"
    );
    let mut cloud = PointCloud::sphere(10, glam::Vec3::ZERO, 1.0, Some(1.0));
    cloud.radii.as_mut().unwrap()[3] = -1.0;
    assert!(cloud
        .complete(1.0)
        .unwrap_err()
        .to_string()
        .contains("point 3"));
    cloud.radii = None;
    cloud.normals.as_mut().unwrap().pop();
    assert!(cloud.complete(1.0).is_err());
    assert!(PointCloud::default().complete(1.0).is_err());
    let huge = PointCloud::sphere(10, glam::Vec3::ZERO, 1.0, Some(1e30));
    assert!(huge
        .complete(1e30)
        .unwrap_err()
        .to_string()
        .contains("splat"));
    // OBJ: vertices only (faces ignored), colours when every vertex has them; bad numbers.
    let obj = temp_file(
        "points.obj",
        "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nf 1 2 2\nv 0 1 0 0 0 1\n",
    );
    let cloud = PointCloud::load(&obj).unwrap();
    assert_eq!(cloud.len(), 3);
    assert_eq!(cloud.colors.unwrap()[2], [0.0, 0.0, 1.0]);
    let bad = temp_file("bad_points.obj", "v 0 0 0\nv 1 nan_x 0\n");
    let err = PointCloud::load(&bad).unwrap_err().to_string();
    assert!(err.contains("line 2") && err.contains("nan_x"), "{err}");
    let ctx = common::gpu();
    let options = SplatOptions {
        depth: SplatDepth::Exact,
        epsilon: f32::NAN,
    };
    let err = PointSplatter::new(&ctx.device, Method::SinglePass, options)
        .err()
        .unwrap();
    assert!(err.to_string().contains("epsilon"), "{err}");
    // More groups than texture-array layers: refused before any grouping work.
    let (splats, _) = PointCloud::sphere(50, glam::Vec3::ZERO, 1.0, Some(1.0))
        .complete(1.0)
        .unwrap();
    let groups = autostereo::points::GroupCount::Fixed(1_000_000_000);
    let err = autostereo::points::SplatScene::new(&ctx.device, &splats, groups)
        .err()
        .unwrap();
    assert!(matches!(err, Error::LimitExceeded { .. }), "{err}");
}
