// Multi-view camera (docs/DESIGN.md §2). Keep in sync with src/camera/gpu.rs.

struct Camera {
    eye_from_world: mat4x4<f32>,
    normal_from_world: mat4x4<f32>,
    focal_window: vec2<f32>, // W, H of the shared window on the focal plane
    focal_distance: f32,
    separation: f32,
    viewport: vec2<f32>,     // image size in pixels
    views: u32,
    near: f32,
    far: f32,
    model: u32,              // CAMERA_*
    window_offset: vec2<f32>, // the window's centre on the focal plane (a band's: off-centre)
}

// Camera models (src/camera/mod.rs `CameraModel`).
const CAMERA_SKEWED: u32 = 0u;
const CAMERA_PARALLEL: u32 = 1u;
const CAMERA_TOE_IN: u32 = 2u;

// One camera of the N-pass baseline / single view.
struct View {
    clip_from_eye: mat4x4<f32>,
    origin: vec4<f32>, // eye-space camera origin (vd, 0, 0, 1)
}

// Eye-space point on the focal plane under the pixel position `frag` (framebuffer coordinates,
// y top-down; pixel centres at +0.5).
fn camera_focal_point(cam: Camera, frag: vec2<f32>) -> vec3<f32> {
    let uv = frag / cam.viewport;
    return vec3<f32>(
        (uv.x - 0.5) * cam.focal_window.x + cam.window_offset.x,
        (0.5 - uv.y) * cam.focal_window.y + cam.window_offset.y,
        -cam.focal_distance,
    );
}

// (cos φ, sin φ) of the toe-in camera at offset `vd`, turned about +y towards (0, 0, −fd).
fn toe_in_turn(cam: Camera, vd: f32) -> vec2<f32> {
    return vec2<f32>(cam.focal_distance, vd) / length(vec2<f32>(cam.focal_distance, vd));
}

// Direction of the ray of the camera at offset `vd` through pixel position `frag` of its image,
// scaled so that the camera's own depth along it is t·fd (docs/DESIGN.md §4). Skewed and
// parallel: to the shared focal-plane point; toe-in: the centre's ray turned by φ.
fn camera_ray_direction(cam: Camera, frag: vec2<f32>, vd: f32) -> vec3<f32> {
    let x = camera_focal_point(cam, frag);
    if (cam.model == CAMERA_TOE_IN) {
        let r = toe_in_turn(cam, vd);
        return vec3<f32>(r.x * x.x + r.y * x.z, x.y, r.x * x.z - r.y * x.x);
    }
    return x - vec3<f32>(vd, 0.0, 0.0);
}

// Focal-plane coordinates, in the image of the camera at offset `vd`, of eye-space point `q`,
// and that camera's depth of it (src/camera `project_offset`).
fn camera_project(cam: Camera, q: vec3<f32>, vd: f32) -> vec3<f32> {
    if (cam.model == CAMERA_TOE_IN) {
        let r = toe_in_turn(cam, vd);
        let p = q - vec3<f32>(vd, 0.0, 0.0);
        let local = vec3<f32>(r.x * p.x - r.y * p.z, p.y, r.y * p.x + r.x * p.z);
        return vec3<f32>(local.xy * (cam.focal_distance / -local.z), -local.z);
    }
    let s = cam.focal_distance / -q.z;
    return vec3<f32>(q.x * s + vd * (1.0 - s), q.y * s, -q.z);
}
