//! Viewer windows for a host that keeps its own main thread (a Python notebook's kernel): one
//! event loop, made on whichever thread the host gives the viewer, runs each window to its end
//! and stays for the next (winit allows one event loop per process).

use winit::event_loop::EventLoop;

use crate::{Error, Options, Report, Result, Scene};

/// An event loop for viewer windows, made on any thread (X11, Wayland, Windows; macOS allows
/// only the main thread and says so through [`Error::WindowSystem`]).
pub struct Windows {
    event_loop: EventLoop<()>,
}

impl Windows {
    /// The event loop, on the calling thread. One per process: a second is refused by winit.
    pub fn new() -> Result<Self> {
        let mut builder = EventLoop::builder();
        #[cfg(all(unix, not(target_vendor = "apple"), not(target_os = "android")))]
        {
            use winit::platform::wayland::EventLoopBuilderExtWayland;
            use winit::platform::x11::EventLoopBuilderExtX11;
            EventLoopBuilderExtX11::with_any_thread(&mut builder, true);
            EventLoopBuilderExtWayland::with_any_thread(&mut builder, true);
        }
        #[cfg(target_os = "windows")]
        {
            use winit::platform::windows::EventLoopBuilderExtWindows;
            builder.with_any_thread(true);
        }
        let event_loop = builder.build().map_err(Error::WindowSystem)?;
        Ok(Self { event_loop })
    }

    /// Open a window on `scene` and run it until it is closed or `options`' scripted end, as
    /// [`crate::run`] does; the event loop stays for the next window.
    pub fn run(&mut self, scene: Scene, options: Options) -> Result<Report> {
        crate::app::run_on(&mut self.event_loop, scene, options)
    }
}
