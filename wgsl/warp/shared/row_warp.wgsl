// Backward warping of one reference row into a view (docs/WARPING.md): views differ by a
// horizontal shift only, so the sample of reference row `row` that lands on column u of a view
// is found by searching that row. Sample x lands at x + k·(n − focus), n its nearness; the pair
// of neighbours whose landings straddle u gives the value, the nearest pair winning
// (occlusion). A pair warped further apart than `hole_gap` straddles a disocclusion, filled
// from its far (background) sample. Where no pair reaches (the image's edges), the sample
// landing nearest u is used, marked filled.
//
// The stage defines the reads: `near_at(layer, x, row) -> f32` and
// `color_at(layer, x, row) -> vec3<f32>` (warp/rgbd.wgsl: one 2D image;
// warp/references.wgsl: the layers of the reference views).

struct Warped {
    color: vec3<f32>,
    nearness: f32,
    filled: bool, // a disocclusion or the image's edge, not a seen sample
    found: bool,  // a pair of samples straddled u (else the nearest landing was taken)
}

// Reference `layer`, row `row`, as seen at column u by a view whose shift per unit of
// nearness − focus is k, searching the samples whose landing can reach u: those of nearness
// in [near_lo, near_hi] lie in u − k·(n − focus) (one pixel of margin either side). `width` is
// the row's length and `hole_gap` the hole threshold, both in reference pixels.
fn warp_row(layer: u32, row: i32, u: f32, k: f32, focus: f32, near_lo: f32, near_hi: f32, width: u32, hole_gap: f32) -> Warped {
    let last = i32(width) - 1;
    let a = u - k * (near_lo - focus);
    let b = u - k * (near_hi - focus);
    let lo = clamp(i32(floor(min(a, b))) - 1, 0, last);
    let hi = clamp(i32(ceil(max(a, b))) + 1, 0, last);
    var d0 = near_at(layer, lo, row);
    var l0 = f32(lo) + k * (d0 - focus);
    var best = -1.0; // nearness of the winning pair
    var value = vec3<f32>(0.0);
    var filled = false;
    var closest = abs(l0 - u); // the fallback: the sample landing nearest u
    var fallback = lo;
    for (var x1 = lo + 1; x1 <= hi; x1++) {
        let d1 = near_at(layer, x1, row);
        let l1 = f32(x1) + k * (d1 - focus);
        let gap = l1 - l0;
        if (gap > 0.0 && l0 <= u && u <= l1) {
            let f = (u - l0) / gap;
            if (gap > hole_gap) {
                // A disocclusion: the background side fills it.
                let far = select(x1, x1 - 1, d0 < d1);
                let d = min(d0, d1);
                if (d > best) {
                    best = d;
                    value = color_at(layer, far, row);
                    filled = true;
                }
            } else {
                let d = mix(d0, d1, f);
                // At equal depth a seen pair beats a filled one (a hole's far sample is seen
                // itself at the hole's edge).
                if (d > best || (d == best && filled)) {
                    best = d;
                    value = mix(color_at(layer, x1 - 1, row), color_at(layer, x1, row), f);
                    filled = false;
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
        return Warped(color_at(layer, fallback, row), near_at(layer, fallback, row), true, false);
    }
    return Warped(value, best, filled, true);
}
