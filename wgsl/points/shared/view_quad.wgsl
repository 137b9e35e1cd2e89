// The duplication methods' splat quads: corner `vertex % 6` of splat `vertex / 6`'s covering
// rectangle for one camera, computed per copy (the vertex stage projects every view's copy, as
// engines that duplicate geometry do) and clipped to that view's image. Reads `eye_splats`.

struct ViewQuadOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) centre_radius: vec4<f32>,
    @location(1) @interpolate(flat) normal: vec3<f32>,
    @location(2) @interpolate(flat) color: u32,
    @location(3) @interpolate(flat) view: u32,
}

// The view's NDC position of the corner (z = 0.5, w = 1), or OFF_TARGET for an empty quad.
fn view_quad_corner(vertex: u32, view: u32) -> vec4<f32> {
    let s = eye_splats[vertex / 6u];
    var rect = EMPTY;
    if (valid_radius(s.radius) && all(s.position == s.position)) {
        let vd = view_offset(view);
        rect = splat_cover_rect(s.position, s.radius, s.normal, vd, vd);
    }
    // The rasteriser would clip to the view's image; here the copy must not reach a neighbour.
    rect = vec4<f32>(max(rect.xy, vec2<f32>(-1.0)), min(rect.zw, vec2<f32>(1.0)));
    if (rect.x > rect.z || rect.y > rect.w) {
        return OFF_TARGET;
    }
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex % 6u];
    let xy = vec2<f32>(
        select(rect.x, rect.z, (corner & 1u) != 0u),
        select(rect.y, rect.w, (corner & 2u) != 0u),
    );
    return vec4<f32>(xy, 0.5, 1.0);
}

// Outside every clip volume: an empty quad's six corners all land here, a zero-area triangle
// the rasteriser drops.
const OFF_TARGET: vec4<f32> = vec4<f32>(-4.0, -4.0, 0.5, 1.0);

fn view_quad_out(position: vec4<f32>, vertex: u32, view: u32) -> ViewQuadOut {
    let s = eye_splats[vertex / 6u];
    return ViewQuadOut(position, vec4<f32>(s.position, s.radius), s.normal, s.color, view);
}

fn view_quad_splat(in: ViewQuadOut) -> Splat {
    return Splat(in.centre_radius.xyz, in.centre_radius.w, in.normal, in.color);
}
