#![no_main]
//! Looking Glass quilt names (`…_qs5x9a0.75.png`), and the layout and file name they make.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    use autostereo::render::quilt_image::{QuiltImage, QuiltName};
    if let Some(n) = QuiltName::parse(&text) {
        let views = n.cols.saturating_mul(n.rows).min(256);
        let size = [n.cols.saturating_mul(64), n.rows.saturating_mul(64)];
        if let Ok(q) = QuiltImage::in_size([n.cols, n.rows], size, views, n.aspect) {
            let _ = (q.layout.tile_origin(views.saturating_sub(1)), q.suffix());
            let _ = q.file_name(std::path::Path::new(text.as_ref()));
        }
    }
});
