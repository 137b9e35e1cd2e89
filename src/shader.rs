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

/// Shared WGSL, by import path: frame-level code in `shared/`, each primitive's own in
/// `PRIMITIVE/shared/`. Shared files hold types, constants and functions, never bindings.
const SHARED: &[(&str, &str)] = &[
    wgsl!("shared/camera.wgsl"),
    wgsl!("shared/mask.wgsl"),
    wgsl!("shared/shading.wgsl"),
    wgsl!("shared/frame.wgsl"),
    wgsl!("shared/multiview.wgsl"),
    wgsl!("shared/ray.wgsl"),
    wgsl!("shared/quilt.wgsl"),
    wgsl!("shared/view_lattice.wgsl"),
    wgsl!("warp/shared/warp.wgsl"),
    wgsl!("warp/shared/row_warp.wgsl"),
    wgsl!("mesh/shared/mesh_data.wgsl"),
    wgsl!("mesh/shared/eye_triangle.wgsl"),
    wgsl!("mesh/shared/cover_bounds.wgsl"),
    wgsl!("mesh/shared/cover_data.wgsl"),
    wgsl!("mesh/shared/cover.wgsl"),
    wgsl!("mesh/shared/texture.wgsl"),
    wgsl!("mesh/shared/shade_hit.wgsl"),
    wgsl!("mesh/shared/resolve.wgsl"),
    wgsl!("mesh/shared/view_vertex.wgsl"),
    wgsl!("mesh/shared/tiled_vertex.wgsl"),
    wgsl!("mesh/shared/cluster_cover.wgsl"),
    wgsl!("mesh/shared/large_triangles.wgsl"),
    wgsl!("volume/shared/volume.wgsl"),
    wgsl!("volume/shared/march.wgsl"),
    wgsl!("volume/shared/share.wgsl"),
    wgsl!("points/shared/splat.wgsl"),
    wgsl!("points/shared/splat_quad.wgsl"),
    wgsl!("points/shared/cover_rect.wgsl"),
    wgsl!("points/shared/ray_sample.wgsl"),
    wgsl!("points/shared/view_quad.wgsl"),
    wgsl!("shared/upsample.wgsl"),
    wgsl!("gaussians/shared/gaussian.wgsl"),
];

/// One WGSL file per pipeline stage, by path under `wgsl/`: `render/` for the frame-level
/// passes, `PRIMITIVE/` for each primitive's, named after the Rust module that drives them.
/// Each declares every `@group/@binding` it uses at its top.
pub const STAGES: &[(&str, &str)] = &[
    wgsl!("render/mask_image.wgsl"),
    wgsl!("mesh/npass.wgsl"),
    wgsl!("mesh/tiled.wgsl"),
    wgsl!("mesh/tiled_discard.wgsl"),
    wgsl!("mesh/layered.wgsl"),
    wgsl!("mesh/mrt.wgsl"),
    wgsl!("render/composite.wgsl"),
    wgsl!("render/composite_atlas.wgsl"),
    wgsl!("render/camera_crop.wgsl"),
    wgsl!("warp/rgbd.wgsl"),
    wgsl!("warp/references.wgsl"),
    wgsl!("warp/row_bounds.wgsl"),
    wgsl!("render/depth_readback.wgsl"),
    wgsl!("render/output.wgsl"),
    wgsl!("render/stereo.wgsl"),
    wgsl!("gpu/storage_fence.wgsl"),
    wgsl!("mesh/single_pass_cover.wgsl"),
    wgsl!("mesh/single_pass_fast.wgsl"),
    wgsl!("mesh/single_pass_exact.wgsl"),
    wgsl!("mesh/single_pass_exact_resolve.wgsl"),
    wgsl!("mesh/single_pass_atomic.wgsl"),
    wgsl!("mesh/single_pass_atomic_resolve.wgsl"),
    wgsl!("mesh/single_pass_compute.wgsl"),
    wgsl!("mesh/single_pass_compute_large.wgsl"),
    wgsl!("volume/raycast.wgsl"),
    wgsl!("volume/raycast_layered.wgsl"),
    wgsl!("volume/raycast_tiled.wgsl"),
    wgsl!("volume/raycast_reference.wgsl"),
    wgsl!("volume/slices.wgsl"),
    wgsl!("points/cover.wgsl"),
    wgsl!("points/pixel.wgsl"),
    wgsl!("points/subpixel.wgsl"),
    wgsl!("points/composite.wgsl"),
    wgsl!("points/tiled.wgsl"),
    wgsl!("points/layered.wgsl"),
    wgsl!("gaussians/splat.wgsl"),
    wgsl!("render/accumulation_resolve.wgsl"),
    wgsl!("gaussians/sort_keys.wgsl"),
    wgsl!("gaussians/sort_step.wgsl"),
    wgsl!("gaussians/colors.wgsl"),
];

