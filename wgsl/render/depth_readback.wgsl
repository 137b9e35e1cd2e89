// A depth buffer copied into an R32Uint image, texel for texel (the f32 bits; GL renders to no 32-bit float
// format): adapters without
// depth-to-buffer copies (GL) read depth this way, and so does every other adapter (one path).
#import shared/frame.wgsl

// Bound as an unfilterable float texture (GLSL cannot textureLoad a depth texture).
@group(0) @binding(0) var depth: texture_2d<f32>;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<u32> {
    return vec4<u32>(bitcast<u32>(textureLoad(depth, vec2<u32>(position.xy), 0).r), 0u, 0u, 1u);
}
