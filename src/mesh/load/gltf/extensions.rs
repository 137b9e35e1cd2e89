//! What a glTF file must be before it is read: version 2.0, and no required extension this
//! reader does not decode (each named, with what to do).

/// The required extensions this reader decodes.
const READ_EXTENSIONS: &[&str] = &["KHR_texture_transform", "KHR_draco_mesh_compression"];

/// What to do about a required extension this reader does not decode.
fn extension_advice(name: &str) -> &'static str {
    match name {
        "EXT_meshopt_compression" => {
            "its geometry is compressed; decompress it first, e.g. `npx @gltf-transform/cli \
             copy in.glb out.glb` (gltf-transform writes plain accessors)"
        }
        "KHR_mesh_quantization" => {
            "its attributes are quantised; `npx @gltf-transform/cli dequantize in.glb out.glb` \
             writes floats"
        }
        "KHR_texture_basisu" | "EXT_texture_webp" | "EXT_texture_avif" => {
            "its textures are in a format this reader does not decode"
        }
        _ => "this reader does not decode it",
    }
}

/// glTF 1.0 named as such (its JSON is another schema; the serde error would say "invalid
/// type: map, expected a sequence"), and every extension the file requires that this reader
/// does not decode named, with what to do (`extensionsRequired`; an optional extension is
/// ignored, as the format allows).
pub(super) fn check_version_and_extensions(bytes: &[u8]) -> std::result::Result<(), String> {
    let json: &[u8] = match bytes {
        [b'g', b'l', b'T', b'F', ..] if bytes.len() >= 20 => {
            let len = u32::from_le_bytes([bytes[12], bytes[13], bytes[14], bytes[15]]) as usize;
            bytes.get(20..20usize.saturating_add(len)).unwrap_or(&[])
        }
        _ => bytes,
    };
    // Unreadable JSON is the crate's to describe below.
    let Ok(root) = serde_json::from_slice::<serde_json::Value>(json) else {
        return Ok(());
    };
    let version = root["asset"]["version"].as_str().unwrap_or("");
    if version.starts_with('1') || (root.get("asset").is_none() && root["meshes"].is_object()) {
        return Err(format!(
            "glTF {} (a glTF 1.0 file): only glTF 2.0 is read; convert it, e.g. with Blender's \
             glTF importer and exporter",
            if version.is_empty() { "1.0" } else { version }
        ));
    }
    let required: Vec<&str> = root["extensionsRequired"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|e| e.as_str())
        .filter(|e| !READ_EXTENSIONS.contains(e))
        .collect();
    match required.first() {
        None => Ok(()),
        Some(_) => Err(format!(
            "requires {}",
            required
                .iter()
                .map(|e| format!("{e} ({})", extension_advice(e)))
                .collect::<Vec<_>>()
                .join("; ")
        )),
    }
}
