//! What the viewer checks before it opens or fills a window: the monitor against a Looking
//! Glass calibration's panel, and the window's size against the largest surface an adapter
//! makes (wgpu and winit would panic on a larger one).

use crate::error::{Error, Result};
use autostereo::display::Display;
use winit::window::Window;

/// Say so when the window's monitor is not the display's panel (a Looking Glass calibration
/// knows its panel's size): the mask then does not meet the lenses it was made for.
pub(super) fn check_monitor(
    window: &Window,
    fullscreen_on: Option<&winit::monitor::MonitorHandle>,
    display: &Display,
) {
    let monitor = fullscreen_on.cloned().or_else(|| window.current_monitor());
    let (Some(panel), Some(monitor)) = (display.panel_size(), monitor) else {
        return;
    };
    let size = monitor.size();
    let name = monitor.name().unwrap_or_else(|| "?".into());
    if [size.width, size.height] == panel {
        eprintln!(
            "monitor {name} ({}x{}) has the calibration's panel size",
            size.width, size.height
        );
    } else {
        eprintln!(
            "note: this window is on monitor {name} ({}x{}), but the calibration's panel is \
             {}x{}: the image matches the lenses only on the Looking Glass itself (full screen \
             on its monitor)",
            size.width, size.height, panel[0], panel[1]
        );
    }
}

/// The largest surface side among the adapters the viewer could choose (`WGPU_BACKEND`,
/// `WGPU_ADAPTER_NAME`), and that adapter's name; wgpu's default limit (8192) where none is
/// found (the context's own error then says so).
pub(super) fn largest_surface(instance: &wgpu::Instance) -> (u32, String) {
    let backends = autostereo::gpu::GpuOptions::default().backends();
    let name = std::env::var("WGPU_ADAPTER_NAME")
        .ok()
        .filter(|n| !n.is_empty())
        .map(|n| n.to_lowercase());
    block_on(instance.enumerate_adapters(backends))
        .into_iter()
        .filter_map(|adapter| {
            let info = adapter.get_info();
            let chosen = name
                .as_ref()
                .is_none_or(|n| info.name.to_lowercase().contains(n));
            chosen.then(|| {
                (
                    adapter.limits().max_texture_dimension_2d,
                    format!("{} ({:?})", info.name, info.backend),
                )
            })
        })
        .max_by_key(|(limit, _)| *limit)
        .unwrap_or_else(|| {
            (
                wgpu::Limits::default().max_texture_dimension_2d,
                "any adapter".into(),
            )
        })
}

/// Refuse a window larger than `limit` per side (the surface's largest on `adapter`).
/// `fullscreen`: the size is the monitor's, not the one asked for.
pub(super) fn check_window_size(
    size: [u32; 2],
    fullscreen: bool,
    limit: u32,
    adapter: &str,
) -> Result<()> {
    if size[0] > limit || size[1] > limit {
        return Err(Error::WindowTooLarge {
            size,
            fullscreen,
            limit,
            adapter: adapter.to_string(),
        });
    }
    Ok(())
}

/// Run a future that does not wait on anything outside (wgpu's adapter list) to its end.
fn block_on<F: std::future::Future>(future: F) -> F::Output {
    let mut future = std::pin::pin!(future);
    let mut cx = std::task::Context::from_waker(std::task::Waker::noop());
    loop {
        if let std::task::Poll::Ready(out) = future.as_mut().poll(&mut cx) {
            return out;
        }
        std::thread::yield_now();
    }
}
