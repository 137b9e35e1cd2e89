// Volumes, compute path: one invocation per pixel marches the rays of the pixel's K views
// (or, for the N-pass baseline and the single view, one ray from a fixed camera) through the
// volume box, front to back with early termination, classified by the pre-integration table
// (Engel et al. 2001) and Blinn-Phong shaded from the averaged Sobel gradients (paper §3.5.1).
//
// Samples sit on the eye-depth planes d = k·Δ shared by every view (the view-aligned slices of
// the paper), so a single-pass ray and the N-pass ray of the same view and pixel take the same
// samples: the two methods differ only in which views they evaluate per pixel.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/volume.wgsl

@group(2) @binding(0) var output: texture_storage_2d<rgba8unorm, write>;

// Premultiplied RGBA along the ray origin + t·dir (eye depth t·fd).
fn march(origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    let fd = frame.camera.focal_distance;
    let o = (params.tex_from_eye * vec4<f32>(origin, 1.0)).xyz;
    let d = (params.tex_from_eye * vec4<f32>(dir, 0.0)).xyz;
    // Slab test against [0, 1]³ (IEEE division: axis-parallel rays give ±inf, handled by min/max).
    let inv = 1.0 / d;
    let a = (vec3<f32>(0.0) - o) * inv;
    let b = (vec3<f32>(1.0) - o) * inv;
    let t_in = max(max(min(a.x, b.x), min(a.y, b.y)), min(a.z, b.z));
    let t_out = min(min(max(a.x, b.x), max(a.y, b.y)), max(a.z, b.z));
    let d_in = max(t_in * fd, frame.camera.near);
    let d_out = min(t_out * fd, frame.camera.far);
    if (!(d_out > d_in)) {
        return vec4<f32>(0.0);
    }
    let k0 = ceil(d_in / params.step);
    let k1 = floor(d_out / params.step);
    let count = min(u32(max(k1 - k0, 0.0)), params.max_samples);
    var front = textureSampleLevel(volume, linear_clamp, o + (k0 * params.step / fd) * d, 0.0);
    var acc = vec4<f32>(0.0);
    for (var i = 1u; i <= count; i++) {
        let depth = (k0 + f32(i)) * params.step;
        let back = textureSampleLevel(volume, linear_clamp, o + (depth / fd) * d, 0.0);
        let seg = shaded_segment(front, back, origin + (depth / fd) * dir, origin);
        acc = vec4<f32>(acc.rgb + (1.0 - acc.a) * seg.rgb, acc.a + (1.0 - acc.a) * seg.a);
        if (acc.a >= OPAQUE) {
            break;
        }
        front = back;
    }
    return acc;
}

fn ray_color(frag: vec2<f32>, offset: f32) -> vec4<f32> {
    let x = camera_focal_point(frame.camera, frag);
    let o = vec3<f32>(offset, 0.0, 0.0);
    return march(o, x - o);
}

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
    // Exact per channel: each subpixel is composited over the background with its own α.
    let rgb = color + (vec3<f32>(1.0) - alpha) * frame.background.rgb;
    textureStore(output, px, vec4<f32>(rgb, 1.0));
}
