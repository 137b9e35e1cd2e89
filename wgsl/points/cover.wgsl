// Covering quads of splats (docs/DESIGN.md §3), one invocation per splat: the eye-space splat and the
// NDC rectangle covering its disk for every camera offset in [cover_lo, cover_hi].
//
// The disk's axis-aligned box (half-extent r·√(1 − n_j²) per axis) is clipped to the near
// plane, and its 8 corners are projected for the two extreme offsets: for a fixed offset a the
// map x ↦ (x − a)·fd/d + a is a perspective projection, so the convex box's image is the hull of
// its corners' images, and x is linear in a, so the extremes lie at cover_lo and cover_hi.
#import points/shared/splat.wgsl

// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var<storage, read> splats: array<Splat>;
@group(1) @binding(1) var<storage, read_write> eye_splats: array<Splat>;
@group(1) @binding(2) var<storage, read_write> cover_rects: array<vec4<f32>>;

const WORKGROUP: u32 = 64u;
// Padding, pixels: a sliver where fragments sample pixel centres; the subpixel-resolution pass
// (fragments at x + 1/6, 1/2, 5/6 cast the ray of the pixel centre) needs half a pixel.
override COVER_PADDING_PX: f32 = 0.0625;

const EMPTY: vec4<f32> = vec4<f32>(1.0, 1.0, -1.0, -1.0);

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let id = (group.y * groups.x + group.x) * WORKGROUP + local;
    if (id >= arrayLength(&cover_rects)) {
        return;
    }
    let s = splats[id];
    let centre = (frame.camera.eye_from_world * vec4<f32>(s.position, 1.0)).xyz;
    var normal = (frame.camera.normal_from_world * vec4<f32>(s.normal, 0.0)).xyz;
    let len = length(normal);
    normal = select(vec3<f32>(0.0, 0.0, 1.0), normal / len, len > 0.0);
    eye_splats[id] = Splat(centre, s.radius, normal, s.color);
    if (!valid_radius(s.radius) || any(centre != centre)) {
        cover_rects[id] = EMPTY;
        return;
    }
    let half_extent = s.radius * sqrt(max(vec3<f32>(0.0), 1.0 - normal * normal));
    let near = frame.camera.near;
    let z_far = centre.z - half_extent.z;
    let z_near = min(centre.z + half_extent.z, -near);
    if (z_far > z_near) {
        cover_rects[id] = EMPTY; // wholly behind the near plane
        return;
    }
    let fd = frame.camera.focal_distance;
    var lo = vec2<f32>(3.0e38);
    var hi = vec2<f32>(-3.0e38);
    for (var k = 0u; k < 8u; k++) {
        let q = vec3<f32>(
            select(centre.x - half_extent.x, centre.x + half_extent.x, (k & 1u) != 0u),
            select(centre.y - half_extent.y, centre.y + half_extent.y, (k & 2u) != 0u),
            select(z_far, z_near, (k & 4u) != 0u),
        );
        let scale = fd / -q.z;
        let y = q.y * scale;
        let x_lo = q.x * scale + params.cover_lo * (1.0 - scale);
        let x_hi = q.x * scale + params.cover_hi * (1.0 - scale);
        lo = min(lo, vec2<f32>(min(x_lo, x_hi), y));
        hi = max(hi, vec2<f32>(max(x_lo, x_hi), y));
    }
    let pad = COVER_PADDING_PX * frame.camera.focal_window / frame.camera.viewport;
    let half = 0.5 * frame.camera.focal_window;
    let ndc_lo = clamp((lo - pad) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    let ndc_hi = clamp((hi + pad) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    cover_rects[id] = vec4<f32>(ndc_lo, ndc_hi);
}
