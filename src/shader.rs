//! WGSL sources and their tiny composition step.
//!
//! A stage file pulls shared code with `#import shared/NAME.wgsl` lines; each shared file is
//! inserted once, depth first, and `enable` directives are hoisted to the top (WGSL wants them
//! first). Nothing else is rewritten, so error line numbers map back by eye.

use std::collections::HashSet;

use crate::error::{Error, Result};

/// `(path, contents)` of a file under `wgsl/`.
macro_rules! wgsl {
    ($path:literal) => {
        ($path, include_str!(concat!("../wgsl/", $path)))
    };
}

/// Shared WGSL, by import path.
const SHARED: &[(&str, &str)] = &[
    wgsl!("shared/camera.wgsl"),
    wgsl!("shared/mask.wgsl"),
    wgsl!("shared/shading.wgsl"),
    wgsl!("shared/frame.wgsl"),
    wgsl!("shared/multiview.wgsl"),
    wgsl!("shared/ray.wgsl"),
    wgsl!("shared/mesh_data.wgsl"),
    wgsl!("shared/eye_triangle.wgsl"),
    wgsl!("shared/cover_bounds.wgsl"),
    wgsl!("shared/cover_data.wgsl"),
    wgsl!("shared/cover.wgsl"),
    wgsl!("shared/resolve.wgsl"),
    wgsl!("shared/volume.wgsl"),
    wgsl!("shared/splat.wgsl"),
    wgsl!("shared/splat_quad.wgsl"),
];

/// One WGSL file per pipeline stage, by file name.
pub const STAGES: &[(&str, &str)] = &[
    wgsl!("mask_image.wgsl"),
    wgsl!("mesh_view.wgsl"),
    wgsl!("composite.wgsl"),
    wgsl!("mesh_cover.wgsl"),
    wgsl!("mesh_single_pass_fast.wgsl"),
    wgsl!("mesh_single_pass_subpixel.wgsl"),
    wgsl!("mesh_single_pass_subpixel_resolve.wgsl"),
    wgsl!("mesh_single_pass_atomic.wgsl"),
    wgsl!("mesh_single_pass_atomic_resolve.wgsl"),
    wgsl!("mesh_single_pass_compute.wgsl"),
    wgsl!("volume_raycast.wgsl"),
    wgsl!("volume_slices.wgsl"),
    wgsl!("volume_slices_resolve.wgsl"),
    wgsl!("splat_cover.wgsl"),
    wgsl!("splat_pixel.wgsl"),
    wgsl!("splat_subpixel.wgsl"),
    wgsl!("splat_composite.wgsl"),
];

