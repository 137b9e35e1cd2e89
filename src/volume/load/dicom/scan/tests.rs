//! The length scan against hand-made files: each kind of oversize declaration refused by its
//! tag, well-formed structure passing, and the fuzz regressions.

use super::*;
use crate::volume::load::dicom::parse_dicom;
use std::path::Path;

const EXPLICIT_LE: &str = "1.2.840.10008.1.2.1";
const IMPLICIT_LE: &str = "1.2.840.10008.1.2";

/// An explicit VR little endian element (a 32-bit length for the VRs that have one).
fn explicit(tag: (u16, u16), vr: &[u8; 2], len: u32, value: &[u8]) -> Vec<u8> {
    let mut b = [tag.0.to_le_bytes(), tag.1.to_le_bytes()].concat();
    b.extend(vr);
    if matches!(vr, b"OB" | b"OW" | b"SQ" | b"UN" | b"UT") {
        b.extend([0, 0]);
        b.extend(len.to_le_bytes());
    } else {
        b.extend((len as u16).to_le_bytes());
    }
    b.extend(value);
    b
}

/// An item or delimiter header, or an implicit VR element header.
fn header(tag: (u16, u16), len: u32) -> Vec<u8> {
    [
        &tag.0.to_le_bytes()[..],
        &tag.1.to_le_bytes(),
        &len.to_le_bytes(),
    ]
    .concat()
}

/// Preamble, magic and a file meta group naming `ts`, then `data_set`.
fn file(ts: &str, data_set: &[u8]) -> Vec<u8> {
    let mut uid = ts.as_bytes().to_vec();
    if uid.len() % 2 == 1 {
        uid.push(0);
    }
    let meta = explicit((0x0002, 0x0010), b"UI", uid.len() as u32, &uid);
    let mut b = vec![0u8; 128];
    b.extend(b"DICM");
    b.extend(explicit(
        (0x0002, 0x0000),
        b"UL",
        4,
        &(meta.len() as u32).to_le_bytes(),
    ));
    b.extend(meta);
    b.extend(data_set);
    b
}

fn name() -> Vec<u8> {
    explicit((0x0010, 0x0010), b"PN", 4, b"Doe ")
}

