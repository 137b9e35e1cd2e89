// One compare-and-swap step (k, j) of a bitonic sort of (key, value) pairs, ascending by key
// (docs/GAUSSIANS.md): thread t compares element i (bit j clear) with i + j, the direction set
// by bit k of i. The host runs k = 2, 4, … , n and for each j = k/2, … , 1.
struct SortStep {
    k: u32,
    j: u32,
    _pad0: u32,
    _pad1: u32,
}

@group(0) @binding(0) var<storage, read_write> keys: array<u32>;
@group(0) @binding(1) var<storage, read_write> values: array<u32>;
@group(0) @binding(2) var<uniform> step: SortStep;

override WORKGROUP: u32 = 256u;

@compute @workgroup_size(WORKGROUP)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let t = id.x + id.y * groups.x * WORKGROUP;
    let n = arrayLength(&keys);
    let i = 2u * step.j * (t / step.j) + (t % step.j);
    let l = i + step.j;
    if (l >= n) {
        return;
    }
    let ascending = (i & step.k) == 0u;
    let a = keys[i];
    let b = keys[l];
    if ((a > b) == ascending && a != b) {
        keys[i] = b;
        keys[l] = a;
        let v = values[i];
        values[i] = values[l];
        values[l] = v;
    }
}
