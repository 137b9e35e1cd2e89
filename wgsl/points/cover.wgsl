// Covering quads of splats (docs/DESIGN.md §3), one invocation per splat: the eye-space splat and the
// NDC rectangle covering its disk for every camera offset in [cover_lo, cover_hi]
// (points/shared/cover_rect.wgsl).
#import points/shared/splat.wgsl
#import points/shared/cover_rect.wgsl

// Bindings read by points/shared/splat.wgsl.
@group(2) @binding(0) var<uniform> params: SplatParams;
// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var<storage, read> splats: array<Splat>;
@group(1) @binding(1) var<storage, read_write> eye_splats: array<Splat>;
@group(1) @binding(2) var<storage, read_write> cover_rects: array<vec4<f32>>;

const WORKGROUP: u32 = 64u;

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let id = (group.y * groups.x + group.x) * WORKGROUP + local;
    if (id >= arrayLength(&cover_rects)) {
        return;
    }
    let s = splats[id];
    let centre = (frame.camera.eye_from_world * vec4<f32>(s.position, 1.0)).xyz;
    var normal = (frame.camera.normal_from_world * vec4<f32>(s.normal, 0.0)).xyz;
    let len = length(normal);
    normal = select(vec3<f32>(0.0, 0.0, 1.0), normal / len, len > 0.0);
    eye_splats[id] = Splat(centre, s.radius, normal, s.color);
    if (!valid_radius(s.radius) || any(centre != centre)) {
        cover_rects[id] = EMPTY;
        return;
    }
    cover_rects[id] = splat_cover_rect(centre, s.radius, normal, params.cover_lo, params.cover_hi);
}
