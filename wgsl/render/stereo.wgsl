// Two views (left and right eye, each a spatial target of one view everywhere) into one stereo
// image (src/render/stereo.rs): anaglyphs (colour, half-colour, Dubois least squares),
// side by side, top and bottom, and the interlaced formats of stereo monitors (rows, columns,
// checkerboard).
#import shared/frame.wgsl

// Keep in sync with `StereoUniform` in src/render/stereo.rs.
struct Stereo {
    format: u32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

@group(0) @binding(0) var left: texture_2d<f32>;
@group(0) @binding(1) var right: texture_2d<f32>;
@group(0) @binding(2) var<uniform> stereo: Stereo;

const ANAGLYPH_COLOR: u32 = 0u;
const ANAGLYPH_HALF_COLOR: u32 = 1u;
const ANAGLYPH_DUBOIS: u32 = 2u;
const SIDE_BY_SIDE: u32 = 3u;
const TOP_BOTTOM: u32 = 4u;
const ROWS: u32 = 5u;
const COLUMNS: u32 = 6u;
const CHECKERBOARD: u32 = 7u;

fn luma(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.299, 0.587, 0.114));
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let eye = textureDimensions(left);
    let composed = select(select(eye, vec2<u32>(eye.x, 2u * eye.y), stereo.format == TOP_BOTTOM),
        vec2<u32>(2u * eye.x, eye.y), stereo.format == SIDE_BY_SIDE);
    if (any(px >= composed)) {
        return vec4<f32>(0.0, 0.0, 0.0, 1.0); // the spare column or row of an odd output
    }
    switch stereo.format {
        case SIDE_BY_SIDE: {
            if (px.x < eye.x) {
                return textureLoad(left, px, 0);
            }
            return textureLoad(right, vec2<u32>(px.x - eye.x, px.y), 0);
        }
        case TOP_BOTTOM: {
            if (px.y < eye.y) {
                return textureLoad(left, px, 0);
            }
            return textureLoad(right, vec2<u32>(px.x, px.y - eye.y), 0);
        }
        case ROWS: {
            // Even rows (0, 2, …) the left eye, as line-interleaved monitors expect.
            if (px.y % 2u == 0u) {
                return textureLoad(left, px, 0);
            }
            return textureLoad(right, px, 0);
        }
        case COLUMNS: {
            if (px.x % 2u == 0u) {
                return textureLoad(left, px, 0);
            }
            return textureLoad(right, px, 0);
        }
        case CHECKERBOARD: {
            if ((px.x + px.y) % 2u == 0u) {
                return textureLoad(left, px, 0);
            }
            return textureLoad(right, px, 0);
        }
        default: {}
    }
    let l = textureLoad(left, px, 0).rgb;
    let r = textureLoad(right, px, 0).rgb;
    switch stereo.format {
        case ANAGLYPH_HALF_COLOR: {
            return vec4<f32>(luma(l), r.g, r.b, 1.0);
        }
        case ANAGLYPH_DUBOIS: {
            // Dubois's least-squares red-cyan matrices (rows: output R, G, B).
            let red = clamp(
                dot(vec3<f32>(0.456, 0.500, 0.176), l) + dot(vec3<f32>(-0.043, -0.088, -0.002), r),
                0.0,
                1.0,
            );
            let green = clamp(
                dot(vec3<f32>(-0.040, -0.038, -0.016), l) + dot(vec3<f32>(0.378, 0.734, -0.018), r),
                0.0,
                1.0,
            );
            let blue = clamp(
                dot(vec3<f32>(-0.015, -0.021, -0.005), l) + dot(vec3<f32>(-0.072, -0.113, 1.226), r),
                0.0,
                1.0,
            );
            return vec4<f32>(red, green, blue, 1.0);
        }
        default: {
            return vec4<f32>(l.r, r.g, r.b, 1.0);
        }
    }
}
