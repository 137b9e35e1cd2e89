// Volumes, tiled duplication: one dispatch marches every view of every pixel (z = view) into
// the view's tile of a quilt atlas; the atlas compositing follows (volume/shared/march.wgsl
// marches, the same samples as the N-pass).
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/quilt.wgsl
#import volume/shared/volume.wgsl
#import volume/shared/march.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by volume/shared/volume.wgsl.
@group(1) @binding(0) var volume: texture_3d<f32>;
@group(1) @binding(1) var linear_clamp: sampler;
@group(1) @binding(2) var preintegration: texture_2d<f32>;
@group(1) @binding(3) var<uniform> params: VolumeParams;

@group(1) @binding(4) var empty_distance: texture_3d<u32>;
@group(2) @binding(0) var atlas: texture_storage_2d<rgba8unorm, write>;
@group(2) @binding(1) var<uniform> quilt: Quilt;

@compute @workgroup_size(8, 8, 1)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = vec2<u32>(frame.camera.viewport);
    if (id.x >= size.x || id.y >= size.y || id.z >= VIEW_COUNT) {
        return;
    }
    let c = ray_color(vec2<f32>(id.xy) + 0.5, view_offset(id.z));
    let texel = quilt_tile_origin(quilt, id.z) + id.xy;
    textureStore(atlas, texel, over_background(c.rgb, vec3<f32>(c.a)));
}
