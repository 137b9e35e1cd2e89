//! Triangle meshes: loading (OBJ, PLY, STL, glTF), generated test shapes, GPU buffers.

mod generate;
mod load;
pub(crate) mod options;
mod order;
pub(crate) mod passes;
mod scene;
mod texture;
pub(crate) mod texture_buffers;

pub use options::{CoverBounds, MeshOptions, TileClip, ViewClusters, Visibility};
pub use passes::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled,
};
pub use scene::{GpuVertex, MeshBuffers};
pub use texture::{Filter, Texture, Wrap, MAX_TEXELS, NO_TEXTURE};

use glam::{Vec2, Vec3};

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;
use crate::render::Method;

/// The methods that render meshes: every one ([`crate::RendererOptions::mesh_renderer`]).
pub const METHODS: [Method; 7] = Method::ALL;

/// Colour given to vertices when the file has neither vertex nor material colours.
pub const DEFAULT_COLOR: [f32; 4] = [0.8, 0.8, 0.8, 1.0];

/// An indexed triangle mesh with per-vertex normals and colours, and optionally base-colour
/// textures that multiply the colours.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals (same length as `positions`).
    pub normals: Vec<Vec3>,
    /// Linear RGBA vertex colours (same length as `positions`).
    pub colors: Vec<[f32; 4]>,
    /// Triangle list, three indices per triangle.
    pub indices: Vec<u32>,
    /// Texture coordinates (same length as `positions`, or empty: no textures).
    pub tex_coords: Vec<Vec2>,
    /// Which of `textures` each vertex samples, or [`NO_TEXTURE`] (same length as `positions`,
    /// or empty). A triangle is textured as its first vertex says.
    pub texture_ids: Vec<u32>,
    /// Base-colour textures ([`Texture`]).
    pub textures: Vec<Texture>,
}

impl Mesh {
    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Bounding box; `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Bounds> {
        Bounds::of_points(self.positions.iter().copied())
    }

    /// Check array lengths, index range and that every coordinate is finite.
    pub fn validate(&self) -> Result<()> {
        let fail = |reason: String| Error::invalid(Param::Mesh, reason);
        let n = self.positions.len();
        if self.normals.len() != n || self.colors.len() != n {
            return Err(fail(format!(
                "{n} positions but {} normals and {} colours",
                self.normals.len(),
                self.colors.len()
            )));
        }
        if self.indices.is_empty() || !self.indices.len().is_multiple_of(3) {
            return Err(fail(format!(
                "{} indices: need a non-empty multiple of 3",
                self.indices.len()
            )));
        }
        if let Some(&i) = self.indices.iter().find(|&&i| i as usize >= n) {
            return Err(fail(format!("index {i} out of range for {n} vertices")));
        }
        if let Some(i) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(fail(format!(
                "vertex {i} has a non-finite coordinate {}",
                self.positions[i]
            )));
        }
        if self.normals.iter().any(|v| !v.is_finite())
            || self.colors.iter().flatten().any(|c| !c.is_finite())
        {
            return Err(fail("a normal or colour is not finite".into()));
        }
        self.validate_textures(n)
    }

    /// Texture coordinates and ids: both empty or one per vertex, finite, naming textures
    /// that exist and fit [`MAX_TEXELS`].
    fn validate_textures(&self, n: usize) -> Result<()> {
        let fail = |reason: String| Error::invalid(Param::Mesh, reason);
        let (uvs, ids) = (self.tex_coords.len(), self.texture_ids.len());
        if !(uvs == ids && (uvs == 0 || uvs == n)) {
            return Err(fail(format!(
                "{n} positions but {uvs} texture coordinates and {ids} texture ids (both must \
                 be empty or one per vertex)"
            )));
        }
        if let Some(i) = self.tex_coords.iter().position(|t| !t.is_finite()) {
            return Err(fail(format!(
                "vertex {i} has a non-finite texture coordinate {}",
                self.tex_coords[i]
            )));
        }
        let count = self.textures.len();
        if let Some(&id) = self
            .texture_ids
            .iter()
            .find(|&&id| id != NO_TEXTURE && id as usize >= count)
        {
            return Err(fail(format!(
                "texture {id} does not exist (the mesh has {count})"
            )));
        }
        texture::check_textures(&self.textures)
    }

    /// Whether any vertex samples a texture.
    pub fn is_textured(&self) -> bool {
        self.texture_ids.iter().any(|&id| id != NO_TEXTURE)
    }

    /// Area-weighted vertex normals from the triangles (replaces `normals`). Vertices of only
    /// degenerate triangles get +z rather than NaN.
    pub fn compute_normals(&mut self) {
        let mut acc = vec![Vec3::ZERO; self.positions.len()];
        for t in self.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| self.positions[i as usize]);
            let n = (b - a).cross(c - a); // length = 2·area: area weighting for free
            for &i in t {
                acc[i as usize] += n;
            }
        }
        self.normals = acc
            .into_iter()
            .map(|n| n.try_normalize().unwrap_or(Vec3::Z))
            .collect();
    }

    /// Append `other` (indices and texture ids shifted).
    pub fn append(&mut self, other: &Mesh) {
        let n = self.positions.len();
        let base = n as u32;
        if self.tex_coords.is_empty() && !other.tex_coords.is_empty() {
            self.tex_coords = vec![Vec2::ZERO; n];
            self.texture_ids = vec![NO_TEXTURE; n];
        }
        if !self.tex_coords.is_empty() {
            let m = other.positions.len();
            let first = self.textures.len() as u32;
            match other.tex_coords.is_empty() {
                true => {
                    self.tex_coords.extend(std::iter::repeat_n(Vec2::ZERO, m));
                    self.texture_ids.extend(std::iter::repeat_n(NO_TEXTURE, m));
                }
                false => {
                    self.tex_coords.extend_from_slice(&other.tex_coords);
                    self.texture_ids
                        .extend(other.texture_ids.iter().map(|&id| match id {
                            NO_TEXTURE => NO_TEXTURE,
                            id => id + first,
                        }));
                }
            }
            self.textures.extend_from_slice(&other.textures);
        }
        self.positions.extend_from_slice(&other.positions);
        self.normals.extend_from_slice(&other.normals);
        self.colors.extend_from_slice(&other.colors);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }

    /// Transform positions by `m` (normals by its inverse transpose).
    pub fn transform(&mut self, m: glam::Mat4) {
        let normal = glam::Mat3::from_mat4(m).inverse().transpose();
        for p in &mut self.positions {
            *p = m.transform_point3(*p);
        }
        for n in &mut self.normals {
            *n = (normal * *n).try_normalize().unwrap_or(Vec3::Z);
        }
    }
}
