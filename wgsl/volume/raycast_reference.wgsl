// Volumes as a warp's reference views (src/warp): one dispatch marches every reference view of
// every pixel (z = reference) with the N-pass's samples, writing the colour and the nearness
// fd / d (as bits) of the ray's representative depth d (volume/shared/march.wgsl, TRACK_DEPTH).
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
@group(2) @binding(0) var colors: texture_storage_2d_array<rgba8unorm, write>;
@group(2) @binding(1) var nearness: texture_storage_2d_array<r32uint, write>;

@compute @workgroup_size(8, 8, 1)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = vec2<u32>(frame.camera.viewport);
    if (id.x >= size.x || id.y >= size.y || id.z >= VIEW_COUNT) {
        return;
    }
    half_depth = 0.0;
    weighted_depth = vec2<f32>(0.0);
    let c = ray_color(vec2<f32>(id.xy) + 0.5, view_offset(id.z));
    textureStore(colors, id.xy, id.z, over_background(c.rgb, vec3<f32>(c.a)));
    let d = representative_depth();
    let n = select(0.0, frame.camera.focal_distance / d, d > 0.0);
    textureStore(nearness, id.xy, id.z, vec4<u32>(bitcast<u32>(n), 0u, 0u, 0u));
}
