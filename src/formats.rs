//! What a file is: its format from its first bytes where the format has a signature, else from
//! its extension, and which primitive reads it, so that a file given as the wrong kind is
//! refused saying what it is ([`Error::WrongKind`]: "head.nrrd: this is a volume (NRRD), not a
//! mesh") instead of failing inside the wrong parser.

use std::fmt;
use std::io::Read;
use std::path::Path;

pub use crate::data_kind::DataKind;
use crate::error::{Error, Result};

/// The file formats the project knows, read or not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Wavefront OBJ (meshes; its vertices as points).
    Obj,
    /// Stanford PLY (a mesh when it has faces; its vertices as points).
    Ply,
    /// STL, binary or ASCII.
    Stl,
    /// glTF 2.0, JSON (`.gltf`) or binary (`.glb`).
    Gltf,
    /// NRRD (`.nrrd`, `.nhdr`).
    Nrrd,
    /// VolPack's `.den`.
    Den,
    /// Raw voxels (`.raw`, with the dimensions and type given separately).
    Raw,
    /// NIfTI-1 (`.nii`, `.nii.gz`).
    Nifti,
    /// DICOM (a file of a series).
    Dicom,
    /// MetaImage (`.mha`, `.mhd`).
    MetaImage,
    /// VTK image data (`.vti`, legacy `.vtk`).
    Vtk,
    /// LAS / LAZ lidar points.
    Las,
    /// PNG images.
    Png,
    /// JPEG images.
    Jpeg,
    /// antimatter15's `.splat` Gaussian splats.
    Splat,
    /// Niantic's `.spz` Gaussian splats.
    Spz,
}

/// Every format, in the order errors list them.
pub const FORMATS: [Format; 16] = [
    Format::Obj,
    Format::Ply,
    Format::Stl,
    Format::Gltf,
    Format::Nrrd,
    Format::Den,
    Format::Raw,
    Format::Nifti,
    Format::Dicom,
    Format::MetaImage,
    Format::Vtk,
    Format::Las,
    Format::Png,
    Format::Jpeg,
    Format::Splat,
    Format::Spz,
];

impl Format {
    /// The format's usual name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Obj => "OBJ",
            Self::Ply => "PLY",
            Self::Stl => "STL",
            Self::Gltf => "glTF",
            Self::Nrrd => "NRRD",
            Self::Den => "DEN",
            Self::Raw => "raw voxels",
            Self::Nifti => "NIfTI",
            Self::Dicom => "DICOM",
            Self::MetaImage => "MetaImage",
            Self::Vtk => "VTK image data",
            Self::Las => "LAS/LAZ",
            Self::Png => "PNG",
            Self::Jpeg => "JPEG",
            Self::Splat => "antimatter15 splat",
            Self::Spz => "SPZ",
        }
    }

    /// The extensions that name it (lower case, without the dot).
    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            Self::Obj => &["obj"],
            Self::Ply => &["ply"],
            Self::Stl => &["stl"],
            Self::Gltf => &["gltf", "glb"],
            Self::Nrrd => &["nrrd", "nhdr"],
            Self::Den => &["den"],
            Self::Raw => &["raw"],
            Self::Nifti => &["nii", "nii.gz"],
            Self::Dicom => &["dcm"],
            Self::MetaImage => &["mha", "mhd"],
            Self::Vtk => &["vti", "vtk"],
            Self::Las => &["las", "laz"],
            Self::Png => &["png"],
            Self::Jpeg => &["jpg", "jpeg"],
            Self::Splat => &["splat"],
            Self::Spz => &["spz"],
        }
    }

    /// The kinds of data a file of this format can hold, the usual one first.
    pub fn kinds(self) -> &'static [DataKind] {
        match self {
            Self::Obj => &[DataKind::Mesh, DataKind::Points],
            Self::Ply => &[DataKind::Mesh, DataKind::Points, DataKind::Gaussians],
            Self::Stl | Self::Gltf => &[DataKind::Mesh],
            Self::Nrrd
            | Self::Den
            | Self::Raw
            | Self::Nifti
            | Self::Dicom
            | Self::MetaImage
            | Self::Vtk => &[DataKind::Volume],
            Self::Las => &[DataKind::Points],
            Self::Png | Self::Jpeg => &[DataKind::Image],
            Self::Splat | Self::Spz => &[DataKind::Gaussians],
        }
    }

    /// Whether this build reads the format as `kind` (some formats are recognised before
    /// they are read, so that the error says what the file is).
    pub fn is_read_as(self, kind: DataKind) -> bool {
        self.kinds().contains(&kind)
            && match self {
                Self::Obj
                | Self::Ply
                | Self::Nrrd
                | Self::Den
                | Self::Raw
                | Self::MetaImage
                | Self::Png
                | Self::Splat
                | Self::Spz => true,
                Self::Stl => cfg!(feature = "stl"),
                Self::Gltf => cfg!(feature = "gltf"),
                Self::Jpeg => cfg!(feature = "jpeg"),
                Self::Nifti => cfg!(feature = "nifti"),
                Self::Las => cfg!(feature = "las"),
                Self::Dicom => cfg!(feature = "dicom"),
                Self::Vtk => cfg!(feature = "vti"),
            }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// How many leading bytes the signatures need (DICOM's `DICM` sits at 128, NIfTI-1's magic
/// at 344).
const SNIFF_BYTES: u64 = 512;

/// The format of the file at `path`: its signature where the first bytes carry one, else its
/// extension. Refuses special files (as every reader does) and names the supported formats
/// when neither tells.
pub fn detect(path: &Path) -> Result<Format> {
    crate::file::check_regular(path)?;
    let mut head = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(SNIFF_BYTES).read_to_end(&mut head))
        .map_err(|e| Error::io(path, e))?;
    if let Some(format) = by_signature(&head) {
        return Ok(format);
    }
    by_extension(path).ok_or_else(|| Error::Format {
        path: path.into(),
        reason: format!("unknown format; {}", supported()),
    })
}

