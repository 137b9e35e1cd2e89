//! Which cameras a renderer evaluates: one enum for every primitive.

use crate::error::{Error, Result};
use crate::param::Param;

/// How a multi-view frame is made. Not every primitive has every method: MRT (one depth
/// buffer shared by the views of a draw) is the meshes' alone, and an RGB-D image is only
/// warped; the others are refused with the reason when the renderer is built
/// ([`crate::RendererOptions`]). Options that only one primitive has (mesh visibility, splat
/// depth, volume path) sit in that primitive's options. New methods are new variants
/// (deliberately not `#[non_exhaustive]`: the tools match every method, so the compiler lists
/// each place a new one must be handled).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Method {
    /// One pass: each (sub)pixel evaluates its own view(s) straight into the spatial image.
    #[default]
    SinglePass,
    /// One ordinary render per view into its own layer, then mask compositing: the accuracy
    /// oracle and the speed baseline.
    NPass,
    /// The centre camera only (what a 2D display would show).
    SingleView,
    /// de Sorbier et al.: the geometry duplicated per view in one draw (instancing), each copy
    /// in its own tile of one atlas laid out as a Looking Glass quilt, one depth buffer; then
    /// the mask composites from the atlas.
    Tiled,
    /// Beck et al.: one draw into the layers of a texture array, per-layer depth (multiview
    /// where the adapter has it, in as few passes as its view limit allows; one pass per
    /// layer where it has none); then the mask composites.
    Layered,
    /// de Sorbier, Nozick & Biri: up to 8 views per draw into multiple render targets sharing
    /// one depth buffer. Views of one draw occlude each other through that buffer: an
    /// approximation, measured against the N-pass.
    Mrt,
    /// Beck et al.: R reference views rendered with their depth (N-pass of R views), every
    /// view synthesised by warping them, holes filled from the background side
    /// ([`crate::warp::SceneWarp`]; R = [`crate::warp::DEFAULT_REFERENCES`] unless its options
    /// say otherwise). An approximation, measured against the N-pass.
    Warp,
}

impl Method {
    /// Every method, in the order the tools list them.
    pub const ALL: [Method; 7] = [
        Method::SinglePass,
        Method::NPass,
        Method::SingleView,
        Method::Tiled,
        Method::Layered,
        Method::Mrt,
        Method::Warp,
    ];

    /// The per-view duplication methods (one draw renders every view's copy).
    pub const DUPLICATION: [Method; 3] = [Method::Tiled, Method::Layered, Method::Mrt];

    /// Name as the CLI spells it.
    pub fn name(self) -> &'static str {
        match self {
            Method::SinglePass => "single-pass",
            Method::NPass => "n-pass",
            Method::SingleView => "single-view",
            Method::Tiled => "tiled",
            Method::Layered => "layered",
            Method::Mrt => "mrt",
            Method::Warp => "warp",
        }
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// As its name (`"single-pass"`), in reports.
impl serde::Serialize for Method {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl std::str::FromStr for Method {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        Method::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                let names: Vec<_> = Method::ALL.iter().map(|m| m.name()).collect();
                Error::invalid(
                    Param::Method,
                    format!("'{s}': expected one of {}", names.join(", ")),
                )
            })
    }
}

#[cfg(test)]
mod tests {
    use super::Method;

    #[test]
    fn names_round_trip() {
        for m in Method::ALL {
            assert_eq!(m.name().parse::<Method>().unwrap(), m);
        }
        assert!("tile".parse::<Method>().is_err());
    }
}
