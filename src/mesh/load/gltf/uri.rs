//! The bytes a glTF names: a URI's (its buffers' and images'), a `data:` URI's base64 or a
//! file beside the glTF (relative paths without `..`, read bounded like every input); and a
//! buffer view's, within its buffer.

use std::path::Path;

use base64::Engine as _;

/// A buffer's or image's bytes from a `data:` URI or a file beside the glTF.
pub(super) fn uri_data(uri: &str, dir: Option<&Path>) -> std::result::Result<Vec<u8>, String> {
    if let Some(data) = uri.strip_prefix("data:") {
        let (_, encoded) = data
            .split_once(";base64,")
            .ok_or("a data: URI that is not base64")?;
        return base64::engine::general_purpose::STANDARD
            .decode(encoded)
            .map_err(|e| format!("a data: URI's base64: {e}"));
    }
    let name = percent_decode(uri)?;
    let relative = Path::new(&name);
    if uri.contains("://")
        || relative.is_absolute()
        || relative
            .components()
            .any(|c| !matches!(c, std::path::Component::Normal(_)))
    {
        return Err(format!(
            "buffer '{uri}': only files beside the glTF are read (no absolute paths, '..' or URLs)"
        ));
    }
    let dir = dir.ok_or_else(|| format!("buffer '{uri}' is an external file (not read here)"))?;
    crate::file::read_bounded(
        &dir.join(relative),
        crate::file::MAX_TEXT_BYTES,
        "the glTF limit",
    )
    .map_err(|e| format!("buffer '{uri}': {e}"))
}

/// `%20` and the like in a URI's path.
fn percent_decode(uri: &str) -> std::result::Result<String, String> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = uri
                .get(i + 1..i + 3)
                .filter(|h| h.bytes().all(|b| b.is_ascii_hexdigit()))
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("buffer '{uri}': a bad %-escape"))?;
            out.push(hex);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| format!("buffer '{uri}' is not UTF-8"))
}

/// The bytes of buffer view `view` (its buffer checked to exist by `check_document`); `None`
/// where the view runs past its buffer.
pub(super) fn view_bytes<'b>(
    view: &gltf::json::buffer::View,
    buffers: &'b [std::borrow::Cow<'_, [u8]>],
) -> Option<&'b [u8]> {
    let buffer = buffers.get(view.buffer.value())?;
    let start = view.byte_offset.map_or(0, |o| o.0 as usize);
    let end = start.checked_add(view.byte_length.0 as usize)?;
    buffer.get(start..end)
}