/// The format of `path` read as `kind`: refused by name when the file holds another kind of
/// data or when this build does not read the format. A PLY is 3D Gaussian splats when its vertices have all of
/// [`GAUSSIAN_PLY_PROPERTIES`], read only as such; a PLY with none of them is not Gaussian
/// splats. A file of another kind is refused with [`Error::WrongKind`].
pub fn expect(path: &Path, kind: DataKind) -> Result<Format> {
    let format = detect(path)?;
    let wrong = |holds: DataKind, detail: String| Error::WrongKind {
        path: path.into(),
        holds,
        wanted: Some(kind),
        detail,
    };
    if format == Format::Ply {
        let splats = ply_gaussian_properties(path);
        let all = splats.len() == GAUSSIAN_PLY_PROPERTIES.len();
        if all && kind != DataKind::Gaussians {
            return Err(wrong(
                DataKind::Gaussians,
                format!(
                    "a 3DGS PLY: its vertices have {}",
                    GAUSSIAN_PLY_PROPERTIES.join(", ")
                ),
            ));
        }
        if splats.is_empty() && kind == DataKind::Gaussians {
            let (theirs, what) = match ply_faces(path) {
                Ok(faces) if faces > 0 => (DataKind::Mesh, format!("{faces} faces")),
                _ => (DataKind::Points, "vertices only".to_string()),
            };
            return Err(wrong(
                theirs,
                format!("PLY, {what}; no {}", GAUSSIAN_PLY_PROPERTIES.join(", ")),
            ));
        }
    }
    if !format.kinds().contains(&kind) {
        return Err(wrong(format.kinds()[0], format.to_string()));
    }
    if !format.is_read_as(kind) {
        return Err(Error::Format {
            path: path.into(),
            reason: format!("{format} is not read yet; {}", supported()),
        });
    }
    Ok(format)
}

