// Display mask: which view each (sub)pixel shows (docs/DESIGN.md §1).
// Keep in sync with `MaskUniform` / `Mask::view` in src/display/mask.rs: the same 0.32
// fixed-point, wrap-around integer arithmetic, operation for operation.

struct DisplayMask {
    step_column: u32, // frac(1/P) in 0.32 fixed point
    step_row: u32,    // frac(s/P)
    phase: u32,       // frac(φ/P)
    views: u32,       // N
    origin_x: u32,    // window origin on the panel, pixels
    origin_y: u32,
    flags: u32,       // 1 = subpixel mask, 2 = flip view order, 4 = BGR panel
    _pad: u32,
}

const MASK_SUBPIXEL: u32 = 1u;
const MASK_FLIP: u32 = 2u;
const MASK_BGR: u32 = 4u;

// (t · n) >> 32 from 16-bit halves (no 64-bit integers in core WGSL).
fn mask_mul_high(t: u32, n: u32) -> u32 {
    let hi = (t >> 16u) * n;
    let lo = ((t & 0xffffu) * n) >> 16u;
    return (hi + lo) >> 16u;
}

// View of channel c (0 = R) of window pixel px (y top-down).
fn mask_view(m: DisplayMask, px: vec2<u32>, c: u32) -> u32 {
    let slot = select(c, 2u - c, (m.flags & MASK_BGR) != 0u);
    let x = px.x + m.origin_x;
    let column = select(x, 3u * x + slot, (m.flags & MASK_SUBPIXEL) != 0u);
    let row = px.y + m.origin_y;
    let t = column * m.step_column + row * m.step_row + m.phase;
    let v = mask_mul_high(t, m.views);
    return select(v, m.views - 1u - v, (m.flags & MASK_FLIP) != 0u);
}

// Views of R, G, B of pixel px.
fn mask_views(m: DisplayMask, px: vec2<u32>) -> vec3<u32> {
    return vec3<u32>(mask_view(m, px, 0u), mask_view(m, px, 1u), mask_view(m, px, 2u));
}
