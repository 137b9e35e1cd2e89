// One triangle's subpixels, visited in software by the `compute` visibility
// (mesh/single_pass_compute.wgsl, mesh/single_pass_compute_large.wgsl) in work units.
//
// View clusters (docs/DESIGN.md §3): the N views are split into C clusters of adjacent views;
// per row and cluster only the span the triangle covers in that cluster's views is visited (the
// span of the projections of its first and last view: a vertex's x is linear in the view
// offset) and, on it, only the subpixels showing a view of the cluster (shared/view_lattice.wgsl).
// C = 1 is the whole disparity range at once; C = N tests each subpixel against its own view's
// projection only. Every C tests every subpixel the triangle can cover: the result is the same.
//
// Work units: (row, cluster, chunk of CHUNK_PX columns of the covering rectangle), numbered row
// by row, cluster by cluster, chunk by chunk. Each unit's loops are bounded by its chunk, so an
// invocation can stop after a budget of units and hand the rest on: Mesa's llvmpipe (lavapipe)
// ends every loop of an invocation once 65535 iterations in all have run, which would silently
// drop the rows of a large triangle past that point.
// Reads `frame`, `nearest_keys` (the stage's bindings).

// Clusters of adjacent views; 0: chosen per triangle (`clusters_for`); 1: the covering
// rectangle, every view at once. Toe-in cameras turn, so their projections are not linear in
// the view offset: they take the rectangle.
override VIEW_CLUSTERS: u32 = 0u;
// Padding of the spans, pixels: rounding of the projections (a ray through an edge hits within
// the ray test's barycentric slack).
const SPAN_PAD_PX: f32 = 0.01;
// Columns of one work unit.
const CHUNK_PX: u32 = 64u;
// Loop iterations one batch of SIMD lanes may spend, well below llvmpipe's 65535 (the loops
// before the units, in cover_bounds and projected_polygon, take 6·N at most). llvmpipe counts
// per batch (8 lanes at 256 bits), every step of a loop while any lane is in it: lanes walking
// one flat loop of units pay the dearest unit per step (the large triangles' pass), lanes in
// the per-triangle pass's nested loops may add up, so each of those gets a share (llvmpipe's
// vectors are at most 256 bits: 8 lanes of 32 bits).
const LOOP_BUDGET: u32 = 30000u;
const LANE_BUDGET: u32 = LOOP_BUDGET / 8u;

// A triangle ready to be visited.
struct TriangleCover {
    p: array<vec3<f32>, 3>,
    poly: Polygon,
    tri: u32,
    clusters: u32,
    // Covering rectangle in pixels (inclusive), clipped to the image.
    x0: u32,
    x1: u32,
    y0: u32,
    y1: u32,
    chunks: u32, // CHUNK_PX-column chunks of the rectangle
    // Every row visits the whole rectangle with every view (one cluster: the paper's covering
    // quad; toe-in cameras, whose projections are not linear in the view offset).
    rect: bool,
    visible: bool,
}

// The covering rectangle of eye-space triangle p in pixels (inclusive, clipped to the image):
// (x0, x1, y0, y1); x0 > x1 where nothing of it is visible.
fn cover_rect(p: array<vec3<f32>, 3>) -> vec4<u32> {
    let none = vec4<u32>(1u, 0u, 1u, 0u);
    let b = cover_bounds(p);
    if (b.lo.x > b.hi.x) {
        return none; // behind the near plane
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
        return none; // outside the image
    }
    let r = vec4<u32>(
        u32(max(ceil(x_lo), 0.0)),
        u32(min(floor(x_hi), size.x - 1.0)),
        u32(max(ceil(y_lo), 0.0)),
        u32(min(floor(y_hi), size.y - 1.0)),
    );
    if (r.x > r.y || r.z > r.w) {
        return none;
    }
    return r;
}

// Whether every row visits the whole rectangle with every view: one cluster (the paper's
// covering quad), or toe-in cameras, whose projections are not linear in the view offset.
fn rect_mode() -> bool {
    return frame.camera.model == CAMERA_TOE_IN || VIEW_CLUSTERS == 1u;
}

// The cover of triangle `tri` with eye-space vertices p, within rectangle r (cover_rect).
fn triangle_cover(tri: u32, p: array<vec3<f32>, 3>, r: vec4<u32>) -> TriangleCover {
    var out: TriangleCover;
    out.p = p;
    out.tri = tri;
    out.visible = r.x <= r.y;
    if (!out.visible) {
        return out;
    }
    out.x0 = r.x;
    out.x1 = r.y;
    out.y0 = r.z;
    out.y1 = r.w;
    out.chunks = (out.x1 - out.x0) / CHUNK_PX + 1u;
    out.rect = rect_mode();
    if (out.rect) {
        out.clusters = 1u;
    } else {
        out.poly = projected_polygon(p);
        if (VIEW_CLUSTERS == 0u) {
            out.clusters = clusters_for(out.poly);
        } else {
            out.clusters = VIEW_CLUSTERS;
        }
    }
    return out;
}

fn cover_units(t: TriangleCover) -> u32 {
    return (t.y1 - t.y0 + 1u) * t.clusters * t.chunks;
}

