// 3D Gaussian splats (docs/GAUSSIANS.md): the per-view rules of graphdeco's renderer, evaluated
// for the camera at eye-space offset `vd` along x (skewed and parallel cameras: every view is
// the centre camera moved along its x axis, so eye depth and the 3D covariance in eye space are
// the same in every view; only the 2D mean, the Jacobian and the SH direction change).
// Reads `frame` (shared/frame.wgsl), `params`, `geometry` and `sh` (the stage's bindings).

// One Gaussian. Keep in sync with `GaussianGpu` in src/gaussians/scene.rs.
struct Gaussian {
    mean_opacity: vec4<f32>, // world-space mean, opacity after the sigmoid
    cov_a: vec4<f32>,        // world-space covariance xx, xy, xz, yy
    cov_b: vec4<f32>,        // yz, zz, unused, unused
}

// Per-pass constants. Keep in sync with `GaussianParams` in src/gaussians/passes/mod.rs.
struct GaussianParams {
    camera_world: vec4<f32>, // the centre camera's position, world space
    right_world: vec4<f32>,  // its unit x axis, world space (view vd sits at camera + vd·right)
    offsets: vec4<f32>,      // x, y: the cover's offset range; z: the fixed view's offset
    tile: vec4<f32>,         // xy: the view image's origin in the target (a quilt tile's)
    count: u32,              // Gaussians in the scene
    coefficients: u32,       // SH coefficients per Gaussian, (degree + 1)²
    fixed_view: u32,         // 1: every channel shows the view at offsets.z (N-pass, single view)
    color_table: u32,        // 1: the colours per Gaussian and view are in the colour table
}

// Nothing drawn past this transmittance-free opacity (graphdeco: α < 1/255 is skipped).
const MIN_ALPHA: f32 = 0.003921569;
// Largest α of one Gaussian (graphdeco).
const MAX_ALPHA: f32 = 0.99;
// Added to the 2D covariance, pixels² (graphdeco's low-pass filter).
const BLUR_PX2: f32 = 0.3;
// The Jacobian's x/z and y/z are clamped to this many half-widths of the frustum (graphdeco).
const JACOBIAN_LIMIT: f32 = 1.3;

// Real SH constants (graphdeco's forward.cu).
const SH_C0: f32 = 0.28209479177387814;
const SH_C1: f32 = 0.4886025119029199;
const SH_C2 = array<f32, 5>(1.0925484305920792, -1.0925484305920792, 0.31539156525252005,
    -1.0925484305920792, 0.5462742152960396);
const SH_C3 = array<f32, 7>(-0.5900435899266435, 2.890611442640554, -0.4570457994644658,
    0.3731763325901154, -0.4570457994644658, 1.445305721320277, -0.5900435899266435);

// Channel c of coefficient k of Gaussian i: halves packed two per word
// (src/gaussians/scene.rs).
fn sh_value(i: u32, k: u32, c: u32) -> f32 {
    let half = (i * params.coefficients + k) * 3u + c;
    let pair = unpack2x16float(sh[half >> 1u]);
    return select(pair.x, pair.y, (half & 1u) != 0u);
}

// The real SH basis up to degree 3 along unit direction `dir` (graphdeco's order and signs;
// entries past the scene's coefficients are not read).
fn sh_basis(dir: vec3<f32>) -> array<f32, 16> {
    let x = dir.x;
    let y = dir.y;
    let z = dir.z;
    let xx = x * x;
    let yy = y * y;
    let zz = z * z;
    return array<f32, 16>(
        SH_C0,
        -SH_C1 * y, SH_C1 * z, -SH_C1 * x,
        SH_C2[0] * x * y, SH_C2[1] * y * z, SH_C2[2] * (2.0 * zz - xx - yy), SH_C2[3] * x * z,
        SH_C2[4] * (xx - yy),
        SH_C3[0] * y * (3.0 * xx - yy), SH_C3[1] * x * y * z, SH_C3[2] * y * (4.0 * zz - xx - yy),
        SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy), SH_C3[4] * x * (4.0 * zz - xx - yy),
        SH_C3[5] * z * (xx - yy), SH_C3[6] * x * (xx - 3.0 * yy),
    );
}

// Channel c of Gaussian i's colour for the SH basis `basis`: the sum, + 0.5, clamped at 0.
fn sh_channel(i: u32, basis: array<f32, 16>, c: u32) -> f32 {
    var sum = 0.0;
    for (var k = 0u; k < params.coefficients; k++) {
        sum += basis[k] * sh_value(i, k, c);
    }
    return max(sum + 0.5, 0.0);
}

// `rgb` rounded to half floats, as the colour table holds it (so every method's colours agree
// bit for bit).
fn half_rgb(rgb: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(unpack2x16float(pack2x16float(rgb.rg)), unpack2x16float(pack2x16float(rgb.bb)).x);
}

