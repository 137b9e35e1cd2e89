//! Display models (docs/DESIGN.md §1): which view each (sub)pixel of the panel shows.
//!
//! Every kind compiles to one [`Mask`]: a slanted-lens phase in 32-bit fixed point that Rust
//! ([`Mask::view`]) and WGSL (`wgsl/shared/mask.wgsl`) evaluate with the same integer arithmetic,
//! so CPU and GPU agree on every subpixel of any panel size.

mod lkg_discovery;
mod lkg_family;
mod looking_glass;
mod mask;
mod spec;
mod subpixel_cells;

pub use lkg_discovery::{attached_calibrations, find_attached, mount_points};
pub use lkg_family::LookingGlassFamily;
pub use looking_glass::Calibration;
pub use mask::{hubner8_paper_view, Mask, MaskUniform};
pub use subpixel_cells::{CellPattern, SubpixelCell, SubpixelCells};

use crate::error::{Error, Result};
use crate::param::Param;

/// Most views any display or renderer supports (texture-array layers, u8 view images).
pub const MAX_VIEWS: u32 = 256;

/// The optical layout of a panel.
#[derive(Clone, Debug, PartialEq)]
pub enum DisplayKind {
    /// Pixel-level lenticular sheet: `view = (x + ox) mod N`, one view per pixel (K = 1).
    Lenticular {
        /// Number of views N.
        views: u32,
    },
    /// The paper's 8-view wavelength-selective 8×12 mask (Eq. 4–6), K = 3.
    Hubner8,
    /// General slanted lenticular: `view = ⌊N·frac((k + s·l + φ)/P)⌋` on subpixel columns k.
    Slanted {
        /// Number of views N.
        views: u32,
        /// Lens pitch P in subpixels.
        pitch: f64,
        /// Slant s in subpixels per row (signed).
        slant: f64,
        /// Phase φ in subpixels.
        phase: f64,
    },
    /// Every pixel shows view `view` of N: a 2D monitor showing one view. Any method then
    /// renders that one view at full resolution (per-view images, stereo outputs, pictures).
    OneView {
        /// Number of views N of the camera.
        views: u32,
        /// The view shown, 0 … N − 1.
        view: u32,
    },
    /// A Looking Glass calibration (`visual.json`), mapped onto the slanted model.
    LookingGlass {
        /// Number of views N (the quilt's view count; not in the calibration).
        views: u32,
        /// The calibration.
        calibration: Calibration,
    },
}

/// A display: its optics plus where the rendered window sits on the panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Display {
    /// The optical layout.
    pub kind: DisplayKind,
    /// Window origin on the physical panel, in pixels (0,0 for full screen / offline);
    /// negative where the window starts left of or above the panel.
    pub origin: [i32; 2],
    /// Reverse the view order (view 0 on the other side).
    pub flip_views: bool,
    /// Panel subpixels are ordered B, G, R left to right.
    pub bgr: bool,
}

/// Default view count for Looking Glass displays whose serial names no known family (those of
/// a known family default to its quilt's: [`LookingGlassFamily::views`]).
pub const LOOKING_GLASS_DEFAULT_VIEWS: u32 = 45;

impl Display {
    /// A display of `kind` at origin 0, no flip, RGB order.
    pub fn new(kind: DisplayKind) -> Result<Self> {
        let display = Self {
            kind,
            origin: [0, 0],
            flip_views: false,
            bgr: false,
        };
        display.validate()?;
        Ok(display)
    }

    /// Parse a SPEC string: `hubner8` | `lenticular:N` | `slanted:N,PITCH,SLANT,PHASE` | `lkg:PATH.json` | `view:N,V`.
    /// Numbers in `slanted` may be fractions (`2/3`).
    pub fn parse(spec: &str) -> Result<Self> {
        Self::new(spec::parse_kind(spec)?)
    }

    /// Number of views N.
    pub fn views(&self) -> u32 {
        match &self.kind {
            DisplayKind::Lenticular { views }
            | DisplayKind::OneView { views, .. }
            | DisplayKind::Slanted { views, .. }
            | DisplayKind::LookingGlass { views, .. } => *views,
            DisplayKind::Hubner8 => 8,
        }
    }

    /// Distinct views per pixel, K: 1 for pixel-level masks, 3 for subpixel masks.
    pub fn views_per_pixel(&self) -> u32 {
        if self.subpixel() {
            3
        } else {
            1
        }
    }

    fn subpixel(&self) -> bool {
        !matches!(
            self.kind,
            DisplayKind::Lenticular { .. } | DisplayKind::OneView { .. }
        )
    }