fn lookup(table: &[(&str, &'static str)], name: &str) -> Option<&'static str> {
    table.iter().find(|(n, _)| *n == name).map(|(_, s)| *s)
}

/// The stage `name` (e.g. `"composite.wgsl"`) with its imports resolved.
pub fn compose(name: &str) -> Result<String> {
    let source = lookup(STAGES, name).ok_or_else(|| shader_error(name, "no such stage"))?;
    let mut enables = Vec::new();
    let mut body = String::new();
    let mut seen = HashSet::new();
    expand(name, source, &mut seen, &mut enables, &mut body)?;
    let mut out = enables.join("\n");
    out.push('\n');
    out.push_str(&body);
    Ok(out)
}

fn expand(
    name: &str,
    source: &str,
    seen: &mut HashSet<String>,
    enables: &mut Vec<String>,
    out: &mut String,
) -> Result<()> {
    for line in source.lines() {
        let trimmed = line.trim();
        if let Some(path) = trimmed.strip_prefix("#import ") {
            let path = path.trim();
            if seen.insert(path.to_string()) {
                let shared = lookup(SHARED, path)
                    .ok_or_else(|| shader_error(name, &format!("unknown import '{path}'")))?;
                expand(path, shared, seen, enables, out)?;
            }
        } else if trimmed.starts_with("enable ") {
            if !enables.iter().any(|e| e == trimmed) {
                enables.push(trimmed.to_string());
            }
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    Ok(())
}

fn shader_error(name: &str, message: &str) -> Error {
    Error::Gpu {
        operation: format!("composing shader {name}"),
        message: message.to_string(),
    }
}

/// Create the shader module for stage `name`.
pub fn module(device: &wgpu::Device, name: &str) -> Result<wgpu::ShaderModule> {
    let source = compose(name)?;
    Ok(device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(name),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    }))
}

/// Parse and validate a composed stage with naga (no GPU needed).
pub fn validate(name: &str) -> Result<naga::Module> {
    let source = compose(name)?;
    let module = naga::front::wgsl::parse_str(&source)
        .map_err(|e| shader_error(name, &e.emit_to_string(&source)))?;
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .map_err(|e| shader_error(name, &format!("{e:?}")))?;
    Ok(module)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_stage_validates_with_naga() {
        for (name, _) in STAGES {
            if let Err(e) = validate(name) {
                panic!("{e}");
            }
        }
    }

    /// Every file under wgsl/ is registered, so none escapes naga validation.
    #[test]
    fn every_wgsl_file_is_registered() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("wgsl");
        let mut on_disk = Vec::new();
        for dir in [root.clone(), root.join("shared")] {
            for entry in std::fs::read_dir(&dir).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "wgsl") {
                    let rel = path
                        .strip_prefix(&root)
                        .unwrap()
                        .to_string_lossy()
                        .replace('\\', "/");
                    on_disk.push(rel);
                }
            }
        }
        for file in on_disk {
            assert!(
                SHARED.iter().chain(STAGES).any(|(name, _)| *name == file),
                "wgsl/{file} is not listed in src/shader.rs"
            );
        }
    }

    #[test]
    fn imports_are_inserted_once_and_enables_hoisted() {
        let text = compose("composite.wgsl").unwrap();
        assert_eq!(text.matches("struct DisplayMask").count(), 1);
        assert!(!text.contains("#import"));
    }

    /// Struct sizes seen by naga equal the Rust `#[repr(C)]` sizes.
    #[test]
    fn gpu_struct_layouts_match_rust() {
        /// Size naga computes for struct `name` of stage `stage`.
        fn wgsl_size(stage: &str, name: &str) -> usize {
            let module = validate(stage).unwrap();
            let mut layouter = naga::proc::Layouter::default();
            layouter.update(module.to_ctx()).unwrap();
            let (handle, _) = module
                .types
                .iter()
                .find(|(_, t)| t.name.as_deref() == Some(name))
                .unwrap_or_else(|| panic!("type {name} in {stage}"));
            layouter[handle].size as usize
        }
        use std::mem::size_of as rs;
        let mesh = |name| wgsl_size("mesh_view.wgsl", name);
        assert_eq!(mesh("Camera"), rs::<crate::camera::CameraUniform>());
        assert_eq!(mesh("View"), rs::<crate::camera::ViewUniform>());
        assert_eq!(mesh("DisplayMask"), rs::<crate::display::MaskUniform>());
        assert_eq!(mesh("Light"), rs::<crate::frame::LightUniform>());
        assert_eq!(mesh("Frame"), rs::<crate::frame::FrameUniform>());
        assert_eq!(
            wgsl_size("mesh_single_pass_compute.wgsl", "MeshVertex"),
            rs::<crate::mesh::GpuVertex>()
        );
        assert_eq!(
            wgsl_size("volume_raycast.wgsl", "VolumeParams"),
            rs::<crate::render::VolumeParams>()
        );
        assert_eq!(
            wgsl_size("splat_cover.wgsl", "Splat"),
            rs::<crate::points::GpuSplat>()
        );
        assert_eq!(
            wgsl_size("splat_composite.wgsl", "SplatParams"),
            rs::<crate::render::splat::SplatParams>()
        );
    }
}
