//! Progress on standard error for work that takes more than a few seconds
//! (indicatif): a bar that counts steps, hidden when standard error is not
//! a terminal, so that logs and pipes stay clean.
//!
//! ```
//! let bar = speclab_cli::progress::bar("cells", 3);
//! for _ in 0..3 {
//!     bar.inc(1);
//! }
//! bar.finish_and_clear();
//! ```

use indicatif::{ProgressBar, ProgressStyle};

/// A bar of `len` steps labelled `what`, on standard error (drawn only on
/// a terminal).
#[must_use]
pub fn bar(what: &str, len: u64) -> ProgressBar {
    let style = ProgressStyle::with_template("{prefix} {wide_bar} {pos}/{len} ({elapsed}, ~{eta} left)")
        .unwrap_or_else(|_| ProgressStyle::default_bar());
    ProgressBar::new(len).with_style(style).with_prefix(what.to_string())
}
