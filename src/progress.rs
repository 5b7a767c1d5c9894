//! Long sweeps: parallel over positions (rayon), with a progress bar on a
//! terminal (indicatif). Results never depend on either: each position's
//! work is independent once the positions themselves are found in order,
//! and the results are gathered in the order of the positions.

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::io::IsTerminal;

/// From this many items a sweep runs in parallel: fewer do not pay for
/// waking the thread pool.
pub const PARALLEL_FROM: usize = 32;

/// From this many items a sweep shows a progress bar (on a terminal only).
pub const BAR_FROM: usize = 2000;

/// A progress bar for `len` items of `what`: drawn on standard error when
/// that is a terminal and the sweep is long, hidden otherwise (pipes, files,
/// tests).
pub fn bar(len: usize, what: &str) -> ProgressBar {
    if len < BAR_FROM || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::new(len as u64);
    if let Ok(style) = ProgressStyle::with_template("{msg} {wide_bar} {pos}/{len} ({eta} left)") {
        pb.set_style(style);
    }
    pb.set_message(what.to_string());
    pb
}

/// `f` over `items`, in parallel for long sweeps, results in the items'
/// order; with a progress bar for very long ones.
pub fn map<T: Sync, R: Send>(items: &[T], what: &str, f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let pb = bar(items.len(), what);
    let out = map_on(items, &pb, f);
    pb.finish_and_clear();
    out
}

/// As [`map`], counting on a bar made by the caller (one bar for a sweep
/// done a part at a time).
pub fn map_on<T: Sync, R: Send>(
    items: &[T],
    pb: &ProgressBar,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    if items.len() >= PARALLEL_FROM {
        items
            .par_iter()
            .map(|x| {
                let r = f(x);
                pb.inc(1);
                r
            })
            .collect()
    } else {
        items
            .iter()
            .map(|x| {
                let r = f(x);
                pb.inc(1);
                r
            })
            .collect()
    }
}
