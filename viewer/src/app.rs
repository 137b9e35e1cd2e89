//! The window, its event loop and one frame: render the scene into a spatial target, copy it
//! into the surface texture (`OutputBlit`), present.

use std::sync::Arc;
use std::time::Instant;

use crate::error::{Error, Result};
use autostereo::display::Display;
use autostereo::gpu::GpuContext;
use autostereo::render::{Method, OutputBlit, Renderer, StereoCompositor, OUTPUT_FORMATS};
use autostereo::target::SpatialTarget;
use autostereo::AnyRenderer;
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::window::{Fullscreen, Window, WindowId};

use crate::options::{Options, Preview};
use crate::scene::{Scene, Uploaded};
use crate::Report;
use autostereo::camera::Orbit;

mod clip;
mod controls;
mod frames;
mod images;
mod memory;
mod report;
mod window_checks;

use images::copyable_target;
use memory::MemoryLog;
use window_checks::{check_monitor, check_window_size, largest_surface};

/// Frames after which `--screenshot` is taken (and the viewer exits, without `--keep-open`)
/// without `--quit-after-frames`.
const SCREENSHOT_FRAME: u32 = 3;

/// Displays the `d` key steps through after the one given.
const MORE_DISPLAYS: [&str; 4] = [
    "hubner8",
    "lenticular:8",
    "slanted:45,8,2/3,7/6",
    "lenticular:4",
];

pub fn run(scene: Scene, options: Options) -> Result<Report> {
    let event_loop = EventLoop::new().map_err(Error::WindowSystem)?;
    let mut app = App::new(scene, options);
    event_loop.run_app(&mut app)?;
    app.report()
}

/// [`run`] on an event loop that outlives the window (`crate::Windows`): the window closes
/// when the run ends, the loop stays for the next.
pub fn run_on(event_loop: &mut EventLoop<()>, scene: Scene, options: Options) -> Result<Report> {
    use winit::platform::run_on_demand::EventLoopExtRunOnDemand;
    let mut app = App::new(scene, options);
    event_loop.run_app_on_demand(&mut app)?;
    app.report()
}

impl App {
    fn new(scene: Scene, options: Options) -> Self {
        Self {
            options,
            scene: Some(scene),
            state: None,
            error: None,
        }
    }

    /// What the run showed, or why it failed.
    fn report(self) -> Result<Report> {
        match (self.error, &self.state) {
            (Some(e), _) => Err(e),
            (None, Some(state)) => Ok(report::report(state)),
            (None, None) => Err(Error::NeverOpened),
        }
    }
}

struct App {
    options: Options,
    /// Until the window opens and it is uploaded.
    scene: Option<Scene>,
    state: Option<State>,
    error: Option<Error>,
}

