// Splat geometry pass, one fragment per pixel (the paper's): for each of the pixel's K rays the
// ray-splat test (Eq. 2), Gaussian weight and shading; channel c keeps its view's colour·weight
// and weight (two halves packed in a u32), and the pixel gets ONE depth — the mean of the hit
// depths — for the in-group z-test and the ε test of the compositing. Exact when K = 1 (pixel
// masks, the N-pass views, the single view).
#import points/shared/splat_quad.wgsl

// Bindings read by points/shared/splat_quad.wgsl.
@group(1) @binding(0) var<storage, read> eye_splats: array<Splat>;
// NDC rectangle (lo.xy, hi.xy) covering the splat in every camera of the pass; lo > hi: culled.
@group(1) @binding(1) var<storage, read> cover_rects: array<vec4<f32>>;
// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

struct PixelOut {
    @location(0) packed: vec4<u32>, // xyz: pack2x16float(colour_c · w_c, w_c); w: depth bits
    @builtin(frag_depth) depth: f32,
}

@fragment
fn fs_main(in: SplatQuadOut) -> PixelOut {
    let s = quad_splat(in);
    let px = vec2<u32>(in.position.xy);
    var packed = vec4<u32>(0u);
    var depth_sum = 0.0;
    var hits = 0.0;
    let rays = select(VIEWS_PER_PIXEL, 1u, params.use_mask == 0u);
    for (var c = 0u; c < rays; c++) {
        let ray = offset_ray(in.position.xy, pass_offset(px, c));
        let hit = splat_hit(ray, s);
        if (hit.weight <= 0.0) {
            continue;
        }
        let color = splat_color(s, ray, hit) * hit.weight;
        if (rays == 1u) {
            packed = vec4<u32>(
                pack2x16float(vec2<f32>(color.r, hit.weight)),
                pack2x16float(vec2<f32>(color.g, hit.weight)),
                pack2x16float(vec2<f32>(color.b, hit.weight)),
                0u,
            );
        } else {
            packed[c] = pack2x16float(vec2<f32>(color[c], hit.weight));
        }
        depth_sum += hit.depth;
        hits += 1.0;
    }
    if (hits == 0.0) {
        discard;
    }
    let depth = depth_sum / hits;
    packed.w = bitcast<u32>(depth);
    return PixelOut(packed, window_depth(depth));
}
