// RGB-D image → spatial image by backward warping straight into each subpixel's view: no
// per-view images (src/rgbd/passes.rs, docs/WARPING.md). The views differ by a horizontal
// shift only, so each subpixel searches its reference row for the pair of neighbouring samples
// whose warped positions straddle it; the nearest such pair wins (occlusion), and a pair warped
// further apart than `hole_gap` straddles a disocclusion, filled from its far (background)
// sample. Where no pair reaches (the image's edges), the sample landing nearest is used.
#import shared/frame.wgsl

// Keep in sync with `WarpUniform` in src/rgbd/passes.rs.
struct Warp {
    reference: vec2<u32>, // reference image size
    parallax: f32,        // shift (reference pixels) per unit nearness − focus at t = +1
    focus: f32,           // nearness on the display plane (no shift)
    fixed_view: u32,      // NO_VIEW: each subpixel's view from the mask; else this view
    hole_gap: f32,        // neighbours warped further apart than this straddle a hole
    hole_mask: u32,       // 1: write 1 where a subpixel was filled (hole or edge), 0 elsewhere
    _pad1: u32,
}

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var color: texture_2d<f32>;
@group(1) @binding(1) var nearness: texture_2d<f32>;
@group(1) @binding(2) var<uniform> warp: Warp;

const NO_VIEW: u32 = 0xffffffffu;

// Position t ∈ [−1, 1] of view v among the display's N (0 for a single view).
fn view_position(v: u32) -> f32 {
    let n = frame.mask.views;
    if (n <= 1u) {
        return 0.0;
    }
    return 2.0 * f32(v) / f32(n - 1u) - 1.0;
}

fn near_at(x: i32, row: i32) -> f32 {
    return textureLoad(nearness, vec2<i32>(x, row), 0).r;
}

fn color_at(x: i32, row: i32) -> vec3<f32> {
    return textureLoad(color, vec2<i32>(x, row), 0).rgb;
}

// Reference row `row` as seen from view position t at reference column u (rgb), and whether
// it was filled (w = 1: a disocclusion or the image's edge) rather than seen (0).
fn warped(row: i32, u: f32, t: f32) -> vec4<f32> {
    let k = warp.parallax * t;
    let reach = abs(k) * max(warp.focus, 1.0 - warp.focus);
    let last = i32(warp.reference.x) - 1;
    let lo = clamp(i32(floor(u - reach)) - 1, 0, last);
    let hi = clamp(i32(ceil(u + reach)) + 1, 0, last);
    var d0 = near_at(lo, row);
    var l0 = f32(lo) + k * (d0 - warp.focus);
    var best = -1.0; // nearness of the winning pair
    var value = vec3<f32>(0.0);
    var filled = 0.0;
    var closest = abs(l0 - u); // the fallback: the sample landing nearest u
    var fallback = lo;
    for (var x1 = lo + 1; x1 <= hi; x1++) {
        let d1 = near_at(x1, row);
        let l1 = f32(x1) + k * (d1 - warp.focus);
        let gap = l1 - l0;
        if (gap > 0.0 && l0 <= u && u <= l1) {
            let f = (u - l0) / gap;
            if (gap > warp.hole_gap) {
                // A disocclusion: the background side fills it.
                let far = select(x1, x1 - 1, d0 < d1);
                let d = min(d0, d1);
                if (d > best) {
                    best = d;
                    value = color_at(far, row);
                    filled = 1.0;
                }
            } else {
                let d = mix(d0, d1, f);
                // At equal depth a seen pair beats a filled one (a hole's far sample is seen
                // itself at the hole's edge).
                if (d > best || (d == best && filled == 1.0)) {
                    best = d;
                    value = mix(color_at(x1 - 1, row), color_at(x1, row), f);
                    filled = 0.0;
                }
            }
        }
        if (abs(l1 - u) < closest) {
            closest = abs(l1 - u);
            fallback = x1;
        }
        d0 = d1;
        l0 = l1;
    }
    if (best < 0.0) {
        return vec4<f32>(color_at(fallback, row), 1.0);
    }
    return vec4<f32>(value, filled);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let panel = frame.camera.viewport;
    let reference = vec2<f32>(warp.reference);
    // The pixel centre in reference pixels (the reference may be of another size).
    let u = (f32(px.x) + 0.5) * reference.x / panel.x - 0.5;
    let row = min(i32((f32(px.y) + 0.5) * reference.y / panel.y), i32(warp.reference.y) - 1);
    // One search per distinct view of the pixel (a per-pixel mask: one for all three).
    var out = vec3<f32>(0.0);
    var searched = NO_VIEW;
    var w = vec4<f32>(0.0);
    for (var c = 0u; c < 3u; c++) {
        var v = warp.fixed_view;
        if (v == NO_VIEW) {
            v = mask_view(frame.mask, px, c);
        }
        if (v != searched) {
            w = warped(row, u, view_position(v));
            searched = v;
        }
        out[c] = select(w[c], w.w, warp.hole_mask == 1u);
    }
    return vec4<f32>(out, 1.0);
}
