//! Values in the scan's units: a CT series as scanners write it (signed 16-bit stored values,
//! RescaleIntercept −1024, Modality CT, a WindowWidth/WindowCenter) of a head — air −1000 HU,
//! tissue 40, a bone shell 1000 — inside a circular field of view, with and without −3024 HU
//! padding outside it. The CT presets (defined in HU) render both the same; `--window` in HU is
//! the same window as a normalised transfer function (docs/VOLUMES.md "Windows and presets").

use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};
use autostereo::render::Method;
use autostereo::volume::{Modality, Transfer, TransferFunction, Units};
use autostereo::{
    AnyData, AnyRenderer, AnyScene, LoadOptions, Renderer, RendererOptions, VolumeLoad,
};
use dicom_core::{dicom_value, DataElement, PrimitiveValue, VR};
use dicom_dictionary_std::tags;
use dicom_object::{FileMetaTableBuilder, InMemDicomObject};

use crate::common;

const N: usize = 40;
const SLICES: usize = 20;

/// Hounsfield units of voxel (x, y, slice z): a head in a field of view; `padding` outside it.
fn hu(x: usize, y: usize, z: usize, padding: f64) -> f64 {
    let c = |v: usize, n: usize| v as f64 + 0.5 - n as f64 / 2.0;
    let (dx, dy, dz) = (c(x, N), c(y, N), c(z, SLICES) * 2.0);
    let (r_plane, r) = (
        (dx * dx + dy * dy).sqrt(),
        (dx * dx + dy * dy + dz * dz).sqrt(),
    );
    match () {
        _ if r_plane > 19.0 => padding,
        _ if r < 10.5 => 40.0,
        _ if r < 13.0 => 1000.0,
        _ => -1000.0,
    }
}

fn ds(values: &[f64]) -> PrimitiveValue {
    PrimitiveValue::Strs(values.iter().map(|v| format!("{v}")).collect())
}

/// The series in `dir`: slice files of stored = HU + 1024 (signed), as scanners write them.
fn write_series(dir: &Path, padding: f64) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    for z in 0..SLICES {
        let mut obj = InMemDicomObject::new_empty();
        let mut put = |tag, vr, value: PrimitiveValue| obj.put(DataElement::new(tag, vr, value));
        let instance = format!("1.2.826.0.1.3680043.99.{}", z + 1);
        put(
            tags::SOP_CLASS_UID,
            VR::UI,
            "1.2.840.10008.5.1.4.1.1.2".into(),
        );
        put(tags::SOP_INSTANCE_UID, VR::UI, instance.as_str().into());
        put(tags::MODALITY, VR::CS, "CT".into());
        put(
            tags::SERIES_INSTANCE_UID,
            VR::UI,
            "1.2.826.0.1.3680043.99".into(),
        );
        put(tags::SAMPLES_PER_PIXEL, VR::US, dicom_value!(U16, [1]));
        put(tags::ROWS, VR::US, dicom_value!(U16, [N as u16]));
        put(tags::COLUMNS, VR::US, dicom_value!(U16, [N as u16]));
        put(tags::BITS_ALLOCATED, VR::US, dicom_value!(U16, [16]));
        put(tags::BITS_STORED, VR::US, dicom_value!(U16, [16]));
        put(tags::PIXEL_REPRESENTATION, VR::US, dicom_value!(U16, [1]));
        put(
            tags::IMAGE_ORIENTATION_PATIENT,
            VR::DS,
            ds(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
        );
        put(
            tags::IMAGE_POSITION_PATIENT,
            VR::DS,
            ds(&[0.0, 0.0, 2.0 * z as f64]),
        );
        put(tags::PIXEL_SPACING, VR::DS, ds(&[1.0, 1.0]));
        put(tags::SLICE_THICKNESS, VR::DS, ds(&[2.0]));
        put(tags::RESCALE_SLOPE, VR::DS, ds(&[1.0]));
        put(tags::RESCALE_INTERCEPT, VR::DS, ds(&[-1024.0]));
        put(tags::WINDOW_CENTER, VR::DS, ds(&[40.0]));
        put(tags::WINDOW_WIDTH, VR::DS, ds(&[400.0]));
        let stored: Vec<i16> = (0..N * N)
            .map(|i| (hu(i % N, i / N, z, padding) + 1024.0) as i16)
            .collect();
        put(tags::PIXEL_DATA, VR::OW, PrimitiveValue::I16(stored.into()));
        let meta = FileMetaTableBuilder::new()
            .transfer_syntax("1.2.840.10008.1.2.1")
            .media_storage_sop_class_uid("1.2.840.10008.5.1.4.1.1.2")
            .media_storage_sop_instance_uid(instance.as_str());
        let path = dir.join(format!("slice{z:02}.dcm"));
        obj.with_meta(meta).unwrap().write_to_file(&path).unwrap();
    }
    dir.join("slice00.dcm")
}

