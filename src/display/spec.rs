//! Parsing of display SPEC strings (CLI contract).

use super::{Calibration, DisplayKind, LOOKING_GLASS_DEFAULT_VIEWS};
use crate::error::{Error, Result};

fn spec_error(spec: &str, reason: impl Into<String>) -> Error {
    Error::DisplaySpec {
        spec: spec.to_string(),
        reason: reason.into(),
    }
}

/// A number, or a fraction `a/b` (so that `2/3` stays exact to f64 precision).
fn parse_number(spec: &str, what: &str, text: &str) -> Result<f64> {
    let text = text.trim();
    let value = match text.split_once('/') {
        Some((a, b)) => {
            let a: f64 = a.trim().parse().map_err(|_| bad(spec, what, text))?;
            let b: f64 = b.trim().parse().map_err(|_| bad(spec, what, text))?;
            if b == 0.0 {
                return Err(spec_error(spec, format!("{what} '{text}' divides by zero")));
            }
            a / b
        }
        None => text.parse().map_err(|_| bad(spec, what, text))?,
    };
    if !value.is_finite() {
        return Err(spec_error(spec, format!("{what} '{text}' is not finite")));
    }
    Ok(value)
}

fn bad(spec: &str, what: &str, text: &str) -> Error {
    spec_error(spec, format!("{what} '{text}' is not a number"))
}

/// The spec kinds, for an error that does not know which one was meant.
const KINDS: &str =
    "expected hubner8 | lenticular:N | slanted:N,PITCH,SLANT,PHASE | lkg[:PATH.json] | view:N,V";

fn parse_views(spec: &str, text: &str) -> Result<u32> {
    let text = text.trim();
    text.parse().map_err(|_| {
        spec_error(
            spec,
            format!("'{text}' is not a view count (a whole number ≥ 1)"),
        )
    })
}