// The eye-space covariance W Σ Wᵀ (W: the camera's rotation) as xx, xy, xz, yy | yz, zz.
fn eye_covariance(g: Gaussian) -> array<vec3<f32>, 2> {
    let s = mat3x3<f32>(
        vec3<f32>(g.cov_a.x, g.cov_a.y, g.cov_a.z),
        vec3<f32>(g.cov_a.y, g.cov_a.w, g.cov_b.x),
        vec3<f32>(g.cov_a.z, g.cov_b.x, g.cov_b.y),
    );
    let m = frame.camera.eye_from_world;
    let w = mat3x3<f32>(m[0].xyz, m[1].xyz, m[2].xyz);
    let e = w * s * transpose(w);
    return array<vec3<f32>, 2>(vec3<f32>(e[0][0], e[0][1], e[0][2]),
        vec3<f32>(e[1][1], e[1][2], e[2][2]));
}

// The Gaussian in the image of the camera at offset vd: its mean in pixels (y down, the
// frame's viewport), its conic (the inverse 2D covariance: a, b, c of a·dx² + 2b·dx·dy + c·dy²)
// and its radius in pixels (0: not drawn).
struct Projected {
    mean: vec2<f32>,
    cov: vec3<f32>, // the 2D covariance a, b, c (pixels², the filter added)
    conic: vec3<f32>,
    radius: f32,
}

fn project(q: vec3<f32>, cov: array<vec3<f32>, 2>, vd: f32) -> Projected {
    let cam = frame.camera;
    let p = q - vec3<f32>(vd, 0.0, 0.0);
    let tz = -p.z;
    let fd = cam.focal_distance;
    let focal = vec2<f32>(cam.viewport.x * fd / cam.focal_window.x,
        cam.viewport.y * fd / cam.focal_window.y);
    // Focal-plane position in this view's image (shared/camera.wgsl camera_project), in pixels.
    let on_plane = vec2<f32>(p.x * fd / tz + vd, p.y * fd / tz);
    let uv = (on_plane - cam.window_offset) / cam.focal_window;
    let mean = vec2<f32>((uv.x + 0.5) * cam.viewport.x, (0.5 - uv.y) * cam.viewport.y);
    // Graphdeco clamps x/z and y/z to 1.3 half-widths of the frustum about its axis; a skewed
    // view's frustum is centred on the window's centre seen from (vd, 0, 0).
    let centre = vec2<f32>(cam.window_offset.x - vd, cam.window_offset.y) / fd;
    let half = 0.5 * cam.focal_window / fd;
    let t = clamp(p.xy / tz, centre - JACOBIAN_LIMIT * half, centre + JACOBIAN_LIMIT * half);
    // J = ∂(u, v)/∂(x, y, z) in eye space (v grows downwards), rows as vectors.
    let j0 = vec3<f32>(focal.x / tz, 0.0, focal.x * t.x / tz);
    let j1 = vec3<f32>(0.0, -focal.y / tz, -focal.y * t.y / tz);
    let s = mat3x3<f32>(
        vec3<f32>(cov[0].x, cov[0].y, cov[0].z),
        vec3<f32>(cov[0].y, cov[1].x, cov[1].y),
        vec3<f32>(cov[0].z, cov[1].y, cov[1].z),
    );
    let sj0 = s * j0;
    let sj1 = s * j1;
    let a = dot(j0, sj0) + BLUR_PX2;
    let b = dot(j0, sj1);
    let c = dot(j1, sj1) + BLUR_PX2;
    let det = a * c - b * b;
    if (!(det > 0.0) || !(tz > 0.0)) {
        return Projected(mean, vec3<f32>(a, b, c), vec3<f32>(0.0), 0.0);
    }
    let mid = 0.5 * (a + c);
    let lambda = mid + sqrt(max(0.1, mid * mid - det));
    return Projected(mean, vec3<f32>(a, b, c), vec3<f32>(c, -b, a) / det, ceil(3.0 * sqrt(lambda)));
}

// α of a projected Gaussian at pixel position `px` (graphdeco: inside the 3σ square, the
// exponent not positive, α ≥ 1/255).
fn splat_alpha(g: Projected, opacity: f32, px: vec2<f32>) -> f32 {
    let d = px - g.mean;
    if (g.radius <= 0.0 || any(abs(d) > vec2<f32>(g.radius))) {
        return 0.0;
    }
    let power = -0.5 * (g.conic.x * d.x * d.x + g.conic.z * d.y * d.y) - g.conic.y * d.x * d.y;
    if (power > 0.0) {
        return 0.0;
    }
    let alpha = min(MAX_ALPHA, opacity * exp(power));
    return select(0.0, alpha, alpha >= MIN_ALPHA);
}

// Unit world direction from the camera at offset vd to the world point `mean`.
fn view_direction(mean: vec3<f32>, vd: f32) -> vec3<f32> {
    let centre = params.camera_world.xyz + vd * params.right_world.xyz;
    return normalize(mean - centre);
}
