use glam::{Vec3, Vec4Swizzles};

use super::*;

fn camera(views: u32, separation: f32) -> MultiViewCamera {
    let bounds = Bounds {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    MultiViewCamera::framing(bounds, views, Some(separation), 0.6, 1.5).unwrap()
}

/// Matrix projection of eye-space `p` in view `i`, in focal-plane coordinates.
fn matrix_projection(c: &MultiViewCamera, i: u32, p: Vec3) -> glam::Vec2 {
    let clip = c.projection(i) * p.extend(1.0);
    let ndc = clip.xy() / clip.w;
    ndc * c.focal_window() * 0.5
}

#[test]
fn focal_plane_point_projects_to_same_pixel_in_all_views() {
    let c = camera(8, 0.3);
    let fd = c.focal_distance;
    for p in [
        Vec3::new(0.2, -0.4, -fd),
        Vec3::new(-1.1, 0.7, -fd),
        Vec3::new(0.0, 0.0, -fd),
    ] {
        let centre = c.focal_to_pixel(c.project_offset(0.0, p), [512, 384]);
        for i in 0..c.views {
            for q in [c.project(i, p), matrix_projection(&c, i, p)] {
                let px = c.focal_to_pixel(q, [512, 384]);
                assert!(
                    (px - centre).abs().max_element() < 1e-3,
                    "view {i}: {px} vs {centre}"
                );
            }
        }
    }
}

#[test]
fn zero_separation_or_one_view_equals_centre_view() {
    let p = Vec3::new(0.3, 0.2, -7.0);
    for c in [camera(8, 0.0), camera(1, 0.5)] {
        let centre = c.project_offset(0.0, p);
        for i in 0..c.views {
            assert_eq!(c.view_offset(i), 0.0);
            assert_eq!(c.project(i, p), centre);
            assert_eq!(c.projection(i), c.projection_for_offset(0.0));
        }
    }
}

#[test]
fn matrix_form_equals_closed_form() {
    let c = camera(8, 0.25);
    let fd = c.focal_distance;
    for i in 0..c.views {
        for p in [
            Vec3::new(0.5, 0.1, -0.5 * fd),
            Vec3::new(-0.8, 0.4, -1.3 * fd),
            Vec3::new(0.1, -0.9, -3.0 * fd),
        ] {
            let closed = c.project(i, p);
            let matrix = matrix_projection(&c, i, p);
            assert!(
                (closed - matrix).abs().max_element() < 1e-4 * fd,
                "view {i} {p}: {closed} vs {matrix}"
            );
        }
    }
}

#[test]
fn depth_range_maps_near_far_to_zero_one() {
    let c = camera(4, 0.1);
    for i in 0..4 {
        let m = c.projection(i);
        let near = m * Vec3::new(0.0, 0.0, -c.near).extend(1.0);
        let far = m * Vec3::new(0.0, 0.0, -c.far).extend(1.0);
        assert!((near.z / near.w).abs() < 1e-5);
        assert!((far.z / far.w - 1.0).abs() < 1e-5);
    }
}

#[test]
fn parallax_sign_follows_design() {
    // x_f = p.x·fd/d + vd·(1 − fd/d): behind the focal plane (d > fd) a point moves with the
    // camera offset, in front of it (d < fd) against it.
    let c = camera(2, 1.0);
    let far = Vec3::new(0.0, 0.0, -2.0 * c.focal_distance);
    let near = Vec3::new(0.0, 0.0, -0.5 * c.focal_distance);
    assert!(c.project(1, far).x > c.project(0, far).x);
    assert!(c.project(1, near).x < c.project(0, near).x);
}

#[test]
fn invalid_parameters_are_errors() {
    let good = camera(8, 0.1);
    let mut bad = good.clone();
    bad.views = 0;
    assert!(bad.validate().is_err());
    let mut bad = good.clone();
    bad.focal_distance = f32::NAN;
    assert!(bad.validate().is_err());
    let mut bad = good.clone();
    bad.far = bad.near;
    assert!(bad.validate().is_err());
    let mut bad = good;
    bad.separation = f32::INFINITY;
    assert!(bad.validate().is_err());
}

#[test]
fn looking_at_the_framings_own_points_is_the_framing() {
    let bounds = Bounds {
        min: Vec3::new(-1.0, -0.5, -2.0),
        max: Vec3::new(3.0, 1.5, 0.0),
    };
    let framed = MultiViewCamera::framing(bounds, 8, None, 0.6, 1.5).unwrap();
    let eye = framed.eye_position();
    let looking =
        MultiViewCamera::looking_at(bounds, eye, bounds.center(), Vec3::Y, 8, None, 0.6, 1.5)
            .unwrap();
    assert!(looking
        .eye_from_world
        .abs_diff_eq(framed.eye_from_world, 1e-5));
    for (a, b) in [
        (looking.focal_distance, framed.focal_distance),
        (looking.near, framed.near),
        (looking.far, framed.far),
        (looking.separation, framed.separation),
    ] {
        assert!((a - b).abs() <= 1e-5 * b.abs(), "{a} vs {b}");
    }
}

#[test]
fn looking_at_puts_the_eye_target_and_up_where_asked() {
    let bounds = Bounds {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    let (from, at) = (Vec3::new(-1.0, 2.0, -3.0), Vec3::new(0.5, 0.0, 0.0));
    let c =
        MultiViewCamera::looking_at(bounds, from, at, Vec3::NEG_Y, 4, Some(0.1), 0.6, 1.0).unwrap();
    assert!((c.eye_position() - from).length() < 1e-5);
    // The target on the axis, on the focal plane.
    let target = c.eye_from_world.transform_point3(at);
    assert!(target.truncate().length() < 1e-5, "{target}");
    assert!((-target.z - c.focal_distance).abs() < 1e-5);
    assert!((c.focal_distance - (at - from).length()).abs() < 1e-5);
    // World −y is the image's up: a point below the target projects above it.
    let below = c.eye_from_world.transform_point3(at - Vec3::Y * 0.1);
    assert!(below.y > 0.0, "{below}");
    // Near and far enclose the bounding sphere, the near plane ahead of the eye.
    let d = c.depth_of(bounds.center());
    assert!(c.near > 0.0 && c.near <= d - bounds.radius() && c.far >= d + bounds.radius());
    assert_eq!(c.separation, 0.1);
    // From inside the scene: near stays ahead of the eye, far beyond the sphere.
    let inside =
        MultiViewCamera::looking_at(bounds, Vec3::ZERO, Vec3::Z, Vec3::Y, 4, None, 0.6, 1.0)
            .unwrap();
    assert!(inside.near > 0.0 && inside.far >= bounds.radius());
}

#[test]
fn a_degenerate_look_at_is_refused_by_name() {
    let bounds = Bounds {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    let refused = |from: Vec3, at: Vec3, up: Vec3, name: &str, says: &str| {
        let e = MultiViewCamera::looking_at(bounds, from, at, up, 8, None, 0.6, 1.0).unwrap_err();
        match &e {
            Error::InvalidParameter { param, .. } => assert_eq!(param.name(), name, "{e}"),
            other => panic!("{other}"),
        }
        assert!(e.to_string().contains(says), "{e}");
    };
    let z = Vec3::new(0.0, 0.0, 5.0);
    refused(z, z, Vec3::Y, "look-at", "looks nowhere");
    refused(
        z,
        Vec3::ZERO,
        Vec3::Z,
        "up",
        "parallel to the view direction",
    );
    refused(z, Vec3::ZERO, Vec3::NEG_Z * 3.0, "up", "parallel");
    refused(z, Vec3::ZERO, Vec3::ZERO, "up", "zero vector");
    refused(
        Vec3::new(f32::NAN, 0.0, 0.0),
        Vec3::ZERO,
        Vec3::Y,
        "look-from",
        "finite",
    );
    refused(z, Vec3::splat(f32::INFINITY), Vec3::Y, "look-at", "finite");
    refused(z, Vec3::ZERO, Vec3::new(0.0, f32::NAN, 0.0), "up", "finite");
    // Looking away from the scene.
    refused(
        z,
        Vec3::new(0.0, 0.0, 10.0),
        Vec3::Y,
        "look-at",
        "wholly behind the camera",
    );
}
