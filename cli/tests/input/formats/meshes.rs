//! Every mesh format (PLY both byte orders, STL binary and ASCII, glTF and GLB) renders as the
//! same mesh does from an OBJ.

use super::*;

#[test]
fn every_mesh_format_renders_as_the_same_obj_does() {
    let mesh = torus();
    let reference = render_mesh(&write("torus.obj", obj_text(&mesh, None).as_bytes()), "obj");
    let files = [
        ("ply_le", write("torus_le.ply", &ply_binary(&mesh, false))),
        ("ply_be", write("torus_be.ply", &ply_binary(&mesh, true))),
        ("stl_binary", write("torus.stl", &stl_binary(&mesh))),
        (
            "stl_ascii_crlf",
            write("torus_ascii.stl", &stl_ascii_crlf(&mesh)),
        ),
        ("glb", write("torus.glb", &gltf(&mesh, true, None))),
        (
            "gltf_data_uri",
            write("torus.gltf", &gltf(&mesh, false, None)),
        ),
        // The signature wins over a misleading extension.
        (
            "glb_named_obj",
            write("torus_glb.obj", &gltf(&mesh, true, None)),
        ),
    ];
    for (name, file) in &files {
        let loaded = Mesh::load(file).unwrap();
        assert_eq!(loaded.triangle_count(), mesh.triangle_count(), "{name}");
        // Every triangle's corners where the OBJ's are (STL merges and renumbers vertices).
        for (t, corners) in loaded.indices.chunks(3).enumerate() {
            for (k, &i) in corners.iter().enumerate() {
                let want = mesh.positions[mesh.indices[3 * t + k] as usize];
                let got = loaded.positions[i as usize];
                assert!(
                    got.distance(want) < 1e-5,
                    "{name} triangle {t}: {got} vs {want}"
                );
            }
        }
        let image = render_mesh(file, name);
        let diff = compare(&image, &reference).unwrap();
        assert!(diff.max_abs_err <= 1, "{name}: {diff:?}");
    }
    // Colour: a glTF material's base colour factor is an OBJ's vertex colour.
    let red_obj = write("red.obj", obj_text(&mesh, Some([0.9, 0.2, 0.1])).as_bytes());
    let red_gltf = write("red.glb", &gltf(&mesh, true, Some([0.9, 0.2, 0.1, 1.0])));
    let diff = compare(
        &render_mesh(&red_gltf, "red_glb"),
        &render_mesh(&red_obj, "red_obj"),
    )
    .unwrap();
    assert!(diff.max_abs_err <= 1, "red: {diff:?}");
}
