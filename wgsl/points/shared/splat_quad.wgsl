// Vertex stage of the splat geometry passes: splat vertex / 6's covering rectangle (from
// points/cover.wgsl) as two triangles; the eye-space splat travels as flat varyings.
#import points/shared/splat.wgsl

struct SplatQuadOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) centre_radius: vec4<f32>,
    @location(1) @interpolate(flat) normal: vec3<f32>,
    @location(2) @interpolate(flat) color: u32,
}

@vertex
fn vs_splat(@builtin(vertex_index) vertex: u32) -> SplatQuadOut {
    let id = vertex / 6u;
    let rect = cover_rects[id];
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex % 6u];
    var xy = vec2<f32>(
        select(rect.x, rect.z, (corner & 1u) != 0u),
        select(rect.y, rect.w, (corner & 2u) != 0u),
    );
    if (rect.x > rect.z) {
        xy = vec2<f32>(-2.0); // empty: collapses to a point the rasteriser drops
    }
    let s = eye_splats[id];
    return SplatQuadOut(vec4<f32>(xy, 0.5, 1.0), vec4<f32>(s.position, s.radius), s.normal, s.color);
}

fn quad_splat(in: SplatQuadOut) -> Splat {
    return Splat(in.centre_radius.xyz, in.centre_radius.w, in.normal, in.color);
}
