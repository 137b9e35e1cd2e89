#![no_main]
//! A quilt image's layout from its name, size, grid flag and view count (what `autostereo
//! interleave` checks before it reads a pixel): the first 16 bytes are the numbers, the rest
//! the name.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if data.len() < 16 {
        return;
    }
    let word = |i: usize| u32::from_le_bytes(data[i..i + 4].try_into().unwrap());
    let size = [word(0), word(4)];
    let grid = (word(8) & 1 == 1).then(|| [word(8) >> 16, word(12) >> 16]);
    let views = word(12) & 0xffff;
    let name = String::from_utf8_lossy(&data[16..]);
    if let Ok(q) = autostereo::render::quilt_image::QuiltImage::read(&name, size, grid, views) {
        let l = q.layout;
        let _ = (l.size(), l.tile_origin(views.saturating_sub(1)), q.suffix());
    }
});
