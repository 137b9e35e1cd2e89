// Sample sharing among a pixel's K rays (`--share-samples TAU`, src/volume/scene.rs
// `share_samples`): an approximation of the exact single pass (volume/raycast.wgsl).
//
// On sample plane k (eye depth k·Δ) ray r samples P_r(k) = o_r + k·(Δ/fd)·d_r, linear in k, so
// two rays' samples are |A + k·B| apart (voxels) and the planes where every pair is within TAU
// form one interval around the focal plane, where the views converge. There the K rays take
// the samples of their mean ray instead of their own: one march instead of K. Outside it each
// ray marches its own samples, so per-channel α stays exact there. Front-to-back compositing
// is associative, so a ray's colour is its own front range, then the shared range, then its
// own back range, each marched by `march_planes` (volume/shared/march.wgsl) and composited.
//
// Reads `frame`, `volume`, `params` (and what march.wgsl reads).

// The plane interval (x ≤ k ≤ y) where samples of rays a and b (texture-space origins and
// directions) lie within `tau` voxels; empty (x > y) where they never do.
fn planes_within(oa: vec3<f32>, da: vec3<f32>, ob: vec3<f32>, db: vec3<f32>, tau: f32) -> vec2<f32> {
    let voxels = vec3<f32>(textureDimensions(volume));
    let a = (oa - ob) * voxels;
    let b = (da - db) * voxels * (params.step / frame.camera.focal_distance);
    let bb = dot(b, b);
    let ab = dot(a, b);
    let c = dot(a, a) - tau * tau;
    if (bb <= 1e-20) {
        // Parallel rays: the same distance on every plane.
        return select(vec2<f32>(1.0, -1.0), vec2<f32>(-ALL_PLANES, ALL_PLANES), c <= 0.0);
    }
    let disc = ab * ab - bb * c;
    if (disc < 0.0) {
        return vec2<f32>(1.0, -1.0);
    }
    let r = sqrt(disc);
    return vec2<f32>((-ab - r) / bb, (-ab + r) / bb);
}

// What is left to reach OPAQUE behind opacity `a`: a range composited behind `a` may stop
// once its own opacity reaches this, as the exact march stops at OPAQUE in all.
fn opaque_behind(a: f32) -> f32 {
    return 1.0 - (1.0 - OPAQUE) / max(1.0 - a, 1e-6);
}

// Colour (per channel) and α (per channel) of pixel centre `frag`'s K rays, sharing samples
// where they lie within params.share_tolerance voxels of each other.
fn shared_rays(px: vec2<u32>, frag: vec2<f32>) -> array<vec4<f32>, 3> {
    var origins: array<vec3<f32>, 3>;
    var dirs: array<vec3<f32>, 3>;
    var tex_o: array<vec3<f32>, 3>;
    var tex_d: array<vec3<f32>, 3>;
    var mean_o = vec3<f32>(0.0);
    var mean_d = vec3<f32>(0.0);
    for (var k = 0u; k < VIEWS_PER_PIXEL; k++) {
        let vd = view_offset(ray_view(px, k));
        origins[k] = vec3<f32>(vd, 0.0, 0.0);
        dirs[k] = camera_ray_direction(frame.camera, frag, vd);
        tex_o[k] = (params.tex_from_eye * vec4<f32>(origins[k], 1.0)).xyz;
        tex_d[k] = (params.tex_from_eye * vec4<f32>(dirs[k], 0.0)).xyz;
        mean_o += origins[k] / f32(VIEWS_PER_PIXEL);
        mean_d += dirs[k] / f32(VIEWS_PER_PIXEL);
    }
    var span = vec2<f32>(-ALL_PLANES, ALL_PLANES);
    for (var a = 0u; a < VIEWS_PER_PIXEL; a++) {
        for (var b = a + 1u; b < VIEWS_PER_PIXEL; b++) {
            let s = planes_within(tex_o[a], tex_d[a], tex_o[b], tex_d[b], params.share_tolerance);
            span = vec2<f32>(max(span.x, s.x), min(span.y, s.y));
        }
    }
    var acc: array<vec4<f32>, 3>;
    let first = ceil(span.x);
    let last = floor(span.y);
    if (!(last > first)) {
        // No whole segment to share: the exact rays.
        for (var k = 0u; k < VIEWS_PER_PIXEL; k++) {
            acc[k] = march(origins[k], dirs[k]);
        }
        return acc;
    }
    let share = true;
    // The phases, marched by one `march_planes` (one copy of the loop in the compiled kernel):
    // 0 … K−1 each ray's front range, K the shared range (marched until every ray would be
    // opaque), K+1 … 2K each ray's back range while it is not opaque.
    for (var phase = 0u; phase <= 2u * VIEWS_PER_PIXEL; phase++) {
        var o = mean_o;
        var d = mean_d;
        var planes = vec2<f32>(first, last);
        var opaque = OPAQUE;
        let ray = select(phase - VIEWS_PER_PIXEL - 1u, phase, phase < VIEWS_PER_PIXEL);
        if (phase < VIEWS_PER_PIXEL) {
            o = origins[ray];
            d = dirs[ray];
            planes = vec2<f32>(-ALL_PLANES, first);
        } else if (phase == VIEWS_PER_PIXEL) {
            let least_opaque = min(min(acc[0].a, acc[1].a), acc[2].a);
            if (!share || least_opaque >= OPAQUE) {
                continue;
            }
            opaque = opaque_behind(least_opaque);
        } else {
            if (!share || acc[ray].a >= OPAQUE) {
                continue;
            }
            o = origins[ray];
            d = dirs[ray];
            planes = vec2<f32>(last, ALL_PLANES);
            opaque = opaque_behind(acc[ray].a);
        }
        let c = march_planes(o, d, planes, opaque);
        if (phase == VIEWS_PER_PIXEL) {
            for (var k = 0u; k < VIEWS_PER_PIXEL; k++) {
                acc[k] = over(acc[k], c);
            }
        } else {
            acc[ray] = over(acc[ray], c);
        }
    }
    return acc;
}
