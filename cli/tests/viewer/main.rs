//! The viewer in a real window (`autostereo view` under Xvfb, lavapipe presenting to the X
//! surface): what it presents equals the headless render with the window's position as the
//! mask origin; moving the window moves the mask phase with it; switching methods, displays and
//! sizes for hundreds of frames neither fails nor grows memory. Without Xvfb on the machine (CI
//! installs it: .ci/run), the test asserts the viewer's clear error instead.

#[path = "../common/mod.rs"]
mod common;

mod memory;
mod monitors;
mod presented;
mod previews;

use std::path::Path;

use autostereo::image_io::{compare, RgbImage};

use common::xvfb::{headless, xvfb_or_clear_error, Xvfb};

use crate::common::out;

/// ≥ 99.9 % of subpixels within 2/255 of the headless render.
fn assert_same(name: &str, shot: &Path, headless: &Path) {
    let a = RgbImage::load_png(shot).unwrap();
    let b = RgbImage::load_png(headless).unwrap();
    let diff = compare(&a, &b).unwrap();
    assert!(diff.frac_off_2 <= 0.001, "{name}: {diff:?}");
}
