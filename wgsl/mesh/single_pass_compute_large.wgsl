// Single-pass meshes, `compute` visibility, the large triangles: those
// mesh/single_pass_compute.wgsl listed (mesh/shared/large_triangles.wgsl) are finished here,
// their units from the first one left spread over many invocations, each within the loop budget
// (mesh/shared/cluster_cover.wgsl). Dispatched indirectly: x·z workgroups over the listed
// triangles, y over each one's units.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import mesh/shared/eye_triangle.wgsl
#import mesh/shared/cover_bounds.wgsl
#import shared/view_lattice.wgsl
#import mesh/shared/cluster_cover.wgsl
#import mesh/shared/large_triangles.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/mesh_data.wgsl (imported with the eye triangles; unused here).
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;
// Eye-space triangles, written by mesh/single_pass_compute.wgsl.
@group(1) @binding(2) var<storage, read> eye_triangles: array<EyeTriangle>;
// [0] the count, then the entries (mesh/shared/large_triangles.wgsl).
@group(1) @binding(3) var<storage, read> large: array<u32>;
@group(2) @binding(0) var<storage, read_write> nearest_keys: array<atomic<u64>>;

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let index = group.z * MAX_WORKGROUPS + group.x;
    if (index >= large[0]) {
        return;
    }
    let entry = LARGE_LIST + LARGE_ENTRY * index;
    let tri = large[entry];
    let first = large[entry + 1u];
    let units = large[entry + 2u];
    let groups = large[entry + 3u];
    // Units first + i, first + i + S, … for invocation i of S.
    let invocations = groups * LARGE_WORKGROUP;
    let start = first + group.y * LARGE_WORKGROUP + local;
    if (group.y >= groups || start >= units) {
        return;
    }
    let e = eye_triangles[tri];
    let p = array<vec3<f32>, 3>(e.p0.xyz, e.p1.xyz, e.p2.xyz);
    let t = triangle_cover(tri, p, cover_rect(p));
    for (var u = start; u < units; u += invocations) {
        cover_unit(t, u);
    }
}
