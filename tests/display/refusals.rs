//! Bad displays, calibrations, frames and targets are clear errors, never panics. (The command
//! line's reports of bad input: cli/tests/input/bad_input.rs.)

use crate::common;

use autostereo::camera::Bounds;
use autostereo::camera::MultiViewCamera;
use autostereo::display::{Calibration, Display};
use autostereo::frame::Frame;
use autostereo::mesh::Mesh;
use autostereo::Error;

/// The sample Looking Glass calibration, as text and as JSON.
fn sample_calibration_json() -> (String, serde_json::Value) {
    let full = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/lkg_sample_visual.json"
    ))
    .unwrap();
    let json = serde_json::from_str(&full).unwrap();
    (full, json)
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
    let (full, json) = sample_calibration_json();
    for (i, (field, value)) in [("slope", 1e-300), ("slope", -1e-300), ("center", 1e300)]
        .into_iter()
        .enumerate()
    {
        let mut bad = json.clone();
        bad[field]["value"] = value.into();
        let path = common::input_file(&format!("lkg_bad_{i}.json"), bad.to_string());
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
    let (_, json) = sample_calibration_json();
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
    let (_, json) = sample_calibration_json();
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