fn load(path: &Path, transfer: Option<Transfer>) -> autostereo::VolumeData {
    let options = LoadOptions {
        volume: VolumeLoad {
            transfer,
            ..Default::default()
        },
        ..Default::default()
    };
    match autostereo::load(path, &options).unwrap() {
        AnyData::Volume(v) => *v,
        _ => panic!("a volume"),
    }
}

fn render(data: autostereo::VolumeData) -> RgbImage {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let data = AnyData::Volume(Box::new(data));
    let frame = common::frame(data.bounds().unwrap(), "hubner8", 0.06, 1.0, [96, 96]);
    let scene = AnyScene::upload(device, queue, &data).unwrap();
    let mut renderer =
        AnyRenderer::new(device, &scene, &RendererOptions::new(Method::SinglePass)).unwrap();
    renderer
        .render_image(device, queue, &scene, &frame)
        .unwrap()
}

#[test]
fn ct_presets_in_hounsfield_units_ignore_the_scanners_padding() {
    let padded = write_series(&common::out_dir().join("ct_padded"), -3024.0);
    let plain = write_series(&common::out_dir().join("ct_plain"), -1000.0);
    let data = load(&padded, None);
    let values = &data.volume.values;
    assert_eq!(values.units, Units::Hounsfield);
    assert_eq!(values.modality, Some(Modality::Ct));
    assert_eq!(values.range, [-3024.0, 1000.0]);
    assert_eq!(values.window, Some([400.0, 40.0]));
    assert_eq!(data.preset, Some("ct-skin"), "a CT gets the CT preset");
    assert_eq!(load(&plain, None).volume.values.range, [-1000.0, 1000.0]);
    for preset in ["ct-skin", "ct-bone"] {
        let choice = || Some(Transfer::Preset(preset.into()));
        let (a, b) = (
            render(load(&padded, choice())),
            render(load(&plain, choice())),
        );
        let drawn = a.data.chunks(3).filter(|p| p != &&a.data[..3]).count();
        assert!(drawn > 500, "{preset}: the head is drawn ({drawn} pixels)");
        let diff = compare(&a, &b).unwrap();
        println!("{preset}: padded vs not, PSNR {:.2} dB", diff.psnr_db);
        assert!(diff.psnr_db >= 40.0, "{preset}: {:.2} dB", diff.psnr_db);
    }
}

#[test]
fn a_window_in_hounsfield_units_is_that_window_normalised() {
    let padded = write_series(&common::out_dir().join("ct_window"), -3024.0);
    let windowed = load(&padded, Some(Transfer::Window(Some([400.0, 40.0]))));
    let values = windowed.volume.values.clone();
    let ramp = TransferFunction::new(vec![
        (values.normalise(-160.0), [0.0; 4]),
        (values.normalise(240.0), [1.0; 4]),
    ])
    .unwrap();
    let normalised = load(&padded, Some(Transfer::Normalised(ramp)));
    // The file's own window (DICOM's WindowWidth/WindowCenter) is the same one.
    let own = load(&padded, Some(Transfer::Window(None)));
    let (a, b, c) = (render(windowed), render(normalised), render(own));
    assert_eq!(a.data, b.data, "--window 400,40 vs the normalised ramp");
    assert_eq!(a.data, c.data, "the file's window");
    let drawn = a.data.chunks(3).filter(|p| p != &&a.data[..3]).count();
    assert!(drawn > 500, "the window shows the head ({drawn} pixels)");
}
