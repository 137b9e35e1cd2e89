//! Pipeline specialisation: the override constants of `wgsl/shared/multiview.wgsl`.

/// What a single-pass pipeline is specialised for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Specialization {
    /// Views per pixel K (1 or 3).
    pub views_per_pixel: u32,
    /// Number of views N.
    pub view_count: u32,
}

impl Specialization {
    /// Specialisation for `frame`'s display.
    pub fn of(frame: &crate::frame::Frame) -> Self {
        Self {
            views_per_pixel: frame.display.views_per_pixel(),
            view_count: frame.camera.views,
        }
    }

    /// The override constants, plus any `extra` ones of the stage.
    pub fn constants(&self, extra: &[(&'static str, f64)]) -> Vec<(&'static str, f64)> {
        let mut c = vec![
            ("VIEWS_PER_PIXEL", self.views_per_pixel as f64),
            ("VIEW_COUNT", self.view_count as f64),
        ];
        c.extend_from_slice(extra);
        c
    }
}
