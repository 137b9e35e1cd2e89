//! The compute visibility's view clusters (`ViewClusters`, `--clusters`) against the N-pass: every
//! cluster count C ∈ {1, 2, 7, N} and the per-triangle choice on subpixel displays (the paper's
//! 8 views, Looking Glass's 49 with subpixel cells), and triangles too large for one invocation
//! (handed on to the large triangles' pass: lavapipe ends an invocation's loops after 65535
//! iterations, which silently dropped their lower rows).

use super::single_pass_mesh::{display, framed, versus_npass, SIZE};
use crate::common;

use autostereo::camera::MultiViewCamera;
use autostereo::frame::Frame;
use autostereo::mesh::{CoverBounds, Mesh, MeshSinglePassOptions, ViewClusters, Visibility};
use glam::Vec3;

fn compute(clusters: ViewClusters) -> MeshSinglePassOptions {
    MeshSinglePassOptions {
        visibility: Visibility::Compute,
        bounds: CoverBounds::Exact,
        clusters,
    }
}

fn lkg_spec() -> String {
    concat!(
        "lkg:",
        env!("CARGO_MANIFEST_DIR"),
        "/data/lkg_sample_32in_landscape_gen3_visual.json"
    )
    .to_string()
}

/// `frame` rendered with each cluster count equals the N-pass (`None` on adapters without
/// compute visibility, after checking their error).
fn assert_every_clustering_matches(name: &str, mesh: &Mesh, frame: &Frame, views: u32) {
    let counts = [
        ViewClusters::Fixed(1),
        ViewClusters::Fixed(2),
        ViewClusters::Fixed(7),
        ViewClusters::Fixed(views),
        ViewClusters::PerTriangle,
    ];
    for clusters in counts {
        let label = format!("{name}-clusters-{clusters}");
        if let Some(diff) = versus_npass(&label, mesh, frame, compute(clusters)) {
            assert!(diff.frac_off_2 <= 0.001, "{label}: {diff:?}");
        }
    }
}

#[test]
fn every_cluster_count_equals_the_npass() {
    let mesh = Mesh::torus_scene();
    for (name, spec, views) in [
        ("hubner8", "hubner8".to_string(), 8),
        ("lkg-cells", lkg_spec(), 49),
    ] {
        // A wide disparity range (separation 0.15 of the radius): clusters see narrow spans.
        let frame = Frame::new(framed(&mesh, views, 0.15, 1.2), display(&spec), SIZE).unwrap();
        assert_every_clustering_matches(name, &mesh, &frame, views);
    }
}

/// Two triangles filling most of a 256² frame: each covers ~65 000 pixels × 3 subpixels, past
/// one invocation's budget, so most of their rows are the large triangles' pass's.
#[test]
fn triangles_larger_than_one_invocation_are_finished() {
    let corners = [
        Vec3::new(-1.0, -1.0, 0.0),
        Vec3::new(1.0, -1.0, 0.3),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(-1.0, 1.0, -0.3),
    ];
    let mesh = Mesh {
        positions: corners.to_vec(),
        normals: vec![Vec3::Z; 4],
        colors: vec![[0.9, 0.6, 0.3, 1.0]; 4],
        indices: vec![0, 1, 2, 0, 2, 3],
        ..Default::default()
    };
    let size = [256, 256];
    let bounds = mesh.bounds().unwrap();
    let camera =
        MultiViewCamera::framing(bounds, 49, Some(0.1 * bounds.radius()), 0.6, 1.0).unwrap();
    let frame = Frame::new(camera, display(&lkg_spec()), size).unwrap();
    for clusters in [ViewClusters::Fixed(1), ViewClusters::Fixed(7)] {
        let label = format!("large-triangles-clusters-{clusters}");
        if let Some(diff) = versus_npass(&label, &mesh, &frame, compute(clusters)) {
            assert!(diff.frac_off_2 <= 0.001, "{label}: {diff:?}");
        }
    }
}

#[test]
fn clusters_need_compute_visibility_and_at_least_one() {
    let device = &common::gpu().device;
    let zero = autostereo::mesh::MeshSinglePass::new(device, compute(ViewClusters::Fixed(0)));
    let message = zero.err().expect("0 clusters is refused").to_string();
    assert!(
        message.contains("view clusters") && message.contains("at least one"),
        "{message}"
    );
    let exact = MeshSinglePassOptions {
        visibility: Visibility::Exact,
        ..compute(ViewClusters::Fixed(7))
    };
    let message = autostereo::mesh::MeshSinglePass::new(device, exact)
        .err()
        .expect("clusters with exact visibility are refused")
        .to_string();
    assert!(
        message.contains("only compute visibility groups views"),
        "{message}"
    );
}
