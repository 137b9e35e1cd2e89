// One ray's sample of a splat in a geometry pass (points/pixel.wgsl per ray, the duplication
// methods' points/tiled.wgsl and points/layered.wgsl for their one ray per fragment).

// A group-image texel and its depth: xyz pack2x16float(colour_c · w_c, w_c), w the depth bits.
struct PixelOut {
    @location(0) packed: vec4<u32>,
    @builtin(frag_depth) depth: f32,
}

// Colour·weight, weight and hit depth of splat `s` on the ray of camera offset `offset` through
// framebuffer position `frag`; weight 0: a miss.
struct RaySample {
    color: vec3<f32>,
    weight: f32,
    depth: f32,
}

fn ray_sample(s: Splat, frag: vec2<f32>, offset: f32) -> RaySample {
    let ray = offset_ray(frag, offset);
    let hit = splat_hit(ray, s);
    if (hit.weight <= 0.0) {
        return RaySample(vec3<f32>(0.0), 0.0, 0.0);
    }
    return RaySample(splat_color(s, ray, hit) * hit.weight, hit.weight, hit.depth);
}

// The texel of a hit that is every channel's (one ray per pixel).
fn one_ray_texel(r: RaySample) -> PixelOut {
    let packed = vec4<u32>(
        pack2x16float(vec2<f32>(r.color.r, r.weight)),
        pack2x16float(vec2<f32>(r.color.g, r.weight)),
        pack2x16float(vec2<f32>(r.color.b, r.weight)),
        bitcast<u32>(r.depth),
    );
    return PixelOut(packed, window_depth(r.depth));
}
