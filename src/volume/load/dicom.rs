//! DICOM series (the `dicom-object` crate, feature `dicom`): a folder of slices, or any file of
//! one (its series is read from the files beside it). Slices are grouped by SeriesInstanceUID
//! (several series in a folder: an error listing them; a file picks its own), sorted by their
//! position along the slice normal — never by file name — and checked: one size, orientation
//! and pixel spacing, uniformly spaced with no slice missing. A multi-frame file is its frames,
//! spaced by SpacingBetweenSlices (else SliceThickness). Each slice's RescaleSlope/Intercept is
//! applied (CT: Hounsfield units); ImageOrientationPatient (LPS+) places the voxel axes
//! (`crate::volume::orientation`). Pixel data must be uncompressed (the native transfer
//! syntaxes); compressed data is refused by name.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use dicom_dictionary_std::tags;
use dicom_object::file::ReadPreamble;
use dicom_object::{DefaultDicomObject, OpenFileOptions, Tag};
use glam::{DVec3, Mat3};

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::orientation::{screen_axes_from_ras, LPS_TO_RAS};
use crate::volume::Volume;

/// Files looked at in one folder (a guard; a CT series has hundreds, rarely thousands).
const MAX_FILES: usize = 20_000;
/// Largest DICOM file read (one slice, or a multi-frame file of all of them).
const MAX_FILE_BYTES: u64 = 4 << 30;
/// How far slice gaps may differ from the series' spacing (a share of it).
const SPACING_TOLERANCE: f64 = 0.01;

/// Load the DICOM series at `path`: a folder holding one series, or a file of one.
pub fn load_dicom(path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let (dir, wanted) = if path.is_dir() {
        (path.to_path_buf(), None)
    } else {
        crate::file::check_regular(path)?;
        let slice = read_slice(path)?;
        // A bare file name's folder is the working directory.
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        (dir.to_path_buf(), Some(slice.series.clone()))
    };
    let mut series: BTreeMap<String, Vec<Slice>> = BTreeMap::new();
    let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map_err(|e| err(format!("reading the folder: {e}")))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .take(MAX_FILES + 1)
        .collect();
    if names.len() > MAX_FILES {
        return Err(err(format!("more than {MAX_FILES} files in the folder")));
    }
    names.sort();
    let mut budget = 0u64;
    for file in names {
        if !is_dicom(&file) {
            continue; // DICOMDIR's neighbours, notes, thumbnails
        }
        budget = budget.saturating_add(std::fs::metadata(&file).map_or(0, |m| m.len()));
        crate::budget::check(
            || format!("DICOM files of {budget} bytes"),
            budget.saturating_mul(3),
        )?;
        if wanted.is_some() && series_of(&file) != wanted {
            continue; // another series beside the file given
        }
        let slice = match read_slice(&file) {
            Ok(slice) => slice,
            // A file without pixel data (DICOMDIR, a report) is not a slice.
            Err(_) if !has_pixels(&file) => continue,
            Err(e) => return Err(e),
        };
        series.entry(slice.series.clone()).or_default().push(slice);
    }
    let slices = match series.len() {
        0 => return Err(err("no DICOM slices with pixel data".into())),
        1 => series.into_values().next().unwrap_or_default(),
        n => {
            let list: Vec<String> = series
                .iter()
                .map(|(uid, s)| format!("{uid} ({} slices: {})", s.len(), s[0].file.display()))
                .collect();
            return Err(err(format!(
                "{n} series in this folder; give one file of the series to show: {}",
                list.join("; ")
            )));
        }
    };
    stack(path, slices)
}

/// What one file holds: its geometry, pixels and rescale.
struct Slice {
    file: PathBuf,
    series: String,
    size: [u32; 2],
    /// Row direction (increasing column index) and column direction, LPS+.
    orientation: [DVec3; 2],
    position: DVec3,
    /// Between rows, between columns (DICOM's PixelSpacing order).
    pixel_spacing: [f64; 2],
    /// Frames in the file and their spacing (multi-frame).
    frames: u32,
    frame_spacing: Option<f64>,
    kind: SampleType,
    big_endian: bool,
    pixels: Vec<u8>,
    rescale: [f64; 2],
}

fn is_dicom(path: &Path) -> bool {
    let mut head = [0u8; 132];
    std::fs::File::open(path)
        .and_then(|mut f| std::io::Read::read_exact(&mut f, &mut head))
        .is_ok()
        && &head[128..] == b"DICM"
}

/// The SeriesInstanceUID of a file (its header only).
fn series_of(path: &Path) -> Option<String> {
    let obj = open(path, false).ok()?;
    let uid = obj.element(tags::SERIES_INSTANCE_UID).ok()?.to_str().ok()?;
    Some(uid.trim().to_string())
}

