// Covering quads (DESIGN §3), one compute invocation per triangle: eye-space vertices and the
// NDC rectangle that covers the triangle's projections in all views. y from the centre
// projection; x widened per vertex by vd·|1 − fd/d| (exact for the sheared frusta; the paper's
// printed vd·fd/d under-covers geometry beyond 2·fd and is kept only as a measured option).
// Vertices behind the near plane are clipped first, so a triangle crossing it gets the bounds of
// its visible part. Computing this once per triangle (not once per quad corner) keeps the vertex
// stage to one 16-byte load.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/mesh_data.wgsl

override PAPER_BOUNDS: bool = false;

struct EyeTriangle {
    p0: vec4<f32>,
    p1: vec4<f32>,
    p2: vec4<f32>,
}

@group(1) @binding(2) var<storage, read_write> eye_triangles: array<EyeTriangle>;
@group(1) @binding(3) var<storage, read_write> cover_rects: array<vec4<f32>>;

struct Bounds {
    lo: vec2<f32>,
    hi: vec2<f32>,
}

fn extend(b: Bounds, q: vec3<f32>) -> Bounds {
    let s = frame.camera.focal_distance / -q.z;
    let centre = q.xy * s;
    var spread = max_view_offset() * abs(1.0 - s);
    if (PAPER_BOUNDS) {
        spread = max_view_offset() * s;
    }
    return Bounds(
        min(b.lo, vec2<f32>(centre.x - spread, centre.y)),
        max(b.hi, vec2<f32>(centre.x + spread, centre.y)),
    );
}

// Focal-plane bounds of the part of triangle p in front of the near plane.
fn cover_bounds(p: array<vec3<f32>, 3>) -> Bounds {
    let near = frame.camera.near;
    var b = Bounds(vec2<f32>(3.0e38), vec2<f32>(-3.0e38));
    for (var e = 0u; e < 3u; e++) {
        let a = p[e];
        let c = p[(e + 1u) % 3u];
        let da = -a.z;
        let dc = -c.z;
        if (da >= near) {
            b = extend(b, a);
        }
        if ((da >= near) != (dc >= near)) {
            b = extend(b, mix(a, c, (near - da) / (dc - da)));
        }
    }
    return b;
}

const WORKGROUP: u32 = 64u;
// Padding of the covering rectangles, pixels: a sliver where fragments sample pixel centres;
// the subpixel-resolution pass (samples at x + 1/6, x + 1/2, x + 5/6) needs half a pixel.
override COVER_PADDING_PX: f32 = 0.0625;

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let tri = (group.y * groups.x + group.x) * WORKGROUP + local;
    if (tri >= arrayLength(&cover_rects)) {
        return;
    }
    let p = array<vec3<f32>, 3>(
        eye_position(triangle_vertex(tri, 0u)),
        eye_position(triangle_vertex(tri, 1u)),
        eye_position(triangle_vertex(tri, 2u)),
    );
    eye_triangles[tri] = EyeTriangle(vec4<f32>(p[0], 1.0), vec4<f32>(p[1], 1.0), vec4<f32>(p[2], 1.0));
    let b = cover_bounds(p);
    if (b.lo.x > b.hi.x) {
        cover_rects[tri] = vec4<f32>(1.0, 1.0, -1.0, -1.0); // behind the near plane: empty
        return;
    }
    // Rays go through pixel centres and the bounds are exact, so a pixel whose centre any view's
    // projection covers is inside the rectangle already; a sliver of padding absorbs rounding
    // (DESIGN §3 suggests a whole pixel, which triples the fragments of 1-pixel triangles).
    // Then to NDC (focal window ↦ [−1, 1]), clamped so that near triangles stay finite.
    let pad = COVER_PADDING_PX * frame.camera.focal_window / frame.camera.viewport;
    let half = 0.5 * frame.camera.focal_window;
    let lo = clamp((b.lo - pad) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    let hi = clamp((b.hi + pad) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    cover_rects[tri] = vec4<f32>(lo, hi);
}
