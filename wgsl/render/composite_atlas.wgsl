// Compositing from a quilt atlas (the tiled method's, or a quilt image read from a file):
// I(x, y, c) = tile_view(x,y,c)(x, y, c) with the display mask.
#import shared/frame.wgsl
#import shared/quilt.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var atlas: texture_2d<f32>;
@group(1) @binding(1) var<uniform> quilt: Quilt;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let panel = vec2<u32>(frame.camera.viewport);
    let v = mask_views(frame.mask, px);
    return vec4<f32>(
        textureLoad(atlas, quilt_texel(quilt, v.x, px, panel), 0).r,
        textureLoad(atlas, quilt_texel(quilt, v.y, px, panel), 0).g,
        textureLoad(atlas, quilt_texel(quilt, v.z, px, panel), 0).b,
        1.0,
    );
}
