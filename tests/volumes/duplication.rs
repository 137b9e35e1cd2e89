//! The per-view duplication methods (tiled, layered) against the N-pass oracle on volumes, on
//! several displays and N = 1, 2, 8, 45 ([`common::DISPLAYS`]).

use crate::common;

use autostereo::render::Method;
use autostereo::volume::VolumeRaycaster;
use autostereo::volume::VolumeSettings;

#[test]
fn volume_tiled_and_layered_match_the_npass_exactly() {
    let (scene, bounds) = common::head_scene();
    let device = common::gpu().device.clone();
    for &(spec, size) in common::DISPLAYS {
        let frame = common::frame(bounds, spec, 0.15, 1.0, size);
        let mut npass =
            VolumeRaycaster::new(&device, Method::NPass, VolumeSettings::default()).unwrap();
        let oracle = common::render(&mut npass, &scene, &frame);
        for method in [Method::Tiled, Method::Layered] {
            let mut renderer =
                VolumeRaycaster::new(&device, method, VolumeSettings::default()).unwrap();
            let image = common::render(&mut renderer, &scene, &frame);
            // The same rays and samples: identical, not just close.
            let diff = common::assert_matches(&format!("volume-{method}-{spec}"), &image, &oracle);
            assert_eq!(diff.max_abs_err, 0, "volume {method} {spec}: {diff:?}");
        }
    }
    let error = VolumeRaycaster::new(&device, Method::Mrt, VolumeSettings::default())
        .err()
        .unwrap();
    assert!(error.to_string().contains("meshes only"), "{error}");
}
