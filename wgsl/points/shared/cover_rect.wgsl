// The NDC rectangle covering an eye-space splat disk for every camera offset in [lo, hi]
// (docs/DESIGN.md §3): the cover pass's, and the duplication methods' per-view quads.
//
// The disk's axis-aligned box (half-extent r·√(1 − n_j²) per axis) is clipped to the near
// plane, and its 8 corners are projected for the two extreme offsets: for a fixed offset a the
// map x ↦ (x − a)·fd/d + a is a perspective projection, so the convex box's image is the hull of
// its corners' images, and x is linear in a, so the extremes lie at lo and hi (toe-in cameras:
// every view's image of the corners, since turned views move x and y non-linearly). Reads `frame`.

// Padding, pixels: a sliver where fragments sample pixel centres; the subpixel-resolution pass
// (fragments at x + 1/6, 1/2, 5/6 cast the ray of the pixel centre) needs half a pixel.
override COVER_PADDING_PX: f32 = 0.0625;

// An empty rectangle (lo > hi): the quad is culled.
const EMPTY: vec4<f32> = vec4<f32>(1.0, 1.0, -1.0, -1.0);

fn splat_cover_rect(centre: vec3<f32>, radius: f32, normal: vec3<f32>, lo: f32, hi: f32) -> vec4<f32> {
    let half_extent = radius * sqrt(max(vec3<f32>(0.0), 1.0 - normal * normal));
    let near = frame.camera.near;
    let z_far = centre.z - half_extent.z;
    let z_near = min(centre.z + half_extent.z, -near);
    if (z_far > z_near) {
        return EMPTY; // wholly behind the near plane
    }
    let fd = frame.camera.focal_distance;
    var lo_xy = vec2<f32>(3.0e38);
    var hi_xy = vec2<f32>(-3.0e38);
    for (var k = 0u; k < 8u; k++) {
        let q = vec3<f32>(
            select(centre.x - half_extent.x, centre.x + half_extent.x, (k & 1u) != 0u),
            select(centre.y - half_extent.y, centre.y + half_extent.y, (k & 2u) != 0u),
            select(z_far, z_near, (k & 4u) != 0u),
        );
        if (frame.camera.model == CAMERA_TOE_IN) {
            // Turned cameras: each view's projection of the corner (x and y move, not
            // linearly in the offset): the cameras at lo and hi and the views between.
            for (var i = 0u; i < VIEW_COUNT + 2u; i++) {
                var vd = lo;
                if (i == 1u) {
                    vd = hi;
                } else if (i > 1u) {
                    vd = view_offset(i - 2u);
                    if (!(vd > lo && vd < hi)) {
                        continue;
                    }
                }
                let p = camera_project(frame.camera, q, vd);
                if (!(p.z > 0.0)) {
                    return vec4<f32>(-2.0, -2.0, 2.0, 2.0); // beside the camera: everything
                }
                lo_xy = min(lo_xy, p.xy);
                hi_xy = max(hi_xy, p.xy);
            }
            continue;
        }
        let scale = fd / -q.z;
        let y = q.y * scale;
        let x_lo = q.x * scale + lo * (1.0 - scale);
        let x_hi = q.x * scale + hi * (1.0 - scale);
        lo_xy = min(lo_xy, vec2<f32>(min(x_lo, x_hi), y));
        hi_xy = max(hi_xy, vec2<f32>(max(x_lo, x_hi), y));
    }
    let pad = COVER_PADDING_PX * frame.camera.focal_window / frame.camera.viewport;
    let half = 0.5 * frame.camera.focal_window;
    let window_centre = frame.camera.window_offset;
    let ndc_lo = clamp((lo_xy - pad - window_centre) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    let ndc_hi = clamp((hi_xy + pad - window_centre) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    return vec4<f32>(ndc_lo, ndc_hi);
}
