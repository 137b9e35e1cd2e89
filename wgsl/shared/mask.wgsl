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
    flags: u32,       // 1 = subpixel mask, 2 = flip view order, 4 = BGR panel, 8 = cells
    cell_pattern: u32, // subpixel cells: CellPatternMode
    panel_top: u32,   // subpixel cells: the panel's last row, H − 1
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
    cell_r: vec4<u32>, // subpixel cells: phase of R per cell index 0…3
    cell_g: vec4<u32>,
    cell_b: vec4<u32>,
}

const MASK_SUBPIXEL: u32 = 1u;
const MASK_FLIP: u32 = 2u;
const MASK_BGR: u32 = 4u;
const MASK_CELLS: u32 = 8u;

// Cell index 0…3 of panel column x, row up from the bottom (`cell_index` in the Rust).
fn mask_cell(pattern: u32, x: u32, up: u32) -> u32 {
    switch pattern {
        case 1u: { return (x ^ up) & 1u; }
        case 2u: { return x & 1u; }
        case 3u: { return (up + 2u * (x & 1u)) & 3u; }
        case 4u: { return up & 1u; }
        default: { return 0u; }
    }
}

// Phase of channel slot (0 = R) of cell index `cell`.
fn mask_cell_phase(m: DisplayMask, cell: u32, slot: u32) -> u32 {
    if slot == 0u {
        return m.cell_r[cell];
    }
    if slot == 1u {
        return m.cell_g[cell];
    }
    return m.cell_b[cell];
}

// (t · n) >> 32 from 16-bit halves (no 64-bit integers in core WGSL).
fn mask_mul_high(t: u32, n: u32) -> u32 {
    let hi = (t >> 16u) * n;
    let lo = ((t & 0xffffu) * n) >> 16u;
    return (hi + lo) >> 16u;
}

// Lens phase of channel c (0 = R) of window pixel px (y top-down), 0.32 fixed point: the view
// before flipping is (phase · N) >> 32 (`mask_view`).
fn mask_phase(m: DisplayMask, px: vec2<u32>, c: u32) -> u32 {
    let slot = select(c, 2u - c, (m.flags & MASK_BGR) != 0u);
    let x = px.x + m.origin_x;
    let row = px.y + m.origin_y;
    var column = select(x, 3u * x + slot, (m.flags & MASK_SUBPIXEL) != 0u);
    var phase = m.phase;
    if (m.flags & MASK_CELLS) != 0u {
        column = x;
        phase = mask_cell_phase(m, mask_cell(m.cell_pattern, x, m.panel_top - row), slot);
    }
    return column * m.step_column + row * m.step_row + phase;
}

// View of channel c (0 = R) of window pixel px (y top-down).
fn mask_view(m: DisplayMask, px: vec2<u32>, c: u32) -> u32 {
    let v = mask_mul_high(mask_phase(m, px, c), m.views);
    return select(v, m.views - 1u - v, (m.flags & MASK_FLIP) != 0u);
}

// Pixels between two along a row whose channel c has the same cell phase, so that its lens phase
// steps by a constant (shared/view_lattice.wgsl): 2 where subpixel cells alternate with the
// column's parity (cell patterns 1–3), else 1.
fn mask_lattice_stride(m: DisplayMask) -> u32 {
    let alternating = m.cell_pattern >= 1u && m.cell_pattern <= 3u;
    return select(1u, 2u, (m.flags & MASK_CELLS) != 0u && alternating);
}

// Views of R, G, B of pixel px.
fn mask_views(m: DisplayMask, px: vec2<u32>) -> vec3<u32> {
    return vec3<u32>(mask_view(m, px, 0u), mask_view(m, px, 1u), mask_view(m, px, 2u));
}