/// The byte layout of a `#[repr(C)]` Rust struct that mirrors WGSL struct `wgsl`: its size and
/// the offset of each named (non-padding) field. The naga layout test compares it with the
/// offsets naga computes for the WGSL struct, member by member and by name.
#[derive(Debug)]
pub struct GpuLayout {
    /// The WGSL struct's name.
    pub wgsl: &'static str,
    /// `size_of` the Rust struct.
    pub size: usize,
    /// (field name, byte offset); padding fields left out.
    pub fields: &'static [(&'static str, usize)],
}

/// `impl Type { pub const GPU_LAYOUT: GpuLayout }` from the field list, with `offset_of!`, in
/// the module that defines `Type` (private fields are visible there).
macro_rules! gpu_layout {
    ($ty:ty, $wgsl:literal, [$($field:ident),* $(,)?]) => {
        impl $ty {
            /// Byte layout, checked against the WGSL struct by `src/shader.rs`'s tests.
            #[allow(dead_code)]
            pub(crate) const GPU_LAYOUT: $crate::shader::GpuLayout = $crate::shader::GpuLayout {
                wgsl: $wgsl,
                size: ::std::mem::size_of::<$ty>(),
                fields: &[$((stringify!($field), ::std::mem::offset_of!($ty, $field))),*],
            };
        }
    };
}
pub(crate) use gpu_layout;