/// Everything a running window holds.
struct State {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    ctx: GpuContext,
    blit: OutputBlit,
    scene: Uploaded,
    /// The methods the scene's primitive has on this adapter, and the one in use.
    methods: Vec<Method>,
    method: usize,
    /// One renderer per method, built when first used and kept: switching back is instant and,
    /// once every method has run, nothing new is built (the exercise run's flat memory).
    renderers: Vec<Option<AnyRenderer>>,
    /// The displays the `d` key steps through (the given one first), parsed once.
    displays: Vec<(String, Display)>,
    display: usize,
    preview: Preview,
    /// The view shown by the one-view preview.
    preview_view: Option<u32>,
    orbit: Orbit,
    separation_scale: f32,
    focal_scale: f32,
    /// A volume's key-driven clipping plane, and the planes the scene came with.
    key_clip: clip::KeyClip,
    given_clip: Vec<autostereo::volume::ClipPlane>,
    /// The window's spatial image, and the stereo previews' left and right eyes.
    targets: [Option<SpatialTarget>; 3],
    stereo: StereoCompositor,
    /// Window client area on its monitor (the mask's origin).
    position: [i32; 2],
    /// The monitor a full-screen window was put on (its position on the desktop): the panel,
    /// whatever the window system says the window's monitor is before it has moved there.
    fullscreen_on: Option<winit::monitor::MonitorHandle>,
    cursor: Option<PhysicalPosition<f64>>,
    buttons: (bool, bool),
    frames: u32,
    last_ms: f64,
    /// What an exercise run records of its memory.
    memory: MemoryLog,
    /// The exercise run's report, made when it ends (printed by `report::print`).
    exercise_report: Option<serde_json::Value>,
    /// Files written (the screenshot), for `--json`.
    written: Vec<std::path::PathBuf>,
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        let Some(scene) = self.scene.take() else {
            return;
        };
        match State::new(event_loop, scene, &self.options) {
            Ok(state) => {
                state.window.request_redraw();
                self.state = Some(state);
            }
            Err(e) => {
                self.error = Some(e);
                event_loop.exit();
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(state) = self.state.as_mut() else {
            return;
        };
        let result = match event {
            WindowEvent::CloseRequested => {
                event_loop.exit();
                Ok(())
            }
            WindowEvent::Resized(size) => {
                state.resize(size);
                Ok(())
            }
            WindowEvent::Moved(_) => {
                state.update_position();
                Ok(())
            }
            WindowEvent::RedrawRequested => state.redraw(&self.options).map(|done| {
                if done {
                    event_loop.exit();
                } else {
                    state.window.request_redraw();
                }
            }),
            WindowEvent::KeyboardInput { event, .. } if event.state == ElementState::Pressed => {
                state.key(&event.logical_key, event_loop)
            }
            WindowEvent::MouseInput {
                state: s, button, ..
            } => {
                let down = s == ElementState::Pressed;
                match button {
                    MouseButton::Left => state.buttons.0 = down,
                    MouseButton::Right | MouseButton::Middle => state.buttons.1 = down,
                    _ => {}
                }
                Ok(())
            }
            WindowEvent::CursorMoved { position, .. } => {
                state.drag(position);
                Ok(())
            }
            WindowEvent::MouseWheel { delta, .. } => {
                let steps = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                };
                state.orbit.dolly(steps);
                Ok(())
            }
            _ => Ok(()),
        };
        if let Err(e) = result {
            self.error = Some(e);
            event_loop.exit();
        }
    }
}

