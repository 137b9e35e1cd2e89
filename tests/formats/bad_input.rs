//! Bad input is a clear error, never a panic: malformed meshes and point clouds, inconsistent
//! volumes and transfer functions, splat and sampling settings out of range. (The command
//! line's reports of bad input: cli/tests/input/bad_input.rs.)

use crate::common;

use autostereo::mesh::Mesh;
use autostereo::volume::VolumeSettings;
use autostereo::Error;

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
        let path = common::input_file(name, text);
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
fn bad_point_clouds_and_splat_settings_are_errors() {
    use autostereo::points::PointCloud;
    use autostereo::points::{PointSplatter, SplatDepth, SplatOptions};
    use autostereo::render::Method;
    let missing = PointCloud::load("no/such/cloud.ply".as_ref()).unwrap_err();
    assert!(matches!(missing, Error::Io { .. }), "{missing}");
    let ply = common::input_file("not_ply.ply", "hello\n");
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
    let obj = common::input_file(
        "points.obj",
        "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nf 1 2 2\nv 0 1 0 0 0 1\n",
    );
    let cloud = PointCloud::load(&obj).unwrap();
    assert_eq!(cloud.len(), 3);
    assert_eq!(cloud.colors.unwrap()[2], [0.0, 0.0, 1.0]);
    let bad = common::input_file("bad_points.obj", "v 0 0 0\nv 1 nan_x 0\n");
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
