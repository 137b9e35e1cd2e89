// Covering quads (docs/DESIGN.md §3), one compute invocation per triangle: eye-space vertices and the
// NDC rectangle that covers the triangle's projections in all views (shared/cover_bounds.wgsl).
// Computing this once per triangle (not once per quad corner) keeps the vertex stage to one
// 16-byte load.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import mesh/shared/eye_triangle.wgsl
#import mesh/shared/cover_bounds.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/mesh_data.wgsl.
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;

@group(1) @binding(2) var<storage, read_write> eye_triangles: array<EyeTriangle>;
@group(1) @binding(3) var<storage, read_write> cover_rects: array<vec4<f32>>;

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
    let p = transform_triangle(tri);
    eye_triangles[tri] = eye_triangle(p);
    let b = cover_bounds(p);
    if (b.lo.x > b.hi.x) {
        cover_rects[tri] = vec4<f32>(1.0, 1.0, -1.0, -1.0); // behind the near plane: empty
        return;
    }
    // Rays go through pixel centres and the bounds are exact, so a pixel whose centre any view's
    // projection covers is inside the rectangle already; a sliver of padding absorbs rounding
    // (docs/DESIGN.md §3 suggests a whole pixel, which triples the fragments of 1-pixel triangles).
    // Then to NDC (focal window ↦ [−1, 1]), clamped so that near triangles stay finite.
    let pad = COVER_PADDING_PX * frame.camera.focal_window / frame.camera.viewport;
    let half = 0.5 * frame.camera.focal_window;
    let centre = frame.camera.window_offset;
    let lo = clamp((b.lo - pad - centre) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    let hi = clamp((b.hi + pad - centre) / half, vec2<f32>(-2.0), vec2<f32>(2.0));
    cover_rects[tri] = vec4<f32>(lo, hi);
}
