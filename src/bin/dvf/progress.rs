//! Progress of a long command on standard error: a bar when standard error is a terminal, and
//! nothing at all otherwise, so that a pipe or a log file gets no progress bytes.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;

/// A bar of `len` items named `unit` (`step`, `scenario`) on standard error when that is a
/// terminal; hidden otherwise.
pub fn bar(len: usize, unit: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::with_draw_target(Some(len as u64), ProgressDrawTarget::stderr());
    let template = format!("{{elapsed_precise}} {{wide_bar}} {unit} {{pos}}/{{len}}, {{eta}} left");
    if let Ok(style) = ProgressStyle::with_template(&template) {
        bar.set_style(style);
    }
    bar
}
