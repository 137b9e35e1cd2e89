//! Library errors in the command line's words: the library names a parameter and its advice in
//! its own terms ("sampling step", "use Visibility::Exact"); here the message also names the
//! flag that sets the parameter (`--step`) and gives the advice as flags (`--visibility exact`).

/// (library parameter name, the flag that sets it).
const FLAGS: &[(&str, &str)] = &[
    ("sampling step", "--step"),
    ("sample sharing tolerance", "--share-samples"),
    (
        "probing stride through transparent material",
        "--empty-stride",
    ),
    ("thin-material opacity", "--thin-alpha"),
    ("volume path", "--path"),
    ("hole gap", "--hole-gap"),
    ("references", "--references"),
    ("epsilon", "--epsilon"),
    ("radius scale", "--radius-scale"),
    ("view scale", "--view-scale"),
    ("focus", "--focus"),
    ("depthiness", "--depthiness"),
    ("separation", "--separation"),
    ("downsample factor", "--downsample"),
    ("method", "--method"),
    ("camera model", "--camera"),
    ("look-from", "--look-from"),
    ("look-at", "--look-at"),
    ("up", "--up"),
    ("focal distance", "--focal/--focal-scale"),
    ("views", "--views"),
    ("groups", "--groups"),
    ("splat groups", "--groups"),
    ("field of view", "--fov"),
];

/// (library term in an error's advice, the command line's words for it).
const TERMS: &[(&str, &str)] = &[
    ("Visibility::Exact", "--visibility exact"),
    ("Visibility::Fast", "--visibility fast"),
    ("Visibility::Compute", "--visibility compute"),
    ("SplatDepth::Exact", "--depth exact"),
    ("SplatDepth::Paper", "--depth paper"),
    ("TileClip::Discard", "--tile-clip discard"),
    ("VolumePath::RayMarch", "--path compute"),
    ("VolumePath::Slices", "--path slices"),
    ("Volume::downsample(2)", "--downsample 2"),
    ("budget::set_max_memory", "--max-memory"),
    ("RawSpec::header_bytes = ", "--raw-header "),
    ("RawSpec", "--raw-dims X,Y,Z and --raw-type"),
    ("QuiltLayout::for_image's grid", "--quilt COLSxROWS"),
    ("DepthMapOptions::resample", "--depth-resample"),
];

/// The flag that sets the library parameter `name`, where one does.
pub fn flag_of(name: &str) -> Option<&'static str> {
    FLAGS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, flag)| *flag)
}

/// `error` and its causes as `{:#}` prints them, each invalid library parameter prefixed with
/// its flag.
pub fn describe(error: &anyhow::Error) -> String {
    let parts: Vec<String> = error
        .chain()
        .map(|cause| match cause.downcast_ref::<autostereo::Error>() {
            Some(autostereo::Error::InvalidParameter { name, .. }) => match flag_of(name) {
                Some(flag) => format!("{flag}: {cause}"),
                None => cause.to_string(),
            },
            // Every display spec the user types is `--display`'s.
            Some(autostereo::Error::DisplaySpec { spec, reason }) => {
                format!("--display {spec}: {reason}")
            }
            // The frame is the image `--size` asked for (the views of an unbandable frame,
            // or the window's): named as the user typed it, the library's advice after it.
            Some(autostereo::Error::SubpixelWidth { size: [w, h], .. }) => {
                format!("--size {w}x{h}: {cause}")
            }
            Some(autostereo::Error::LimitExceeded { what, limit, .. })
                if what == "image width" || what == "image height" =>
            {
                format!("{cause} (--size: at most {limit} pixels a side on this adapter)")
            }
            // A count a flag sets, over what the adapter takes: the flag and the most it takes.
            Some(autostereo::Error::LimitExceeded { what, limit, .. }) => match flag_of(what) {
                Some(flag) => format!("{flag}: {cause} (at most {flag} {limit} on this adapter)"),
                None => cause.to_string(),
            },
            _ => cause.to_string(),
        })
        .collect();
    let text = TERMS.iter().fold(parts.join(": "), |text, (term, words)| {
        text.replace(term, words)
    });
    printable(&text)
}

/// `text` with its control characters but line breaks escaped: whatever a message quotes (a
/// file's bytes, an OS error, a wgpu message), printing it never moves the cursor, rings or
/// retitles the terminal.
fn printable(text: &str) -> String {
    text.chars()
        .map(|c| match c.is_control() && c != '\n' {
            true => c.escape_debug().to_string(),
            false => c.to_string(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_invalid_parameter_is_named_by_its_flag() {
        let settings = autostereo::volume::VolumeSettings {
            empty_stride: 0,
            ..Default::default()
        };
        let error = anyhow::Error::from(settings.validate().unwrap_err()).context("volume");
        let text = describe(&error);
        assert!(
            text.starts_with("volume: --empty-stride: invalid probing stride"),
            "{text}"
        );
        let plain = anyhow::anyhow!("no such file");
        assert_eq!(describe(&plain), "no such file");
        let advice = anyhow::anyhow!("X needs Y; use Visibility::Exact");
        assert_eq!(describe(&advice), "X needs Y; use --visibility exact");
    }

    #[test]
    fn control_characters_are_escaped() {
        let raw = anyhow::anyhow!("line '\u{1b}[31mred\u{7}\r'\nnext");
        assert_eq!(describe(&raw), "line '\\u{1b}[31mred\\u{7}\\r'\nnext");
    }
}
