//! Which cameras a renderer evaluates: one enum for every primitive.

use crate::error::{Error, Result};

/// How a multi-view frame is made. Every primitive has every method; options that only one
/// primitive has (mesh visibility, splat depth, volume path) sit in that renderer's options.
/// New methods are new variants (deliberately not `#[non_exhaustive]`: the tools match every
/// method, so the compiler lists each place a new one must be handled).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// One pass: each (sub)pixel evaluates its own view(s) straight into the spatial image.
    SinglePass,
    /// One ordinary render per view into its own layer, then mask compositing: the accuracy
    /// oracle and the speed baseline.
    NPass,
    /// The centre camera only (what a 2D display would show).
    SingleView,
}

impl Method {
    /// Every method, in the order the tools list them.
    pub const ALL: [Method; 3] = [Method::SinglePass, Method::NPass, Method::SingleView];

    /// Name as the CLI spells it.
    pub fn name(self) -> &'static str {
        match self {
            Method::SinglePass => "single-pass",
            Method::NPass => "n-pass",
            Method::SingleView => "single-view",
        }
    }
}

impl std::fmt::Display for Method {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
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
                    "method",
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
        assert!("tiled".parse::<Method>().is_err());
    }
}
