#![no_main]
//! Looking Glass `visual.json` text (the stripe model or subpixel cells), the display it makes
//! and its mask at a few subpixels.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(c) = autostereo::display::Calibration::from_json(&text, "visual.json".as_ref()) {
        let display =
            autostereo::display::Display::new(autostereo::display::DisplayKind::LookingGlass {
                calibration: c,
                views: 45,
            });
        if let Ok(display) = display {
            let mask = display.mask();
            for (x, y) in [(0, 0), (7, 3), (u32::MAX, u32::MAX)] {
                let _ = mask.pixel_views(x, y);
            }
        }
    }
});
