//! The kinds of data the library renders, as files hold them: what [`crate::load`] tells a
//! file by, and what a [`crate::Error::WrongKind`] names.

/// A kind of data.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum DataKind {
    /// Triangle meshes.
    Mesh,
    /// Point clouds.
    Points,
    /// Scalar volumes.
    Volume,
    /// Images: RGB-D colour and depth maps, quilts (no scene: not a `--kind` to choose).
    #[cfg_attr(feature = "clap", value(skip))]
    Image,
    /// 3D Gaussian splats.
    Gaussians,
}

impl DataKind {
    /// Every kind.
    pub const ALL: [DataKind; 5] = [
        DataKind::Mesh,
        DataKind::Points,
        DataKind::Volume,
        DataKind::Image,
        DataKind::Gaussians,
    ];

    /// Its name: `mesh`, `points`, `volume`, `image`, `gaussians`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Mesh => "mesh",
            Self::Points => "points",
            Self::Volume => "volume",
            Self::Image => "image",
            Self::Gaussians => "gaussians",
        }
    }

    /// What data of this kind is, in a sentence ("a mesh", "3D Gaussian splats").
    pub fn article(self) -> &'static str {
        match self {
            Self::Mesh => "a mesh",
            Self::Points => "a point cloud",
            Self::Volume => "a volume",
            Self::Image => "an image",
            Self::Gaussians => "3D Gaussian splats",
        }
    }
}

impl std::str::FromStr for DataKind {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| {
                format!("'{s}' is not a kind of data (mesh, points, volume, image, gaussians)")
            })
    }
}
