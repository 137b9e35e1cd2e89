//! What a viewer run shows and how it runs: the display, the camera, the window, the starting
//! method and preview, and the scripted runs (screenshot, frame count, moves, the exercise).

use std::path::PathBuf;

use autostereo::camera::CameraSettings;
use autostereo::display::Display;
use autostereo::render::Method;

/// What the exercise run switches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Switch {
    Methods,
    Displays,
    Sizes,
}

/// What the window shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Preview {
    /// The interleaved image for the panel.
    Spatial,
    /// One view on every pixel (the centre view; keys , and . step through the views), for
    /// ordinary monitors.
    View,
    /// Red-cyan anaglyph (Dubois) of two views a quarter of the views apart about the middle
    /// (the render commands' default `--eyes`).
    Anaglyph,
    /// The same two views side by side, each half the window's width.
    SideBySide,
    /// Every view in a Looking Glass quilt (view 0 bottom-left).
    Quilt,
}

impl Preview {
    /// The stereo format of the two-view previews.
    pub(crate) fn stereo(self) -> Option<autostereo::render::StereoFormat> {
        use autostereo::render::StereoFormat;
        match self {
            Preview::Anaglyph => Some(StereoFormat::AnaglyphDubois),
            Preview::SideBySide => Some(StereoFormat::SideBySide),
            Preview::Spatial | Preview::View | Preview::Quilt => None,
        }
    }

    /// The preview's name, as `--preview` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Preview::Spatial => "spatial",
            Preview::View => "view",
            Preview::Anaglyph => "anaglyph",
            Preview::SideBySide => "side-by-side",
            Preview::Quilt => "quilt",
        }
    }

    /// The next preview key `p` shows: spatial → view → anaglyph → side-by-side → quilt →
    /// spatial.
    pub(crate) fn next(self) -> Self {
        match self {
            Preview::Spatial => Preview::View,
            Preview::View => Preview::Anaglyph,
            Preview::Anaglyph => Preview::SideBySide,
            Preview::SideBySide => Preview::Quilt,
            Preview::Quilt => Preview::Spatial,
        }
    }
}

/// A viewer run's settings. [`Options::new`] gives a 512×512 window on the first monitor's
/// desktop, the single pass, the spatial preview, the default camera, running until closed.
#[derive(Clone, Debug)]
pub struct Options {
    /// The display; the mask's origin is the window's position on the monitor it is on (the
    /// panel) plus the display's own `origin`.
    pub display: Display,
    /// What the title and the report call the display (the spec it was made from).
    pub display_name: String,
    pub camera: CameraSettings,
    /// Where the camera starts, turned from `camera`'s framing (the mouse turns it from
    /// there; key r goes back to the framing).
    pub orbit: autostereo::camera::Orbit,
    /// Window client-area size in pixels.
    pub size: [u32; 2],
    /// Window position on the desktop (the mask's origin follows it).
    pub position: Option<[i32; 2]>,
    /// Full screen on this monitor (by number, or the display's panel).
    pub fullscreen: Option<crate::Monitor>,
    /// The starting method (key m cycles through the scene's methods).
    pub method: Method,
    pub preview: Preview,
    /// Save what was presented as PNG after `quit_after_frames` frames (else after 3), then
    /// end unless `keep_open`.
    pub screenshot: Option<PathBuf>,
    pub keep_open: bool,
    /// End after this many presented frames.
    pub quit_after_frames: Option<u32>,
    /// Move the window to this position after this frame (tests: the mask must follow).
    pub move_after: Option<(u32, [i32; 2])>,
    /// The scripted stress run for this many frames: switch the method every 10 frames, the
    /// display every 70, the window size every 35, recording memory (`Report::exercise`).
    pub exercise: Option<u32>,
    /// What the exercise run switches.
    pub exercise_switch: Vec<Switch>,
}

impl Options {
    /// The defaults for `display`, called `display_name`.
    pub fn new(display: Display, display_name: impl Into<String>) -> Self {
        Self {
            display,
            display_name: display_name.into(),
            camera: CameraSettings::default(),
            orbit: Default::default(),
            size: [512, 512],
            position: None,
            fullscreen: None,
            method: Method::SinglePass,
            preview: Preview::Spatial,
            screenshot: None,
            keep_open: false,
            quit_after_frames: None,
            move_after: None,
            exercise: None,
            exercise_switch: vec![Switch::Methods, Switch::Displays, Switch::Sizes],
        }
    }
}
