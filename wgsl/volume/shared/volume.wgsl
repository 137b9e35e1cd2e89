// Volume data, classification and shading shared by the ray-marching and slicing stages.
#import shared/frame.wgsl

// Keep in sync with `VolumeParams` in src/volume/passes/raycast.rs.
struct VolumeParams {
    tex_from_eye: mat4x4<f32>,    // eye space → texture coordinates (box = [0, 1]³)
    normal_from_tex: mat4x4<f32>, // gradient (volume space) → eye-space normal direction
    step: f32,                    // Δ, eye-depth distance between samples
    fixed_offset: f32,            // camera offset vd when use_mask == 0
    use_mask: u32,                // 1: K views per pixel from the mask; 0: one fixed camera
    max_samples: u32,             // guard against runaway loops
    shade: u32,                   // 1: Blinn-Phong from gradients; 0: emission-absorption only
    share_tolerance: f32,         // voxels within which a pixel's rays share samples
    clip_count: u32,              // clipping planes in use (src/volume/clip.rs)
    _pad: u32,
    clip: array<vec4<f32>, 6>,    // keep texture coordinates t with xyz·t ≤ w
}

// The span [t.x, t.y] of the ray o + u·d (texture space) narrowed to the clipping planes'
// kept side (empty, x > y, where it leaves none).
fn clip_span(o: vec3<f32>, d: vec3<f32>, span: vec2<f32>) -> vec2<f32> {
    var t = span;
    for (var i = 0u; i < params.clip_count; i++) {
        let plane = params.clip[i];
        let along = dot(plane.xyz, d);
        let room = plane.w - dot(plane.xyz, o);
        if (along > 0.0) {
            t.y = min(t.y, room / along);
        } else if (along < 0.0) {
            t.x = max(t.x, room / along);
        } else if (room < 0.0) {
            return vec2<f32>(1.0, -1.0);
        }
    }
    return t;
}

// Texture coordinate t on the kept side of every clipping plane.
fn inside_clip(t: vec3<f32>) -> bool {
    for (var i = 0u; i < params.clip_count; i++) {
        let plane = params.clip[i];
        if (dot(plane.xyz, t) > plane.w) {
            return false;
        }
    }
    return true;
}

const TABLE_SIZE: f32 = 256.0;
const OPAQUE: f32 = 0.995;

// Table coordinate of scalar s (texel centres hold s = i / 255).
fn table_coord(s: f32) -> f32 {
    return (s * (TABLE_SIZE - 1.0) + 0.5) / TABLE_SIZE;
}

// Pre-integrated, shaded, premultiplied RGBA of the segment between samples `front` and `back`
// (gradient in xyz, scalar in w) whose back end is at eye-space `position`, seen from `origin`.
// Paper: C = Ia·c + Id·c·(N·L) + Is·c·(N·H)^sh, c the pre-integrated colour, N the averaged
// gradient (two-sided).
fn shaded_segment(front: vec4<f32>, back: vec4<f32>, position: vec3<f32>, origin: vec3<f32>) -> vec4<f32> {
    let seg = textureSampleLevel(preintegration, linear_clamp, vec2<f32>(table_coord(back.a), table_coord(front.a)), 0.0);
    if (params.shade == 0u || seg.a <= 0.0) {
        return seg;
    }
    let g = (params.normal_from_tex * vec4<f32>(front.xyz + back.xyz, 0.0)).xyz;
    if (dot(g, g) <= 1e-12) {
        return seg;
    }
    return vec4<f32>(seg.rgb * blinn_phong(g, position, origin), seg.a);
}

// The paper's light factor Ia + Id·(N·L) + Is·(N·H)^sh at eye-space `position` seen from
// `origin`, N the normalised −gradient `g` turned toward the eye (two-sided); nonzero `g`.
fn blinn_phong(g: vec3<f32>, position: vec3<f32>, origin: vec3<f32>) -> vec3<f32> {
    let light = frame.light;
    let to_eye = normalize(origin - position);
    var n = normalize(-g);
    if (dot(n, to_eye) < 0.0) {
        n = -n;
    }
    let h = normalize(light.direction.xyz + to_eye);
    let diffuse = max(dot(n, light.direction.xyz), 0.0);
    let specular = pow(max(dot(n, h), 0.0), light.specular.w);
    return light.ambient.rgb + light.diffuse.rgb * diffuse + light.specular.rgb * specular;
}