impl State {
    fn new(event_loop: &ActiveEventLoop, scene: Scene, options: &Options) -> Result<Self> {
        let mut attributes = Window::default_attributes()
            .with_title("autostereo")
            .with_inner_size(PhysicalSize::new(options.size[0], options.size[1]));
        if let Some([x, y]) = options.position {
            attributes = attributes.with_position(PhysicalPosition::new(x, y));
        }
        let mut fullscreen_on = None;
        if let Some(choice) = options.fullscreen {
            let monitors: Vec<_> = event_loop.available_monitors().collect();
            let (monitor, said) = crate::monitors::pick(&monitors, choice, &options.display)?;
            eprintln!("{said}");
            fullscreen_on = Some(monitor.clone());
            // Also the monitor's position and size: without a window manager (Xvfb, a kiosk
            // panel) nothing acts on the fullscreen request.
            attributes = attributes
                .with_position(monitor.position())
                .with_inner_size(monitor.size())
                .with_fullscreen(Some(Fullscreen::Borderless(Some(monitor))));
        }
        let mut desc = wgpu::InstanceDescriptor::new_with_display_handle(Box::new(
            event_loop.owned_display_handle(),
        ));
        desc.backends = autostereo::gpu::GpuOptions::default().backends();
        let instance = wgpu::Instance::new(desc);
        // Before the window: a size no adapter here can present is refused by name (the window
        // system and wgpu's surface validation would panic on it).
        if options.fullscreen.is_none() {
            let (limit, adapter) = largest_surface(&instance);
            check_window_size(options.size, false, limit, &adapter)?;
        }
        let window = Arc::new(event_loop.create_window(attributes)?);
        let surface = instance.create_surface(window.clone())?;
        let ctx = GpuContext::for_surface(&instance, &surface, &Default::default())?;
        // And on the adapter chosen, which may allow less than the largest.
        let inner = window.inner_size();
        let size = match options.fullscreen {
            None => options.size,
            Some(_) => [inner.width, inner.height],
        };
        check_window_size(
            size,
            options.fullscreen.is_some(),
            ctx.device.limits().max_texture_dimension_2d,
            &ctx.adapter_label(),
        )?;
        let caps = surface.get_capabilities(&ctx.adapter);
        let format = caps
            .formats
            .iter()
            .copied()
            .find(|f| OUTPUT_FORMATS.contains(f))
            .ok_or_else(|| Error::SurfaceFormat {
                wanted: OUTPUT_FORMATS.to_vec(),
            })?;
        let size = window.inner_size();
        // COPY_SRC where offered, so that --screenshot reads what was presented.
        let usage =
            wgpu::TextureUsages::RENDER_ATTACHMENT | (caps.usages & wgpu::TextureUsages::COPY_SRC);
        let config = wgpu::SurfaceConfiguration {
            usage,
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width: size.width.max(1),
            height: size.height.max(1),
            desired_maximum_frame_latency: 2,
            present_mode: wgpu::PresentMode::Fifo,
            alpha_mode: wgpu::CompositeAlphaMode::Auto,
            view_formats: vec![],
        };
        surface.configure(&ctx.device, &config);
        let blit = OutputBlit::new(&ctx.device, format)?;
        let stereo = StereoCompositor::new(&ctx.device)?;
        let scene = scene.upload(&ctx)?;
        let methods: Vec<Method> = Method::ALL
            .into_iter()
            .filter(|&m| AnyRenderer::new(&ctx.device, &scene.scene, &scene.options(m)).is_ok())
            .collect();
        let method = methods
            .iter()
            .position(|&m| m == options.method)
            .ok_or_else(|| Error::MethodUnavailable {
                method: options.method,
                primitive: scene.scene.primitive().to_string(),
                available: methods.clone(),
            })?;
        let mut renderers: Vec<Option<AnyRenderer>> = methods.iter().map(|_| None).collect();
        renderers[method] = Some(AnyRenderer::new(
            &ctx.device,
            &scene.scene,
            &scene.options(methods[method]),
        )?);
        check_monitor(&window, fullscreen_on.as_ref(), &options.display);
        let mut displays = vec![(options.display_name.clone(), options.display.clone())];
        for spec in MORE_DISPLAYS.iter().filter(|d| **d != options.display_name) {
            displays.push((spec.to_string(), Display::parse(spec)?));
        }
        let given_clip = match &scene.scene {
            autostereo::AnyScene::Volume(v) => v.clip.clone(),
            _ => Vec::new(),
        };
        let mut state = Self {
            window,
            surface,
            config,
            ctx,
            blit,
            scene,
            methods,
            method,
            renderers,
            displays,
            display: 0,
            preview: options.preview,
            preview_view: None,
            orbit: options.orbit,
            separation_scale: 1.0,
            focal_scale: 1.0,
            key_clip: clip::KeyClip::default(),
            given_clip,
            targets: [None, None, None],
            stereo,
            position: [0, 0],
            fullscreen_on,
            cursor: None,
            buttons: (false, false),
            frames: 0,
            last_ms: 0.0,
            memory: MemoryLog::default(),
            exercise_report: None,
            written: Vec::new(),
        };
        state.update_position();
        Ok(state)
    }

    /// The mask's origin from where the client area sits on its monitor (the panel: its pixels
    /// are the mask's, wherever the monitor is on the desktop).
    fn update_position(&mut self) {
        if let Ok(p) = self.window.inner_position() {
            let monitor = self
                .fullscreen_on
                .clone()
                .or_else(|| self.window.current_monitor());
            let monitor = monitor.map(|m| m.position());
            let [mx, my] = monitor.map_or([0, 0], |m| [m.x, m.y]);
            self.position = [p.x - mx, p.y - my];
        }
    }

    fn resize(&mut self, size: PhysicalSize<u32>) {
        if size.width == 0 || size.height == 0 {
            return;
        }
        self.config.width = size.width;
        self.config.height = size.height;
        self.surface.configure(&self.ctx.device, &self.config);
        self.update_position();
    }

