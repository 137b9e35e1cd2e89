//! The monitors the window system has, and the one a full-screen window goes to: by number, or
//! the one that is a Looking Glass calibration's panel (its size, and its name where the system
//! gives one), so that nobody types where the panel sits on the desktop.

use autostereo::display::Display;
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::monitor::MonitorHandle;
use winit::window::WindowId;

use crate::error::{Error, Result};

/// One monitor, as the window system describes it.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct MonitorInfo {
    /// Its number (the order the system lists them; `Monitor::Index`).
    pub index: usize,
    /// Its name, where the system gives one (X11: the RandR output, e.g. `HDMI-1`).
    pub name: Option<String>,
    /// Size in physical pixels.
    pub size: [u32; 2],
    /// Top-left corner on the desktop, in physical pixels.
    pub position: [i32; 2],
    /// The system's scale factor for it.
    pub scale: f64,
}

impl MonitorInfo {
    pub(crate) fn of(index: usize, monitor: &MonitorHandle) -> Self {
        let (size, position) = (monitor.size(), monitor.position());
        Self {
            index,
            name: monitor.name(),
            size: [size.width, size.height],
            position: [position.x, position.y],
            scale: monitor.scale_factor(),
        }
    }

    /// `0: HDMI-1 3840x2160 at 1920,0 (scale 1)`.
    pub fn line(&self) -> String {
        format!(
            "{}: {} {}x{} at {},{} (scale {})",
            self.index,
            self.name.as_deref().unwrap_or("(no name)"),
            self.size[0],
            self.size[1],
            self.position[0],
            self.position[1],
            self.scale
        )
    }
}

/// Which monitor a full-screen window fills.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Monitor {
    /// The monitor of this number (0 = the first the system lists).
    Index(usize),
    /// The display's panel: the monitor of a Looking Glass calibration's size (one whose name
    /// says Looking Glass first, where several have it); any other display: the first.
    Panel,
}

/// The monitors there are (a window-system connection of its own: call it before or instead
/// of [`crate::run`], not while a viewer runs).
pub fn monitors() -> Result<Vec<MonitorInfo>> {
    struct List(Option<Vec<MonitorInfo>>);
    impl ApplicationHandler for List {
        fn resumed(&mut self, event_loop: &ActiveEventLoop) {
            let found = event_loop.available_monitors().enumerate();
            self.0 = Some(found.map(|(i, m)| MonitorInfo::of(i, &m)).collect());
            event_loop.exit();
        }
        fn window_event(&mut self, _: &ActiveEventLoop, _: WindowId, _: WindowEvent) {}
    }
    let event_loop = EventLoop::new().map_err(Error::WindowSystem)?;
    let mut list = List(None);
    event_loop.run_app(&mut list)?;
    Ok(list.0.unwrap_or_default())
}

/// The monitor `choice` names among `monitors` for `display`, and what to say of the choice.
pub(crate) fn pick(
    monitors: &[MonitorHandle],
    choice: Monitor,
    display: &Display,
) -> Result<(MonitorHandle, String)> {
    let listed = || {
        monitors
            .iter()
            .enumerate()
            .map(|(i, m)| MonitorInfo::of(i, m))
            .collect()
    };
    let chosen = match (choice, display.panel_size()) {
        (Monitor::Index(index), _) => monitors.get(index).ok_or(Error::NoMonitor {
            index,
            found: monitors.len(),
        })?,
        (Monitor::Panel, None) => monitors
            .first()
            .ok_or(Error::NoMonitor { index: 0, found: 0 })?,
        (Monitor::Panel, Some(panel)) => {
            let sized = |m: &&MonitorHandle| [m.size().width, m.size().height] == panel;
            let named = |m: &&&MonitorHandle| {
                m.name().is_some_and(|n| {
                    let n = n.to_lowercase();
                    n.contains("lkg") || n.contains("looking glass")
                })
            };
            let candidates: Vec<&MonitorHandle> = monitors.iter().filter(sized).collect();
            let best = candidates.iter().find(named).or(candidates.first());
            *best.ok_or_else(|| Error::NoPanelMonitor {
                panel,
                monitors: listed(),
            })?
        }
    };
    let index = monitors.iter().position(|m| m == chosen).unwrap_or(0);
    let info = MonitorInfo::of(index, chosen);
    let why = match (choice, display.panel_size()) {
        (Monitor::Panel, Some(_)) => "the calibration's panel size",
        (Monitor::Panel, None) => "the first monitor; this display has no panel to look for",
        (Monitor::Index(_), _) => "as asked",
    };
    Ok((
        chosen.clone(),
        format!("full screen on monitor {} ({why})", info.line()),
    ))
}
