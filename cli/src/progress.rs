//! Progress bars for long runs (turntables, the bench: bench/src/lib.rs includes this file),
//! on stderr. indicatif hides them when
//! stderr is not a terminal, so logs and tests see only the lines printed through
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

/// Print a line on stderr without tearing the bar (and even where the bar is hidden, unlike
/// `ProgressBar::println`, which then prints nothing).
#[allow(
    dead_code,
    reason = "the bench's (bench/src/lib.rs includes this file); the CLI logs none"
)]
pub fn log(bar: &ProgressBar, line: &str) {
    bar.suspend(|| eprintln!("{line}"));
}
