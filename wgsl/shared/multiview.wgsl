// Pipeline specialisation of the single-pass renderers: views per pixel K and view count N are
// override constants, so a K = 1 display compiles to one ray per fragment and vd_i folds.
// Set by the Rust side at pipeline creation (src/render/specialize.rs).

override VIEWS_PER_PIXEL: u32 = 3u;
override VIEW_COUNT: u32 = 8u;

// Eye-space offset vd_i = (i − (N−1)/2)·e of view i (docs/DESIGN.md §2).
fn view_offset(view: u32) -> f32 {
    return (f32(view) - 0.5 * f32(VIEW_COUNT - 1u)) * frame.camera.separation;
}

// Largest |vd_i|.
fn max_view_offset() -> f32 {
    return 0.5 * f32(VIEW_COUNT - 1u) * abs(frame.camera.separation);
}

// View of the c-th ray of pixel px: one per channel on subpixel masks, one per pixel otherwise.
fn ray_view(px: vec2<u32>, c: u32) -> u32 {
    return mask_view(frame.mask, px, c);
}
