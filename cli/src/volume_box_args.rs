//! What of a volume is kept, as the `volume` and `view` flags give it: `--crop` (a box of
//! voxels or mm, applied at load) and `--clip` (half-spaces, kept by every method); their
//! values parsed here, the library's `Crop` and `ClipPlane` made from them.

use autostereo::volume::Volume;

/// One `--clip` plane as given: keep `normal · p ≤ offset`, `p` in voxels or (`mm`) in the
/// spacing's units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipArg {
    normal: [f32; 3],
    offset: f32,
    mm: bool,
}

impl ClipArg {
    /// The plane for `volume` (its spacing turns voxels into the library's units).
    pub fn plane(self, volume: &Volume) -> autostereo::volume::ClipPlane {
        use autostereo::volume::ClipPlane;
        let normal = glam::Vec3::from(self.normal);
        match self.mm {
            true => ClipPlane::new(normal, self.offset),
            false => ClipPlane::from_voxels(normal, self.offset, volume.spacing.into()),
        }
    }
}

/// `--clip x<40`, `--clip z>12.5mm` or `--clip NX,NY,NZ,D[mm]`.
pub fn parse_clip(value: &str) -> std::result::Result<ClipArg, String> {
    let bad = || {
        format!(
            "'{value}' is not a clipping plane: AXIS<V or AXIS>V (x, y or z; `--clip x<40`,              `--clip z>12.5mm`) or NX,NY,NZ,D keeping NX·x + NY·y + NZ·z ≤ D; voxels, or `mm`              after it for the spacing's units"
        )
    };
    let text = value.trim();
    let (text, mm) = match text.strip_suffix("mm") {
        Some(rest) => (rest.trim(), true),
        None => (text, false),
    };
    let number = |s: &str| s.trim().parse::<f32>().ok().filter(|x| x.is_finite());
    if let Some(at) = text.find(['<', '>']) {
        let axis = match text[..at].trim() {
            "x" | "X" => 0,
            "y" | "Y" => 1,
            "z" | "Z" => 2,
            _ => return Err(bad()),
        };
        let v = number(&text[at + 1..]).ok_or_else(bad)?;
        let sign = if text.as_bytes()[at] == b'<' {
            1.0
        } else {
            -1.0
        };
        let mut normal = [0.0; 3];
        normal[axis] = sign;
        return Ok(ClipArg {
            normal,
            offset: sign * v,
            mm,
        });
    }
    let v: Vec<f32> = text
        .split(',')
        .map(number)
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    match v[..] {
        [x, y, z, d] if [x, y, z] != [0.0; 3] => Ok(ClipArg {
            normal: [x, y, z],
            offset: d,
            mm,
        }),
        [_, _, _, _] => Err(format!(
            "'{value}': the plane's normal NX,NY,NZ must not be 0,0,0"
        )),
        _ => Err(bad()),
    }
}

/// `--crop X0,Y0,Z0,X1,Y1,Z1` in voxels, or with `mm` after it in the spacing's units.
pub fn parse_crop(value: &str) -> std::result::Result<autostereo::volume::Crop, String> {
    use autostereo::volume::Crop;
    let (numbers, world) = match value.trim().strip_suffix("mm") {
        Some(rest) => (rest, true),
        None => (value, false),
    };
    let v: Vec<f32> = numbers
        .split(',')
        .map(|p| p.trim().parse::<f32>())
        .collect::<std::result::Result<_, _>>()
        .ok()
        .filter(|v: &Vec<f32>| v.len() == 6 && v.iter().all(|x| x.is_finite() && *x >= 0.0))
        .ok_or_else(|| {
            format!(
                "'{value}' is not X0,Y0,Z0,X1,Y1,Z1: six numbers ≥ 0 (voxels; `mm` after them: \
                 the spacing's units)"
            )
        })?;
    let corner = |at: usize| [v[at], v[at + 1], v[at + 2]];
    match world {
        true => Ok(Crop::World {
            min: corner(0),
            max: corner(3),
        }),
        false if v.iter().all(|x| x.fract() == 0.0 && *x <= u32::MAX as f32) => Ok(Crop::Voxels {
            min: corner(0).map(|x| x as u32),
            max: corner(3).map(|x| x as u32),
        }),
        false => Err(format!(
            "'{value}': voxel indices are whole numbers (or end it in mm)"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clip_planes_read_as_an_axis_side_or_a_plane_in_voxels_or_mm() {
        let below = parse_clip("x<40").unwrap();
        assert_eq!(
            (below.normal, below.offset, below.mm),
            ([1.0, 0.0, 0.0], 40.0, false)
        );
        let above = parse_clip("z > 12.5mm").unwrap();
        assert_eq!(
            (above.normal, above.offset, above.mm),
            ([0.0, 0.0, -1.0], -12.5, true)
        );
        let plane = parse_clip("1,-1,0,-3").unwrap();
        assert_eq!((plane.normal, plane.offset), ([1.0, -1.0, 0.0], -3.0));
        for bad in ["w<3", "x<", "0,0,0,1", "1,2,3", "x<nan", ""] {
            assert!(parse_clip(bad).is_err(), "{bad}");
        }
        // Voxels become the spacing's units: x < 40 voxels of 0.5 mm is x < 20 mm.
        let volume = Volume::new([2, 2, 2], [0.5, 1.0, 1.0], vec![0.0; 8]).unwrap();
        let mm = below.plane(&volume);
        assert!((mm.offset / mm.normal.x - 20.0).abs() < 1e-5);
    }
}
