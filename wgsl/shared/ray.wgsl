// Per-subpixel rays (docs/DESIGN.md §4): from view origin O_i = (vd_i, 0, 0) through the pixel centre
// X on the focal plane. With D = X − O_i the ray is O_i + t·D and the eye depth is t·fd.

struct Ray {
    origin: vec3<f32>,
    direction: vec3<f32>,
}

fn view_ray(frag: vec2<f32>, view: u32) -> Ray {
    let vd = view_offset(view);
    return Ray(vec3<f32>(vd, 0.0, 0.0), camera_ray_direction(frame.camera, frag, vd));
}

// Barycentric slack so that rays through an edge shared by two triangles hit at least one of
// them (float Möller–Trumbore is not watertight; the rasteriser's fixed-point edge test is).
const BARY_EPS: f32 = 1e-6;

// Möller–Trumbore (paper Eq. 3). Returns (t, u, v); t < 0 means no hit. NaN-safe: degenerate
// triangles (det = 0 or non-finite results) never hit.
fn ray_triangle(ray: Ray, p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    let miss = vec3<f32>(-1.0, 0.0, 0.0);
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let pv = cross(ray.direction, e2);
    let det = dot(e1, pv);
    if (det == 0.0) {
        return miss;
    }
    let inv = 1.0 / det;
    let s = ray.origin - p0;
    let u = dot(s, pv) * inv;
    if (!(u >= -BARY_EPS && u <= 1.0 + BARY_EPS)) {
        return miss;
    }
    let q = cross(s, e1);
    let v = dot(ray.direction, q) * inv;
    if (!(v >= -BARY_EPS && u + v <= 1.0 + BARY_EPS)) {
        return miss;
    }
    let t = dot(e2, q) * inv;
    // Only what lies between the near and far planes is visible, as in the N-pass baseline.
    let depth = t * frame.camera.focal_distance;
    if (!(depth >= frame.camera.near && depth <= frame.camera.far)) {
        return miss;
    }
    return vec3<f32>(t, u, v);
}

// Window depth (0..1) of eye depth d, as the off-axis projection produces it (src/camera).
fn window_depth(d: f32) -> f32 {
    let n = frame.camera.near;
    let f = frame.camera.far;
    return f * (d - n) / ((f - n) * d);
}
