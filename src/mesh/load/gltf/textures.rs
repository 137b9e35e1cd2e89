//! glTF base-colour textures: the material's `baseColorTexture`, its sampler's wrapping and
//! magnification filter, its `TEXCOORD_n` set and `KHR_texture_transform` (an affine map of
//! the texture coordinates, applied to each vertex here: interpolation is linear, so that is
//! the same as applying it per sample). Images come from a buffer view, a `data:` URI or a
//! file beside the glTF. An image that cannot be read (a missing file, a format this build
//! does not decode) is said in the log and its primitives are drawn in their colours; an
//! index that names nothing is refused with the document ([`check_indices`]).

use std::collections::HashMap;
use std::path::Path;

use glam::{Mat3, Vec2};
use gltf::json::validation::Checked;

use crate::mesh::{Filter, Texture, Wrap};

/// How a primitive samples its texture: which of the mesh's textures, which coordinate set,
/// and the coordinates' transform.
#[derive(Clone, Copy, Debug)]
pub(super) struct Sampling {
    pub texture: u32,
    pub set: u32,
    pub transform: Mat3,
}

impl Sampling {
    /// `uv` through the texture transform.
    pub fn apply(&self, uv: [f32; 2]) -> Vec2 {
        self.transform.transform_point2(Vec2::from(uv))
    }
}

/// The textures read so far (each glTF texture once, however many primitives use it).
pub(super) struct Textures<'a> {
    root: &'a gltf::json::Root,
    buffers: &'a [std::borrow::Cow<'a, [u8]>],
    dir: Option<&'a Path>,
    path: &'a Path,
    read: HashMap<usize, Option<u32>>,
    pub list: Vec<Texture>,
}

impl<'a> Textures<'a> {
    pub fn new(
        root: &'a gltf::json::Root,
        buffers: &'a [std::borrow::Cow<'a, [u8]>],
        dir: Option<&'a Path>,
        path: &'a Path,
    ) -> Self {
        Self {
            root,
            buffers,
            dir,
            path,
            read: HashMap::new(),
            list: Vec::new(),
        }
    }

    /// How material `material` samples its base-colour texture; `None` without one, or when
    /// its image could not be read (said once in the log).
    pub fn sampling(&mut self, material: Option<usize>) -> Option<Sampling> {
        let info = self.root.materials.get(material?)?;
        let info = info.pbr_metallic_roughness.base_color_texture.as_ref()?;
        let texture = self.texture(info.index.value())?;
        let transform = info
            .extensions
            .as_ref()
            .and_then(|e| e.texture_transform.as_ref());
        Some(Sampling {
            texture,
            set: transform
                .and_then(|t| t.tex_coord)
                .unwrap_or(info.tex_coord),
            transform: transform.map_or(Mat3::IDENTITY, |t| {
                texture_transform(t.offset.0, t.rotation.0, t.scale.0)
            }),
        })
    }

    /// The mesh texture of glTF texture `index`, read on first use.
    fn texture(&mut self, index: usize) -> Option<u32> {
        if let Some(&id) = self.read.get(&index) {
            return id;
        }
        let id = match self.load(index) {
            Ok(texture) => {
                self.list.push(texture);
                Some(self.list.len() as u32 - 1)
            }
            Err(reason) => {
                log::warn!(
                    "{}: texture {index} is not shown ({reason}); its primitives are drawn in \
                     their colours",
                    self.path.display()
                );
                None
            }
        };
        self.read.insert(index, id);
        id
    }

    fn load(&self, index: usize) -> Result<Texture, String> {
        let json = &self.root.textures[index];
        let image = &self.root.images[json.source.value()];
        let (wrap, filter) = match json.sampler {
            Some(s) => sampler(&self.root.samplers[s.value()]),
            None => ([Wrap::Repeat; 2], Filter::Linear),
        };
        let name = Path::new(image.uri.as_deref().unwrap_or("")).to_path_buf();
        let bytes: Vec<u8> = match (image.buffer_view, &image.uri) {
            (Some(view), _) => {
                super::uri::view_bytes(&self.root.buffer_views[view.value()], self.buffers)
                    .ok_or("its buffer view runs past its buffer")?
                    .to_vec()
            }
            (None, Some(uri)) => super::uri::uri_data(uri, self.dir)?,
            (None, None) => return Err("its image has neither a buffer view nor a URI".into()),
        };
        let label = match name.as_os_str().is_empty() || name.starts_with("data:") {
            true => self.path.join(format!("#image{}", json.source.value())),
            false => name,
        };
        Texture::decode(&bytes, &label, wrap, filter).map_err(|e| e.to_string())
    }
}

