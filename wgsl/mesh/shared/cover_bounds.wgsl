// Covering bounds (docs/DESIGN.md §3) of one triangle on the focal plane: y from the centre projection,
// x widened per vertex by vd·|1 − fd/d| (exact for the sheared and parallel frusta; toe-in
// cameras take the bounds of every view's projection; the paper's printed
// vd·fd/d under-covers geometry beyond 2·fd and is kept only as a measured option). Vertices
// behind the near plane are clipped first, so a triangle crossing it gets the bounds of its
// visible part. Used by mesh/single_pass_cover.wgsl and mesh/single_pass_compute.wgsl.

override PAPER_BOUNDS: bool = false;

struct Bounds {
    lo: vec2<f32>,
    hi: vec2<f32>,
}

fn extend(b: Bounds, q: vec3<f32>) -> Bounds {
    if (frame.camera.model == CAMERA_TOE_IN) {
        return extend_toe_in(b, q);
    }
    let s = frame.camera.focal_distance / -q.z;
    let centre = q.xy * s;
    var spread = max_view_offset() * abs(1.0 - s);
    if (PAPER_BOUNDS) {
        spread = max_view_offset() * s;
    }
    return Bounds(
        min(b.lo, vec2<f32>(centre.x - spread, centre.y)),
        max(b.hi, vec2<f32>(centre.x + spread, centre.y)),
    );
}

// Toe-in cameras turn, so a vertex moves in x and y from view to view, not linearly in vd:
// the bounds of its projections in every view (N is a pipeline constant). A view that sees it
// at no positive depth gets the whole image (such a triangle is near the camera plane).
fn extend_toe_in(b: Bounds, q: vec3<f32>) -> Bounds {
    var out = b;
    for (var i = 0u; i < VIEW_COUNT; i++) {
        let p = camera_project(frame.camera, q, view_offset(i));
        if (!(p.z > 0.0)) {
            let everything = 2.0 * frame.camera.focal_window;
            let centre = frame.camera.window_offset;
            return Bounds(centre - everything, centre + everything);
        }
        out = Bounds(min(out.lo, p.xy), max(out.hi, p.xy));
    }
    return out;
}

// Focal-plane bounds of the part of triangle p in front of the near plane.
fn cover_bounds(p: array<vec3<f32>, 3>) -> Bounds {
    let near = frame.camera.near;
    var b = Bounds(vec2<f32>(3.0e38), vec2<f32>(-3.0e38));
    for (var e = 0u; e < 3u; e++) {
        let a = p[e];
        let c = p[(e + 1u) % 3u];
        let da = -a.z;
        let dc = -c.z;
        if (da >= near) {
            b = extend(b, a);
        }
        if ((da >= near) != (dc >= near)) {
            b = extend(b, mix(a, c, (near - da) / (dc - da)));
        }
    }
    return b;
}

