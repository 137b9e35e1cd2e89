//! Finding an attached Looking Glass's calibration where Looking Glass software finds it: the
//! display carries a small USB volume with `LKG_calibration/visual.json`, mounted by the system
//! under one of the usual mount points (`/media/USER/VOLUME`, `/run/media/USER/VOLUME`,
//! `/mnt/VOLUME`, `/Volumes/VOLUME`, a drive letter on Windows).

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::param::Param;

/// The calibration's path on the display's volume.
const ON_VOLUME: [&str; 2] = ["LKG_calibration", "visual.json"];

/// The folders whose sub-folders (one or two levels down) are searched for a display's volume.
pub fn mount_points() -> Vec<PathBuf> {
    let mut bases: Vec<PathBuf> = ["/media", "/run/media", "/mnt", "/Volumes"]
        .iter()
        .map(PathBuf::from)
        .collect();
    if cfg!(windows) {
        bases.extend((b'D'..=b'Z').map(|d| PathBuf::from(format!("{}:\\", d as char))));
    }
    bases
}

/// Every `LKG_calibration/visual.json` on a volume mounted in `bases` (the base itself, one or
/// two folders down), sorted.
pub fn attached_calibrations(bases: &[PathBuf]) -> Vec<PathBuf> {
    let calibration = |volume: &Path| {
        let path = ON_VOLUME
            .iter()
            .fold(volume.to_path_buf(), |p, c| p.join(c));
        path.is_file().then_some(path)
    };
    let folders = |dir: &Path| -> Vec<PathBuf> {
        std::fs::read_dir(dir)
            .map(|entries| {
                entries
                    .filter_map(|e| e.ok().map(|e| e.path()))
                    .filter(|p| p.is_dir())
                    .collect()
            })
            .unwrap_or_default()
    };
    let mut found = Vec::new();
    for base in bases {
        found.extend(calibration(base));
        for volume in folders(base) {
            found.extend(calibration(&volume));
            for inner in folders(&volume) {
                found.extend(calibration(&inner));
            }
        }
    }
    found.sort();
    found.dedup();
    found
}

/// The one attached display's calibration under `bases`: an error saying where it looked when
/// there is none, and listing them when there are several.
pub fn find_attached(bases: &[PathBuf]) -> Result<PathBuf> {
    let found = attached_calibrations(bases);
    let list = |paths: &[PathBuf]| {
        paths
            .iter()
            .map(|p| p.display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    match found.as_slice() {
        [one] => Ok(one.clone()),
        [] => Err(Error::invalid(
            Param::LookingGlassCalibration,
            format!(
                "no attached display found: looked for {} on the volumes mounted in {} (one or \
                 two folders down); connect the display and let the system mount its volume, \
                 or give the file: lkg:PATH",
                ON_VOLUME.join("/"),
                list(bases)
            ),
        )),
        several => Err(Error::invalid(
            Param::LookingGlassCalibration,
            format!(
                "{} attached displays found ({}): choose one with lkg:PATH",
                several.len(),
                list(several)
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_calibration_on_a_mounted_volume_and_says_where_it_looked() {
        let root = std::env::temp_dir().join(format!("autostereo-lkg-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let bases = vec![root.join("media"), root.join("mnt")];
        let err = find_attached(&bases).unwrap_err().to_string();
        assert!(
            err.contains("LKG_calibration/visual.json") && err.contains("mnt"),
            "{err}"
        );
        let volume = root.join("media").join("user").join("LKG-J00332");
        std::fs::create_dir_all(volume.join("LKG_calibration")).unwrap();
        let file = volume.join("LKG_calibration").join("visual.json");
        std::fs::write(&file, "{}").unwrap();
        assert_eq!(find_attached(&bases).unwrap(), file);
        let second = root.join("mnt").join("LKG-E01").join("LKG_calibration");
        std::fs::create_dir_all(&second).unwrap();
        std::fs::write(second.join("visual.json"), "{}").unwrap();
        let err = find_attached(&bases).unwrap_err().to_string();
        assert!(
            err.contains("2 attached displays") && err.contains("LKG-E01"),
            "{err}"
        );
        std::fs::remove_dir_all(&root).unwrap();
    }
}