/// KHR_texture_transform's matrix: translation · rotation · scale. The rotation's sense is the
/// one that takes the specification's worked example to the quadrant it names (tested below):
/// u' = cos·u + sin·v, v' = −sin·u + cos·v, as three.js and Babylon.js apply it.
fn texture_transform(offset: [f32; 2], rotation: f32, scale: [f32; 2]) -> Mat3 {
    let (sin, cos) = rotation.sin_cos();
    let translation =
        Mat3::from_cols_array(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, offset[0], offset[1], 1.0]);
    let rotation = Mat3::from_cols_array(&[cos, -sin, 0.0, sin, cos, 0.0, 0.0, 0.0, 1.0]);
    let scale = Mat3::from_diagonal(glam::Vec3::new(scale[0], scale[1], 1.0));
    translation * rotation * scale
}

fn sampler(json: &gltf::json::texture::Sampler) -> ([Wrap; 2], Filter) {
    use gltf::json::texture::{MagFilter, WrappingMode};
    let wrap = |mode: &Checked<WrappingMode>| match mode {
        Checked::Valid(WrappingMode::ClampToEdge) => Wrap::Clamp,
        Checked::Valid(WrappingMode::MirroredRepeat) => Wrap::Mirror,
        _ => Wrap::Repeat,
    };
    let filter = match json.mag_filter {
        Some(Checked::Valid(MagFilter::Nearest)) => Filter::Nearest,
        _ => Filter::Linear,
    };
    ([wrap(&json.wrap_s), wrap(&json.wrap_t)], filter)
}

/// Every texture, image, sampler and buffer view the base-colour textures name exists.
pub(super) fn check_indices(root: &gltf::json::Root) -> Result<(), String> {
    let exists = |i: usize, len: usize, what: &str| match i < len {
        true => Ok(()),
        false => Err(format!("{what} {i} does not exist (there are {len})")),
    };
    for m in &root.materials {
        if let Some(info) = &m.pbr_metallic_roughness.base_color_texture {
            exists(info.index.value(), root.textures.len(), "texture")?;
        }
    }
    for t in &root.textures {
        exists(t.source.value(), root.images.len(), "image")?;
        if let Some(s) = t.sampler {
            exists(s.value(), root.samplers.len(), "sampler")?;
        }
    }
    for image in &root.images {
        if let Some(view) = image.buffer_view {
            exists(view.value(), root.buffer_views.len(), "buffer view")?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_transform_takes_the_specifications_example_to_its_quadrant() {
        // KHR_texture_transform's README: offset (0, 1), rotation π/2 and scale ½ use "only
        // the lower left quadrant of the source image, rotated clockwise 90°".
        let m = texture_transform([0.0, 1.0], std::f32::consts::FRAC_PI_2, [0.5, 0.5]);
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let expected = [[0.0, 1.0], [0.0, 0.5], [0.5, 0.5], [0.5, 1.0]];
        for (c, e) in corners.iter().zip(expected) {
            let p = m.transform_point2(Vec2::from(*c));
            assert!(
                (p - Vec2::from(e)).length() < 1e-5,
                "{c:?} → {p}, not {e:?}"
            );
        }
    }
}
