#![no_main]
//! Looking Glass quilt names (`…_qs5x9a0.75.png`), and the layout and file name they make.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Some((cols, rows, aspect)) = autostereo::render::quilt::parse_quilt_name(&text) {
        let views = cols.saturating_mul(rows).min(256);
        let tile = [64, (64.0 / aspect).clamp(1.0, 1e6) as u32];
        if let Ok(q) = autostereo::render::quilt::QuiltLayout::with_grid(cols, rows, tile, views) {
            let _ = (q.size(), q.tile_origin(views.saturating_sub(1)), q.suffix());
            let _ = q.file_name(std::path::Path::new(text.as_ref()));
        }
    }
});
