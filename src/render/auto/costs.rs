//! The cost model of `Method` auto (docs/DESIGN.md §10): predicted milliseconds per frame of
//! each candidate from the frame's counts ([`super::census`]), with constants fitted to one
//! adapter's measurements (llvmpipe through lavapipe, docs/AUTO.md lists them beside what the
//! model predicts). The model decides between candidates; its absolute figures are a guide.

use super::census::MeshCensus;

/// Nanoseconds per unit of work, fitted on lavapipe by `docs/tools/auto_fit.py` (docs/AUTO.md).
pub(super) mod ns {
    /// Mesh single pass: per subpixel of the image (clear, resolve, crop).
    pub const MESH_SP_SUBPIXEL: f64 = 32.9;
    /// Mesh single pass: per subpixel its covering rectangles visit.
    pub const MESH_SP_COVER: f64 = 9.16;
    /// Mesh single pass: per triangle (transform, bounds, dispatch).
    pub const MESH_SP_TRIANGLE: f64 = 68.0;
    /// Rasterised views (N-pass, quilt): per view pixel (clear, composite read).
    pub const VIEW_PIXEL: f64 = 2.78;
    /// Rasterised views: per triangle and view.
    pub const VIEW_TRIANGLE: f64 = 165.0;
    /// Rasterised views: per unit of edge length, √(filled pixels × triangles), and view.
    pub const VIEW_EDGE: f64 = 73.5;
    /// Interleaving a quilt: per subpixel of the image.
    pub const INTERLEAVE_SUBPIXEL: f64 = 7.9;
    /// Ray-cast and splatted primitives, per ray that reaches the scene's bounds: [single
    /// pass, per-view images], each from one scene (brainsmall; the dragon's points; the
    /// generated Gaussians) on the 16" panel and on hubner8.
    pub const VOLUME_RAY: [f64; 2] = [1009.0, 903.0];
    pub const POINTS_RAY: [f64; 2] = [955.0, 1605.0];
    pub const GAUSSIANS_RAY: [f64; 2] = [1490.0, 1368.0];
}

/// What the model needs of one frame.
#[derive(Clone, Copy, Debug)]
pub(super) struct Counts {
    /// Pixels of the spatial image.
    pub pixels: f64,
    /// Views per pixel, K.
    pub per_pixel: f64,
    /// Views, N.
    pub views: f64,
    /// Share of the image the scene's bounds cover.
    pub coverage: f64,
}

/// The work, as a model of one primitive.
#[derive(Clone, Copy, Debug)]
pub(super) enum Work {
    Mesh(MeshCensus),
    /// Ray-cast or splatted per ray: ns per ray of [single pass, per-view images].
    Rays([f64; 2]),
}

/// The single pass, ms.
pub(super) fn single_pass(work: &Work, c: &Counts) -> f64 {
    let subpixels = c.pixels * c.per_pixel;
    let ns = match work {
        Work::Mesh(m) => {
            subpixels * ns::MESH_SP_SUBPIXEL
                + m.cover_pixels * c.per_pixel * ns::MESH_SP_COVER
                + m.triangles as f64 * ns::MESH_SP_TRIANGLE
        }
        Work::Rays(per_ray) => subpixels * c.coverage * per_ray[0],
    };
    ns * 1e-6
}

/// N views rendered at `view_pixels` each, then composited (`interleave`: read back from a
/// quilt at another size than the image), ms.
pub(super) fn per_view(work: &Work, c: &Counts, view_pixels: f64, interleave: bool) -> f64 {
    let scale = view_pixels / c.pixels;
    let per_view = view_pixels * ns::VIEW_PIXEL
        + match work {
            Work::Mesh(m) => {
                let triangles = m.triangles as f64;
                triangles * ns::VIEW_TRIANGLE
                    + (m.triangle_pixels * scale * triangles).sqrt() * ns::VIEW_EDGE
            }
            Work::Rays(per_ray) => view_pixels * c.coverage * per_ray[1],
        };
    let composite = match interleave {
        true => c.pixels * c.per_pixel * ns::INTERLEAVE_SUBPIXEL,
        false => 0.0,
    };
    (c.views * per_view + composite) * 1e-6
}
