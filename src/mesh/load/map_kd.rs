//! An MTL `map_Kd` statement: the diffuse texture's file name after its options. Of the
//! options, `-o` (offset), `-s` (scale) and `-clamp on` change what the renderers draw and are
//! applied; the rest (`-bm`, `-mm`, `-blendu`, …) are skipped with their arguments.

use std::path::Path;

use glam::Vec2;

use crate::mesh::{Filter, Texture, Wrap};

/// A parsed `map_Kd`: the file, and how texture coordinates map onto it.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct MapKd {
    pub file: String,
    pub offset: Vec2,
    pub scale: Vec2,
    pub clamp: bool,
}

impl MapKd {
    /// The arguments after `map_Kd` (options, then a file name that may hold spaces).
    pub fn parse(args: &str) -> Result<Self, String> {
        let words: Vec<&str> = args.split_whitespace().collect();
        let mut map = MapKd {
            file: String::new(),
            offset: Vec2::ZERO,
            scale: Vec2::ONE,
            clamp: false,
        };
        let mut i = 0;
        while let Some(option) = words.get(i).filter(|w| w.starts_with('-')) {
            i += 1;
            // Up to three numbers follow -o, -s and -t; a fixed count the others.
            let numbers = |i: &mut usize| {
                let mut values = Vec::new();
                while values.len() < 3 {
                    match words.get(*i).and_then(|w| w.parse::<f32>().ok()) {
                        Some(v) if v.is_finite() => values.push(v),
                        _ => break,
                    }
                    *i += 1;
                }
                values
            };
            match *option {
                "-o" | "-s" => {
                    let v = numbers(&mut i);
                    let Some(&u) = v.first() else {
                        return Err(format!("{option} without numbers"));
                    };
                    let pair = Vec2::new(
                        u,
                        v.get(1).copied().unwrap_or(match *option {
                            "-o" => 0.0,
                            _ => u,
                        }),
                    );
                    match *option {
                        "-o" => map.offset = pair,
                        _ => map.scale = pair,
                    }
                }
                "-t" => {
                    numbers(&mut i);
                }
                "-clamp" => {
                    map.clamp = words.get(i) == Some(&"on");
                    i += 1;
                }
                "-mm" => i += 2,
                _ => i += 1,
            }
        }
        map.file = words.get(i..).unwrap_or(&[]).join(" ");
        if map.file.is_empty() {
            return Err("map_Kd names no file".into());
        }
        Ok(map)
    }

    /// OBJ texture coordinate `uv` (v up from the image's bottom) as the renderers take it
    /// (v down from the top), through the offset and scale.
    pub fn tex_coord(&self, uv: [f32; 2]) -> Vec2 {
        let mapped = Vec2::from(uv) * self.scale + self.offset;
        Vec2::new(mapped.x, 1.0 - mapped.y)
    }

    /// The texture, read from `dir` (relative names; an absolute one as it is).
    pub fn load(&self, dir: &Path) -> crate::error::Result<Texture> {
        let path = dir.join(self.file.replace('\\', "/"));
        let bytes = crate::file::read_bounded(
            &path,
            crate::image_io::MAX_IMAGE_FILE_BYTES,
            "the image-file limit",
        )?;
        let wrap = [if self.clamp {
            Wrap::Clamp
        } else {
            Wrap::Repeat
        }; 2];
        Texture::decode(&bytes, &path, wrap, Filter::Linear)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_are_read_and_the_name_keeps_its_spaces() {
        let m = MapKd::parse("-o 0.5 0.25 -s 2 -bm 1 -clamp on -mm 0 1 my texture.png").unwrap();
        assert_eq!(m.file, "my texture.png");
        assert_eq!(m.offset, Vec2::new(0.5, 0.25));
        assert_eq!(m.scale, Vec2::new(2.0, 2.0));
        assert!(m.clamp);
        assert_eq!(m.tex_coord([0.0, 0.0]), Vec2::new(0.5, 0.75));
        assert_eq!(MapKd::parse("wood.jpg").unwrap().file, "wood.jpg");
        assert!(MapKd::parse("-s 1 1").is_err());
        assert!(MapKd::parse("-o").is_err());
    }
}
