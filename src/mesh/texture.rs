//! Base-colour textures of a mesh: the images, how they wrap and filter, and how each method
//! samples them (`wgsl/mesh/shared/texture.wgsl`: the same texels, the same bilinear filter,
//! for the single pass's ray hits and the rasterised baselines alike).
//!
//! No mipmaps: the single pass shades a ray hit, not a fragment with screen-space derivatives,
//! so a level of detail would have to come from ray differentials; every method samples the
//! full-resolution image, so they stay equal to each other (a texture much finer than the
//! screen aliases in all of them alike).

use std::path::Path;

use crate::error::{Error, Result};

/// The texture index of a vertex that has none ([`super::Mesh::texture_ids`]).
pub const NO_TEXTURE: u32 = u32::MAX;

/// Most texels a mesh's textures hold together: 32 M (128 MiB of RGBA8, the storage-binding
/// limit of wgpu's default limits, where the shaders read them).
pub const MAX_TEXELS: u64 = 1 << 25;

/// How a texture coordinate outside 0..1 is mapped back into the image (glTF's sampler
/// `wrapS`/`wrapT`; OBJ's `-clamp on`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    /// The image tiles the plane (glTF's default, and OBJ's).
    #[default]
    Repeat,
    /// The edge texels extend.
    Clamp,
    /// The image tiles, every other copy mirrored.
    Mirror,
}

/// How a texture is sampled between texel centres (glTF's sampler `magFilter`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Filter {
    /// The nearest texel.
    Nearest,
    /// Bilinear between the four nearest texel centres, in linear colour (glTF's default).
    #[default]
    Linear,
}

/// One base-colour texture: an sRGB-encoded image (alpha is not drawn: meshes are opaque)
/// that multiplies the vertex colours of the triangles that use it.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Where it came from (a file name, or "texture N" of a glTF), for messages.
    pub name: String,
    /// The texels; texture coordinate (0, 0) is the image's top-left corner, (1, 1) its
    /// bottom-right (glTF's convention; the OBJ reader flips its v).
    pub image: image::RgbaImage,
    /// Wrapping along u (x) and v (y).
    pub wrap: [Wrap; 2],
    /// Filtering.
    pub filter: Filter,
}

impl Texture {
    /// A texture from an image file's bytes (PNG; JPEG with the `jpeg` feature), decoded after
    /// its size passed the image and memory checks; `path` names it in errors.
    pub fn decode(bytes: &[u8], path: &Path, wrap: [Wrap; 2], filter: Filter) -> Result<Self> {
        let image = crate::image_io::decode_bytes(bytes, path)?.to_rgba8();
        Ok(Self {
            name: path.display().to_string(),
            image,
            wrap,
            filter,
        })
    }

    /// Texels of the image.
    pub fn texels(&self) -> u64 {
        u64::from(self.image.width()) * u64::from(self.image.height())
    }
}

/// The textures of a mesh together hold at most [`MAX_TEXELS`], each at least one texel.
pub(crate) fn check_textures(textures: &[Texture]) -> Result<()> {
    if let Some(t) = textures.iter().find(|t| t.texels() == 0) {
        return Err(Error::invalid(
            crate::param::Param::Mesh,
            format!("texture {} has no texels", t.name),
        ));
    }
    let texels: u64 = textures.iter().map(Texture::texels).sum();
    if texels > MAX_TEXELS {
        return Err(Error::LimitExceeded {
            what: format!("texels of the mesh's {} textures", textures.len()),
            value: texels,
            limit: MAX_TEXELS,
            param: None,
            advice: Some(crate::advice::Advice::text(
                "scale the textures down (e.g. `npx @gltf-transform/cli resize --width 2048 \
                 --height 2048 in.glb out.glb`)",
            )),
        });
    }
    Ok(())
}
