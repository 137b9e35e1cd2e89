//! The autostereo viewer: a real window rendering a scene live for an autostereoscopic
//! display, on the library's public API (a surface, prepare/encode into the viewer's encoder,
//! `OutputBlit` into the surface texture). The mask follows the window: the display's origin
//! is the client area's position on the screen plus the display's own origin. Mouse: orbit,
//! zoom, pan; keys: m method, d display, p preview, , . view, [ ] separation, - = focal plane,
//! c a volume's clipping plane (off, x, y, z, −x, −y, −z), 9 0 move it, r reset, Esc quit.
//!
//! ```no_run
//! # fn main() -> Result<(), autostereo_viewer::Error> {
//! let data = autostereo::load("head.nrrd".as_ref(), &Default::default())?;
//! let scene = autostereo_viewer::Scene::new(data, Default::default(), "head.nrrd")?;
//! let options = autostereo_viewer::Options::new(autostereo::display::Display::parse("hubner8")?, "hubner8");
//! let report = autostereo_viewer::run(scene, options)?;
//! println!("{} frames", report.frames);
//! # Ok(())
//! # }
//! ```

mod app;
mod error;
mod monitors;
mod options;
mod scene;
mod windows;

pub use error::{Error, Result};
pub use monitors::{monitors, Monitor, MonitorInfo};
pub use options::{Options, Preview, Switch};
pub use scene::Scene;
pub use windows::Windows;

/// What a viewer run showed, when it ends: the scene, the method and display last shown, the
/// window, the frames presented, the adapter and the files written (the screenshot); an
/// exercise run's memory report.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Report {
    pub scene: String,
    pub primitive: String,
    pub method: String,
    pub display: String,
    pub window_size: [u32; 2],
    pub frames: u32,
    pub adapter: String,
    pub written: Vec<std::path::PathBuf>,
    /// The exercise run's memory samples and period (`Options::exercise`).
    #[serde(skip)]
    pub exercise: Option<serde_json::Value>,
}

/// Open the window, render `scene` until it is closed (Esc, the window's close button) or the
/// options' scripted end, and say what was shown.
pub fn run(scene: Scene, options: Options) -> Result<Report> {
    app::run(scene, options)
}
