//! Progress on stderr for long runs: bars where the work is countable (turntable and video
//! frames, the bench: bench/src/lib.rs includes this file), spinners with the time elapsed
//! where it is not (loading a file, rendering a frame). indicatif hides them when stderr is
//! not a terminal, so logs, tests and `--json` runs see only the lines printed through
//! [`log`].

use indicatif::{ProgressBar, ProgressStyle};

/// A bar of `total` steps labelled `what`, with elapsed time and an estimate of what is left.
pub fn bar(total: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::new(total);
    let style = ProgressStyle::with_template(
        "{msg} [{bar:30}] {pos}/{len}, {elapsed} elapsed, about {eta} left",
    )
    .expect("a valid template")
    .progress_chars("=> ");
    bar.set_style(style);
    bar.set_message(what.to_string());
    bar
}

/// A spinner labelled `what` with the time elapsed, while `work` runs.
#[allow(
    dead_code,
    reason = "the CLI's; the bench (which includes this file) has no spinner"
)]
pub fn during<T>(what: &str, work: impl FnOnce() -> T) -> T {
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg} ({elapsed})").expect("a valid template"),
    );
    spinner.set_message(what.to_string());
    spinner.enable_steady_tick(std::time::Duration::from_millis(120));
    let out = work();
    spinner.finish_and_clear();
    out
}

/// "loading FILE (N MB)".
#[allow(dead_code, reason = "the CLI's")]
pub fn loading(path: &std::path::Path) -> String {
    let mb = std::fs::metadata(path).map_or(0.0, |m| m.len() as f64 / 1e6);
    format!("loading {} ({mb:.1} MB)", path.display())
}

/// Print a line on stderr without tearing the bar (and even where the bar is hidden, unlike
/// `ProgressBar::println`, which then prints nothing).
#[allow(
    dead_code,
    reason = "the bench's (bench/src/lib.rs includes this file); the CLI logs none"
)]
pub fn log(bar: &ProgressBar, line: &str) {
    bar.suspend(|| eprintln!("{line}"));
}
