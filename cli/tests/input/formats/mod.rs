//! The data people have (issue 29) as the command line reads it: JPEG images are read wherever
//! PNGs are, a volume renders alike from each of its formats, and a file of another kind or an
//! unknown format is refused naming what reads it. Every file is generated here. (Every mesh
//! format loading and rendering as its OBJ: tests/formats/mesh_formats.rs.)

use crate::common;

mod images;
mod kinds;
mod windows;

use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};

fn out(name: &str) -> PathBuf {
    common::out(&format!("formats_{name}"))
}

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = out(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}
