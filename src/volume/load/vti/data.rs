//! A `.vti` array's values from where the XML says they are: ASCII numbers, base64 or raw
//! binary with UInt32/UInt64 headers, either byte order, uncompressed or zlib blocks; every
//! size checked against the grid before anything is allocated.

use std::borrow::Cow;
use std::io::Read;

use base64::engine::{DecodePaddingMode, GeneralPurpose, GeneralPurposeConfig};
use base64::Engine;

use super::{decode, Layout, Res, Stored, Vti};

/// `n` whitespace-separated numbers from `text` (further ones are ignored).
pub(in crate::volume::load) fn ascii_values(text: &[u8], n: usize) -> Res<Vec<f32>> {
    // Each number takes at least two bytes but the last: a short text is refused before
    // anything is allocated for it.
    let mut values = Vec::with_capacity(n.min(text.len() / 2 + 1));
    for token in text
        .split(|b| b.is_ascii_whitespace())
        .filter(|t| !t.is_empty())
    {
        if values.len() == n {
            break;
        }
        let value = std::str::from_utf8(token)
            .ok()
            .and_then(|s| s.parse::<f64>().ok())
            .ok_or_else(|| {
                let shown = crate::error::quote(String::from_utf8_lossy(token));
                format!("{shown} is not a number")
            })?;
        values.push(value as f32);
    }
    if values.len() < n {
        return Err(format!("too few values: {} of {n}", values.len()));
    }
    Ok(values)
}

pub(super) fn read_samples(file: &Vti, expected: usize) -> Res<Vec<f32>> {
    let count = expected / file.kind.size() as usize;
    let mut blob = match &file.data {
        Stored::Ascii(text) => return ascii_values(text, count),
        Stored::Binary(text) => {
            let clean: Vec<u8> = text
                .iter()
                .copied()
                .filter(|b| !b.is_ascii_whitespace())
                .collect();
            let mut blob = Blob::Base64(Base64::new(&clean));
            let bytes = read_blob(&mut blob, file.layout, expected)?;
            return Ok(decode(&bytes, file.kind, file.layout.big_endian));
        }
        Stored::Appended { offset, section } => {
            let data = section.data.get(*offset..).ok_or_else(|| {
                format!(
                    "offset {offset} is past the appended data's {} bytes",
                    section.data.len()
                )
            })?;
            if section.base64 {
                Blob::Base64(Base64::new(data))
            } else {
                Blob::Raw(data)
            }
        }
    };
    let bytes = read_blob(&mut blob, file.layout, expected)?;
    Ok(decode(&bytes, file.kind, file.layout.big_endian))
}

/// Binary data: raw bytes, or base64 text decoded as far as it is read.
pub(super) enum Blob<'a> {
    Raw(&'a [u8]),
    Base64(Base64<'a>),
}

impl Blob<'_> {
    /// The most bytes it can hold.
    fn capacity(&self) -> usize {
        match self {
            Blob::Raw(b) => b.len(),
            Blob::Base64(b) => b.text.len() / 4 * 3 + 3,
        }
    }

    /// Its first `n` bytes, or all it has when it holds fewer.
    fn get(&mut self, n: usize) -> Res<&[u8]> {
        match self {
            Blob::Raw(b) => Ok(&b[..n.min(b.len())]),
            Blob::Base64(b) => {
                b.fill(n)?;
                Ok(&b.out[..n.min(b.out.len())])
            }
        }
    }
}

/// Base64 text that may be several encodings one after another (VTK encodes a header and its
/// data separately: `…==` in the middle), decoded on demand.
pub(super) struct Base64<'a> {
    text: &'a [u8],
    at: usize,
    out: Vec<u8>,
}

pub(super) const BASE64: GeneralPurpose = GeneralPurpose::new(
    &base64::alphabet::STANDARD,
    GeneralPurposeConfig::new()
        .with_decode_padding_mode(DecodePaddingMode::Indifferent)
        .with_decode_allow_trailing_bits(true),
);

impl<'a> Base64<'a> {
    /// Text up to the first byte that is not base64 (the appended data's end).
    pub(super) fn new(text: &'a [u8]) -> Self {
        let end = text
            .iter()
            .position(|&b| !(b.is_ascii_alphanumeric() || matches!(b, b'+' | b'/' | b'=')))
            .unwrap_or(text.len());
        Self {
            text: &text[..end],
            at: 0,
            out: Vec::new(),
        }
    }

