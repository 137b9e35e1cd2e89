//! What an error advises its caller to set, typed: the library's message says each setting in
//! the library's terms (`Visibility::Exact`), and a tool says the same value in its own words
//! (the CLI: `--visibility exact`) from [`crate::Error::advice`]. Renaming either side cannot
//! leave the other saying something stale, and a setting a tool has no words for fails to
//! compile there (an exhaustive `match`).

use std::fmt;

use crate::mesh::options::{TileClip, Visibility};
use crate::points::options::SplatDepth;
use crate::volume::options::VolumePath;

/// A setting an error names as the way out. Exhaustive on purpose: a tool's `match` that gives
/// each its words stops compiling when one is added.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Setting {
    /// The single-pass mesh visibility mode.
    Visibility(Visibility),
    /// The point splats' depth mode.
    SplatDepth(SplatDepth),
    /// How tiled duplication clips to its tile.
    TileClip(TileClip),
    /// The volume renderer's path.
    VolumePath(VolumePath),
    /// `Volume::downsample` by this factor.
    Downsample(u32),
    /// The memory budget's figure ([`crate::budget::Budget::set_max`]).
    MaxMemory,
    /// A raw volume's header bytes ([`crate::volume::load::RawSpec::header_bytes`]).
    RawHeaderBytes(u64),
    /// A raw volume's dimensions and sample type ([`crate::volume::load::RawSpec`]).
    RawLayout,
    /// A quilt's grid, given rather than read from its name.
    QuiltGrid,
    /// Resampling a depth map to its colour image's size.
    DepthResample,
}

impl fmt::Display for Setting {
    /// The library's name for the setting, as a Rust caller writes it.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Setting::Visibility(v) => write!(f, "Visibility::{v:?}"),
            Setting::SplatDepth(d) => write!(f, "SplatDepth::{d:?}"),
            Setting::TileClip(c) => write!(f, "TileClip::{c:?}"),
            Setting::VolumePath(VolumePath::RayMarch) => f.write_str("VolumePath::RayMarch"),
            Setting::VolumePath(VolumePath::Slices(_)) => f.write_str("VolumePath::Slices"),
            Setting::Downsample(n) => write!(f, "Volume::downsample({n})"),
            Setting::MaxMemory => f.write_str("Budget::set_max"),
            Setting::RawHeaderBytes(n) => write!(f, "RawSpec::header_bytes = {n}"),
            Setting::RawLayout => f.write_str("RawSpec"),
            Setting::QuiltGrid => f.write_str("QuiltImage::read's grid"),
            Setting::DepthResample => f.write_str("DepthMapOptions::resample"),
        }
    }
}

/// Advice in an error's message: words, with the settings it names kept as values.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Advice {
    pieces: Vec<Piece>,
}

#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Text(String),
    Setting(Setting),
}

impl Advice {
    /// Advice that starts with `text`.
    pub fn text(text: impl Into<String>) -> Self {
        Self::default().then_text(text)
    }

    /// `text` after this advice.
    pub fn then_text(mut self, text: impl Into<String>) -> Self {
        self.pieces.push(Piece::Text(text.into()));
        self
    }

    /// `setting` after this advice.
    pub fn then(mut self, setting: Setting) -> Self {
        self.pieces.push(Piece::Setting(setting));
        self
    }

    /// The settings it names, in order.
    pub fn settings(&self) -> impl Iterator<Item = Setting> + '_ {
        self.pieces.iter().filter_map(|p| match p {
            Piece::Setting(s) => Some(*s),
            Piece::Text(_) => None,
        })
    }

    /// The advice with each setting said by `say` (a tool's words for it).
    pub fn words(&self, say: impl Fn(Setting) -> String) -> String {
        self.pieces
            .iter()
            .map(|p| match p {
                Piece::Text(t) => t.clone(),
                Piece::Setting(s) => say(*s),
            })
            .collect()
    }
}

impl From<Setting> for Advice {
    fn from(setting: Setting) -> Self {
        Self::default().then(setting)
    }
}

impl fmt::Display for Advice {
    /// In the library's terms.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(&self.words(|s| s.to_string()))
    }
}

/// An optional advice as a message's tail (nothing where there is none).
pub(crate) fn tail(advice: &Option<Advice>) -> String {
    advice.as_ref().map_or_else(String::new, Advice::to_string)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn advice_says_settings_in_the_library_terms_or_a_tools_words() {
        let advice = Advice::text("use ")
            .then(Setting::Visibility(Visibility::Exact))
            .then_text(", which every adapter runs");
        assert_eq!(
            advice.to_string(),
            "use Visibility::Exact, which every adapter runs"
        );
        let words = advice.words(|s| match s {
            Setting::Visibility(Visibility::Exact) => "--visibility exact".into(),
            other => panic!("{other} is not in the advice"),
        });
        assert_eq!(words, "use --visibility exact, which every adapter runs");
        assert_eq!(
            advice.settings().collect::<Vec<_>>(),
            [Setting::Visibility(Visibility::Exact)]
        );
    }
}
