//! How meshes render where there is a choice: the settings [`crate::RendererOptions`] holds for
//! them.

use super::{CoverBounds, TileClip, Visibility};

/// Mesh settings.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshOptions {
    /// Single-pass visibility; `None`: the fastest exact mode the adapter has
    /// ([`Visibility::best_exact`]).
    pub visibility: Option<Visibility>,
    /// Single-pass covering-quad bounds.
    pub bounds: CoverBounds,
    /// Tiled method: how each view's copy is kept inside its tile.
    pub tile_clip: TileClip,
}
