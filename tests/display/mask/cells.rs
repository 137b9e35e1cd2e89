//! Looking Glass subpixel cells (configVersion 3): the formula on a full panel, against the
//! stripe model, and broken calibrations refused by name.

use super::*;

/// Every cell pattern (and more patterns than cells, flipped panels, `invView`) against the
/// formula on every subpixel of a full 3840×2160 panel.
#[test]
fn subpixel_cell_masks_equal_the_looking_glass_formula_on_a_full_panel() {
    let size = [3840, 2160];
    let views = 49;
    let cases: [Gen3Case; 7] = [
        (0, &GEN3_CELLS[..1], false, None),
        (1, &GEN3_CELLS[..2], false, Some(false)),
        (2, &GEN3_CELLS[..2], false, None),
        (3, &GEN3_CELLS, false, None),
        (4, &GEN3_CELLS[..2], false, None),
        // Three cells for pattern 3's four indices: index 3 is cell 0 again.
        (3, &GEN3_CELLS[..3], true, None),
        (2, &GEN3_CELLS[..2], true, Some(true)),
    ];
    for (pattern, cells, flip_x, inv) in cases {
        let json = gen3_json(pattern, cells, flip_x, inv, size);
        let calibration = Calibration::from_json(&json, "gen3.json".as_ref()).unwrap();
        let mask = Display::new(DisplayKind::LookingGlass { views, calibration })
            .unwrap()
            .mask();
        assert_eq!(mask.views_per_pixel(), 3);
        let (mut checked, mut boundary) = (0u64, 0u64);
        for y in 0..size[1] {
            for x in 0..size[0] {
                for c in 0..3 {
                    let inv = inv.unwrap_or(false);
                    let (reference, scaled) = gen3_reference_view(
                        pattern, cells, flip_x, inv, size, views, x as i64, y as i64, c,
                    );
                    let ours = mask.view(x, y, c as u32);
                    // 0.32 fixed point: only subpixels within ~(x + y)·2⁻³² lens periods of a
                    // view boundary may differ (there `⌊N(1 − f)⌋` and `N − 1 − ⌊Nf⌋` differ too).
                    let on_boundary = (scaled - scaled.round()).abs() < 1e-4;
                    boundary += u64::from(on_boundary);
                    assert!(
                        ours == reference || on_boundary,
                        "pattern {pattern} ({} cells, flip {flip_x}, inv {inv}) at ({x},{y},{c}): \
                         {ours} vs {reference}",
                        cells.len()
                    );
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 3840 * 2160 * 3);
        assert!(
            boundary < checked / 1000,
            "pattern {pattern}: {boundary} near boundaries"
        );
    }
}

/// The cells matter: the same lens with a stripe puts most subpixels in another view (what a
/// tool that ignores the cells shows on these panels).
#[test]
fn subpixel_cells_change_most_views_against_the_stripe() {
    let size = [3840, 2160];
    let json = gen3_json(3, &GEN3_CELLS, false, Some(false), size);
    let cells = Calibration::from_json(&json, "gen3.json".as_ref()).unwrap();
    let mut stripe = cells.clone();
    stripe.cells = None;
    let mask = |calibration| {
        Display::new(DisplayKind::LookingGlass {
            views: 49,
            calibration,
        })
        .unwrap()
        .mask()
    };
    let (cells, stripe) = (mask(cells), mask(stripe));
    let mut differ = 0;
    let mut total = 0;
    for y in (0..size[1]).step_by(5) {
        for x in (0..size[0]).step_by(3) {
            for c in 0..3 {
                differ += u32::from(cells.view(x, y, c) != stripe.view(x, y, c));
                total += 1;
            }
        }
    }
    assert!(differ * 2 > total, "{differ} of {total} differ");
}

/// Calibration files with cells: the sample set loads, and broken cell tables are refused by
/// name.
#[test]
fn gen3_calibrations_load_and_broken_cells_are_refused_by_name() {
    for name in [
        "lkg_sample_16in_landscape_gen3_visual.json",
        "lkg_sample_16in_portrait_gen3_visual.json",
        "lkg_sample_32in_landscape_gen3_visual.json",
        "lkg_sample_go_gen3_visual.json",
    ] {
        let path = format!("{}/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let calibration = Calibration::load(path.as_ref()).unwrap();
        assert!(calibration.cells.is_some(), "{name}");
        assert!(!calibration.inv_view, "{name}: no invView reads as 0");
        Display::parse(&format!("lkg:{path}")).unwrap();
    }
    let good = gen3_json(2, &GEN3_CELLS[..2], false, None, [3840, 2160]);
    let refused = |edit: &dyn Fn(&mut serde_json::Value), wanted: &str| {
        let mut json: serde_json::Value = serde_json::from_str(&good).unwrap();
        edit(&mut json);
        let err = Calibration::from_json(&json.to_string(), "v.json".as_ref())
            .unwrap_err()
            .to_string();
        assert!(err.contains(wanted) && err.contains("v.json"), "{err}");
    };
    refused(
        &|j| j["CellPatternMode"]["value"] = 5.0.into(),
        "CellPatternMode",
    );
    refused(
        &|j| j["CellPatternMode"]["value"] = 1.5.into(),
        "CellPatternMode",
    );
    refused(
        &|j| drop(j.as_object_mut().unwrap().remove("CellPatternMode")),
        "CellPatternMode",
    );
    refused(
        &|j| j["subpixelCells"][1]["GOffsetY"] = "x".into(),
        "subpixelCells[1].GOffsetY",
    );
    refused(
        &|j| {
            drop(
                j["subpixelCells"][0]
                    .as_object_mut()
                    .unwrap()
                    .remove("BOffsetX"),
            )
        },
        "BOffsetX",
    );
    refused(&|j| j["subpixelCells"] = 3.into(), "subpixelCells");
    refused(&|j| j["screenH"]["value"] = 2160.5.into(), "screenH");
    refused(
        &|j| j["flipImageY"] = serde_json::json!({"value": 1.0}),
        "flipImageY",
    );
    // An empty cell list is the stripe model, as Looking Glass's loaders read it.
    let mut json: serde_json::Value = serde_json::from_str(&good).unwrap();
    json["subpixelCells"] = serde_json::json!([]);
    json["invView"] = serde_json::json!({"value": 1.0});
    let stripe = Calibration::from_json(&json.to_string(), "v.json".as_ref()).unwrap();
    assert!(stripe.cells.is_none());
}