    /// The panel's own size in pixels where the display knows it (a Looking Glass calibration's
    /// `screenW` × `screenH`): what its owner expects an image to have.
    pub fn panel_size(&self) -> Option<[u32; 2]> {
        match &self.kind {
            DisplayKind::LookingGlass { calibration, .. } => Some(calibration.panel_size()),
            _ => None,
        }
    }

    /// The views' angular spread in radians where the display gives it (a Looking Glass
    /// calibration's `viewCone`): the outermost views' directions as seen from the focal point.
    pub fn view_cone(&self) -> Option<f32> {
        match &self.kind {
            DisplayKind::LookingGlass { calibration, .. } => {
                calibration.view_cone.map(|d| (d as f32).to_radians())
            }
            _ => None,
        }
    }

    /// The quilt image of `views` views rendered at `view_size` for this display, as
    /// `--output quilt` writes it and the viewer previews it; `choice` overrides the grid, the
    /// image size or the tile. A Looking Glass gets its family's quilt (size and grid from
    /// [`LookingGlassFamily`]; 4096² and the grid for the view count for an unknown family),
    /// tiles of floor(W / cols) × floor(H / rows) stretched to the panel's aspect, as Looking
    /// Glass software makes it; any other display the grid for the view count with tiles of
    /// `view_size`, shown at their own aspect.
    pub fn quilt(
        &self,
        views: u32,
        view_size: [u32; 2],
        choice: &crate::render::quilt_image::QuiltChoice,
    ) -> Result<crate::render::quilt_image::QuiltImage> {
        use crate::render::quilt::QuiltLayout;
        use crate::render::quilt_image::QuiltImage;
        let panel = self.panel_size();
        let family = match &self.kind {
            DisplayKind::LookingGlass { calibration, .. } => calibration.family(),
            _ => None,
        };
        let shown = panel.unwrap_or(view_size);
        let aspect = shown[0] as f32 / shown[1].max(1) as f32;
        // The family's grid where it holds the views without a whole empty row (a quilt of 4
        // views in 7×7 tiles would play 45 empty ones).
        let fits = |g: &[u32; 2]| {
            let tiles = g[0] as u64 * g[1] as u64;
            tiles >= views as u64 && tiles - (views as u64) < g[0] as u64
        };
        let grid = match choice.grid {
            Some(grid) => {
                let tiles = grid[0] as u64 * grid[1] as u64;
                if tiles >= views as u64 && !fits(&grid) {
                    let fit = QuiltLayout::for_views(views, choice.tile.unwrap_or(shown));
                    return Err(Error::invalid(
                        Param::Quilt,
                        format!(
                            "{}x{}: {} of its tiles would be empty for {views} views (a whole \
                             row or more); give a grid with fewer, e.g. {}x{}",
                            grid[0],
                            grid[1],
                            tiles - views as u64,
                            fit.cols,
                            fit.rows
                        ),
                    ));
                }
                grid
            }
            None => family.map(|f| f.grid).filter(fits).unwrap_or_else(|| {
                let q = QuiltLayout::for_views(views, choice.tile.unwrap_or(shown));
                [q.cols, q.rows]
            }),
        };
        let size = match (choice.size, choice.tile, panel) {
            (Some(size), _, _) => size,
            (None, Some(tile), _) => [
                grid[0].saturating_mul(tile[0]),
                grid[1].saturating_mul(tile[1]),
            ],
            (None, None, Some(_)) => family.map_or([4096, 4096], |f| f.quilt_size),
            (None, None, None) => [
                grid[0].saturating_mul(view_size[0]),
                grid[1].saturating_mul(view_size[1]),
            ],
        };
        QuiltImage::in_size(grid, size, views, aspect)
    }

    /// Set the view count where the display leaves it open (Looking Glass); elsewhere `n` must
    /// equal the display's own N.
    pub fn with_views(mut self, n: u32) -> Result<Self> {
        check_views(n)?;
        let own = self.views();
        match &mut self.kind {
            DisplayKind::LookingGlass { views, .. } => *views = n,
            _ if own == n => {}
            _ => {
                return Err(Error::invalid(
                    Param::Views,
                    format!("this display has {own} views; {n} were requested"),
                ))
            }
        }
        Ok(self)
    }

    /// Place the window at `origin` (pixels) on the panel; negative where it starts left of or
    /// above the panel.
    pub fn with_origin(mut self, origin: [i32; 2]) -> Self {
        self.origin = origin;
        self
    }

