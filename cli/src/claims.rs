//! The files one run reads and writes: never an input, never one file twice. A run's `Claims`
//! are a value it owns: one check, `Claims::check`, refuses a plan of names (each with the flag
//! that names it) before anything is written — the names given, before loading; the names the
//! outputs really get (a quilt's `_qs…` suffix, `_NN` view files, `_NNNN` turntable frames,
//! `output::planned`), before rendering — and every write takes its name (`Claims::claim`)
//! by the same rule, so a name the plan missed is still refused before the file is touched.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::image_io::RgbImage;

/// A run's inputs, and what it has written (with the flag that named each).
#[derive(Clone, Debug, Default)]
pub struct Claims {
    inputs: Vec<PathBuf>,
    written: Vec<(PathBuf, String)>,
}

impl Claims {
    /// A run that reads `inputs` and has written nothing.
    pub fn new(inputs: &[&Path]) -> Self {
        Self {
            inputs: inputs.iter().map(|p| p.to_path_buf()).collect(),
            written: Vec::new(),
        }
    }

    /// Refuse the run if any of the names `planned` (with the flag naming each) is an input or
    /// comes twice; nothing is taken.
    pub fn check(&self, planned: &[(PathBuf, &str)]) -> Result<()> {
        let mut trial = self.clone();
        for (path, flag) in planned {
            trial.claim(path, flag)?;
        }
        Ok(())
    }

    /// Take `path` for `flag`'s output, or say why it may not be written.
    pub fn claim(&mut self, path: &Path, flag: &str) -> Result<()> {
        let same = |other: &Path| crate::parse::same_file(path, other);
        if let Some(input) = self.inputs.iter().find(|i| same(i)) {
            bail!(
                "{flag}: {} is the input file {}; writing would destroy it (choose another name)",
                path.display(),
                input.display()
            );
        }
        if let Some((_, by)) = self.written.iter().find(|(w, _)| same(w)) {
            bail!(
                "{flag}: {} is also written by {by} in this run: two outputs at one file, one \
                 would replace the other (choose names that differ after the suffixes the \
                 outputs get)",
                path.display()
            );
        }
        self.written.push((path.to_path_buf(), flag.to_string()));
        Ok(())
    }

    /// Write `image` to `path`, which `flag` named (`--out`, `--hole-mask`), once taken.
    pub fn save_png(&mut self, image: &RgbImage, path: &Path, flag: &str) -> Result<()> {
        self.claim(path, flag)?;
        image.save_png(path)?;
        Ok(())
    }
}

/// `(path, flag)` for each output given (`None`s skipped): what `Claims::check` takes.
pub fn given<'a>(outputs: &[(Option<&Path>, &'a str)]) -> Vec<(PathBuf, &'a str)> {
    outputs
        .iter()
        .filter_map(|(p, flag)| p.map(|p| (p.to_path_buf(), *flag)))
        .collect()
}
