//! A render run decided from its flags, once: `RenderArgs::plan` checks every flag that can be
//! checked before loading (the names given included) and gives the plan the commands, outputs
//! and turntables take instead of the clap struct. The frame follows from the plan and the
//! scene's bounds (`RunPlan::frame`); the names it will write are checked against each other
//! and the inputs before it renders (`render_and_save`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::camera::{Bounds, CameraSettings};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::render::auto::{Accuracy, Choice, Workload};
use autostereo::render::Method;
use autostereo::RendererOptions;

use crate::args::{image_size, DisplayArgs, FramesArgs, RenderArgs};
use crate::claims::Claims;
use crate::method_arg::MethodArg;
use crate::output::flags::{Axis, OutputArg, OutputArgs};
use crate::warp_cmd::WarpArgs;

/// How large the view images are, where the method renders them.
#[derive(Clone, Copy, Debug, PartialEq)]
enum ViewSizing {
    Scale(f32),
    Size([u32; 2]),
}

/// A checked render run.
pub struct RunPlan {
    /// The method: the one named, or with `--method auto` the single pass until
    /// [`RunPlan::decide`] has chosen.
    pub method: Method,
    /// `--method auto`'s floor, while the method is still to be chosen or was chosen.
    auto: Option<Accuracy>,
    /// The first warp flag given, which leaves auto only the warp.
    warp_flag: Option<&'static str>,
    /// What auto chose and weighed.
    pub choice: Option<Choice>,
    /// Auto's line where the flags left it one method (no model needed).
    auto_note: Option<String>,
    /// The renderer options the shared flags say (method, warp); each command adds its
    /// primitive's.
    pub options: RendererOptions,
    display: Display,
    /// The display's flags, to repeat them in hints and `--json`.
    display_args: DisplayArgs,
    size: Option<[u32; 2]>,
    camera: CameraSettings,
    view_sizing: ViewSizing,
    pub output: OutputArgs,
    /// `--turntable FRAMES` and its axis.
    pub turntable: Option<(u32, Axis)>,
    /// How a video `--out` is encoded.
    pub video: autostereo::video::VideoSettings,
    pub hole_mask: Option<PathBuf>,
    pub timing: FramesArgs,
    pub compare: bool,
    /// The files the run reads and writes.
    pub claims: Claims,
    /// What the run renders: its file (none: the command's built-in scene) and kind, for the
    /// hint that repeats it in `autostereo view`.
    pub input: Option<PathBuf>,
    pub kind: autostereo::DataKind,
    /// The run's memory budget, current while the plan lives (held, never read).
    _budget: autostereo::budget::Entered,
}

impl RenderArgs {
    /// The run these flags and the command's `warp` flags ask for, reading `input` (data of
    /// `kind`): every
    /// check that needs no data, then the budget entered for the run.
    pub fn plan(
        self,
        input: Option<&Path>,
        kind: autostereo::DataKind,
        warp: WarpArgs,
    ) -> Result<RunPlan> {
        let claims = Claims::new(&input.into_iter().collect::<Vec<_>>());
        claims.check(&crate::claims::given(&[
            (self.output.out.as_deref(), "--out"),
            (warp.synthesis.hole_mask.as_deref(), "--hole-mask"),
        ]))?;
        self.output
            .check(self.compare || self.timing.frames.is_some())?;
        let scaled = [Method::NPass, Method::Tiled, Method::Layered, Method::Mrt];
        let flag = match self.view_size {
            Some([w, h]) => Some(format!("--view-size {w}x{h}")),
            None => (self.view_scale != 1.0).then(|| format!("--view-scale {}", self.view_scale)),
        };
        let (method, auto) = match self.method {
            MethodArg::Named(method) => {
                if let Some(db) = self.min_psnr {
                    bail!(
                        "--min-psnr {db}: only --method auto chooses by a PSNR floor (the method \
                         is {method}); drop it or use --method auto"
                    );
                }
                if let Some(flag) = flag.filter(|_| !scaled.contains(&method)) {
                    bail!(
                        "{flag}: the {method} method renders no view images to scale (only \
                         n-pass, tiled, layered and mrt do)"
                    );
                }
                warp.check(method)?;
                (method, None)
            }
            MethodArg::Auto => {
                if let Some(flag) = flag {
                    bail!(
                        "{flag}: sizes the view images of a method that renders them (n-pass, \
                         tiled, layered, mrt); --method auto chooses the method and its view \
                         size together: name the method, e.g. --method tiled {flag}"
                    );
                }
                if warp.given().is_some() {
                    warp.check(Method::Warp)?;
                }
                let accuracy = Accuracy::new(self.min_psnr)?;
                (Method::SinglePass, Some(accuracy))
            }
        };
        if self.output.format != OutputArg::Spatial {
            self.display
                .check_spatial_only(&self.output.format.name())?;
        }
        self.turntable.check(self.output.out.as_deref())?;
        Ok(RunPlan {
            method,
            auto,
            warp_flag: warp.given(),
            choice: None,
            auto_note: None,
            options: RendererOptions {
                method,
                warp: warp.options(),
                ..Default::default()
            },
            display: self.display.display()?,
            display_args: self.display,
            size: self.size,
            camera: self.camera.settings(),
            view_sizing: match self.view_size {
                Some(size) => ViewSizing::Size(size),
                None => ViewSizing::Scale(self.view_scale),
            },
            output: self.output,
            turntable: self.turntable.turntable.map(|n| (n, self.turntable.axis)),
            video: self.turntable.video.settings(30.0),
            hole_mask: warp.synthesis.hole_mask,
            timing: self.timing,
            compare: self.compare,
            claims,
            input: input.map(Path::to_path_buf),
            kind,
            _budget: self.memory.apply(),
        })
    }
}