    fn validate(&self) -> Result<()> {
        check_views(self.views())?;
        match &self.kind {
            DisplayKind::Slanted {
                pitch,
                slant,
                phase,
                ..
            } => check_slanted(*pitch, *slant, *phase),
            DisplayKind::LookingGlass { calibration, .. } => {
                // Derived from the calibration: finite inputs can still give an unusable lens.
                let s = calibration.slanted();
                check_slanted(s.pitch, s.slant, s.phase)
                    .map_err(|e| Error::invalid(Param::LookingGlassCalibration, e.to_string()))
            }
            DisplayKind::OneView { views, view } if view >= views => Err(Error::invalid(
                Param::View,
                format!("{view}: the display has views 0…{}", views - 1),
            )),
            DisplayKind::Lenticular { .. } | DisplayKind::Hubner8 | DisplayKind::OneView { .. } => {
                Ok(())
            }
        }
    }

    /// Compile to the mask evaluated on CPU and GPU.
    pub fn mask(&self) -> Mask {
        let cells = match &self.kind {
            DisplayKind::LookingGlass { calibration, .. } => calibration.cell_geometry(),
            _ => None,
        };
        let (pitch, slant, phase, subpixel, extra_bgr, extra_flip) = match &self.kind {
            DisplayKind::Lenticular { views } => (*views as f64, 0.0, 0.0, false, false, false),
            // Pitch 1: the phase advances by whole periods from pixel to pixel, so every pixel
            // has phase (V + ½)/N, i.e. view V.
            DisplayKind::OneView { views, view } => (
                1.0,
                0.0,
                (*view as f64 + 0.5) / *views as f64,
                false,
                false,
                false,
            ),
            // docs/DESIGN.md §1: Eq. 4–6 are exactly slanted(N=8, P=8, s=2/3, φ=7/6); a test proves it.
            DisplayKind::Hubner8 => (8.0, 2.0 / 3.0, 7.0 / 6.0, true, false, false),
            DisplayKind::Slanted {
                pitch,
                slant,
                phase,
                ..
            } => (*pitch, *slant, *phase, true, false, false),
            // With cells the channel order is the cells' (`cells` above), not a reversed
            // stripe.
            DisplayKind::LookingGlass { calibration, .. } => {
                let s = calibration.slanted();
                let bgr = s.bgr && cells.is_none();
                (s.pitch, s.slant, s.phase, true, bgr, s.flip_views)
            }
        };
        Mask::new(mask::MaskGeometry {
            views: self.views(),
            pitch,
            slant,
            phase,
            subpixel,
            origin: self.origin,
            flip_views: self.flip_views ^ extra_flip,
            bgr: self.bgr ^ extra_bgr,
            cells,
        })
    }
}

/// Largest |slant / pitch| and |phase / pitch| (in lens periods) the mask resolves: its 0.32
/// fixed-point phase takes the fraction of these ratios, which an f64 still holds to 2⁻²⁰ here.
const MAX_PERIODS: f64 = (1u64 << 32) as f64;

/// A slanted lens the mask can evaluate (subnormal, huge or non-finite values would make the
/// fixed-point phase meaningless without any error): pitch ≥ [`MIN_PITCH`] subpixels, the slant
/// and the phase finite and within [`MAX_PERIODS`] lens pitches.
fn check_slanted(pitch: f64, slant: f64, phase: f64) -> Result<()> {
    if !(pitch.is_finite() && pitch >= MIN_PITCH) {
        return Err(Error::invalid(
            Param::Pitch,
            format!("{pitch}: the lens pitch must be a positive, finite number of subpixels"),
        ));
    }
    for (name, v) in [(Param::Slant, slant), (Param::Phase, phase)] {
        if !(v.is_finite() && (v / pitch).abs() <= MAX_PERIODS) {
            return Err(Error::invalid(
                name,
                format!(
                    "{v}: the {name} must be finite and within ±2^32 lens pitches, which at a \
                     pitch of {pitch} subpixels is ±{:e} subpixels",
                    MAX_PERIODS * pitch
                ),
            ));
        }
    }
    Ok(())
}

/// Smallest lens pitch in subpixels: the step per subpixel, 1 / pitch lens periods, stays within
/// 2³² periods (what the fixed-point phase resolves).
pub const MIN_PITCH: f64 = 1.0 / MAX_PERIODS;

/// Check a view count: 1 ..= [`MAX_VIEWS`].
pub fn check_views(n: u32) -> Result<()> {
    if n == 0 || n > MAX_VIEWS {
        return Err(Error::invalid(
            Param::Views,
            format!("{n}: the number of views must be between 1 and {MAX_VIEWS}"),
        ));
    }
    Ok(())
}