#[test]
fn an_element_declaring_gigabytes_is_refused_by_tag() {
    // Explicit VR: a UT of 0xFFFFFFF0 bytes after a name.
    let bytes = file(
        EXPLICIT_LE,
        &[
            name(),
            explicit((0x0040, 0xA160), b"UT", 0xFFFF_FFF0, b"abcd"),
        ]
        .concat(),
    );
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(
        e.contains("element (0040,A160) at byte 184 declares 4294967280 bytes")
            && e.contains("only 4 are left"),
        "{e}"
    );
    // Implicit VR: every length is 32-bit.
    let bytes = file(
        IMPLICIT_LE,
        &[header((0x0010, 0x0010), 0xFFFF_FFF0), b"Doe ".to_vec()].concat(),
    );
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(
        e.contains("element (0010,0010) at byte 170 declares 4294967280 bytes"),
        "{e}"
    );
    // The same through the parser's entry point: the scan's error, naming the file.
    let e = parse_dicom(&bytes, Path::new("huge.dcm"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("huge.dcm") && e.contains("declares 4294967280 bytes"),
        "{e}"
    );
}

#[test]
fn a_number_value_of_uneven_length_is_refused() {
    // dicom-parser reads an FL of 2 bytes as no float and the next header from its value
    // (the fuzzer's file: then an element of 0x2E300008 bytes, zero-filled).
    let bytes = file(
        EXPLICIT_LE,
        &[name(), explicit((0x0028, 0x0011), b"FL", 2, &[6, 0])].concat(),
    );
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(
        e.contains("element (0028,0011) at byte 184 declares 2 bytes, not a whole number")
            && e.contains("4-byte values"),
        "{e}"
    );
    // Implicit VR: the dictionary's VR (Rows, US) and an odd length.
    let bytes = file(
        IMPLICIT_LE,
        &[header((0x0028, 0x0010), 3), vec![1, 2, 3]].concat(),
    );
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(e.contains("2-byte values"), "{e}");
    // Whole values pass.
    let bytes = file(
        EXPLICIT_LE,
        &[name(), explicit((0x0028, 0x0011), b"US", 2, &[6, 0])].concat(),
    );
    check_lengths(&bytes, true).unwrap();
}

#[test]
fn a_transfer_syntax_padded_with_whitespace_is_scanned() {
    // dicom-object trims a transfer syntax UID's trailing whitespace and NULs: the fuzzer's
    // "1.2.840.10008.1.2\n\0\0" is implicit VR little endian to it, but the scan trimmed
    // only spaces and NULs, took it for a syntax dicom-object refuses and stopped, and
    // dicom-parser zero-filled an implicit UL of 822 MB (out of memory at -rss_limit_mb
    // 4096 while fuzzing) or an unknown element of 0xABABABAB bytes (2.9 GB, 19 s).
    for padded in [
        "1.2.840.10008.1.2\n",
        "1.2.840.10008.1.2\r\n\0\0",
        "1.2.840.10008.1.2\t ",
    ] {
        let bytes = file(
            padded,
            &[header((0x0010, 0x0010), 0xFFFF_FFF0), b"Doe ".to_vec()].concat(),
        );
        let e = check_lengths(&bytes, true).unwrap_err();
        assert!(
            e.contains("element (0010,0010)") && e.contains("4294967280"),
            "{padded:?}: {e}"
        );
    }
    // Explicit VR little endian padded the same way.
    let bytes = file(
        "1.2.840.10008.1.2.1\n",
        &[
            name(),
            explicit((0x0040, 0xA160), b"UT", 0xFFFF_FFF0, b"abcd"),
        ]
        .concat(),
    );
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(e.contains("element (0040,A160)"), "{e}");
    // The fuzzer's files: refused by the scan, naming the file.
    for (name, expected) in [
        (
            "ts_newline_padded_ul_800mb.dcm",
            "(0000,0000) at byte 332 declares 822086656 bytes",
        ),
        (
            "ts_newline_padded_un_2_9gb.dcm",
            "declares 2880154539 bytes",
        ),
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fuzz/regressions/dicom")
            .join(name);
        let e = parse_dicom(&std::fs::read(&path).unwrap(), &path)
            .unwrap_err()
            .to_string();
        assert!(e.contains(name) && e.contains(expected), "{e}");
    }
}

#[test]
fn an_oversize_element_inside_a_sequence_item_is_refused() {
    let inner = explicit((0x0042, 0x0011), b"OB", 0xFFFF_FFF0, &[1, 2]);
    // Undefined lengths: sequence, item, then the element.
    let undefined = [
        explicit((0x0008, 0x1140), b"SQ", UNDEFINED, &[]),
        header(ITEM, UNDEFINED),
        inner.clone(),
    ]
    .concat();
    // Defined lengths: the walk goes into the sequence too.
    let item = [header(ITEM, inner.len() as u32), inner.clone()].concat();
    let defined = explicit((0x0008, 0x1140), b"SQ", item.len() as u32, &item);
    for data_set in [undefined, defined] {
        let e = check_lengths(&file(EXPLICIT_LE, &data_set), true).unwrap_err();
        assert!(
            e.contains("element (0042,0011) at byte 192 declares 4294967280 bytes")
                && e.contains("only 2"),
            "{e}"
        );
    }
    // Implicit VR: the dictionary says (0008,1140) is a sequence, even of defined length.
    let inner = [header((0x0008, 0x1150), 0xFFFF_FFF0), b"1.2".to_vec()].concat();
    let item = [header(ITEM, inner.len() as u32), inner].concat();
    let data_set = [header((0x0008, 0x1140), item.len() as u32), item].concat();
    let e = check_lengths(&file(IMPLICIT_LE, &data_set), true).unwrap_err();
    assert!(
        e.contains("element (0008,1150) at byte 186 declares 4294967280"),
        "{e}"
    );
}

#[test]
fn oversize_pixel_fragments_and_meta_elements_are_refused() {
    // Encapsulated pixel data: an empty offset table, then a fragment of 0x7FFFFFF0 bytes.
    let data_set = [
        name(),
        explicit(PIXEL_DATA, b"OB", UNDEFINED, &[]),
        header(ITEM, 0),
        header(ITEM, 0x7FFF_FFF0),
        vec![0; 6],
    ]
    .concat();
    let e = check_lengths(&file("1.2.840.10008.1.2.4.50", &data_set), true).unwrap_err();
    assert!(
        e.contains("a fragment of pixel data (7FE0,0010) at byte 206 declares 2147483632 bytes"),
        "{e}"
    );
    // A meta group UID written with a 32-bit length (dicom-object reads it whole).
    let mut bytes = vec![0u8; 128];
    bytes.extend(b"DICM");
    bytes.extend(explicit((0x0002, 0x0000), b"UL", 4, &20u32.to_le_bytes()));
    bytes.extend(explicit((0x0002, 0x0010), b"UN", 0xFFFF_FFF0, b"1.2."));
    let e = check_lengths(&bytes, true).unwrap_err();
    assert!(
        e.contains("file meta element (0002,0010) at byte 144 declares 4294967280"),
        "{e}"
    );
}

#[test]
fn deep_nesting_and_deflated_data_sets_are_refused() {
    let level = [
        explicit((0x0008, 0x1140), b"SQ", UNDEFINED, &[]),
        header(ITEM, UNDEFINED),
    ]
    .concat();
    let e = check_lengths(&file(EXPLICIT_LE, &level.repeat(MAX_NESTING + 1)), true).unwrap_err();
    assert!(e.contains("nested more than 32 deep"), "{e}");
    assert!(check_lengths(&file(EXPLICIT_LE, &level.repeat(MAX_NESTING)), true).is_ok());
    let e = check_lengths(&file("1.2.840.10008.1.2.1.99", &name()), true).unwrap_err();
    assert!(e.contains("deflated data set is not read"), "{e}");
}

#[test]
fn well_formed_structure_passes_the_scan() {
    // Sequences closed by delimiters and by their lengths, an empty item, a stray item
    // delimiter at the top level, encapsulated pixel data with two fragments, odd lengths.
    let item = [header(ITEM, 12), name()].concat();
    let data_set = [
        name(),
        explicit((0x0008, 0x1140), b"SQ", UNDEFINED, &[]),
        header(ITEM, UNDEFINED),
        name(),
        header(ITEM_END, 0),
        header(ITEM, 0),
        header(SEQUENCE_END, 0),
        explicit((0x0008, 0x1115), b"SQ", item.len() as u32, &item),
        explicit((0x0008, 0x1120), b"SQ", 0, &[]),
        header(ITEM_END, 0),
        explicit((0x0010, 0x0020), b"LO", 3, b"abc"),
        explicit(PIXEL_DATA, b"OB", UNDEFINED, &[]),
        header(ITEM, 4),
        vec![0; 4],
        header(ITEM, 6),
        vec![7; 6],
        header(SEQUENCE_END, 0),
    ]
    .concat();
    for ts in [EXPLICIT_LE, "1.2.840.10008.1.2.4.50"] {
        check_lengths(&file(ts, &data_set), true).unwrap();
    }
    // A header-only read stops at the pixel data: a truncated PixelData passes it.
    let cut = [name(), explicit(PIXEL_DATA, b"OW", 1 << 20, &[0; 8])].concat();
    assert!(check_lengths(&file(EXPLICIT_LE, &cut), true).is_err());
    check_lengths(&file(EXPLICIT_LE, &cut), false).unwrap();
    // Not DICOM, or a broken meta group: left to dicom-object.
    check_lengths(b"not a dicom file", true).unwrap();
    // The fuzz seeds (real files written by dicom-object) pass.
    for seed in ["slice.dcm", "multiframe.dcm"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fuzz/seeds/dicom")
            .join(seed);
        check_lengths(&std::fs::read(path).unwrap(), true).unwrap();
    }
}
