// Splat geometry pass, one fragment per pixel (the paper's): for each of the pixel's K rays the
// ray-splat test (Eq. 2), Gaussian weight and shading; channel c keeps its view's colour·weight
// and weight (two halves packed in a u32), and the pixel gets ONE depth — the mean of the hit
// depths — for the in-group z-test and the ε test of the compositing. Exact when K = 1 (pixel
// masks, the N-pass views, the single view).
#import points/shared/splat_quad.wgsl
#import points/shared/ray_sample.wgsl

// Bindings read by points/shared/splat_quad.wgsl.
@group(1) @binding(0) var<storage, read> eye_splats: array<Splat>;
// NDC rectangle (lo.xy, hi.xy) covering the splat in every camera of the pass; lo > hi: culled.
@group(1) @binding(1) var<storage, read> cover_rects: array<vec4<f32>>;
// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@fragment
fn fs_main(in: SplatQuadOut) -> PixelOut {
    let s = quad_splat(in);
    let px = vec2<u32>(in.position.xy);
    var packed = vec4<u32>(0u);
    var depth_sum = 0.0;
    var hits = 0.0;
    let rays = select(VIEWS_PER_PIXEL, 1u, params.use_mask == 0u);
    for (var c = 0u; c < rays; c++) {
        let r = ray_sample(s, in.position.xy, pass_offset(px, c));
        if (r.weight <= 0.0) {
            continue;
        }
        if (rays == 1u) {
            packed = one_ray_texel(r).packed;
        } else {
            packed[c] = pack2x16float(vec2<f32>(r.color[c], r.weight));
        }
        depth_sum += r.depth;
        hits += 1.0;
    }
    if (hits == 0.0) {
        discard;
    }
    let depth = depth_sum / hits;
    packed.w = bitcast<u32>(depth);
    return PixelOut(packed, window_depth(depth));
}
