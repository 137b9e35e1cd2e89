// Volumes, layered duplication: one dispatch marches every view of every pixel (z = view) into
// the layers of a texture array; the N-pass compositing follows (volume/shared/march.wgsl
// marches, the same samples as the N-pass).
#import shared/frame.wgsl
#import shared/multiview.wgsl
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
@group(2) @binding(0) var layers: texture_storage_2d_array<rgba8unorm, write>;

@compute @workgroup_size(8, 8, 1)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = vec2<u32>(frame.camera.viewport);
    if (id.x >= size.x || id.y >= size.y || id.z >= VIEW_COUNT) {
        return;
    }
    let c = ray_color(vec2<f32>(id.xy) + 0.5, view_offset(id.z));
    textureStore(layers, id.xy, id.z, over_background(c.rgb, vec3<f32>(c.a)));
}
