// Looking Glass quilt addressing (src/render/quilt.rs): view 0 bottom-left, left → right then
// bottom → top. Keep `Quilt` in sync with `QuiltUniform` in src/render/quilt.rs.

struct Quilt {
    grid: vec2<u32>,  // tiles per row, rows
    tile: vec2<u32>,  // texels of one tile
    panel: vec2<u32>, // the spatial image's size, when compositing (else the tile's)
    bilinear: u32,    // compositing: 1 = up-sample tiles bilinearly, 0 = nearest texel
    _pad: u32,
}

// Top-left texel of view `view`'s tile (texel rows top-down).
fn quilt_tile_origin(q: Quilt, view: u32) -> vec2<u32> {
    let col = view % q.grid.x;
    let row_from_top = q.grid.y - 1u - view / q.grid.x;
    return vec2<u32>(col, row_from_top) * q.tile;
}

// Texel of view `view`'s tile under pixel `px` of a `panel`-sized image: the tile texel whose
// centre is nearest the pixel centre (1:1 when the tile is the panel's size).
fn quilt_texel(q: Quilt, view: u32, px: vec2<u32>, panel: vec2<u32>) -> vec2<u32> {
    let t = min((2u * px + 1u) * q.tile / (2u * panel), q.tile - 1u);
    return quilt_tile_origin(q, view) + t;
}

// A view's clip-space position moved into its tile of the atlas: the view's NDC square
// [−1, 1]² maps onto the tile (clip.w is kept, so interpolation stays perspective-correct).
fn quilt_clip(q: Quilt, view: u32, clip: vec4<f32>) -> vec4<f32> {
    let grid = vec2<f32>(q.grid);
    let cell = vec2<f32>(f32(view % q.grid.x), f32(view / q.grid.x));
    let xy = (clip.xy + clip.w * (1.0 + 2.0 * cell)) / grid - clip.w;
    return vec4<f32>(xy, clip.z, clip.w);
}

// Whether framebuffer position `frag` of the atlas lies in view `view`'s tile.
fn quilt_in_tile(q: Quilt, view: u32, frag: vec2<f32>) -> bool {
    let lo = vec2<f32>(quilt_tile_origin(q, view));
    let hi = lo + vec2<f32>(q.tile);
    return all(frag >= lo) && all(frag < hi);
}
