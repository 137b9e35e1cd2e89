//! The viewer's errors: the library's, the window system's, and what the viewer refuses before
//! it renders (a monitor that is not there, a window no adapter presents, a method the scene
//! has not). Each says which setting: a command line names its flag for it.

use autostereo::render::Method;

/// What went wrong in a viewer run.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The library refused something (the scene, the display, the camera, a renderer).
    #[error(transparent)]
    Library(#[from] autostereo::Error),
    /// No window system to open a window on.
    #[error(
        "opening the window system (is DISPLAY or WAYLAND_DISPLAY set? without a screen, run \
         it in a virtual one: xvfb-run -a …)"
    )]
    WindowSystem(#[source] winit::error::EventLoopError),
    /// The event loop ended in an error.
    #[error(transparent)]
    EventLoop(#[from] winit::error::EventLoopError),
    /// The window could not be made.
    #[error(transparent)]
    Window(#[from] winit::error::OsError),
    /// The window has no surface wgpu can draw to.
    #[error("creating the window's surface")]
    Surface(#[from] wgpu::CreateSurfaceError),
    /// The surface takes none of the formats the output blit writes.
    #[error("the surface offers none of {wanted:?}")]
    SurfaceFormat { wanted: Vec<wgpu::TextureFormat> },
    /// `Options::fullscreen` names a monitor that is not there.
    #[error("monitor {index}: {found} monitor(s) found, numbered from 0")]
    NoMonitor { index: usize, found: usize },
    /// `Monitor::Panel`: no monitor has the calibration's panel size.
    #[error(
        "no monitor is {}x{}, the calibration's panel: {}",
        .panel[0], .panel[1], monitor_list(.monitors)
    )]
    NoPanelMonitor {
        panel: [u32; 2],
        monitors: Vec<crate::monitors::MonitorInfo>,
    },
    /// A window larger than the adapter's largest surface (`fullscreen`: the monitor's size).
    #[error(
        "{} {}x{}: larger than this adapter's largest surface ({limit} per side on {adapter})",
        if *.fullscreen { "the monitor's size" } else { "window size" }, .size[0], .size[1]
    )]
    WindowTooLarge {
        size: [u32; 2],
        fullscreen: bool,
        limit: u32,
        adapter: String,
    },
    /// `Options::method` is not one of the scene's methods on this adapter.
    #[error("method {method}: {primitive} scenes have {}", names(.available))]
    MethodUnavailable {
        method: Method,
        primitive: String,
        available: Vec<Method>,
    },
    /// The event loop ended before the window opened.
    #[error("the window system ended the run before the window opened")]
    NeverOpened,
    /// The scene has nothing to frame.
    #[error("{name}: the mesh has no vertices")]
    EmptyScene { name: String },
}

/// The viewer's result.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Method names as the library spells them, comma-separated.
pub(crate) fn names(methods: &[Method]) -> String {
    methods
        .iter()
        .map(|m| m.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// The monitors found, one clause each; "none found" where there are none.
fn monitor_list(monitors: &[crate::monitors::MonitorInfo]) -> String {
    match monitors.is_empty() {
        true => "no monitors found".into(),
        false => monitors
            .iter()
            .map(|m| m.line())
            .collect::<Vec<_>>()
            .join("; "),
    }
}
