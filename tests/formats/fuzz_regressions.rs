//! Replays the fuzz seeds and every crash the fuzzers found (`fuzz/seeds/TARGET/`,
//! `fuzz/regressions/TARGET/`) through the same parsers as the fuzz targets (`fuzz/`), so that
//! stable CI checks them without the nightly toolchain: each input gives a value or an error,
//! never a panic.

use std::path::{Path, PathBuf};

use autostereo::display::{Calibration, Display, DisplayKind};
use autostereo::formats::Format;
use autostereo::gaussians::load::{parse_ply, parse_splat, parse_spz};
use autostereo::mesh::Mesh;
use autostereo::volume::load::{parse_den, parse_nrrd, parse_raw, RawSpec};
use autostereo::volume::TransferFunction;

/// What each fuzz target does with one input (the same calls as `fuzz/fuzz_targets/*.rs`).
fn run(target: &str, data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    match target {
        "obj" => drop(Mesh::from_obj_text(&text, "fuzz.obj".as_ref())),
        "mtl" => drop(Mesh::check_mtl_text(&text, "fuzz.mtl".as_ref())),
        "ply" => drop(autostereo::io::ply::parse(data)),
        "nrrd" => {
            let dir = std::env::temp_dir().join("autostereo-fuzz-empty");
            std::fs::create_dir_all(&dir).unwrap();
            drop(parse_nrrd(data, &dir.join("fuzz.nrrd")));
        }
        "raw" => {
            if let Some((spec, file)) = RawSpec::from_fuzz_input(data) {
                drop(parse_raw(file, "fuzz.raw".as_ref(), &spec));
            }
        }
        "den" => drop(parse_den(data, "fuzz.den".as_ref())),
        "transfer" => drop(TransferFunction::parse(&text)),
        "calibration" => {
            if let Ok(calibration) = Calibration::from_json(&text, "visual.json".as_ref()) {
                let display = Display::new(DisplayKind::LookingGlass {
                    calibration,
                    views: 45,
                });
                if let Ok(display) = display {
                    let mask = display.mask();
                    for (x, y) in [(0, 0), (7, 3), (u32::MAX, u32::MAX)] {
                        let _ = mask.pixel_views(x, y);
                    }
                }
            }
        }
        "display_spec" => {
            if let Ok(d) = Display::parse(&text) {
                let mask = d.mask();
                for c in 0..3 {
                    let _ = mask.view(7, 3, c);
                }
            }
        }
        "quilt_name" => {
            use autostereo::render::quilt_image::{QuiltImage, QuiltName};
            if let Some(n) = QuiltName::parse(&text) {
                let views = n.cols.saturating_mul(n.rows).min(256);
                let size = [n.cols.saturating_mul(64), n.rows.saturating_mul(64)];
                if let Ok(q) = QuiltImage::in_size([n.cols, n.rows], size, views, n.aspect) {
                    let _ = (q.layout.tile_origin(views.saturating_sub(1)), q.suffix());
                    let _ = q.file_name(Path::new(text.as_ref()));
                }
            }
        }
        "rgbd" => {
            use autostereo::rgbd::{DepthMapOptions, RgbdImage};
            let options = DepthMapOptions {
                invert: data.len().is_multiple_of(2),
                resample: true,
            };
            let name = Path::new("fuzz.png");
            drop(RgbdImage::side_by_side_from_bytes(data, name, options));
            drop(RgbdImage::from_bytes(data, data, [name, name], options));
        }
        "quilt_image" => {
            if data.len() >= 16 {
                let word = |i: usize| u32::from_le_bytes(data[i..i + 4].try_into().unwrap());
                let size = [word(0), word(4)];
                let grid = (word(8) & 1 == 1).then(|| [word(8) >> 16, word(12) >> 16]);
                let views = word(12) & 0xffff;
                let name = String::from_utf8_lossy(&data[16..]);
                let read =
                    autostereo::render::quilt_image::QuiltImage::read(&name, size, grid, views);
                if let Ok(q) = read {
                    let l = q.layout;
                    let _ = (l.size(), l.tile_origin(views.saturating_sub(1)), q.suffix());
                }
            }
        }
        "ply_mesh" => drop(Mesh::parse(data, Format::Ply, "fuzz.ply".as_ref())),
        "stl" => drop(Mesh::parse(data, Format::Stl, "fuzz.stl".as_ref())),
        "gltf" => drop(Mesh::parse(data, Format::Gltf, "fuzz.glb".as_ref())),
        "las" => drop(autostereo::points::las::parse(data.to_vec())),
        "dicom" => drop(autostereo::volume::load::parse_dicom(
            data,
            "fuzz.dcm".as_ref(),
        )),
        "vti" => drop(autostereo::volume::load::parse_vti(
            data,
            "fuzz.vti".as_ref(),
        )),
        "vtk" => drop(autostereo::volume::load::parse_vtk(
            data,
            "fuzz.vtk".as_ref(),
        )),
        "nifti" | "metaimage" => {
            let dir = std::env::temp_dir().join("autostereo-fuzz-empty");
            std::fs::create_dir_all(&dir).unwrap();
            let path = dir.join(format!("fuzz.{target}"));
            drop(match target {
                "nifti" => autostereo::volume::load::parse_nifti(data, &path),
                _ => autostereo::volume::load::parse_metaimage(data, &path),
            });
        }
        "gaussians_ply" => drop(parse_ply(data, "fuzz.ply".as_ref())),
        "splat" => drop(parse_splat(data, "fuzz.splat".as_ref())),
        "spz" => drop(parse_spz(data, "fuzz.spz".as_ref())),
        other => panic!("no fuzz target '{other}'"),
    }
}