/// What the file at `path` holds: its format and kind — the format's usual kind, except that
/// a PLY whose header declares faces is a mesh (its vertices alone are a point cloud) and one
/// whose vertices have [`GAUSSIAN_PLY_PROPERTIES`] is 3D Gaussian splats.
pub fn kind(path: &Path) -> Result<(Format, DataKind)> {
    if path.is_dir() && Format::Dicom.is_read_as(DataKind::Volume) {
        return Ok((Format::Dicom, DataKind::Volume)); // a series folder
    }
    let format = detect(path)?;
    let kind = match format {
        Format::Ply if ply_faces(path)? > 0 => DataKind::Mesh,
        Format::Ply if ply_gaussian_properties(path).len() == GAUSSIAN_PLY_PROPERTIES.len() => {
            DataKind::Gaussians
        }
        Format::Ply => DataKind::Points,
        other => other.kinds()[0],
    };
    Ok((format, kind))
}

/// How many faces the PLY header of `path` declares (its first 64 KiB hold the header).
pub(crate) fn ply_faces(path: &Path) -> Result<usize> {
    let head = ply_head(path)?;
    crate::io::ply::face_count(&head).map_err(|reason| Error::Points {
        path: path.into(),
        reason,
    })
}

/// The vertex properties that make a PLY 3D Gaussian splats (graphdeco's 3DGS PLY).
pub const GAUSSIAN_PLY_PROPERTIES: [&str; 4] = crate::io::ply::GAUSSIAN_PROPERTIES;

/// Which of [`GAUSSIAN_PLY_PROPERTIES`] the PLY header of `path` declares on its vertices
/// (none when it cannot be read: the loader says why).
fn ply_gaussian_properties(path: &Path) -> Vec<&'static str> {
    ply_head(path)
        .ok()
        .and_then(|head| crate::io::ply::gaussian_properties(&head).ok())
        .unwrap_or_default()
}

/// The first 64 KiB of `path`, where a PLY's header is.
fn ply_head(path: &Path) -> Result<Vec<u8>> {
    let mut head = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(64 << 10).read_to_end(&mut head))
        .map_err(|e| Error::io(path, e))?;
    Ok(head)
}

/// The formats this build reads, per kind, for error messages.
pub fn supported() -> String {
    let kinds = [
        DataKind::Mesh,
        DataKind::Points,
        DataKind::Volume,
        DataKind::Image,
        DataKind::Gaussians,
    ];
    let lists: Vec<String> = kinds
        .iter()
        .map(|&kind| {
            let formats: Vec<String> = FORMATS
                .iter()
                .filter(|f| f.is_read_as(kind))
                .map(|f| {
                    let exts: Vec<String> =
                        f.extensions().iter().map(|e| format!(".{e}")).collect();
                    exts.join(" ")
                })
                .collect();
            format!("{} {}", plural(kind), formats.join(" "))
        })
        .collect();
    format!("read here: {}", lists.join("; "))
}

fn plural(kind: DataKind) -> &'static str {
    match kind {
        DataKind::Mesh => "meshes",
        DataKind::Points => "points",
        DataKind::Volume => "volumes",
        DataKind::Image => "images",
        DataKind::Gaussians => "Gaussian splats",
    }
}

/// The format whose signature `head` (a file's first bytes) starts with.
pub fn by_signature(head: &[u8]) -> Option<Format> {
    let at = |offset: usize, magic: &[u8]| head.get(offset..offset + magic.len()) == Some(magic);
    let text = String::from_utf8_lossy(&head[..head.len().min(256)]);
    if at(0, b"ply") && matches!(head.get(3), Some(b'\n' | b'\r')) {
        Some(Format::Ply)
    } else if at(0, b"glTF") {
        Some(Format::Gltf)
    } else if at(0, b"NRRD000") {
        Some(Format::Nrrd)
    } else if at(0, b"\x89PNG\r\n\x1a\n") {
        Some(Format::Png)
    } else if at(0, b"\xff\xd8\xff") {
        Some(Format::Jpeg)
    } else if at(0, b"LASF") {
        Some(Format::Las)
    } else if at(128, b"DICM") {
        Some(Format::Dicom)
    } else if at(344, b"n+1\0") || at(344, b"ni1\0") {
        Some(Format::Nifti)
    } else if text.trim_start().starts_with("<?xml") && text.contains("<VTKFile")
        || text.starts_with("<VTKFile")
        || text.starts_with("# vtk DataFile")
    {
        Some(Format::Vtk)
    } else if text.starts_with("ObjectType") || text.starts_with("NDims") {
        Some(Format::MetaImage)
    } else {
        None
    }
}