fn has_pixels(path: &Path) -> bool {
    open(path, true).is_ok_and(|o| o.element(tags::PIXEL_DATA).is_ok())
}

fn open(path: &Path, whole: bool) -> Result<DefaultDicomObject> {
    let bytes = crate::file::read_bounded(path, MAX_FILE_BYTES, "the DICOM file limit")?;
    parse_object(&bytes, path, whole)
}

fn parse_object(bytes: &[u8], path: &Path, whole: bool) -> Result<DefaultDicomObject> {
    check_lengths(bytes, whole).map_err(|e| format_error(path, e))?;
    let options = OpenFileOptions::new().read_preamble(ReadPreamble::Always);
    let options = if whole {
        options
    } else {
        options.read_until(tags::PIXEL_DATA)
    };
    options
        .from_reader(bytes)
        .map_err(|e| format_error(path, format!("malformed DICOM: {e}")))
}

/// The transfer syntaxes whose pixel data is read: implicit and explicit VR little endian.
fn native_little_endian(uid: &str) -> bool {
    matches!(uid, "1.2.840.10008.1.2" | "1.2.840.10008.1.2.1")
}

/// One DICOM file's `bytes` as a volume: a slice, or a multi-frame file's frames (`path` names
/// it in errors): what the fuzz target calls.
pub fn parse_dicom(bytes: &[u8], path: &Path) -> Result<Volume> {
    stack(
        path,
        vec![slice_of(parse_object(bytes, path, true)?, path)?],
    )
}

fn read_slice(path: &Path) -> Result<Slice> {
    slice_of(open(path, true)?, path)
}

fn slice_of(obj: DefaultDicomObject, path: &Path) -> Result<Slice> {
    let err = |m: String| format_error(path, m);
    let ts = obj.meta().transfer_syntax().to_string();
    if ts == "1.2.840.10008.1.2.2" {
        return Err(err(
            "transfer syntax 1.2.840.10008.1.2.2 (explicit VR big endian, retired) is not read \
             (convert it, e.g. with gdcmconv --raw)"
                .into(),
        ));
    }
    if !native_little_endian(&ts) {
        return Err(err(format!(
            "transfer syntax {ts}: compressed pixel data is not read (decompress the series, \
             e.g. with dcmdjpeg or gdcmconv --raw)"
        )));
    }
    let big_endian = false;
    let text = |tag: Tag, name: &str| -> Result<String> {
        obj.element(tag)
            .ok()
            .and_then(|e| e.to_str().ok())
            .map(|s| s.trim().to_string())
            .ok_or_else(|| err(format!("no {name}")))
    };
    let int = |tag: Tag, name: &str| -> Result<i64> {
        obj.element(tag)
            .ok()
            .and_then(|e| e.to_int::<i64>().ok())
            .ok_or_else(|| err(format!("no {name}")))
    };
    let floats = |tag: Tag| -> Option<Vec<f64>> {
        obj.element(tag)
            .ok()
            .and_then(|e| e.to_multi_float64().ok())
    };
    let samples = obj
        .element(tags::SAMPLES_PER_PIXEL)
        .ok()
        .and_then(|e| e.to_int::<i64>().ok())
        .unwrap_or(1);
    if samples != 1 {
        return Err(err(format!(
            "{samples} samples per pixel: scalar (grey) images only"
        )));
    }
    let rows = int(tags::ROWS, "Rows")?;
    let cols = int(tags::COLUMNS, "Columns")?;
    let bits = int(tags::BITS_ALLOCATED, "BitsAllocated")?;
    let signed = int(tags::PIXEL_REPRESENTATION, "PixelRepresentation").unwrap_or(0) == 1;
    let kind = match (bits, signed) {
        (8, false) => SampleType::U8,
        (8, true) => SampleType::I8,
        (16, false) => SampleType::U16,
        (16, true) => SampleType::I16,
        (32, false) => SampleType::U32,
        (32, true) => SampleType::I32,
        _ => return Err(err(format!("BitsAllocated {bits}: 8, 16 or 32 only"))),
    };
    let size = [cols, rows].map(|v| u32::try_from(v).unwrap_or(0));
    if size.contains(&0) {
        return Err(err(format!("{cols}x{rows}: not an image size")));
    }
    let frames = obj
        .element(tags::NUMBER_OF_FRAMES)
        .ok()
        .and_then(|e| e.to_int::<i64>().ok())
        .unwrap_or(1);
    let frames = u32::try_from(frames)
        .ok()
        .filter(|&f| f >= 1)
        .ok_or_else(|| err(format!("NumberOfFrames {frames}")))?;
    let orientation = floats(tags::IMAGE_ORIENTATION_PATIENT)
        .filter(|v| v.len() == 6 && v.iter().all(|x| x.is_finite()))
        .ok_or_else(|| err("no ImageOrientationPatient (6 numbers)".into()))?;
    let position = floats(tags::IMAGE_POSITION_PATIENT)
        .filter(|v| v.len() == 3 && v.iter().all(|x| x.is_finite()))
        .ok_or_else(|| err("no ImagePositionPatient (3 numbers)".into()))?;
    let spacing = floats(tags::PIXEL_SPACING)
        .filter(|v| v.len() == 2 && v.iter().all(|s| s.is_finite() && *s > 0.0))
        .ok_or_else(|| err("no PixelSpacing (2 positive numbers)".into()))?;
    let frame_spacing = floats(tags::SPACING_BETWEEN_SLICES)
        .or_else(|| floats(tags::SLICE_THICKNESS))
        .and_then(|v| v.first().copied())
        .filter(|s| s.is_finite() && *s > 0.0);
    let rescale = [
        floats(tags::RESCALE_SLOPE)
            .and_then(|v| v.first().copied())
            .unwrap_or(1.0),
        floats(tags::RESCALE_INTERCEPT)
            .and_then(|v| v.first().copied())
            .unwrap_or(0.0),
    ];
    let expected = super::data_bytes([size[0], size[1], frames].map(u64::from), kind)
        .map_err(|e| err(e.to_string()))?;
    let pixels = obj
        .element(tags::PIXEL_DATA)
        .map_err(|_| err("no PixelData".into()))?
        .to_bytes()
        .map_err(|e| err(format!("PixelData: {e}")))?;
    if (pixels.len() as u64) < expected {
        return Err(err(format!(
            "truncated PixelData: {} bytes, {}x{}x{frames} {kind:?} need {expected}",
            pixels.len(),
            size[0],
            size[1]
        )));
    }
    let v = |a: &[f64]| DVec3::new(a[0], a[1], a[2]);
    Ok(Slice {
        file: path.to_path_buf(),
        series: text(tags::SERIES_INSTANCE_UID, "SeriesInstanceUID")?,
        size,
        orientation: [v(&orientation[..3]), v(&orientation[3..])],
        position: v(&position),
        pixel_spacing: [spacing[0], spacing[1]],
        frames,
        frame_spacing,
        kind,
        big_endian,
        pixels: pixels[..expected as usize].to_vec(),
        rescale,
    })
}

