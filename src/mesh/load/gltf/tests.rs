//! glTF documents made here: a good triangle parses; hostile ones (bad accessors, views,
//! indices, node trees) are refused by name.

use super::*;

/// A glTF of one triangle at the origin (36 zero bytes in a data: URI) with `primitive`,
/// `accessor` (POSITION's) and `view` JSON spliced in, and `nodes`.
fn gltf(primitive: &str, accessor: &str, view: &str, nodes: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},"scenes":[{{"nodes":[0]}}],"nodes":[{nodes}],
"meshes":[{{"primitives":[{{{primitive}}}]}}],
"buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{zeros}"}}],
"bufferViews":[{{"buffer":0,"byteLength":36{view}}}],
"accessors":[{{"bufferView":0,"componentType":5126,"type":"VEC3"{accessor}}}]}}"#,
        zeros = "A".repeat(48)
    )
}

#[test]
fn a_good_triangle_parses() {
    let text = gltf(
        r#""attributes":{"POSITION":0}"#,
        r#","count":3"#,
        "",
        r#"{"mesh":0}"#,
    );
    let mesh = parse(text.as_bytes(), Path::new("ok.gltf"), None).unwrap();
    assert_eq!(mesh.triangle_count(), 1);
}

/// Each of these panicked or allocated without bound inside the crates before the checks.
#[test]
fn hostile_documents_are_refused_by_name() {
    let ok_prim = r#""attributes":{"POSITION":0}"#;
    let node = r#"{"mesh":0}"#;
    // 40 levels, each node's two children the same next node: 2^40 paths.
    let doubling: Vec<String> = (0..40)
        .map(|i| format!(r#"{{"mesh":0,"children":[{},{}]}}"#, i + 1, i + 1))
        .chain([node.to_string()])
        .collect();
    let cases = [
        (
            gltf(r#""attributes":{"POSITION":9}"#, r#","count":3"#, "", node),
            "accessor 9 does not exist",
        ),
        (
            gltf(ok_prim, r#","count":3"#, r#","byteStride":4"#, node),
            "a stride of 4 bytes",
        ),
        (gltf(ok_prim, r#","count":0"#, "", node), "0 elements"),
        (gltf(ok_prim, r#","count":4"#, "", node), "past its view"),
        (
            gltf(
                r#""attributes":{"POSITION":0},"mode":99"#,
                r#","count":3"#,
                "",
                node,
            ),
            "unknown mode",
        ),
        (
            gltf(ok_prim, r#","count":3"#, "", &doubling.join(",")),
            "node visits",
        ),
    ];
    for (text, expected) in cases {
        let e = parse(text.as_bytes(), Path::new("bad.gltf"), None)
            .unwrap_err()
            .to_string();
        assert!(e.contains(expected), "'{e}' lacks '{expected}'");
    }
}

/// glTF 1.0 and required extensions are named (before: a serde message, and "accessor 0:
/// sparse accessors are not read" for a Draco file).
#[test]
fn gltf_1_and_required_extensions_are_named() {
    let path = std::path::Path::new("old.gltf");
    let v1 = r#"{"asset": {"version": "1.0"}, "meshes": {"m": {"primitives": []}}}"#;
    let error = parse(v1.as_bytes(), path, None).unwrap_err().to_string();
    assert!(
        error.contains("glTF 1.0") && error.contains("only glTF 2.0"),
        "{error}"
    );
    let meshopt = r#"{"asset": {"version": "2.0"}, "extensionsUsed": ["EXT_meshopt_compression"],
        "extensionsRequired": ["EXT_meshopt_compression"], "meshes": [], "accessors": []}"#;
    let error = parse(meshopt.as_bytes(), path, None)
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("requires EXT_meshopt_compression") && error.contains("gltf-transform"),
        "{error}"
    );
    let other = r#"{"asset": {"version": "2.0"}, "extensionsRequired": ["EXT_unheard_of"]}"#;
    let error = parse(other.as_bytes(), path, None).unwrap_err().to_string();
    assert!(
        error.contains("requires EXT_unheard_of (this reader does not decode it)"),
        "{error}"
    );
}
