//! The files one run writes: never an input, never one file twice. The early checks
//! (`args::not_an_input`, `args::distinct_outputs`) compare the names given; the names written
//! can differ (a quilt's `_qs…` suffix, `_NN` view files, `_NNNN` turntable frames), so every
//! write is also checked here, by the name it really has, before the file is touched; and the
//! names a run will write are checked together before it renders (`check_planned`).

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{bail, Result};
use autostereo::image_io::RgbImage;

/// The run's inputs, and what it has written (with the flag that named each).
static CLAIMS: Mutex<Claims> = Mutex::new(Claims {
    inputs: Vec::new(),
    written: Vec::new(),
});

struct Claims {
    inputs: Vec<PathBuf>,
    written: Vec<(PathBuf, String)>,
}

/// Record the run's input files (outputs must not replace them).
pub fn inputs(paths: &[&Path]) {
    if let Ok(mut claims) = CLAIMS.lock() {
        claims.inputs.extend(paths.iter().map(|p| p.to_path_buf()));
    }
}

/// Write `image` to `path`, which `flag` named (`--out`, `--hole-mask`), unless `path` is an
/// input or was already written by this run.
pub fn save_png(image: &RgbImage, path: &Path, flag: &str) -> Result<()> {
    claim(path, flag)?;
    image.save_png(path)?;
    Ok(())
}

/// Take `path` for `flag`'s output, or say why it may not be written.
pub fn claim(path: &Path, flag: &str) -> Result<()> {
    let Ok(mut claims) = CLAIMS.lock() else {
        return Ok(());
    };
    claim_in(&mut claims, path, flag)
}

/// Refuse the run before it renders if any of the names it will write (`planned`, with the
/// flag naming each) is an input or comes twice; nothing is taken yet.
pub fn check_planned(planned: &[(PathBuf, &str)]) -> Result<()> {
    let Ok(claims) = CLAIMS.lock() else {
        return Ok(());
    };
    let mut trial = Claims {
        inputs: claims.inputs.clone(),
        written: claims.written.clone(),
    };
    for (path, flag) in planned {
        claim_in(&mut trial, path, flag)?;
    }
    Ok(())
}

fn claim_in(claims: &mut Claims, path: &Path, flag: &str) -> Result<()> {
    if let Some(input) = claims
        .inputs
        .iter()
        .find(|i| crate::args::same_file(path, i))
    {
        bail!(
            "{flag}: {} is the input file {}; writing would destroy it (choose another name)",
            path.display(),
            input.display()
        );
    }
    if let Some((_, by)) = claims
        .written
        .iter()
        .find(|(w, _)| crate::args::same_file(path, w))
    {
        bail!(
            "{flag}: {} is also written by {by} in this run; one would replace the other \
             (choose names that differ after the suffixes the outputs get)",
            path.display()
        );
    }
    claims.written.push((path.to_path_buf(), flag.to_string()));
    Ok(())
}