/// The slices of one series as a volume.
fn stack(path: &Path, mut slices: Vec<Slice>) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let first = &slices[0];
    let (size, orientation, pixel_spacing) = (first.size, first.orientation, first.pixel_spacing);
    for s in &slices {
        let same_orientation = (0..2).all(|i| s.orientation[i].abs_diff_eq(orientation[i], 1e-4));
        if s.size != size || !same_orientation || s.pixel_spacing != pixel_spacing {
            return Err(err(format!(
                "{} differs from {} in size, orientation or pixel spacing: one series is one grid",
                s.file.display(),
                first.file.display()
            )));
        }
    }
    let normal = orientation[0].cross(orientation[1]);
    if normal.length().is_nan() || normal.length() <= 0.5 {
        return Err(err(format!(
            "ImageOrientationPatient {orientation:?}: not two directions"
        )));
    }
    let normal = normal.normalize();
    let (depth, gap) = if slices.len() == 1 {
        let s = &slices[0];
        let gap = match s.frames {
            1 => 1.0,
            _ => s.frame_spacing.ok_or_else(|| {
                err("a multi-frame file without SpacingBetweenSlices or SliceThickness".into())
            })?,
        };
        (s.frames, gap)
    } else {
        if slices.iter().any(|s| s.frames != 1) {
            return Err(err(
                "a series of multi-frame files: one file or one slice per file".into(),
            ));
        }
        // Along the normal, never by file name.
        slices.sort_by(|a, b| a.position.dot(normal).total_cmp(&b.position.dot(normal)));
        let at: Vec<f64> = slices.iter().map(|s| s.position.dot(normal)).collect();
        let gaps: Vec<f64> = at.windows(2).map(|w| w[1] - w[0]).collect();
        if let Some(i) = gaps.iter().position(|g| *g < 1e-6) {
            return Err(err(format!(
                "{} and {} are at the same position: a duplicate slice",
                slices[i].file.display(),
                slices[i + 1].file.display()
            )));
        }
        // The smallest gap is the spacing: a gap of m of them is m − 1 missing slices, any
        // other difference an uneven series (both refused: the volume would be distorted).
        let step = gaps.iter().copied().fold(f64::INFINITY, f64::min);
        if let Some(i) = gaps
            .iter()
            .position(|g| (g - step).abs() > SPACING_TOLERANCE * step)
        {
            let ratio = gaps[i] / step;
            let what = if (ratio - ratio.round()).abs() <= SPACING_TOLERANCE * ratio {
                format!("{} slice(s) missing", ratio.round() as u64 - 1)
            } else {
                "the slices are not evenly spaced".to_string()
            };
            return Err(err(format!(
                "{what}: {:.3} mm between {} and {}, {step:.3} mm elsewhere",
                gaps[i],
                slices[i].file.display(),
                slices[i + 1].file.display()
            )));
        }
        (slices.len() as u32, step)
    };
    let dims = [size[0], size[1], depth];
    data_bytes(dims.map(u64::from), SampleType::F32).map_err(|e| err(e.to_string()))?;
    let per_frame = size[0] as usize * size[1] as usize;
    let mut samples = Vec::with_capacity(per_frame * depth as usize);
    for s in &slices {
        let values = decode(&s.pixels, s.kind, s.big_endian);
        let [slope, intercept] = s.rescale;
        samples.extend(
            values
                .iter()
                .map(|&v| (f64::from(v) * slope + intercept) as f32),
        );
    }
    drop(slices);
    // Rescaled values (Hounsfield units) are normalised by their range (VOLUMES.md "Data").
    let spacing = [pixel_spacing[1] as f32, pixel_spacing[0] as f32, gap as f32];
    let volume = to_volume(path, dims, spacing, samples, SampleType::F32)?;
    let ras = |d: DVec3| LPS_TO_RAS * d.as_vec3();
    let axes = Mat3::from_cols(ras(orientation[0]), ras(orientation[1]), ras(normal));
    volume.with_axes(screen_axes_from_ras(axes).map_err(|e| err(e.to_string()))?)
}

