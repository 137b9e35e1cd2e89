#![no_main]
//! `--display SPEC` strings, and the mask of what they parse to on a small panel.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(d) = autostereo::display::Display::parse(&text) {
        let mask = d.mask();
        for c in 0..3 {
            let _ = mask.view(7, 3, c);
        }
    }
});