    /// Render and present one frame; `Ok(true)` when the run is over.
    fn redraw(&mut self, options: &Options) -> Result<bool> {
        self.exercise_step(options)?;
        let start = Instant::now();
        let frames = self.frames(options)?;
        let device = &self.ctx.device;
        let size = [self.config.width, self.config.height];
        let eyes = frames[0].0.size;
        for (slot, wanted, used) in [
            (0, size, true),
            (1, eyes, frames.len() > 1),
            (2, eyes, self.preview.stereo().is_some()),
        ] {
            if !used {
                self.targets[slot] = None;
            } else if self.targets[slot]
                .as_ref()
                .is_none_or(|t| t.size() != wanted)
            {
                self.targets[slot] = None; // free before allocating the replacement
                self.targets[slot] = Some(copyable_target(device, wanted)?);
            }
        }
        let surface_texture = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t)
            | wgpu::CurrentSurfaceTexture::Suboptimal(t) => t,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(device, &self.config);
                return Ok(false);
            }
            _ => return Ok(false), // timeout, occluded: try the next frame
        };
        let mut encoder = device.create_command_encoder(&Default::default());
        let renderer = self.renderers[self.method]
            .as_mut()
            .expect("built when selected");
        let target = self.targets[0].as_ref().expect("allocated above");
        if self.preview == Preview::Quilt {
            // The tiles may not fill the window: black around them.
            let clear = wgpu::RenderPassColorAttachment {
                view: &target.view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            };
            encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("quilt background"),
                color_attachments: &[Some(clear)],
                ..Default::default()
            });
        }
        if let autostereo::AnyScene::Volume(volume) = &mut self.scene.scene {
            volume.clip = self.key_clip.planes(&self.given_clip, volume.extent);
        }
        for (frame, slot, copy_to) in &frames {
            let into = self.targets[*slot].as_ref().expect("allocated above");
            renderer.prepare(device, &self.ctx.queue, &self.scene.scene, frame)?;
            renderer.encode(device, &mut encoder, &self.scene.scene, frame, into)?;
            if let Some([x, y]) = *copy_to {
                // One tile target serves every view: the copies keep the encoder's order.
                encoder.copy_texture_to_texture(
                    into.texture.as_image_copy(),
                    wgpu::TexelCopyTextureInfo {
                        origin: wgpu::Origin3d { x, y, z: 0 },
                        ..target.texture.as_image_copy()
                    },
                    into.texture.size(),
                );
            }
        }
        if let Some(format) = self.preview.stereo() {
            let eye = |i: usize| self.targets[i].as_ref().expect("allocated above");
            self.stereo
                .encode(device, &mut encoder, format, eye(1), eye(2), target)?;
        }
        self.blit
            .encode(device, &mut encoder, target, &surface_texture.texture)?;
        self.ctx.queue.submit([encoder.finish()]);
        // Free what finished frames held (each frame's small constant buffers and bind
        // groups) now rather than whenever the backend next looks.
        let _ = device.poll(wgpu::PollType::Poll);
        self.frames += 1;
        let shot_at = options.quit_after_frames.unwrap_or(SCREENSHOT_FRAME);
        // A screenshot ends the run (scripts wait for the process) unless --keep-open.
        let last = options.quit_after_frames.or(options.exercise).or(options
            .screenshot
            .as_ref()
            .filter(|_| !options.keep_open)
            .map(|_| shot_at));
        if let Some(path) = options
            .screenshot
            .as_ref()
            .filter(|_| self.frames == shot_at)
        {
            self.screenshot(&surface_texture.texture, target)?
                .save_png(path)?;
            self.written.push(path.clone());
        }
        self.ctx.queue.present(surface_texture);
        self.last_ms = start.elapsed().as_secs_f64() * 1e3;
        self.window.set_title(&format!(
            "autostereo — {}{} — {} — {} ({} views{}) — {:.1} ms",
            self.scene.name,
            self.key_clip
                .describe()
                .map_or_else(String::new, |c| format!(", {c}")),
            self.methods[self.method],
            self.displays[self.display].0,
            frames[0].0.camera.views,
            match self.preview {
                Preview::Spatial => String::new(),
                other => format!(", {} preview", other.name()),
            },
            self.last_ms
        ));
        if let Some((k, [x, y])) = options.move_after {
            if self.frames == k {
                self.window.set_outer_position(PhysicalPosition::new(x, y));
            }
        }
        self.memory.after_frame(self.frames);
        if options.exercise.is_some() && self.frames.is_multiple_of(self.exercise_period(options)) {
            self.memory.end_period(device);
        }
        let done = last.is_some_and(|k| self.frames >= k);
        if done && options.exercise.is_some() {
            let mut report = self.memory.report();
            report["frames"] = self.frames.into();
            report["period_frames"] = self.exercise_period(options).into();
            // The test's heap bound depends on the backend (see cli/tests/viewer/).
            report["backend"] = self.ctx.info().backend.to_str().into();
            self.exercise_report = Some(report);
        }
        Ok(done)
    }
}
