// Single-pass meshes, `compute` visibility: the covering rectangles are rasterised in software,
// one invocation per triangle looping over the pixel centres of its rectangle, testing the K
// subpixel rays and keeping the nearest (depth, triangle) per subpixel with 64-bit atomics, as
// mesh/single_pass_atomic.wgsl does per fragment. A software rasteriser pays per primitive for
// the hardware path (setup of two triangles per rectangle); this loop pays per pixel only.
// mesh/single_pass_atomic_resolve.wgsl then shades each subpixel once.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import mesh/shared/eye_triangle.wgsl
#import mesh/shared/cover_bounds.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/mesh_data.wgsl.
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;

@group(1) @binding(2) var<storage, read_write> eye_triangles: array<EyeTriangle>;
@group(2) @binding(0) var<storage, read_write> nearest_keys: array<atomic<u64>>;

const WORKGROUP: u32 = 64u;

@compute @workgroup_size(64)
fn cs_main(@builtin(workgroup_id) group: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let tri = (group.y * groups.x + group.x) * WORKGROUP + local;
    if (tri >= arrayLength(&mesh_indices) / 3u) {
        return;
    }
    let p = transform_triangle(tri);
    eye_triangles[tri] = eye_triangle(p);
    let b = cover_bounds(p);
    if (b.lo.x > b.hi.x) {
        return; // behind the near plane
    }
    // Focal-plane bounds → the pixels whose centre (x + ½, y + ½) lies inside (y top-down).
    let size = frame.camera.viewport;
    let scale = size / frame.camera.focal_window;
    let lo = b.lo - frame.camera.window_offset;
    let hi = b.hi - frame.camera.window_offset;
    let x_lo = (lo.x * scale.x + 0.5 * size.x) - 0.5;
    let x_hi = (hi.x * scale.x + 0.5 * size.x) - 0.5;
    let y_lo = (0.5 * size.y - hi.y * scale.y) - 0.5;
    let y_hi = (0.5 * size.y - lo.y * scale.y) - 0.5;
    if (x_hi < 0.0 || y_hi < 0.0 || x_lo > size.x - 1.0 || y_lo > size.y - 1.0) {
        return; // outside the image
    }
    let x0 = u32(max(ceil(x_lo), 0.0));
    let x1 = u32(min(floor(x_hi), size.x - 1.0));
    let y0 = u32(max(ceil(y_lo), 0.0));
    let y1 = u32(min(floor(y_hi), size.y - 1.0));
    let width = u32(size.x);
    for (var y = y0; y <= y1; y++) {
        for (var x = x0; x <= x1; x++) {
            let px = vec2<u32>(x, y);
            let centre = vec2<f32>(f32(x) + 0.5, f32(y) + 0.5);
            for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
                let ray = view_ray(centre, ray_view(px, c));
                let hit = ray_triangle(ray, p[0], p[1], p[2]);
                if (hit.x >= 0.0) {
                    let depth = hit.x * frame.camera.focal_distance;
                    let key = (u64(bitcast<u32>(depth)) << 32u) | u64(tri);
                    atomicMax(&nearest_keys[(y * width + x) * VIEWS_PER_PIXEL + c], ~key);
                }
            }
        }
    }
}
