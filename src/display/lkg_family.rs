//! Looking Glass device families and the defaults their owners' software uses: the view count
//! and the quilt (its size and grid), known from the calibration's serial prefix. The values
//! are those Looking Glass publishes in its WebXR library (0.6) for each serial prefix.

/// One family of Looking Glass displays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LookingGlassFamily {
    /// The serial prefix (`LKG-J` …).
    pub prefix: &'static str,
    /// The product name.
    pub name: &'static str,
    /// The quilt size in pixels Looking Glass software renders for it.
    pub quilt_size: [u32; 2],
    /// The quilt grid: columns, rows. Views = columns × rows.
    pub grid: [u32; 2],
}

impl LookingGlassFamily {
    /// The default view count: every tile of the quilt.
    pub fn views(&self) -> u32 {
        self.grid[0] * self.grid[1]
    }

    /// The family of a calibration's `serial`, if it is one Looking Glass publishes defaults
    /// for.
    pub fn of_serial(serial: &str) -> Option<&'static Self> {
        // Longest prefix first: "LKG-2K" before any one-letter prefix could match it.
        FAMILIES
            .iter()
            .filter(|f| serial.starts_with(f.prefix))
            .max_by_key(|f| f.prefix.len())
    }

    /// Every family with published defaults.
    pub fn all() -> &'static [Self] {
        &FAMILIES
    }
}

const fn family(
    prefix: &'static str,
    name: &'static str,
    quilt_size: [u32; 2],
    grid: [u32; 2],
) -> LookingGlassFamily {
    LookingGlassFamily {
        prefix,
        name,
        quilt_size,
        grid,
    }
}

const FAMILIES: [LookingGlassFamily; 13] = [
    family(
        "LKG-2K",
        "Looking Glass 8.9\" (gen 1)",
        [4096, 4096],
        [5, 9],
    ),
    family(
        "LKG-4K",
        "Looking Glass 15.6\" (gen 1)",
        [4096, 4096],
        [5, 9],
    ),
    family("LKG-8K", "Looking Glass 8K (gen 1)", [8192, 8192], [5, 9]),
    family("LKG-P", "Looking Glass Portrait", [3360, 3360], [8, 6]),
    family("LKG-A", "Looking Glass 16\" (gen 2)", [4096, 4096], [5, 9]),
    family("LKG-B", "Looking Glass 32\" (gen 2)", [8192, 8192], [5, 9]),
    family("LKG-D", "Looking Glass 65\"", [8192, 8192], [8, 9]),
    family("LKG-F", "Looking Glass Kiosk", [3360, 3360], [8, 6]),
    family("LKG-E", "Looking Glass Go", [4092, 4092], [11, 6]),
    family(
        "LKG-H",
        "Looking Glass 16\" Spatial Display, portrait",
        [5995, 6000],
        [11, 6],
    ),
    family(
        "LKG-J",
        "Looking Glass 16\" Spatial Display, landscape",
        [5999, 5999],
        [7, 7],
    ),
    family(
        "LKG-K",
        "Looking Glass 32\" Spatial Display, portrait",
        [8184, 8184],
        [11, 6],
    ),
    family(
        "LKG-L",
        "Looking Glass 32\" Spatial Display, landscape",
        [8190, 8190],
        [7, 7],
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serials_find_their_family() {
        assert_eq!(
            LookingGlassFamily::of_serial("LKG-J00332").unwrap().views(),
            49
        );
        assert_eq!(
            LookingGlassFamily::of_serial("LKG-E01234").unwrap().views(),
            66
        );
        assert_eq!(
            LookingGlassFamily::of_serial("LKG-P12345").unwrap().views(),
            48
        );
        assert_eq!(
            LookingGlassFamily::of_serial("LKG-2K00001").unwrap().grid,
            [5, 9]
        );
        assert_eq!(
            LookingGlassFamily::of_serial("LKG-A0001").unwrap().views(),
            45
        );
        assert!(LookingGlassFamily::of_serial("SAMPLE-not-a-real-device").is_none());
        assert!(LookingGlassFamily::of_serial("").is_none());
    }
}
