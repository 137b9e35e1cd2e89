// Bilinear up-sampling of a view image of `src` texels onto a `dst`-pixel image (the view
// images of `--view-scale`, src ≤ dst). Pixel centres map onto each other, texels are clamped
// to the image (no bleeding across quilt tiles); tests/view_scale.rs holds the CPU copy.

struct Bilinear {
    lo: vec2<u32>,     // texel at or left of / above the sample point
    hi: vec2<u32>,     // its right / lower neighbour (clamped)
    weight: vec2<f32>, // share of `hi` in x and y
}

fn bilinear_at(px: vec2<u32>, dst: vec2<u32>, src: vec2<u32>) -> Bilinear {
    let p = (vec2<f32>(px) + 0.5) * vec2<f32>(src) / vec2<f32>(dst) - 0.5;
    let f = floor(p);
    let last = vec2<f32>(src - 1u);
    let lo = clamp(f, vec2<f32>(0.0), last);
    let hi = clamp(f + 1.0, vec2<f32>(0.0), last);
    return Bilinear(vec2<u32>(lo), vec2<u32>(hi), p - f);
}

// The four texels (lo.x lo.y, hi.x lo.y, lo.x hi.y, hi.x hi.y) blended.
fn bilinear_mix(b: Bilinear, t00: vec4<f32>, t10: vec4<f32>, t01: vec4<f32>, t11: vec4<f32>) -> vec4<f32> {
    return mix(mix(t00, t10, b.weight.x), mix(t01, t11, b.weight.x), b.weight.y);
}
