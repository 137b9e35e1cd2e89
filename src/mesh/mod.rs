//! Triangle meshes: loading (OBJ, PLY, STL, glTF), generated test shapes, GPU buffers.

mod generate;
mod load;
pub(crate) mod options;
mod order;
pub(crate) mod passes;
mod scene;

pub use options::{CoverBounds, MeshOptions, TileClip, Visibility};
pub use passes::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled,
};
pub use scene::{GpuVertex, MeshBuffers};

use glam::Vec3;

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;
use crate::render::Method;

/// The methods that render meshes: every one ([`crate::RendererOptions::mesh_renderer`]).
pub const METHODS: [Method; 7] = Method::ALL;

/// Colour given to vertices when the file has neither vertex nor material colours.
pub const DEFAULT_COLOR: [f32; 4] = [0.8, 0.8, 0.8, 1.0];

/// An indexed triangle mesh with per-vertex normals and colours.
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
        Ok(())
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

    /// Append `other` (indices shifted).
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
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
