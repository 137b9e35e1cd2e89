//! The quilts Looking Glass software makes and reads (docs/DISPLAYS.md, "Quilts"): each
//! family's own quilt size and grid, whole-pixel tiles stretched to the panel's aspect.

use autostereo::display::{Calibration, Display, DisplayKind, LookingGlassFamily};
use autostereo::render::quilt_image::QuiltChoice;

/// A calibration of `family` with a 16:9 panel (the quilt does not depend on the lens).
fn display_of(family: &LookingGlassFamily) -> Display {
    let json = format!(
        r#"{{"serial": "{}-TEST", "pitch": {{"value": 47.0}}, "slope": {{"value": -5.5}},
            "center": {{"value": 0.2}}, "viewCone": {{"value": 40.0}}, "DPI": {{"value": 300.0}},
            "screenW": {{"value": 1920.0}}, "screenH": {{"value": 1080.0}}, "invView": {{"value": 1.0}},
            "flipImageX": {{"value": 0.0}}}}"#,
        family.prefix
    );
    let calibration = Calibration::from_json(&json, "visual.json".as_ref()).unwrap();
    Display::new(DisplayKind::LookingGlass {
        views: family.views(),
        calibration,
    })
    .unwrap()
}

/// For every family: the quilt written is the family's size and grid, tiles of
/// floor(W/cols) × floor(H/rows), named for the panel's aspect (the views are shown at it, the
/// tiles stretched), whatever size the views are rendered at.
#[test]
fn every_family_gets_its_own_quilt_size_and_grid() {
    for family in LookingGlassFamily::all() {
        let display = display_of(family);
        let q = display
            .quilt(family.views(), [64, 36], &QuiltChoice::default())
            .unwrap();
        let [w, h] = family.quilt_size;
        let [c, r] = family.grid;
        assert_eq!(q.size, family.quilt_size, "{}", family.name);
        assert_eq!(
            [q.layout.cols, q.layout.rows],
            family.grid,
            "{}",
            family.name
        );
        assert_eq!(q.layout.tile, [w / c, h / r], "{}", family.name);
        assert_eq!(q.suffix(), format!("_qs{c}x{r}a1.7778"), "{}", family.name);
    }
    // The 16" Spatial Display: 7×7 tiles of 857², exactly 5999².
    let j = LookingGlassFamily::of_serial("LKG-J1").unwrap();
    let q = display_of(j)
        .quilt(49, [64, 36], &QuiltChoice::default())
        .unwrap();
    assert_eq!((q.size, q.layout.tile), ([5999, 5999], [857, 857]));
}

/// `--quilt` and `--quilt-size` override the family's; a grid that leaves a whole row empty
/// is refused; a size too small for the grid is refused.
#[test]
fn the_grid_and_size_can_be_chosen() {
    let j = display_of(LookingGlassFamily::of_serial("LKG-J1").unwrap());
    let choice = QuiltChoice {
        grid: Some([8, 6]),
        size: Some([4096, 4096]),
        tile: None,
    };
    let q = j.quilt(48, [64, 36], &choice).unwrap();
    assert_eq!((q.size, q.layout.tile), ([4096, 4096], [512, 682]));
    let empty = QuiltChoice {
        grid: Some([8, 8]),
        ..choice
    };
    let error = j.quilt(48, [64, 36], &empty).unwrap_err().to_string();
    assert!(error.contains("would be empty"), "{error}");
    let tiny = QuiltChoice {
        size: Some([4, 4]),
        ..choice
    };
    assert!(j.quilt(48, [64, 36], &tiny).is_err());
    // Views rendered at a size of their own (--view-size): the quilt is the grid of them,
    // still shown at the panel's aspect.
    let tiles = QuiltChoice {
        tile: Some([857, 857]),
        ..QuiltChoice::default()
    };
    let q = j.quilt(49, [64, 36], &tiles).unwrap();
    assert_eq!(
        (q.size, q.suffix().as_str()),
        ([5999, 5999], "_qs7x7a1.7778")
    );
    // Another display: the grid for the view count, tiles of the view size.
    let lenticular = Display::parse("lenticular:8").unwrap();
    let q = lenticular
        .quilt(8, [48, 32], &QuiltChoice::default())
        .unwrap();
    assert_eq!((q.size, q.layout.tile), ([96, 128], [48, 32]));
    assert_eq!(q.suffix(), "_qs2x4a1.5");
}
