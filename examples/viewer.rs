//! The smallest complete viewer on the public API: a window (winit), its surface, the event
//! loop, resizing, and per frame: prepare, record the single pass into our encoder, copy the
//! spatial image into the surface texture, present. The mask's origin follows the window on
//! the screen, so every subpixel stays on its view when the window moves.
//!
//! `cargo run --release --example viewer` (a window system: under Xvfb, `xvfb-run -a …`).

use std::sync::Arc;

use anyhow::{Context, Result};
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::render::{Method, OutputBlit, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeSettings;
use autostereo::volume::{generate, TransferFunction};
use autostereo::volume::{VolumeRaycaster, VolumeScene};
use glam::Mat4;
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::window::{Window, WindowId};

/// What one open window holds.
struct Viewer {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    ctx: GpuContext,
    blit: OutputBlit,
    scene: VolumeScene,
    bounds: autostereo::camera::Bounds,
    renderer: VolumeRaycaster,
    target: Option<SpatialTarget>,
}

impl Viewer {
    fn new(event_loop: &ActiveEventLoop) -> Result<Self> {
        let window = Arc::new(event_loop.create_window(Window::default_attributes())?);
        // The instance carries the window system's display (GL needs it to present).
        let instance = wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle(
            Box::new(event_loop.owned_display_handle()),
        ));
        let surface = instance.create_surface(window.clone())?;
        let ctx = GpuContext::for_surface(&instance, &surface, &Default::default())?;
        let size = window.inner_size();
        let mut config = surface
            .get_default_config(&ctx.adapter, size.width.max(1), size.height.max(1))
            .context("the adapter cannot present to this window")?;
        // The spatial image must reach the panel value for value: an 8-bit format.
        let caps = surface.get_capabilities(&ctx.adapter);
        config.format = *caps
            .formats
            .iter()
            .find(|f| autostereo::render::OUTPUT_FORMATS.contains(f))
            .context("no 8-bit surface format")?;
        surface.configure(&ctx.device, &config);
        let volume = generate::ct_head(64)?;
        let transfer = TransferFunction::preset("ct-skin")?;
        let scene = VolumeScene::new(&ctx.device, &ctx.queue, &volume, transfer, Mat4::IDENTITY)?;
        Ok(Self {
            blit: OutputBlit::new(&ctx.device, config.format)?,
            renderer: VolumeRaycaster::new(
                &ctx.device,
                Method::SinglePass,
                VolumeSettings::default(),
            )?,
            bounds: volume.bounds(),
            window,
            surface,
            config,
            ctx,
            scene,
            target: None,
        })
    }

    fn draw(&mut self) -> Result<()> {
        let (device, queue) = (&self.ctx.device, &self.ctx.queue);
        let size = [self.config.width, self.config.height];
        let mut display = Display::parse("hubner8")?;
        let position = self.window.inner_position().unwrap_or_default();
        // Negative left of or above the primary monitor: the mask takes it as it is.
        display.origin = [position.x, position.y];
        let aspect = size[0] as f32 / size[1] as f32;
        let camera = MultiViewCamera::framing(self.bounds, display.views(), None, 0.5, aspect)?;
        let frame = Frame::new(camera, display, size)?;
        if self.target.as_ref().is_none_or(|t| t.size() != size) {
            self.target = Some(SpatialTarget::new(device, size)?);
        }
        let target = self.target.as_ref().expect("allocated above");
        self.renderer.prepare(device, queue, &self.scene, &frame)?;
        let wgpu::CurrentSurfaceTexture::Success(texture) = self.surface.get_current_texture()
        else {
            self.surface.configure(device, &self.config);
            return Ok(());
        };
        let mut encoder = device.create_command_encoder(&Default::default());
        self.renderer
            .encode(device, &mut encoder, &self.scene, &frame, target)?;
        self.blit
            .encode(device, &mut encoder, target, &texture.texture)?;
        queue.submit([encoder.finish()]);
        queue.present(texture);
        Ok(())
    }
}

#[derive(Default)]
struct App {
    viewer: Option<Viewer>,
    error: Option<anyhow::Error>,
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.viewer.is_none() {
            match Viewer::new(event_loop) {
                Ok(v) => self.viewer = Some(v),
                Err(e) => {
                    self.error = Some(e);
                    event_loop.exit();
                }
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(viewer) = self.viewer.as_mut() else {
            return;
        };
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) if size.width > 0 && size.height > 0 => {
                viewer.config.width = size.width;
                viewer.config.height = size.height;
                viewer.surface.configure(&viewer.ctx.device, &viewer.config);
            }
            WindowEvent::Moved(_) => viewer.window.request_redraw(),
            WindowEvent::RedrawRequested => {
                if let Err(e) = viewer.draw() {
                    self.error = Some(e);
                    event_loop.exit();
                }
            }
            _ => {}
        }
    }
}

fn main() -> Result<()> {
    let mut app = App::default();
    EventLoop::new()?.run_app(&mut app)?;
    app.error.map_or(Ok(()), Err)
}
