//! GPU forms of the camera. Keep in sync with `wgsl/shared/camera.wgsl`.

use bytemuck::{Pod, Zeroable};
use glam::{Mat3, Mat4};

use super::MultiViewCamera;

/// Camera constants shared by every pipeline (group 0).
/// Keep in sync with `struct Camera` in `wgsl/shared/camera.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct CameraUniform {
    /// World → centre eye space.
    pub eye_from_world: [[f32; 4]; 4],
    /// Inverse-transpose of the upper 3×3 of `eye_from_world`, padded to 4×4.
    pub normal_from_world: [[f32; 4]; 4],
    /// Focal window size (W, H).
    pub focal_window: [f32; 2],
    /// fd.
    pub focal_distance: f32,
    /// e.
    pub separation: f32,
    /// Image size in pixels.
    pub viewport: [f32; 2],
    /// N.
    pub views: u32,
    /// Near distance.
    pub near: f32,
    /// Far distance.
    pub far: f32,
    /// The camera model (`CAMERA_*` in `wgsl/shared/camera.wgsl`).
    pub model: u32,
    /// The window's centre on the focal plane (`MultiViewCamera::window_offset`).
    pub window_offset: [f32; 2],
}
const _: () = assert!(std::mem::size_of::<CameraUniform>() == 176);
crate::shader::gpu_layout!(
    CameraUniform,
    "Camera",
    [
        eye_from_world,
        normal_from_world,
        focal_window,
        focal_distance,
        separation,
        viewport,
        views,
        near,
        far,
        model,
        window_offset
    ]
);

impl CameraUniform {
    pub(super) fn new(c: &MultiViewCamera, size: [u32; 2]) -> Self {
        let normal = Mat3::from_mat4(c.eye_from_world).inverse().transpose();
        Self {
            eye_from_world: c.eye_from_world.to_cols_array_2d(),
            normal_from_world: Mat4::from_mat3(normal).to_cols_array_2d(),
            focal_window: c.focal_window().to_array(),
            focal_distance: c.focal_distance,
            separation: c.separation,
            viewport: [size[0] as f32, size[1] as f32],
            views: c.views,
            near: c.near,
            far: c.far,
            model: c.model.gpu(),
            window_offset: c.window_offset.to_array(),
        }
    }
}

/// One camera of the N-pass baseline (or the single view).
/// Keep in sync with `struct View` in `wgsl/shared/camera.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct ViewUniform {
    /// Eye space → clip space of this camera (includes the −vd translation).
    pub clip_from_eye: [[f32; 4]; 4],
    /// Eye-space origin of this camera (vd, 0, 0, 1).
    pub origin: [f32; 4],
}
const _: () = assert!(std::mem::size_of::<ViewUniform>() == 80);
crate::shader::gpu_layout!(ViewUniform, "View", [clip_from_eye, origin]);

impl ViewUniform {
    pub(super) fn new(clip_from_eye: Mat4, vd: f32) -> Self {
        Self {
            clip_from_eye: clip_from_eye.to_cols_array_2d(),
            origin: [vd, 0.0, 0.0, 1.0],
        }
    }
}
