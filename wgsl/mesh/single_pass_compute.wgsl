// Single-pass meshes, `compute` visibility: the triangles rasterised in software, one invocation
// per triangle visiting the subpixels it may cover (mesh/shared/cluster_cover.wgsl), testing
// their rays and keeping the nearest (depth, triangle) per subpixel with 64-bit atomics, as
// mesh/single_pass_atomic.wgsl does per fragment. A software rasteriser pays per primitive for
// the hardware path (setup of two triangles per rectangle); this loop pays per pixel only.
// A triangle larger than one invocation's budget is handed on where it stopped: listed for
// mesh/single_pass_compute_large.wgsl, which spreads the rest of its units over many
// invocations (the dispatch's size is counted here). mesh/single_pass_atomic_resolve.wgsl then
// shades each subpixel once.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import mesh/shared/eye_triangle.wgsl
#import mesh/shared/cover_bounds.wgsl
#import shared/view_lattice.wgsl
#import mesh/shared/cluster_cover.wgsl
#import mesh/shared/large_triangles.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/mesh_data.wgsl.
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;

@group(1) @binding(2) var<storage, read_write> eye_triangles: array<EyeTriangle>;
// The large triangles: [0] their count, then their entries (mesh/shared/large_triangles.wgsl).
@group(1) @binding(3) var<storage, read_write> large: array<atomic<u32>>;
@group(2) @binding(0) var<storage, read_write> nearest_keys: array<atomic<u64>>;
// Workgroups of the large triangles' dispatch (x, y, z), counted up here.
@group(2) @binding(1) var<storage, read_write> large_dispatch: array<atomic<u32>>;

const WORKGROUP: u32 = 64u;
// Loop iterations charged per row and per cluster before their units (crossings, span).
const ROW_COST: u32 = 8u;
const CLUSTER_COST: u32 = 8u;

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let tri = (group.y * groups.x + group.x) * WORKGROUP + local;
    if (tri >= arrayLength(&mesh_indices) / 3u) {
        return;
    }
    let p = transform_triangle(tri);
    eye_triangles[tri] = eye_triangle(p);
    let r = cover_rect(p);
    if (r.x > r.y) {
        return;
    }
    if (rect_mode()) {
        // One cluster (the default, VIEW_CLUSTERS = 1: the code below is compiled out, which
        // keeps this loop as fast as before the units) or toe-in: a rectangle within one lane's
        // budget is visited whole, a larger one handed on whole.
        if (rect_cost(r) > LANE_BUDGET) {
            hand_on(triangle_cover(tri, p, r), 0u);
            return;
        }
        let width = u32(frame.camera.viewport.x);
        for (var y = r.z; y <= r.w; y++) {
            for (var x = r.x; x <= r.y; x++) {
                for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
                    test_subpixel(vec2<u32>(x, y), c, ray_view(vec2<u32>(x, y), c), tri, p, width);
                }
            }
        }
        return;
    }
    let t = triangle_cover(tri, p, r);
    var spent = 0u;
    let per_row = t.clusters * t.chunks;
    for (var y = t.y0; y <= t.y1; y++) {
        let row_unit = (y - t.y0) * per_row;
        spent += ROW_COST;
        if (spent > LANE_BUDGET) {
            hand_on(t, row_unit);
            return;
        }
        let row = cover_row(t, y);
        for (var k = 0u; k < t.clusters; k++) {
            spent += CLUSTER_COST;
            if (spent > LANE_BUDGET) {
                hand_on(t, row_unit + k * t.chunks);
                return;
            }
            let span = cluster_span(t, row, k);
            if (span.x > span.y) {
                continue;
            }
            let first_chunk = (u32(span.x) - t.x0) / CHUNK_PX;
            let last_chunk = (u32(span.y) - t.x0) / CHUNK_PX;
            for (var chunk = first_chunk; chunk <= last_chunk; chunk++) {
                let pixels = chunk_span(t, span, chunk);
                let cost = unit_cost(u32(pixels.y - pixels.x + 1), t.clusters);
                if (spent + cost > LANE_BUDGET) {
                    hand_on(t, row_unit + k * t.chunks + chunk);
                    return;
                }
                spent += cost;
                cover_pixels(t, y, k, u32(pixels.x), u32(pixels.y));
            }
        }
    }
}

// Loop iterations of visiting rectangle r (cover_rect) whole: its rows, and per pixel its
// channels.
fn rect_cost(r: vec4<u32>) -> u32 {
    let rows = r.w - r.z + 1u;
    let width = r.y - r.x + 1u;
    // Bounded before multiplying: a rectangle wider or taller than the budget is never whole.
    if (rows > LANE_BUDGET || width > LANE_BUDGET) {
        return LANE_BUDGET + 1u;
    }
    return rows * (ROW_COST + (VIEWS_PER_PIXEL + 1u) * width);
}

// List triangle t with its units from `unit` on, and grow the large triangles' dispatch to
// cover them (workgroups: x·z of them, one per listed triangle; y per triangle's units).
fn hand_on(t: TriangleCover, unit: u32) {
    let index = atomicAdd(&large[0], 1u);
    let entry = LARGE_LIST + LARGE_ENTRY * index;
    let groups = large_groups(t, unit);
    atomicStore(&large[entry], t.tri);
    atomicStore(&large[entry + 1u], unit);
    atomicStore(&large[entry + 2u], cover_units(t));
    atomicStore(&large[entry + 3u], groups);
    atomicMax(&large_dispatch[0], min(index + 1u, MAX_WORKGROUPS));
    atomicMax(&large_dispatch[1], groups);
    atomicMax(&large_dispatch[2], index / MAX_WORKGROUPS + 1u);
}
