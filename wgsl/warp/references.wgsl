// Reference views → spatial image by backward warping straight into each subpixel's view, no
// per-view images (src/warp/scene.rs, docs/WARPING.md). R reference views sit evenly over the
// views' span (t ∈ [−1, 1]; R = 1: the centre); each subpixel searches the rows of the two
// references around its view (warp/shared/row_warp.wgsl) and blends them where both see the same
// surface, else keeps the nearer surface or the one that is seen rather than filled.
#import shared/frame.wgsl
#import warp/shared/warp.wgsl
#import warp/shared/row_warp.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var color: texture_2d_array<f32>;
@group(1) @binding(1) var nearness: texture_2d_array<u32>; // the bits of f32 nearness
@group(1) @binding(2) var<uniform> warp: Warp;
// Per reference and row: the nearness range of its surfaces (warp/row_bounds.wgsl).
@group(1) @binding(3) var<storage, read> row_bounds: array<vec2<f32>>;

// The reads warp/shared/row_warp.wgsl makes.
fn near_at(layer: u32, x: i32, row: i32) -> f32 {
    return bitcast<f32>(textureLoad(nearness, vec2<i32>(x, row), layer, 0).r);
}

fn color_at(layer: u32, x: i32, row: i32) -> vec3<f32> {
    return textureLoad(color, vec2<i32>(x, row), layer, 0).rgb;
}

// Position of reference j among the R.
fn reference_position(j: u32) -> f32 {
    if (warp.references <= 1u) {
        return 0.0;
    }
    return 2.0 * f32(j) / f32(warp.references - 1u) - 1.0;
}

// Reference j's row seen from view position t at column u: its surfaces (nearness > 0,
// focus 1) searched over the window the row's nearness range allows; where none lands on u,
// the background.
fn from_reference(j: u32, row: i32, u: f32, t: f32) -> Warped {
    let k = warp.parallax * (t - reference_position(j));
    let bounds = row_bounds[j * warp.size.y + u32(row)];
    if (bounds.x <= bounds.y) {
        let found = warp_row(j, row, u, k, warp.focus, bounds.x, bounds.y, warp.size.x, warp.hole_gap);
        if (found.found) {
            return found;
        }
    }
    return background(j, row, u, k);
}

// No surface of the row lands on u: the background, which (nearness 0) lands from u + k. Seen
// where the reference shows background there; filled with the background colour where the
// reference has a surface there (the view sees past it) or u + k is off the image.
fn background(j: u32, row: i32, u: f32, k: f32) -> Warped {
    let x = i32(round(u + k));
    if (x >= 0 && x < i32(warp.size.x) && near_at(j, x, row) == 0.0) {
        return Warped(color_at(j, x, row), 0.0, false, true);
    }
    return Warped(frame.background.rgb, 0.0, true, true);
}

// Two references' views of one subpixel, the second at weight w: the seen one over a filled
// one; both seen, a blend where they agree on the surface, else the nearer.
fn blend(a: Warped, b: Warped, w: f32) -> Warped {
    if (a.filled != b.filled) {
        if (a.filled) {
            return b;
        }
        return a;
    }
    if (a.filled) {
        if (w > 0.5) {
            return b;
        }
        return a;
    }
    if (abs(a.nearness - b.nearness) <= warp.same_surface * max(a.nearness, b.nearness)) {
        return Warped(mix(a.color, b.color, w), mix(a.nearness, b.nearness, w), false, true);
    }
    if (b.nearness > a.nearness) {
        return b;
    }
    return a;
}

// View v at column u of row `row`: from the references on either side of it (exactly the
// reference where the view is one). View v sits at v·(R−1)/(N−1) in reference units:
// integer arithmetic, so a view that is a reference is found as one, with no rounding.
fn view_value(v: u32, row: i32, u: f32) -> Warped {
    let t = view_position(v);
    let n = frame.mask.views;
    if (warp.references <= 1u || n <= 1u) {
        return from_reference(0u, row, u, t);
    }
    let scaled = v * (warp.references - 1u);
    let j = scaled / (n - 1u);
    let rest = scaled % (n - 1u);
    if (rest == 0u) {
        return from_reference(j, row, u, t);
    }
    let w = f32(rest) / f32(n - 1u);
    return blend(from_reference(j, row, u, t), from_reference(j + 1u, row, u, t), w);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let u = f32(px.x);
    let row = i32(px.y);
    return warp_subpixels(px, row, u);
}