pub(super) fn parse_kind(spec: &str) -> Result<DisplayKind> {
    let (name, args) = spec.split_once(':').unwrap_or((spec, ""));
    match name.trim().to_ascii_lowercase().as_str() {
        "hubner8" if args.is_empty() => Ok(DisplayKind::Hubner8),
        "hubner8" => Err(spec_error(spec, "hubner8 takes no parameters")),
        "lenticular" => {
            if args.is_empty() {
                return Err(spec_error(
                    spec,
                    "lenticular needs a view count: lenticular:N",
                ));
            }
            Ok(DisplayKind::Lenticular {
                views: parse_views(spec, args)?,
            })
        }
        "slanted" => {
            let parts: Vec<&str> = args.split(',').collect();
            if parts.len() != 4 {
                return Err(spec_error(
                    spec,
                    format!(
                        "slanted needs 4 comma-separated values N,PITCH,SLANT,PHASE, got {}",
                        parts.len()
                    ),
                ));
            }
            Ok(DisplayKind::Slanted {
                views: parse_views(spec, parts[0])?,
                pitch: parse_number(spec, "pitch", parts[1])?,
                slant: parse_number(spec, "slant", parts[2])?,
                phase: parse_number(spec, "phase", parts[3])?,
            })
        }
        "view" => {
            let parts: Vec<&str> = args.split(',').collect();
            if parts.len() != 2 {
                return Err(spec_error(
                    spec,
                    "view needs the view count and the view shown: view:N,V",
                ));
            }
            let view = parts[1].trim().parse().map_err(|_| {
                spec_error(
                    spec,
                    format!(
                        "'{}' is not a view index (a whole number from 0)",
                        parts[1].trim()
                    ),
                )
            })?;
            Ok(DisplayKind::OneView {
                views: parse_views(spec, parts[0])?,
                view,
            })
        }
        "lkg" => {
            // No path: the attached display's, where Looking Glass software finds it.
            let path = match args.trim() {
                "" => super::lkg_discovery::find_attached(&super::lkg_discovery::mount_points())
                    .map_err(|e| match e {
                        Error::InvalidParameter { reason, .. } => spec_error(spec, reason),
                        other => other,
                    })?,
                path => path.into(),
            };
            let calibration = Calibration::load(&path).map_err(|e| match e {
                Error::Io { error, .. } if error.kind() == std::io::ErrorKind::NotFound => {
                    spec_error(
                        spec,
                        format!(
                            "no such calibration file {} (lkg:PATH.json names a Looking Glass's \
                             visual.json; lkg alone finds the attached one's)",
                            path.display()
                        ),
                    )
                }
                other => other,
            })?;
            // The family's view count (its quilt's tiles), as Looking Glass software uses.
            let views = calibration
                .family()
                .map_or(LOOKING_GLASS_DEFAULT_VIEWS, |f| f.views());
            Ok(DisplayKind::LookingGlass { views, calibration })
        }
        other => Err(spec_error(
            spec,
            format!("unknown display kind '{other}' ({KINDS})"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_all_kinds() {
        assert_eq!(parse_kind("hubner8").unwrap(), DisplayKind::Hubner8);
        assert_eq!(
            parse_kind("lenticular:5").unwrap(),
            DisplayKind::Lenticular { views: 5 }
        );
        match parse_kind("slanted:8,8,2/3,7/6").unwrap() {
            DisplayKind::Slanted {
                views,
                pitch,
                slant,
                phase,
            } => {
                assert_eq!((views, pitch), (8, 8.0));
                assert!((slant - 2.0 / 3.0).abs() < 1e-15 && (phase - 7.0 / 6.0).abs() < 1e-15);
            }
            k => panic!("{k:?}"),
        }
    }

    #[test]
    fn one_view_shows_its_view_everywhere() {
        assert_eq!(
            parse_kind("view:8,3").unwrap(),
            DisplayKind::OneView { views: 8, view: 3 }
        );
        for (views, view) in [(8, 0), (8, 3), (8, 7), (45, 44), (1, 0)] {
            let display = super::super::Display::parse(&format!("view:{views},{view}")).unwrap();
            assert_eq!(display.views_per_pixel(), 1);
            let mask = display.with_origin([12345, -678]).mask();
            for (x, y, c) in [(0, 0, 0), (1, 0, 2), (4095, 17, 1), (u32::MAX / 4, 99, 0)] {
                assert_eq!(
                    mask.view(x, y, c),
                    view,
                    "view:{views},{view} at ({x}, {y}, {c})"
                );
            }
        }
        let error = super::super::Display::parse("view:8,8").unwrap_err();
        assert!(error.to_string().contains("0…7"), "{error}");
    }

    #[test]
    fn rejects_bad_specs() {
        for spec in [
            "",
            "foo",
            "hubner8:3",
            "lenticular",
            "lenticular:x",
            "lenticular:-2",
            "slanted:8,8,1",
            "slanted:8,8,1/0,0",
            "slanted:8,abc,1,0",
            "slanted:8,8,inf,0",
            "view:8",
            "view:8,x",
            "lkg",
        ] {
            let err = parse_kind(spec).unwrap_err();
            assert!(matches!(err, Error::DisplaySpec { .. }), "{spec}: {err}");
        }
    }

    #[test]
    fn errors_say_what_is_wrong_with_the_number_and_the_file() {
        for (spec, says) in [
            (
                "lenticular:abc",
                "'abc' is not a view count (a whole number ≥ 1)",
            ),
            ("lenticular:-2", "'-2' is not a view count"),
            ("slanted:x,8,1,0", "'x' is not a view count"),
            ("view:8,x", "'x' is not a view index"),
            (
                "hologram",
                "unknown display kind 'hologram' (expected hubner8",
            ),
            ("lkg:nosuch.json", "no such calibration file nosuch.json"),
        ] {
            let err = parse_kind(spec).unwrap_err().to_string();
            assert!(err.contains(says), "{spec}: {err}");
        }
    }
}