// Loop iterations of one unit of `width` pixels at most (lattice windows and pixels per parity
// and channel, and the unit's own setup); with one cluster every pixel and channel, no windows.
fn unit_cost(width: u32, clusters: u32) -> u32 {
    let stride = mask_lattice_stride(frame.mask);
    if (clusters == 1u) {
        return 20u + (VIEWS_PER_PIXEL + 1u) * (width + 2u * stride);
    }
    return 20u + VIEWS_PER_PIXEL * (2u * width + 5u * stride);
}

// Views [v0, v1) of cluster k.
fn cluster_views(t: TriangleCover, k: u32) -> vec2<u32> {
    return vec2<u32>(k * VIEW_COUNT / t.clusters, (k + 1u) * VIEW_COUNT / t.clusters);
}

// Columns [first, last] of row y that cluster k's views may see the triangle at (last < first:
// none), clipped to the rectangle.
fn cluster_span(t: TriangleCover, row: RowCrossings, k: u32) -> vec2<i32> {
    if (t.rect) {
        return vec2<i32>(i32(t.x0), i32(t.x1));
    }
    if (row.count == 0u) {
        return vec2<i32>(1, 0);
    }
    let views = cluster_views(t, k);
    let span = row_span(row, view_offset(views.x), view_offset(views.y - 1u));
    let xl = max(ceil(span.x - SPAN_PAD_PX), f32(t.x0));
    let xr = min(floor(span.y + SPAN_PAD_PX), f32(t.x1));
    if (xl > xr) {
        return vec2<i32>(1, 0);
    }
    return vec2<i32>(i32(xl), i32(xr));
}

// Columns of chunk `chunk` within `span` (last < first: none).
fn chunk_span(t: TriangleCover, span: vec2<i32>, chunk: u32) -> vec2<i32> {
    let start = i32(t.x0 + chunk * CHUNK_PX);
    return vec2<i32>(max(span.x, start), min(span.y, start + i32(CHUNK_PX) - 1));
}

fn cover_row(t: TriangleCover, y: u32) -> RowCrossings {
    if (t.rect) {
        return RowCrossings(array<f32, 4>(), array<f32, 4>(), 0u);
    }
    return row_crossings(t.poly, f32(y));
}

// Unit `u`, whole (the other stage's units: the row is found again).
fn cover_unit(t: TriangleCover, u: u32) {
    let per_row = t.clusters * t.chunks;
    let y = t.y0 + u / per_row;
    let k = (u / t.chunks) % t.clusters;
    let span = chunk_span(t, cluster_span(t, cover_row(t, y), k), u % t.chunks);
    if (span.x <= span.y) {
        cover_pixels(t, y, k, u32(span.x), u32(span.y));
    }
}

// Pixels [first, last] of row y, the subpixels of cluster k's views.
fn cover_pixels(t: TriangleCover, y: u32, k: u32, first: u32, last: u32) {
    let width = u32(frame.camera.viewport.x);
    if (t.rect) {
        for (var x = first; x <= last; x++) {
            for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
                test_subpixel(vec2<u32>(x, y), c, ray_view(vec2<u32>(x, y), c), t.tri, t.p, width);
            }
        }
        return;
    }
    let views = cluster_views(t, k);
    let v0 = views.x;
    let v1 = views.y;
    let all_views = t.clusters == 1u;
    let stride = mask_lattice_stride(frame.mask);
    for (var parity = 0u; parity < stride && first + parity <= last; parity++) {
        let x_start = first + parity;
        let count = (last - x_start) / stride + 1u;
        for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
            var every = all_views;
            var run: LatticeRun;
            if (!every) {
                run = lattice_run(x_start, y, stride, count, c, v0, v1);
                every = run.every;
            }
            if (every) {
                for (var i = 0u; i < count; i++) {
                    test_in_cluster(vec2<u32>(x_start + i * stride, y), c, v0, v1, t.tri, t.p, width);
                }
                continue;
            }
            let windows = run_windows(run);
            for (var w = -1; w < windows - 1; w++) {
                let pixels = run_window(run, w);
                for (var i = pixels.x; i <= pixels.y; i++) {
                    test_in_cluster(vec2<u32>(x_start + u32(i) * stride, y), c, v0, v1, t.tri, t.p, width);
                }
            }
        }
    }
}

// Ray test of subpixel c of pixel px, seen from `view`; the nearest hit is kept.
fn test_subpixel(px: vec2<u32>, c: u32, view: u32, tri: u32, p: array<vec3<f32>, 3>, width: u32) {
    let centre = vec2<f32>(f32(px.x) + 0.5, f32(px.y) + 0.5);
    let hit = ray_triangle(view_ray(centre, view), p[0], p[1], p[2]);
    if (hit.x >= 0.0) {
        let depth = hit.x * frame.camera.focal_distance;
        let key = (u64(bitcast<u32>(depth)) << 32u) | u64(tri);
        atomicMax(&nearest_keys[(px.y * width + px.x) * VIEWS_PER_PIXEL + c], ~key);
    }
}