impl RunPlan {
    /// Refuse flags the method would ignore before anything is loaded (`fits`: the command's
    /// check of its flags against one method); with auto, only flags that no method of the
    /// primitive's `methods` takes.
    pub fn check_flags(
        &self,
        methods: &[Method],
        fits: impl Fn(Method) -> Result<()>,
    ) -> Result<()> {
        match self.auto {
            None => fits(self.method),
            Some(_) if methods.iter().any(|&m| fits(m).is_ok()) => Ok(()),
            Some(_) => fits(Method::SinglePass),
        }
    }

    /// With `--method auto`: choose the method for `frame` (the scene within `bounds`,
    /// `workload` counting it, called only for auto) among the primitive's `methods` that the flags fit, and give
    /// the frame the view size it renders at. A named method keeps the frame as it is.
    pub fn decide(
        &mut self,
        mut frame: Frame,
        bounds: Bounds,
        workload: impl FnOnce(&Frame) -> Workload,
        methods: &[Method],
        fits: impl Fn(Method) -> Result<()>,
    ) -> Result<Frame> {
        let Some(accuracy) = self.auto else {
            return Ok(frame);
        };
        let offered: Vec<Method> = methods
            .iter()
            .copied()
            .filter(|&m| fits(m).is_ok())
            .filter(|&m| self.warp_flag.is_none() || m == Method::Warp)
            .collect();
        let method = match offered.as_slice() {
            [only] => {
                let why = self.warp_flag.unwrap_or("the other flags");
                self.auto_note = Some(format!("auto → {only} (the only method {why} fits)"));
                *only
            }
            _ => {
                let choice = autostereo::render::auto::choose(
                    &frame,
                    bounds,
                    workload(&frame),
                    accuracy,
                    &offered,
                )?;
                let chosen = choice.chosen();
                if chosen.view_size != frame.size {
                    frame.scale_views_to(chosen.view_size)?;
                    frame.validate()?;
                }
                let method = chosen.method;
                self.choice = Some(choice);
                method
            }
        };
        self.method = method;
        self.options.method = method;
        Ok(frame)
    }

    /// What auto chose, in a line for the summary; `None` for a named method.
    pub fn auto_line(&self) -> Option<String> {
        match &self.choice {
            Some(choice) => Some(choice.summary()),
            None => self.auto_note.clone(),
        }
    }

    /// The frame for a scene within `bounds`: display, camera framing, size, view images.
    pub fn frame(&self, bounds: Bounds) -> Result<Frame> {
        let display = self.display.clone();
        let size = image_size(self.size, &display);
        let camera = self.camera.camera(bounds, &display, size)?;
        let mut frame = Frame::new(camera, display, size)?;
        match self.view_sizing {
            ViewSizing::Size(views) => frame
                .scale_views_to(views)
                .map_err(|e| anyhow::anyhow!("--view-size: {e}"))?,
            ViewSizing::Scale(s) => frame.view_scale = [s; 2],
        }
        frame.validate()?;
        Ok(frame)
    }

    /// The display as the user gave it (`--display`'s spec).
    pub fn display_spec(&self) -> &str {
        &self.display_args.display
    }

    /// The display's flags as a command line would repeat them, with `views` views.
    pub fn display_flags(&self, views: u32) -> String {
        self.display_args.flags(views)
    }
}
