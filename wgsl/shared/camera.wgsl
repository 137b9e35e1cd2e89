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
    _pad0: f32,
    _pad1: f32,
    _pad2: f32,
}

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
        (uv.x - 0.5) * cam.focal_window.x,
        (0.5 - uv.y) * cam.focal_window.y,
        -cam.focal_distance,
    );
}
