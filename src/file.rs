//! Reading input files: regular files only, never more bytes than the caller allows.
//!
//! A FIFO blocks forever, `/dev/zero` never ends and a directory is no data: each is refused
//! before any byte is read, and a file is read up to a bound the caller derives from what it
//! expects (a header's declared size, a text format's sane maximum), so no input can make a
//! reader allocate without limit.

use std::io::Read;
use std::path::Path;

use crate::error::{Error, Result};

/// Text inputs (OBJ, MTL, PLY headers, transfer functions, calibrations) larger than this are
/// refused: 4 GiB.
pub const MAX_TEXT_BYTES: u64 = 4 << 30;

/// Refuse what is not a regular file (FIFO, device, socket, directory), naming the kind.
pub fn check_regular(path: &Path) -> Result<std::fs::Metadata> {
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    if meta.is_file() {
        return Ok(meta);
    }
    let kind = if meta.is_dir() {
        "a directory"
    } else {
        special_kind(&meta)
    };
    Err(Error::io(
        path,
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("{kind}, not a regular file"),
        ),
    ))
}

#[cfg(unix)]
fn special_kind(meta: &std::fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = meta.file_type();
    if t.is_fifo() {
        "a FIFO (named pipe)"
    } else if t.is_char_device() || t.is_block_device() {
        "a device"
    } else if t.is_socket() {
        "a socket"
    } else {
        "a special file"
    }
}

#[cfg(not(unix))]
fn special_kind(_: &std::fs::Metadata) -> &'static str {
    "a special file"
}

/// The bytes of regular file `path`, refused when it holds more than `max_bytes` (`what`
/// names the bound in the error, e.g. "the header's 1,000,000 data bytes").
pub fn read_bounded(path: &Path, max_bytes: u64, what: &str) -> Result<Vec<u8>> {
    let meta = check_regular(path)?;
    if meta.len() > max_bytes {
        return Err(too_large(path, meta.len(), max_bytes, what));
    }
    let file = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    // `take`: a file that grows while it is read still stops at the bound.
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::io(path, e))?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large(path, bytes.len() as u64, max_bytes, what));
    }
    Ok(bytes)
}

/// [`read_bounded`] with [`MAX_TEXT_BYTES`], as text: invalid UTF-8 becomes U+FFFD (only
/// comments may hold it; a number with it is an error where it is parsed), a leading byte-order
/// mark is dropped and CR-only or CRLF line ends become LF.
pub fn read_text(path: &Path) -> Result<String> {
    let bytes = read_bounded(path, MAX_TEXT_BYTES, "the text-file limit")?;
    let text = String::from_utf8_lossy(&bytes);
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    Ok(normalize_line_ends(text))
}

/// CRLF and lone CR line ends as LF.
pub fn normalize_line_ends(text: &str) -> String {
    if !text.contains('\r') {
        return text.to_string();
    }
    text.replace("\r\n", "\n").replace('\r', "\n")
}

fn too_large(path: &Path, len: u64, max: u64, what: &str) -> Error {
    Error::io(
        path,
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("{len} bytes, more than {what} ({max} bytes)"),
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_ends_and_bom() {
        assert_eq!(normalize_line_ends("a\r\nb\rc\n"), "a\nb\nc\n");
        let dir = std::env::temp_dir().join("autostereo_file_test");
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("bom.txt");
        std::fs::write(&p, b"\xef\xbb\xbfv 1\r\n# \xff comment\r\n").unwrap();
        assert_eq!(read_text(&p).unwrap(), "v 1\n# \u{fffd} comment\n");
        assert!(read_bounded(&p, 3, "three bytes").is_err());
        assert!(check_regular(&dir)
            .unwrap_err()
            .to_string()
            .contains("directory"));
    }

    #[cfg(unix)]
    #[test]
    fn devices_are_refused_before_reading() {
        let e = read_bounded(Path::new("/dev/zero"), 10, "ten bytes").unwrap_err();
        assert!(
            e.to_string().contains("a device, not a regular file"),
            "{e}"
        );
    }
}
