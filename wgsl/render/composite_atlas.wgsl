// Compositing from a quilt atlas (the tiled method's, or a quilt image read from a file):
// I(x, y, c) = tile_view(x,y,c)(x, y, c) with the display mask. Tiles of another size than the
// panel are sampled nearest (quilts from files) or, with `quilt.bilinear` (the view images of
// `--view-scale`), up-sampled bilinearly within the tile (shared/upsample.wgsl).
#import shared/frame.wgsl
#import shared/quilt.wgsl
#import shared/upsample.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var atlas: texture_2d<f32>;
@group(1) @binding(1) var<uniform> quilt: Quilt;

fn tile_texel(view: u32, px: vec2<u32>) -> vec4<f32> {
    if (quilt.bilinear == 0u || all(quilt.tile == quilt.panel)) {
        return textureLoad(atlas, quilt_texel(quilt, view, px, quilt.panel), 0);
    }
    let o = quilt_tile_origin(quilt, view);
    let b = bilinear_at(px, quilt.panel, quilt.tile);
    return bilinear_mix(
        b,
        textureLoad(atlas, o + b.lo, 0),
        textureLoad(atlas, o + vec2<u32>(b.hi.x, b.lo.y), 0),
        textureLoad(atlas, o + vec2<u32>(b.lo.x, b.hi.y), 0),
        textureLoad(atlas, o + b.hi, 0),
    );
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let v = mask_views(frame.mask, px);
    return vec4<f32>(tile_texel(v.x, px).r, tile_texel(v.y, px).g, tile_texel(v.z, px).b, 1.0);
}