fn test_in_cluster(px: vec2<u32>, c: u32, v0: u32, v1: u32, tri: u32, p: array<vec3<f32>, 3>, width: u32) {
    let view = ray_view(px, c);
    if (view >= v0 && view < v1) {
        test_subpixel(px, c, view, tri, p, width);
    }
}

// The triangle's part in front of the near plane projected to pixel coordinates (pixel index
// units: pixel x's centre is at x): per vertex y, and x = a + b·vd in the view at offset vd.
struct Polygon {
    a: array<f32, 4>,
    b: array<f32, 4>,
    y: array<f32, 4>,
    count: u32,
}

fn projected_polygon(p: array<vec3<f32>, 3>) -> Polygon {
    let size = frame.camera.viewport;
    let scale = size / frame.camera.focal_window;
    let near = frame.camera.near;
    var out = Polygon(array<f32, 4>(), array<f32, 4>(), array<f32, 4>(), 0u);
    for (var e = 0u; e < 3u; e++) {
        let a = p[e];
        let c = p[(e + 1u) % 3u];
        let da = -a.z;
        let dc = -c.z;
        var points = array<vec3<f32>, 2>();
        var n = 0u;
        if (da >= near) {
            points[n] = a;
            n++;
        }
        if ((da >= near) != (dc >= near)) {
            points[n] = mix(a, c, (near - da) / (dc - da));
            n++;
        }
        for (var i = 0u; i < n; i++) {
            let q = points[i];
            // camera_project (shared/camera.wgsl): x = q.x·s + vd·(1 − s), y = q.y·s.
            let s = frame.camera.focal_distance / -q.z;
            out.a[out.count] = (q.x * s - frame.camera.window_offset.x) * scale.x + 0.5 * size.x - 0.5;
            out.b[out.count] = (1.0 - s) * scale.x;
            out.y[out.count] = 0.5 * size.y - (q.y * s - frame.camera.window_offset.y) * scale.y - 0.5;
            out.count++;
        }
    }
    return out;
}

// Where row y meets the polygon's edges: x = a + b·vd at each crossing (clamped to the edge, so
// a row through a vertex keeps it).
struct RowCrossings {
    a: array<f32, 4>,
    b: array<f32, 4>,
    count: u32,
}

fn row_crossings(poly: Polygon, y: f32) -> RowCrossings {
    var out = RowCrossings(array<f32, 4>(), array<f32, 4>(), 0u);
    for (var e = 0u; e < poly.count; e++) {
        let j = (e + 1u) % poly.count;
        let y0 = poly.y[e];
        let y1 = poly.y[j];
        if (y < min(y0, y1) - SPAN_PAD_PX || y > max(y0, y1) + SPAN_PAD_PX || abs(y1 - y0) < 1.0e-6) {
            continue;
        }
        let t = clamp((y - y0) / (y1 - y0), 0.0, 1.0);
        out.a[out.count] = mix(poly.a[e], poly.a[j], t);
        out.b[out.count] = mix(poly.b[e], poly.b[j], t);
        out.count++;
    }
    return out;
}

// The row's span in the views at offsets vd_first … vd_last: each crossing moves linearly with
// the offset, so the leftmost (rightmost) of the span over the views is at one of the two ends.
fn row_span(row: RowCrossings, vd_first: f32, vd_last: f32) -> vec2<f32> {
    var lo = 3.0e38;
    var hi = -3.0e38;
    for (var i = 0u; i < row.count; i++) {
        let x0 = row.a[i] + row.b[i] * vd_first;
        let x1 = row.a[i] + row.b[i] * vd_last;
        lo = min(lo, min(x0, x1));
        hi = max(hi, max(x0, x1));
    }
    return vec2<f32>(lo, hi);
}

// Cost model of the view clusters (docs/DESIGN.md §3) for a triangle w pixels wide in one view
// whose projections spread over D pixels across the views: C clusters visit about C·w + D
// pixels per row (each computing its channels' views) and ray-test K·(w + D/C) subpixels, so
// the time ≈ α·(C·w + D) + β·K·(w + D/C) + γ·C is least at C = √(β·K·D / (α·w + γ)).
const CLUSTER_VISIT_COST: f32 = 1.0;
const CLUSTER_TEST_COST: f32 = 3.0;
const CLUSTER_SETUP_COST: f32 = 4.0;

fn clusters_for(poly: Polygon) -> u32 {
    var a_lo = 3.0e38;
    var a_hi = -3.0e38;
    var b_max = 0.0;
    for (var i = 0u; i < poly.count; i++) {
        a_lo = min(a_lo, poly.a[i]);
        a_hi = max(a_hi, poly.a[i]);
        b_max = max(b_max, abs(poly.b[i]));
    }
    let w = max(a_hi - a_lo, 0.0) + 1.0;
    let spread = b_max * 2.0 * max_view_offset();
    let best = sqrt(CLUSTER_TEST_COST * f32(VIEWS_PER_PIXEL) * spread / (CLUSTER_VISIT_COST * w + CLUSTER_SETUP_COST));
    return u32(clamp(round(best), 1.0, f32(VIEW_COUNT)));
}
