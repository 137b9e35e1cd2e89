//! Mesh files: OBJ and PLY always, STL and glTF with their cargo features, each told by its
//! first bytes, else its extension ([`crate::formats`]).

#[cfg(feature = "gltf")]
mod gltf;
mod map_kd;
mod obj;
mod ply;
#[cfg(feature = "stl")]
mod stl;

use super::Mesh;
use crate::error::{Error, Result};

impl Mesh {
    /// Load a mesh file of any format this build reads ([`crate::formats`]: OBJ and PLY
    /// always, STL and glTF with their cargo features), told by its first bytes, else its
    /// extension. A file of another kind (a volume, a point cloud without faces) is refused
    /// as what it is (`Error::WrongKind`).
    pub fn load(path: &std::path::Path) -> Result<Self> {
        use crate::formats::{expect, DataKind, Format};
        match expect(path, DataKind::Mesh)? {
            Format::Ply => ply::load(path),
            #[cfg(feature = "stl")]
            Format::Stl => stl::load(path),
            #[cfg(feature = "gltf")]
            Format::Gltf => gltf::load(path),
            _ => obj::load(path),
        }
    }

    /// Parse a mesh file's bytes in `format` (`name` labels errors; an OBJ's `mtllib` and a
    /// glTF's external buffers are not read): what the fuzz targets call.
    pub fn parse(
        bytes: &[u8],
        format: crate::formats::Format,
        name: &std::path::Path,
    ) -> Result<Self> {
        use crate::formats::Format;
        match format {
            Format::Ply => ply::parse(bytes, name),
            #[cfg(feature = "stl")]
            Format::Stl => stl::parse(bytes, name),
            #[cfg(feature = "gltf")]
            Format::Gltf => gltf::parse(bytes, name, None),
            Format::Obj => obj::parse(&String::from_utf8_lossy(bytes), name, None),
            other => Err(Error::Mesh {
                path: name.into(),
                reason: format!("{other} is not a mesh format this build reads"),
            }),
        }
    }

    /// Load a Wavefront OBJ (polygons triangulated; normals computed when absent; vertex colour,
    /// else material diffuse colour, else [`DEFAULT_COLOR`]).
    pub fn load_obj(path: &std::path::Path) -> Result<Self> {
        obj::load(path)
    }

    /// Parse OBJ text from memory (`name` labels errors; `mtllib` is not read).
    pub fn from_obj_text(text: &str, name: &std::path::Path) -> Result<Self> {
        obj::parse(text, name, None)
    }

    /// Check MTL text as the OBJ loader reads it (name and diffuse colour per material):
    /// `Ok(materials)` or the first malformed line.
    pub fn check_mtl_text(text: &str, name: &std::path::Path) -> Result<usize> {
        obj::parse_mtl(text, name).map(|(materials, _)| materials.len())
    }
}
