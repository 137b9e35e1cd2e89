// Volumes, compute path: one invocation per pixel marches the rays of the pixel's K views
// (or, for the N-pass baseline and the single view, one ray from a fixed camera) and writes
// the spatial image (volume/shared/march.wgsl marches).
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import volume/shared/volume.wgsl
#import volume/shared/march.wgsl
#import volume/shared/share.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by volume/shared/volume.wgsl.
@group(1) @binding(0) var volume: texture_3d<f32>;
@group(1) @binding(1) var linear_clamp: sampler;
@group(1) @binding(2) var preintegration: texture_2d<f32>;
@group(1) @binding(3) var<uniform> params: VolumeParams;

@group(1) @binding(4) var empty_distance: texture_3d<u32>;
@group(2) @binding(0) var output: texture_storage_2d<rgba8unorm, write>;

// The K rays share samples near the focal plane (volume/shared/share.wgsl); compiled in only
// for `--share-samples` above 0, so the exact path is unchanged.
override SHARE_SAMPLES: bool = false;

@compute @workgroup_size(8, 8)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = vec2<u32>(frame.camera.viewport);
    if (id.x >= size.x || id.y >= size.y) {
        return;
    }
    let px = id.xy;
    let frag = vec2<f32>(px) + 0.5;
    var color = vec3<f32>(0.0);
    var alpha = vec3<f32>(0.0);
    if (params.use_mask == 0u) {
        let c = ray_color(frag, params.fixed_offset);
        color = c.rgb;
        alpha = vec3<f32>(c.a);
    } else if (SHARE_SAMPLES && VIEWS_PER_PIXEL == 3u) {
        let rays = shared_rays(px, frag);
        for (var k = 0u; k < 3u; k++) {
            color[k] = rays[k][k];
            alpha[k] = rays[k].a;
        }
    } else {
        for (var k = 0u; k < VIEWS_PER_PIXEL; k++) {
            let c = ray_color(frag, view_offset(ray_view(px, k)));
            if (VIEWS_PER_PIXEL == 1u) {
                color = c.rgb;
                alpha = vec3<f32>(c.a);
            } else {
                color[k] = c[k];
                alpha[k] = c.a;
            }
        }
    }
    textureStore(output, px, over_background(color, alpha));
}