fn lookup(table: &[(&str, &'static str)], name: &str) -> Option<&'static str> {
    table.iter().find(|(n, _)| *n == name).map(|(_, s)| *s)
}

/// The stage `name` (e.g. `"render/composite.wgsl"`) with its imports resolved.
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
        fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
            for entry in std::fs::read_dir(dir).unwrap() {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    walk(&path, out);
                } else if path.extension().is_some_and(|e| e == "wgsl") {
                    out.push(path);
                }
            }
        }
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("wgsl");
        let mut on_disk = Vec::new();
        walk(&root, &mut on_disk);
        assert!(on_disk.len() >= SHARED.len() + STAGES.len());
        for path in on_disk {
            let file = path
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            assert!(
                SHARED.iter().chain(STAGES).any(|(name, _)| *name == file),
                "wgsl/{file} is not listed in src/shader.rs"
            );
        }
    }

    /// Shared files hold only types, constants and functions: bindings live in the stages.
    #[test]
    fn shared_files_declare_no_bindings() {
        for (name, source) in SHARED {
            for line in source.lines() {
                assert!(
                    !line.trim_start().starts_with("@group"),
                    "wgsl/{name} declares a binding: {line}"
                );
            }
        }
    }

    #[test]
    fn imports_are_inserted_once_and_enables_hoisted() {
        let text = compose("render/composite.wgsl").unwrap();
        assert_eq!(text.matches("struct DisplayMask").count(), 1);
        assert!(!text.contains("#import"));
    }

    /// Every Rust struct that mirrors a WGSL struct has naga's size and, member by member and
    /// by name, naga's offsets (padding members, named `_…`, excepted).
    #[test]
    fn gpu_struct_layouts_match_rust() {
        let cases: &[(&str, GpuLayout)] = &[
            ("mesh/npass.wgsl", crate::camera::CameraUniform::GPU_LAYOUT),
            ("mesh/npass.wgsl", crate::camera::ViewUniform::GPU_LAYOUT),
            ("mesh/npass.wgsl", crate::display::MaskUniform::GPU_LAYOUT),
            ("mesh/npass.wgsl", crate::frame::LightUniform::GPU_LAYOUT),
            ("mesh/npass.wgsl", crate::frame::FrameUniform::GPU_LAYOUT),
            (
                "mesh/npass.wgsl",
                crate::mesh::texture_buffers::GpuTexture::GPU_LAYOUT,
            ),
            (
                "mesh/mrt.wgsl",
                crate::mesh::passes::duplicate::ViewBatch::GPU_LAYOUT,
            ),
            (
                "render/composite.wgsl",
                crate::render::composite::CompositeUniform::GPU_LAYOUT,
            ),
            (
                "render/composite_atlas.wgsl",
                crate::render::quilt::QuiltUniform::GPU_LAYOUT,
            ),
            (
                "warp/rgbd.wgsl",
                crate::warp::uniform::WarpUniform::GPU_LAYOUT,
            ),
            (
                "render/stereo.wgsl",
                crate::render::stereo::StereoUniform::GPU_LAYOUT,
            ),
            (
                "warp/references.wgsl",
                crate::warp::uniform::WarpUniform::GPU_LAYOUT,
            ),
            (
                "mesh/single_pass_compute.wgsl",
                crate::mesh::GpuVertex::GPU_LAYOUT,
            ),
            (
                "volume/raycast.wgsl",
                crate::volume::passes::VolumeParams::GPU_LAYOUT,
            ),
            (
                "volume/slices.wgsl",
                crate::volume::passes::slices::SLICE_LAYOUT,
            ),
            ("points/cover.wgsl", crate::points::GpuSplat::GPU_LAYOUT),
            (
                "points/composite.wgsl",
                crate::points::passes::SplatParams::GPU_LAYOUT,
            ),
            (
                "gaussians/splat.wgsl",
                crate::gaussians::scene::GaussianGpu::GPU_LAYOUT,
            ),
            (
                "gaussians/splat.wgsl",
                crate::gaussians::passes::GAUSSIAN_PARAMS_LAYOUT,
            ),
            (
                "gaussians/sort_step.wgsl",
                crate::gaussians::passes::SORT_STEP_LAYOUT,
            ),
        ];
        // Buffers of WGSL structs that have no Rust mirror: their per-element size.
        let module = validate("mesh/single_pass_cover.wgsl").unwrap();
        let mut layouter = naga::proc::Layouter::default();
        layouter.update(module.to_ctx()).unwrap();
        let (eye_triangle, _) = module
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some("EyeTriangle"))
            .expect("struct EyeTriangle");
        assert_eq!(
            layouter[eye_triangle].size as u64,
            crate::mesh::passes::single_pass::EYE_TRIANGLE_BYTES
        );
        for (stage, rust) in cases {
            let module = validate(stage).unwrap();
            let mut layouter = naga::proc::Layouter::default();
            layouter.update(module.to_ctx()).unwrap();
            let (handle, ty) = module
                .types
                .iter()
                .find(|(_, t)| t.name.as_deref() == Some(rust.wgsl))
                .unwrap_or_else(|| panic!("struct {} in {stage}", rust.wgsl));
            assert_eq!(
                layouter[handle].size as usize, rust.size,
                "size of {}",
                rust.wgsl
            );
            let naga::TypeInner::Struct { members, .. } = &ty.inner else {
                panic!("{} is not a struct", rust.wgsl);
            };
            let wgsl: Vec<(&str, usize)> = members
                .iter()
                .filter_map(|m| Some((m.name.as_deref()?, m.offset as usize)))
                .filter(|(name, _)| !name.starts_with('_'))
                .collect();
            assert_eq!(wgsl, rust.fields, "members of {} ({stage})", rust.wgsl);
        }
    }
}
