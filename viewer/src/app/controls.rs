//! The viewer's input (keys, mouse) and its scripted exercise run.

use crate::error::Result;
use autostereo::AnyRenderer;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event_loop::ActiveEventLoop;
use winit::keyboard::{Key, NamedKey};

use super::State;
use crate::options::{Options, Switch};
use autostereo::camera::Orbit;

/// Window sizes the exercise run alternates between.
const EXERCISE_SIZES: [[u32; 2]; 3] = [[320, 240], [256, 256], [400, 300]];
/// Frames between the exercise run's switches of method, display and window size.
const EVERY: [u32; 3] = [10, 70, 35];

impl State {
    pub(super) fn key(&mut self, key: &Key, event_loop: &ActiveEventLoop) -> Result<()> {
        match key {
            Key::Named(NamedKey::Escape) => event_loop.exit(),
            Key::Character(c) => match c.as_str() {
                "m" => self.next_method()?,
                "d" => self.display = (self.display + 1) % self.displays.len(),
                "p" => self.preview = self.preview.next(),
                "," | "." => {
                    let v = self.preview_view.unwrap_or(u32::MAX / 2) as i64;
                    let step = if c.as_str() == "," { -1 } else { 1 };
                    self.preview_view = Some((v + step).clamp(0, 255) as u32);
                }
                "[" => self.separation_scale /= 1.25,
                "]" => self.separation_scale *= 1.25,
                "-" => self.focal_scale /= 1.1,
                "=" | "+" => self.focal_scale *= 1.1,
                "c" => self.key_clip.next_axis(),
                "9" => self.key_clip.nudge(-1.0),
                "0" => self.key_clip.nudge(1.0),
                "r" => {
                    self.orbit = Orbit::default();
                    self.separation_scale = 1.0;
                    self.focal_scale = 1.0;
                }
                _ => {}
            },
            _ => {}
        }
        Ok(())
    }

    pub(super) fn next_method(&mut self) -> Result<()> {
        self.method = (self.method + 1) % self.methods.len();
        if self.renderers[self.method].is_none() {
            let method = self.methods[self.method];
            let options = self.scene.options(method);
            let renderer = AnyRenderer::new(&self.ctx.device, &self.scene.scene, &options)?;
            self.renderers[self.method] = Some(renderer);
        }
        Ok(())
    }

    pub(super) fn drag(&mut self, position: PhysicalPosition<f64>) {
        if let Some(last) = self.cursor {
            let (dx, dy) = ((position.x - last.x) as f32, (position.y - last.y) as f32);
            if self.buttons.0 {
                self.orbit.turn(dx, dy);
            } else if self.buttons.1 {
                self.orbit.slide(dx, dy, self.config.height as f32);
            }
        }
        self.cursor = Some(position);
    }

    /// The scripted stress run: switch methods, displays and window sizes as it goes.
    pub(super) fn exercise_step(&mut self, options: &Options) -> Result<()> {
        if options.exercise.is_none() || self.frames == 0 {
            return Ok(());
        }
        let f = self.frames;
        let switch = |what| options.exercise_switch.contains(&what);
        if f.is_multiple_of(EVERY[0]) && switch(Switch::Methods) {
            self.next_method()?;
        }
        if f.is_multiple_of(EVERY[1]) && switch(Switch::Displays) {
            self.display = (self.display + 1) % self.displays.len();
        }
        if f.is_multiple_of(EVERY[2]) && switch(Switch::Sizes) {
            let [w, h] = EXERCISE_SIZES[(f / EVERY[2]) as usize % EXERCISE_SIZES.len()];
            if let Some(size) = self.window.request_inner_size(PhysicalSize::new(w, h)) {
                self.resize(size);
            }
        }
        Ok(())
    }
}

impl State {
    /// Frames after which the exercise run's whole state repeats: every switched choice back
    /// where it started, and (from the second period on) every cached renderer holding what it
    /// held a period before, so resident memory one period apart must be equal.
    pub(super) fn exercise_period(&self, options: &Options) -> u32 {
        let cycles = [
            (Switch::Methods, EVERY[0] * self.methods.len() as u32),
            (Switch::Displays, EVERY[1] * self.displays.len() as u32),
            (Switch::Sizes, EVERY[2] * EXERCISE_SIZES.len() as u32),
        ];
        cycles
            .into_iter()
            .filter(|(what, _)| options.exercise_switch.contains(what))
            .fold(1, |period, (_, cycle)| lcm(period, cycle))
    }
}

fn lcm(a: u32, b: u32) -> u32 {
    let gcd = |mut a: u32, mut b: u32| {
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    a / gcd(a, b) * b
}
