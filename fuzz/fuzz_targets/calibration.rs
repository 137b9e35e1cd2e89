#![no_main]
//! Looking Glass `visual.json` text, and the display it makes.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(c) = autostereo::display::Calibration::from_json(&text, "visual.json".as_ref()) {
        let _ = autostereo::display::Display::new(autostereo::display::DisplayKind::LookingGlass {
            calibration: c,
            views: 45,
        });
    }
});
