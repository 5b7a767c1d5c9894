//! The command's terminal: the only printing of mechplan (results on
//! standard output, errors and notes on standard error, a progress bar
//! for long sweeps). The library hands it texts and files written.

use indicatif::{ProgressBar, ProgressStyle};
use mechplan::Progress;
use mechplan::Result;
use mechplan::study::files::{STDOUT, Spool, write_error};
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::sync::Mutex;

/// An error for the user on standard error, every line "mechplan: …";
/// if standard error fails too, the exit status still tells.
pub fn error(text: &str) {
    let _ = writeln!(
        std::io::stderr(),
        "mechplan: {}",
        text.replace('\n', "\nmechplan: ")
    );
}

/// A note for the user on standard error ("mechplan: note: …"); a note
/// that cannot be written is lost, the result is not.
pub fn note(text: &str) {
    let _ = writeln!(std::io::stderr(), "mechplan: note: {text}");
}

/// The notes of a run, then "wrote PATH" lines for the files written.
pub fn wrote(w: &mechplan::study::Written) -> Result<()> {
    for n in &w.notes {
        note(n);
    }
    stdout(&wrote_lines(&w.files))
}

/// "wrote PATH" lines.
fn wrote_lines(paths: &[PathBuf]) -> String {
    paths
        .iter()
        .map(|p| format!("wrote {}\n", p.display()))
        .collect()
}

/// Print `text` on standard output, checked and flushed.
pub fn stdout(text: &str) -> Result<()> {
    let mut o = std::io::stdout().lock();
    o.write_all(text.as_bytes())
        .and_then(|()| o.flush())
        .map_err(|e| write_error(STDOUT, e))
}

/// Pretty JSON with a final newline.
pub fn pretty(v: &serde_json::Value) -> String {
    let mut t = serde_json::to_string_pretty(v).expect("JSON of numbers and strings");
    t.push('\n');
    t
}

/// Print what a spool held back, checked and flushed.
pub fn print_spool(spool: Spool) -> Result<()> {
    spool.finish_into(&mut std::io::stdout().lock(), STDOUT)
}

/// From this many items a sweep shows a progress bar (on a terminal only).
pub const BAR_FROM: usize = 2000;

/// A progress bar on standard error for long sweeps, when it is a
/// terminal; nothing for short sweeps, pipes, files and tests.
pub struct Bar {
    /// From this many items the bar is shown.
    from: usize,
    bar: Mutex<Option<ProgressBar>>,
}

impl Default for Bar {
    /// A bar for sweeps of positions: from [`BAR_FROM`] items.
    fn default() -> Bar {
        Bar::shown_from(BAR_FROM)
    }
}

impl Bar {
    /// A bar shown from `from` items (answers of a group, each checked
    /// far slower than a position is solved: from the first).
    pub fn shown_from(from: usize) -> Bar {
        Bar {
            from,
            bar: Mutex::new(None),
        }
    }
}

impl Progress for Bar {
    fn start(&self, len: usize, what: &str) {
        if len < self.from || !std::io::stderr().is_terminal() {
            return;
        }
        let pb = ProgressBar::new(len as u64);
        if let Ok(style) = ProgressStyle::with_template("{msg} {wide_bar} {pos}/{len} ({eta} left)")
        {
            pb.set_style(style);
        }
        pb.set_message(what.to_string());
        if let Ok(mut b) = self.bar.lock() {
            *b = Some(pb);
        }
    }
    fn advance(&self, n: usize) {
        if let Ok(b) = self.bar.lock()
            && let Some(pb) = b.as_ref()
        {
            pb.inc(n as u64);
        }
    }
    fn finish(&self) {
        if let Ok(mut b) = self.bar.lock()
            && let Some(pb) = b.take()
        {
            pb.finish_and_clear();
        }
    }
}
