//! `--camera`: a model the method cannot render, or one that does not exist, is refused by name.
//! (The camera models themselves, against the N-pass, the skewed render and the closed form:
//! tests/meshes/camera_models.rs.)

use crate::common;

#[test]
fn models_a_method_cannot_render_are_refused_by_name() {
    for (args, expect) in [
        (&["mesh", "--camera", "fisheye"][..], "fisheye"),
        (
            &["mesh", "--camera", "toe-in", "--method", "warp"][..],
            "toe-in",
        ),
    ] {
        let (ok, err) = common::cli(&common::measuring(args));
        assert!(!ok && err.contains(expect), "{args:?}: {err}");
    }
}
