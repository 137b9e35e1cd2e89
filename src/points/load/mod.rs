//! Point-cloud files: PLY (its `vertex` element, through `crate::io::ply`), LAS/LAZ with the
//! `las` feature, and OBJ vertices, each told by its first bytes, else its extension
//! ([`crate::formats`]).

#[cfg(feature = "las")]
pub mod las;

use std::path::Path;

use glam::Vec3;

use super::PointCloud;
use crate::error::{Error, Result};

impl From<crate::io::ply::Vertices> for PointCloud {
    fn from(v: crate::io::ply::Vertices) -> Self {
        Self {
            positions: v.positions,
            normals: v.normals,
            colors: v.colors,
            radii: v.radii,
        }
    }
}

impl PointCloud {
    /// Load a `.ply` (its `vertex` element), `.las`/`.laz` (with the `las` feature) or `.obj`
    /// (its `v` lines, with `v x y z r g b` colours when present; faces, normals and texture
    /// coordinates are ignored), told by
    /// its first bytes, else its extension ([`crate::formats`]); a file of another kind is
    /// refused as what it is (`Error::WrongKind`). A PLY mesh's vertices are read as points,
    /// and the log says that its faces are not drawn.
    pub fn load(path: &Path) -> Result<Self> {
        let cloud = Self::load_any(path)?;
        // Named here, with the file: `validate` (no path) would say only "no points".
        if cloud.is_empty() {
            return Err(Error::Points {
                path: path.to_path_buf(),
                reason: "no points (the file has no vertices): nothing to render".into(),
            });
        }
        Ok(cloud)
    }

    /// [`PointCloud::load`] before the empty check.
    fn load_any(path: &Path) -> Result<Self> {
        use crate::formats::{expect, ply_faces, DataKind, Format};
        match expect(path, DataKind::Points)? {
            Format::Ply => {
                let faces = ply_faces(path)?;
                let cloud = PointCloud::from(crate::io::ply::load(path)?);
                if faces > 0 {
                    log::warn!(
                        "{}: a mesh of {faces} faces; its {} vertices are drawn as points \
                         (read as a mesh, its surface is drawn)",
                        path.display(),
                        cloud.len(),
                    );
                }
                Ok(cloud)
            }
            #[cfg(feature = "las")]
            Format::Las => las::load(path),
            _ => obj_vertices(path),
        }
    }
}

fn obj_vertices(path: &Path) -> Result<PointCloud> {
    let text = crate::file::read_text(path)?;
    // A vertex line takes at least 8 bytes ("v 0 0 0\n").
    crate::budget::check_points(text.len() as u64 / 8).map_err(|e| Error::Points {
        path: path.into(),
        reason: e.to_string(),
    })?;
    let fail = |line: usize, reason: &str| Error::Points {
        path: path.into(),
        reason: format!("line {}: {reason}", line + 1),
    };
    let mut cloud = PointCloud::default();
    let mut colors = Vec::new();
    for (l, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        if words.next() != Some("v") {
            continue;
        }
        let values: Vec<f32> = words
            .map(|w| {
                w.parse::<f32>().map_err(|_| {
                    fail(
                        l,
                        &format!("{w} is not a number", w = crate::error::quote(w)),
                    )
                })
            })
            .collect::<Result<_>>()?;
        match values.len() {
            3 | 4 | 6 | 7 => {}
            k => {
                return Err(fail(
                    l,
                    &format!("a vertex has 3 (or 6 with colour) numbers, not {k}"),
                ))
            }
        }
        let p = Vec3::new(values[0], values[1], values[2]);
        if !p.is_finite() {
            return Err(fail(l, "non-finite position"));
        }
        cloud.positions.push(p);
        if values.len() >= 6 {
            let c = &values[values.len() - 3..];
            colors.push([c[0], c[1], c[2]]);
        }
    }
    if cloud.positions.is_empty() {
        return Err(fail(0, "no vertices ('v x y z' lines)"));
    }
    if colors.len() == cloud.positions.len() {
        cloud.colors = Some(colors);
    }
    Ok(cloud)
}