    /// Decode until `n` bytes are out (or the text ends), in whole groups of 4, each encoding
    /// ended by its padding decoded on its own.
    fn fill(&mut self, n: usize) -> Res<()> {
        while self.out.len() < n && self.at < self.text.len() {
            let groups = (n - self.out.len()).div_ceil(3);
            let mut end = self
                .at
                .saturating_add(groups.saturating_mul(4))
                .min(self.text.len());
            if let Some(p) = self.text[self.at..end].iter().position(|&c| c == b'=') {
                end = (self.at + (p / 4 + 1) * 4).min(self.text.len());
            }
            BASE64
                .decode_vec(&self.text[self.at..end], &mut self.out)
                .map_err(|e| format!("base64 at character {}: {e}", self.at))?;
            self.at = end;
        }
        Ok(())
    }
}

/// The `expected` data bytes of a binary array: after its byte count, or inflated from its zlib
/// blocks (header: block count, block size, last block's size, each block's compressed size).
pub(super) fn read_blob<'b>(
    blob: &'b mut Blob,
    layout: Layout,
    expected: usize,
) -> Res<Cow<'b, [u8]>> {
    let w = if layout.header64 { 8 } else { 4 };
    let word = |b: &[u8], i: usize| -> u64 {
        let b = &b[i * w..(i + 1) * w];
        match (w, layout.big_endian) {
            (8, false) => u64::from_le_bytes(b.try_into().expect("8 bytes")),
            (8, true) => u64::from_be_bytes(b.try_into().expect("8 bytes")),
            (_, false) => u32::from_le_bytes(b.try_into().expect("4 bytes")).into(),
            (_, true) => u32::from_be_bytes(b.try_into().expect("4 bytes")).into(),
        }
    };
    let capacity = blob.capacity() as u64;
    if !layout.zlib {
        let head = blob.get(w)?;
        if head.len() < w {
            return Err("truncated: no byte count before the data".into());
        }
        let count = word(head, 0);
        if count < expected as u64 {
            return Err(format!(
                "{count} bytes of data, the extent and type need {expected}"
            ));
        }
        let all = blob.get(w + expected)?;
        if all.len() < w + expected {
            return Err(format!(
                "truncated: {} bytes of data, {expected} needed",
                all.len() - w
            ));
        }
        return Ok(Cow::Borrowed(&all[w..]));
    }
    let head = blob.get(3 * w)?;
    if head.len() < 3 * w {
        return Err("truncated: no compression header".into());
    }
    let (blocks, size, last) = (word(head, 0), word(head, 1), word(head, 2));
    let header_len = blocks
        .checked_add(3)
        .and_then(|b| b.checked_mul(w as u64))
        .filter(|&l| l <= capacity)
        .ok_or_else(|| format!("{blocks} compressed blocks: more than the file holds"))?
        as usize;
    let head = blob.get(header_len)?;
    if head.len() < header_len {
        return Err(format!("truncated: a header of {blocks} compressed blocks"));
    }
    let compressed: Vec<u64> = (3..3 + blocks as usize).map(|i| word(head, i)).collect();
    let stored = compressed
        .iter()
        .try_fold(0u64, |sum, &c| sum.checked_add(c))
        .filter(|&s| s <= capacity)
        .ok_or("compressed block sizes: more than the file holds")? as usize;
    let total = match blocks {
        0 => Some(0),
        n => (n - 1)
            .checked_mul(size)
            .and_then(|t| t.checked_add(if last == 0 { size } else { last })),
    };
    if total.is_none_or(|t| t < expected as u64) {
        return Err(format!(
            "{blocks} compressed blocks of {size} bytes (last {last}): fewer than the {expected} \
             bytes the extent and type need"
        ));
    }
    let data = blob.get(header_len + stored)?;
    // zlib inflates at most 1032:1: a small file cannot reserve much more than it holds.
    let mut out = Vec::with_capacity(expected.min(stored.saturating_mul(1032)));
    let mut at = header_len;
    for (i, &c) in compressed.iter().enumerate() {
        if out.len() >= expected {
            break;
        }
        let Some(block) = data.get(at..at + c as usize) else {
            return Err(format!(
                "truncated: compressed block {i} of {blocks} ends past the data"
            ));
        };
        let block_size = if i + 1 == compressed.len() && last != 0 {
            last
        } else {
            size
        };
        let want = block_size.min((expected - out.len()) as u64);
        let before = out.len();
        flate2::read::ZlibDecoder::new(block)
            .take(want)
            .read_to_end(&mut out)
            .map_err(|e| format!("zlib block {i}: {e}"))?;
        if ((out.len() - before) as u64) < want {
            return Err(format!(
                "zlib block {i}: {} of {want} bytes (truncated)",
                out.len() - before
            ));
        }
        at += c as usize;
    }
    Ok(Cow::Owned(out))
}
