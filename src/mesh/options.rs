//! How meshes render where there is a choice: the settings [`crate::RendererOptions`] holds for
//! them, and the modes they choose between (plain values: no GPU, no errors, so that an error's
//! advice can name them, `src/advice.rs`).

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
    /// Single pass, compute visibility: how the views are grouped.
    pub clusters: ViewClusters,
}

/// How the single pass's compute rasteriser groups the N views (docs/DESIGN.md §3): each
/// triangle visits, per cluster of adjacent views, only the span its projections in those views
/// cover and only the subpixels showing them. Every grouping tests every subpixel the triangle
/// can cover, so the image is the same; only the time changes.
/// The default is one cluster: on lavapipe every larger C measured slower (docs/MESHES.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ViewClusters {
    /// Chosen per triangle from its width and the spread of its projections over the views
    /// (the cost model of docs/DESIGN.md §3).
    PerTriangle,
    /// C clusters for every triangle: 1 = every view at once (the paper's covering quad), N (or
    /// more, capped at N) = each subpixel tested against its own view's projection only.
    Fixed(u32),
}

impl Default for ViewClusters {
    fn default() -> Self {
        ViewClusters::Fixed(1)
    }
}

impl ViewClusters {
    /// The `VIEW_CLUSTERS` override of wgsl/mesh/shared/cluster_cover.wgsl (0: per triangle).
    pub fn override_value(self, views: u32) -> u32 {
        match self {
            ViewClusters::PerTriangle => 0,
            ViewClusters::Fixed(c) => c.clamp(1, views.max(1)),
        }
    }
}

impl std::fmt::Display for ViewClusters {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ViewClusters::PerTriangle => f.write_str("per-triangle"),
            ViewClusters::Fixed(c) => write!(f, "{c}"),
        }
    }
}

/// How per-subpixel visibility is resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Visibility {
    /// Subpixel-resolution rasterisation + hardware depth test + deferred shading. Exact.
    Exact,
    /// Per-pixel fragments, per-subpixel 64-bit atomic depth + deferred shading. Exact.
    Atomic,
    /// Covering rectangles rasterised by a compute pass, 64-bit atomic depth. Exact.
    Compute,
    /// The paper's one depth per fragment; approximate where triangles split a pixel.
    Fast,
}

impl Visibility {
    /// The fastest exact mode `device` supports: compute rasterisation where 64-bit atomics
    /// exist (fastest on lavapipe by far, docs/MESHES.md), else subpixel rasterisation.
    pub fn best_exact(device: &wgpu::Device) -> Self {
        if device
            .features()
            .contains(Visibility::Compute.required_features())
        {
            Visibility::Compute
        } else {
            Visibility::Exact
        }
    }

    /// Name as the CLI spells it.
    pub fn name(self) -> &'static str {
        match self {
            Visibility::Exact => "exact",
            Visibility::Atomic => "atomic",
            Visibility::Compute => "compute",
            Visibility::Fast => "fast",
        }
    }

    /// Features the mode needs beyond the WebGPU defaults.
    pub fn required_features(self) -> wgpu::Features {
        match self {
            Visibility::Exact => wgpu::Features::empty(),
            Visibility::Atomic | Visibility::Compute => {
                wgpu::Features::SHADER_INT64 | wgpu::Features::SHADER_INT64_ATOMIC_MIN_MAX
            }
            Visibility::Fast => wgpu::Features::DUAL_SOURCE_BLENDING,
        }
    }
}

/// Horizontal extent of the covering rectangles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum CoverBounds {
    /// docs/DESIGN.md §3: `x ± vd·|1 − fd/d|` per vertex. Always covers.
    #[default]
    Exact,
    /// The paper's printed `(x ∓ vd)·fd/d`: under-covers geometry beyond 2·fd (kept to measure).
    Paper,
}

/// How a copy is kept inside its tile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum TileClip {
    /// Clip distances where the adapter has them, else [`TileClip::Discard`].
    #[default]
    Auto,
    /// Four clip distances per vertex (exact clipping before rasterisation; needs
    /// `CLIP_DISTANCES`).
    ClipDistances,
    /// Fragments outside the tile are discarded (any adapter; costs early depth testing).
    Discard,
}

impl TileClip {
    /// Lower-case name (reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::ClipDistances => "clip-distances",
            Self::Discard => "discard",
        }
    }
}
