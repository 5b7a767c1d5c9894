//! The command's terminal: the only printing of mechplan (results on
//! standard output, errors and notes on standard error, a progress bar
//! for long sweeps). The library hands it texts and files written.

use indicatif::{ProgressBar, ProgressStyle};
use mechplan::Progress;
use mechplan::study::files::{STDOUT, Spool, write_error};
use mechplan::{Error, Result};
use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Mutex;
use std::sync::atomic::AtomicBool;

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
    /// Whether a bar is shown: positions advance it only then (checked
    /// without the lock, which the threads finishing positions would
    /// otherwise take a hundred thousand times for nothing).
    shown: AtomicBool,
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
            shown: AtomicBool::new(false),
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
            self.shown.store(true, std::sync::atomic::Ordering::Relaxed);
        }
    }
    fn advance(&self, n: usize) {
        if !self.shown.load(std::sync::atomic::Ordering::Relaxed) {
            return;
        }
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
            self.shown
                .store(false, std::sync::atomic::Ordering::Relaxed);
            pb.finish_and_clear();
        }
    }
}

/// The exit status, an error reported on standard error first: the
/// command's own (0 success; `check`: 1 an item wrong, 4 an item that
/// cannot be judged), 2 bad input or a mechanism that cannot be solved,
/// 3 a failed write, 5 an internal error.
pub fn finish(result: Result<u8>) -> ExitCode {
    let mut e = match result {
        Ok(status) => return ExitCode::from(status),
        Err(e) => e,
    };
    // A reader that closed the pipe (`solve | head`) has what it wanted:
    // the run ends quietly, as a filter does.
    if let Error::Write { path, source } = &e
        && path == "standard output"
        && source.kind() == std::io::ErrorKind::BrokenPipe
    {
        return ExitCode::SUCCESS;
    }
    // The library names its parameters; here they are options.
    if let Some(issues) = e.issues_mut() {
        for i in issues {
            let options = [
                "output",
                "point",
                "sheet",
                "position",
                "positions-from",
                "tolerance",
                "dpi",
                "min-dwell",
                "n",
                "min-time",
                "count",
                "delta",
                "mu",
                "plan",
                "svg",
            ];
            if options.contains(&i.pointer.as_str()) {
                let dash = if i.pointer == "n" { "-" } else { "--" };
                i.pointer = format!("{dash}{}", i.pointer);
            }
        }
    }
    error(&e.to_string());
    ExitCode::from(match e {
        Error::Write { .. } => 3,
        Error::Internal(_) => 5,
        _ => 2,
    })
}
