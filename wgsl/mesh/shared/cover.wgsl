// Vertex stage of the single-pass mesh geometry passes: the covering rectangle of triangle
// vertex / 6 (from mesh/single_pass_cover.wgsl) drawn as two triangles. `vs_cover` passes the triangle id
// and fragments load its eye-space vertices; `vs_cover_flat` also passes the vertices as flat
// varyings, which pays off where fragments are many per triangle (subpixel resolution).
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/ray.wgsl
#import mesh/shared/cover_data.wgsl

struct CoverOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) tri: u32,
}

// Clip-space corner of the covering rectangle for `vertex`.
fn cover_corner(vertex: u32) -> vec4<f32> {
    let tri = vertex / 6u;
    let rect = cover_rects[tri];
    // Corners of two triangles: 0 1 2 / 2 1 3 with bit 0 = x, bit 1 = y. An empty rectangle
    // (lo > hi: the triangle is behind the near plane) collapses to a point the rasteriser drops.
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex % 6u];
    var x = select(rect.x, rect.z, (corner & 1u) != 0u);
    var y = select(rect.y, rect.w, (corner & 2u) != 0u);
    if (rect.x > rect.z) {
        x = -2.0;
        y = -2.0;
    }
    return vec4<f32>(x, y, 0.5, 1.0);
}

@vertex
fn vs_cover(@builtin(vertex_index) vertex: u32) -> CoverOut {
    return CoverOut(cover_corner(vertex), vertex / 6u);
}

struct CoverFlatOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) tri: u32,
    @location(1) @interpolate(flat) p0: vec3<f32>,
    @location(2) @interpolate(flat) p1: vec3<f32>,
    @location(3) @interpolate(flat) p2: vec3<f32>,
}

@vertex
fn vs_cover_flat(@builtin(vertex_index) vertex: u32) -> CoverFlatOut {
    let tri = vertex / 6u;
    let t = eye_triangles[tri];
    return CoverFlatOut(cover_corner(vertex), tri, t.p0.xyz, t.p1.xyz, t.p2.xyz);
}
