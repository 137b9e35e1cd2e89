// The large triangles of the `compute` visibility: those one invocation of
// mesh/single_pass_compute.wgsl could not finish within its loop budget
// (mesh/shared/cluster_cover.wgsl), listed with the first unit left, and the workgroups of
// mesh/single_pass_compute_large.wgsl that finish them (64 invocations each, every invocation
// taking at most `units_per_invocation` units).

// Where the entries start in the list buffer ([0] is their count): per large triangle its
// index, its first unit left, its units and its workgroups (`large_groups`), so that the
// invocations with nothing to do stop before setting the triangle up.
const LARGE_LIST: u32 = 4u;
const LARGE_ENTRY: u32 = 4u;
// Most workgroups along one dimension of a dispatch (wgpu's default limit).
const MAX_WORKGROUPS: u32 = 65535u;
const LARGE_WORKGROUP: u32 = 64u;

fn units_per_invocation(t: TriangleCover) -> u32 {
    return LOOP_BUDGET / (unit_cost(CHUNK_PX, t.clusters) + 20u);
}

// Workgroups finishing t from unit `unit` on (at most MAX_WORKGROUPS: then an invocation
// takes more units than its budget, over 10⁹ units, beyond any image wgpu can make).
fn large_groups(t: TriangleCover, unit: u32) -> u32 {
    let left = cover_units(t) - unit;
    let invocations = (left + units_per_invocation(t) - 1u) / units_per_invocation(t);
    return clamp((invocations + LARGE_WORKGROUP - 1u) / LARGE_WORKGROUP, 1u, MAX_WORKGROUPS);
}