// The length scan. dicom-parser zero-fills each value's declared length (up to 4 GiB) before
// reading it, and dicom-object does the same for the file meta group's UIDs, so a file of a
// few hundred bytes could ask for gigabytes. Before a file's bytes reach them, its elements
// are walked here as dicom-parser will walk them (the same element, item and delimiter
// boundaries, the same VR rules), and a value, or a fragment of encapsulated pixel data,
// declared longer than the bytes left in the file is refused by its tag. Where the walk meets
// what dicom-parser refuses itself (a broken header, an undefined fragment length, an
// inconsistent sequence end), it stops: nothing past that point is read.

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
/// false walks only as far as `read_until(PIXEL_DATA)` reads.
fn check_lengths(bytes: &[u8], whole: bool) -> std::result::Result<(), String> {
    let mut w = Walk {
        bytes,
        pos: 132,
        big_endian: false,
    };
    if bytes.get(128..132) != Some(&b"DICM"[..]) {
        return Ok(()); // dicom-object refuses it
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
        return Ok(());
    };
    let Some(group_length) = w.u32() else {
        return Ok(());
    };
    if tag != (0x0002, 0x0000) {
        return Ok(());
    }
    let mut read = 0u32;
    let mut transfer_syntax = None;
    while read < group_length {
        let start = w.pos;
        let Some((tag, _, len, _)) = w.element_header(true) else {
            return Ok(());
        };
        if len == UNDEFINED {
            return Ok(()); // refused by dicom-object
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
        return Ok(()); // refused by dicom-object
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
        _ => return Ok(()),
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
                    std::cmp::Ordering::Less => return Ok(()), // refused by dicom-parser
                    std::cmp::Ordering::Greater => {}
                }
            }
            check_end = false;
        }
        if in_sequence {
            // An item header or the sequence's delimiter.
            let Some((tag, len)) = w.item_header() else {
                return Ok(());
            };
            match tag {
                ITEM => {
                    let Some(parent) = open.last() else {
                        return Ok(());
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
                _ => return Ok(()), // refused by dicom-parser
            }
        } else if let Some(Open {
            item: true,
            pixel_data: true,
            end,
        }) = open.last()
        {
            // A fragment of encapsulated pixel data (or its offset table), read whole.
            let Some(end) = *end else {
                return Ok(()); // an undefined fragment length: refused by dicom-parser
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
                return Ok(()); // the end of the data set, or a header dicom-parser refuses
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
                return Ok(());
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
                        _ => return Ok(()), // refused by dicom-parser
                    }
                }
            } else {
                if len as usize > w.left() {
                    return Err(over("element", tag, len, at, w.left()));
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
mod tests {
    use super::*;

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
            e.contains(
                "a fragment of pixel data (7FE0,0010) at byte 206 declares 2147483632 bytes"
            ),
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
        let e =
            check_lengths(&file(EXPLICIT_LE, &level.repeat(MAX_NESTING + 1)), true).unwrap_err();
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
}