fn inputs(kind: &str, target: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(kind)
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|d| d.map(|e| e.unwrap().path()).collect())
        .unwrap_or_default();
    files.retain(|p| p.is_file() && p.file_name().is_some_and(|n| n != ".gitkeep"));
    files.sort();
    files
}

#[test]
fn seeds_and_found_crashes_replay_without_panics() {
    let targets = [
        "obj",
        "mtl",
        "ply",
        "nrrd",
        "raw",
        "den",
        "transfer",
        "calibration",
        "display_spec",
        "quilt_name",
        "rgbd",
        "quilt_image",
        "ply_mesh",
        "stl",
        "gltf",
        "nifti",
        "metaimage",
        "las",
        "dicom",
        "vti",
        "vtk",
        "gaussians_ply",
        "splat",
        "spz",
    ];
    let mut replayed = 0;
    for target in targets {
        let seeds = inputs("seeds", target);
        assert!(!seeds.is_empty(), "fuzz/seeds/{target} has no seed");
        for file in seeds.iter().chain(&inputs("regressions", target)) {
            let data = std::fs::read(file).unwrap();
            let outcome = std::panic::catch_unwind(|| run(target, &data));
            assert!(outcome.is_ok(), "{target}: {} panics", file.display());
            replayed += 1;
        }
    }
    assert!(replayed >= targets.len());
}

/// The seeds are valid inputs: they parse (so the fuzzers start from real structure).
#[test]
fn seeds_are_valid_inputs() {
    for file in inputs("seeds", "obj") {
        let text = std::fs::read_to_string(&file).unwrap();
        Mesh::from_obj_text(&text, &file).unwrap();
    }
    for file in inputs("seeds", "nrrd") {
        parse_nrrd(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "raw") {
        let data = std::fs::read(&file).unwrap();
        let (spec, bytes) = RawSpec::from_fuzz_input(&data).unwrap();
        parse_raw(bytes, &file, &spec).unwrap();
    }
    for file in inputs("seeds", "den") {
        parse_den(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "ply") {
        autostereo::io::ply::parse(&std::fs::read(&file).unwrap()).unwrap();
    }
    for (target, format) in [
        ("ply_mesh", Format::Ply),
        ("stl", Format::Stl),
        ("gltf", Format::Gltf),
    ] {
        for file in inputs("seeds", target) {
            Mesh::parse(&std::fs::read(&file).unwrap(), format, &file).unwrap();
        }
    }
    for file in inputs("seeds", "nifti") {
        autostereo::volume::load::parse_nifti(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "metaimage") {
        autostereo::volume::load::parse_metaimage(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "las") {
        autostereo::points::las::parse(std::fs::read(&file).unwrap()).unwrap();
    }
    for file in inputs("seeds", "dicom") {
        autostereo::volume::load::parse_dicom(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for (target, parse) in [
        ("gaussians_ply", parse_ply as fn(&[u8], &Path) -> _),
        ("splat", parse_splat),
        ("spz", parse_spz),
    ] {
        for file in inputs("seeds", target) {
            parse(&std::fs::read(&file).unwrap(), &file).unwrap();
        }
    }
    for file in inputs("seeds", "vti") {
        autostereo::volume::load::parse_vti(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "vtk") {
        autostereo::volume::load::parse_vtk(&std::fs::read(&file).unwrap(), &file).unwrap();
    }
    for file in inputs("seeds", "display_spec") {
        Display::parse(&std::fs::read_to_string(&file).unwrap()).unwrap();
    }
}
