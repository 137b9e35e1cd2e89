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

// Keep in sync with `VolumeParams` in src/render/volume_raycast.rs.
struct VolumeParams {
    tex_from_eye: mat4x4<f32>,    // eye space → texture coordinates (box = [0, 1]³)
    normal_from_tex: mat4x4<f32>, // gradient (volume space) → eye-space normal direction
    step: f32,                    // Δ, eye-depth distance between samples
    fixed_offset: f32,            // camera offset vd when use_mask == 0
    use_mask: u32,                // 1: K views per pixel from the mask; 0: one fixed camera
    max_samples: u32,             // guard against runaway loops
    shade: u32,                   // 1: Blinn-Phong from gradients; 0: emission-absorption only
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

@group(1) @binding(0) var volume: texture_3d<f32>;
@group(1) @binding(1) var linear_clamp: sampler;
@group(1) @binding(2) var preintegration: texture_2d<f32>;
@group(1) @binding(3) var<uniform> params: VolumeParams;
@group(2) @binding(0) var output: texture_storage_2d<rgba8unorm, write>;

const TABLE_SIZE: f32 = 256.0;
const OPAQUE: f32 = 0.995;

// Table coordinate of scalar s (texel centres hold s = i / 255).
fn table_coord(s: f32) -> f32 {
    return (s * (TABLE_SIZE - 1.0) + 0.5) / TABLE_SIZE;
}

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
        let seg = textureSampleLevel(preintegration, linear_clamp, vec2<f32>(table_coord(back.a), table_coord(front.a)), 0.0);
        var rgb = seg.rgb;
        if (params.shade == 1u && seg.a > 0.0) {
            let g = (params.normal_from_tex * vec4<f32>(front.xyz + back.xyz, 0.0)).xyz;
            if (dot(g, g) > 1e-12) {
                let position = origin + (depth / fd) * dir;
                // Paper: C = Ia·c + Id·c·(N·L) + Is·c·(N·H)^sh, c the pre-integrated colour.
                let light = frame.light;
                let to_eye = normalize(origin - position);
                var n = normalize(-g);
                if (dot(n, to_eye) < 0.0) {
                    n = -n;
                }
                let h = normalize(light.direction.xyz + to_eye);
                let diffuse = max(dot(n, light.direction.xyz), 0.0);
                let specular = pow(max(dot(n, h), 0.0), light.specular.w);
                rgb = seg.rgb * (light.ambient.rgb + light.diffuse.rgb * diffuse + light.specular.rgb * specular);
            }
        }
        acc = vec4<f32>(acc.rgb + (1.0 - acc.a) * rgb, acc.a + (1.0 - acc.a) * seg.a);
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