/// The format `path`'s extension names (`.nii.gz` included), if any.
pub fn by_extension(path: &Path) -> Option<Format> {
    let name = path.file_name()?.to_str()?.to_ascii_lowercase();
    FORMATS.into_iter().find(|f| {
        f.extensions()
            .iter()
            .any(|ext| name.ends_with(&format!(".{ext}")))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signatures_win_over_extensions() {
        assert_eq!(by_signature(b"ply\nformat ascii 1.0\n"), Some(Format::Ply));
        assert_eq!(by_signature(b"glTF\x02\0\0\0"), Some(Format::Gltf));
        assert_eq!(by_signature(b"NRRD0004\n"), Some(Format::Nrrd));
        assert_eq!(by_signature(b"\xff\xd8\xff\xe0"), Some(Format::Jpeg));
        let mut dicom = vec![0u8; 132];
        dicom[128..].copy_from_slice(b"DICM");
        assert_eq!(by_signature(&dicom), Some(Format::Dicom));
        let mut nifti = vec![0u8; 348];
        nifti[344..348].copy_from_slice(b"n+1\0");
        assert_eq!(by_signature(&nifti), Some(Format::Nifti));
        assert_eq!(by_signature(b"v 0 0 0\n"), None);
        assert_eq!(
            by_signature(b"solid cube\n"),
            None,
            "ASCII STL goes by extension"
        );
    }

    #[test]
    fn extensions_in_any_case_and_double_ones() {
        let f = |name: &str| by_extension(Path::new(name));
        assert_eq!(f("brain.NII.GZ"), Some(Format::Nifti));
        assert_eq!(f("bunny.Obj"), Some(Format::Obj));
        assert_eq!(f("scan.laz"), Some(Format::Las));
        assert_eq!(f("photo.JPEG"), Some(Format::Jpeg));
        assert_eq!(f("notes.txt"), None);
        assert_eq!(f("noextension"), None);
    }

    #[test]
    fn a_file_of_another_kind_says_what_it_is() {
        let dir = std::env::temp_dir().join("autostereo_formats_test");
        std::fs::create_dir_all(&dir).unwrap();
        let file = |name: &str, bytes: &[u8]| {
            let path = dir.join(name);
            std::fs::write(&path, bytes).unwrap();
            path
        };
        // The signature wins over a misleading extension.
        let volume = file("head.obj", b"NRRD0004\ntype: uchar\n");
        let e = expect(&volume, DataKind::Mesh).unwrap_err().to_string();
        assert!(
            e.contains("this is a volume (NRRD), not a mesh: read it as a volume"),
            "{e}"
        );
        assert!(
            !e.contains("`autostereo "),
            "a library error names no command: {e}"
        );
        let unknown = file("notes.txt", b"hello");
        let e = expect(&unknown, DataKind::Points).unwrap_err().to_string();
        assert!(e.contains("unknown format; read here: meshes .obj"), "{e}");
        let ply = file("cloud.ply", b"ply\nformat ascii 1.0\n");
        assert_eq!(expect(&ply, DataKind::Points).unwrap(), Format::Ply);
        let vti = file("image.vti", b"<VTKFile type=\"ImageData\">");
        match expect(&vti, DataKind::Volume) {
            Ok(format) => assert!(cfg!(feature = "vti") && format == Format::Vtk),
            Err(e) => assert!(
                !cfg!(feature = "vti") && e.to_string().contains("VTK image data is not read yet"),
                "{e}"
            ),
        }
        let e = expect(&dir, DataKind::Volume).unwrap_err().to_string();
        assert!(e.contains("a directory"), "{e}");
    }

    #[test]
    fn the_supported_list_names_what_this_build_reads() {
        let list = supported();
        assert!(list.contains("meshes .obj .ply"), "{list}");
        assert!(list.contains("volumes .nrrd .nhdr .den .raw"), "{list}");
        assert_eq!(list.contains(".vti .vtk"), cfg!(feature = "vti"), "{list}");
    }
}
