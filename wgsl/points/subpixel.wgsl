// Splat geometry pass, `exact` depth: the covering quads are rasterised at subpixel resolution
// (K·W × H), so each fragment is one ray — subpixel c = x mod K of pixel x / K — with its own
// depth for the in-group z-test and the ε test of the compositing.
#import points/shared/splat_quad.wgsl

// Bindings read by points/shared/splat_quad.wgsl.
@group(1) @binding(0) var<storage, read> eye_splats: array<Splat>;
// NDC rectangle (lo.xy, hi.xy) covering the splat in every camera of the pass; lo > hi: culled.
@group(1) @binding(1) var<storage, read> cover_rects: array<vec4<f32>>;
// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

struct SubpixelOut {
    @location(0) packed: vec2<u32>, // x: pack2x16float(colour_c · w, w); y: depth bits
    @builtin(frag_depth) depth: f32,
}

@fragment
fn fs_main(in: SplatQuadOut) -> SubpixelOut {
    let s = quad_splat(in);
    let column = u32(in.position.x);
    let px = vec2<u32>(column / VIEWS_PER_PIXEL, u32(in.position.y));
    let c = column % VIEWS_PER_PIXEL;
    let centre = vec2<f32>(f32(px.x) + 0.5, in.position.y);
    let ray = offset_ray(centre, pass_offset(px, c));
    let hit = splat_hit(ray, s);
    if (hit.weight <= 0.0) {
        discard;
    }
    let color = splat_color(s, ray, hit) * hit.weight;
    let packed = vec2<u32>(pack2x16float(vec2<f32>(color[c], hit.weight)), bitcast<u32>(hit.depth));
    return SubpixelOut(packed, window_depth(hit.depth));
}
