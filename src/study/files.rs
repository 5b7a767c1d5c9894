//! Writing results: every write checked, a failure reported with the path
//! (or "standard output") as [`Error::Write`] (exit status 3 in the
//! binary), and never half a file: a file is written to a temporary beside
//! it and renamed into place; on any failure the temporary is removed.
//! A text for standard output is held back ([`Spool`]: in memory, then in
//! a temporary file for long texts) until the whole text is ready, so that
//! a run refused at a late position prints nothing; the command prints it.

use crate::error::{Error, Result};
use std::fs::File;
use std::io::{BufWriter, Read, Seek, Write};
use std::path::{Path, PathBuf};

/// How errors name standard output.
pub const STDOUT: &str = "standard output";

/// A writer whose errors name their target.
pub struct Output<'a> {
    w: &'a mut dyn Write,
    name: &'a str,
}

impl<'a> Output<'a> {
    /// A writer to `w`, named `name` in its errors.
    pub fn new(w: &'a mut dyn Write, name: &'a str) -> Output<'a> {
        Output { w, name }
    }

    /// Write `text`; an error names the target.
    pub fn write(&mut self, text: &str) -> Result<()> {
        self.write_bytes(text.as_bytes())
    }

    /// Write `bytes`; an error names the target.
    pub fn write_bytes(&mut self, bytes: &[u8]) -> Result<()> {
        self.w
            .write_all(bytes)
            .map_err(|e| write_error(self.name, e))
    }
}

/// The error of a failed write to `name`.
pub fn write_error(name: &str, source: std::io::Error) -> Error {
    Error::Write {
        path: name.to_string(),
        source,
    }
}

/// Write to a temporary file beside `path`, then rename: never half a file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomically_with(path, |out| out.write_bytes(bytes))
}

/// As [`write_atomically`], the text made by `fill` a piece at a time (a
/// long result need not be held in memory). An error of `fill` (a refused
/// position, a failed write) removes the temporary and is returned.
pub fn write_atomically_with(
    path: &Path,
    fill: impl FnOnce(&mut Output) -> Result<()>,
) -> Result<()> {
    match write_pending(path, fill)? {
        Pending::Direct => Ok(()),
        Pending::Temp(tmp) => std::fs::rename(&tmp, path).map_err(|e| {
            let _ = std::fs::remove_file(&tmp);
            write_error(&path.display().to_string(), e)
        }),
    }
}

/// Write several files, all or nothing as far as the file system allows:
/// every file goes to its temporary first, and any failure removes every
/// temporary of this call; only then are they renamed into place (a
/// failing rename removes the temporaries not yet renamed).
pub fn write_files_atomically(files: &[(PathBuf, &[u8])]) -> Result<()> {
    let mut staged = Staged::default();
    for (path, bytes) in files {
        staged.put(path, bytes)?;
    }
    staged.commit()
}

/// Files written one by one to temporaries beside their places and
/// renamed into place together by [`Staged::commit`]; dropped before it,
/// every temporary is removed: nothing is written half-way, and a long
/// run need not hold its files in memory until the end.
#[derive(Default)]
pub struct Staged {
    temps: Vec<(PathBuf, PathBuf)>,
}

impl Staged {
    /// Write `path`'s content to its temporary (a device or pipe
    /// directly).
    pub fn put(&mut self, path: &Path, bytes: &[u8]) -> Result<()> {
        if let Pending::Temp(tmp) = write_pending(path, |out| out.write_bytes(bytes))? {
            self.temps.push((tmp, path.to_path_buf()));
        }
        Ok(())
    }

    /// Rename every temporary into its place.
    pub fn commit(mut self) -> Result<()> {
        let temps = std::mem::take(&mut self.temps);
        for (k, (tmp, path)) in temps.iter().enumerate() {
            if let Err(e) = std::fs::rename(tmp, path) {
                for (t, _) in &temps[k..] {
                    let _ = std::fs::remove_file(t);
                }
                return Err(write_error(&path.display().to_string(), e));
            }
        }
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        for (tmp, _) in &self.temps {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// A file written and still to be renamed into place, or written directly.
enum Pending {
    Temp(PathBuf),
    Direct,
}

/// The temporary beside `path`: `.NAME.tmpPID`.
fn temp_path(path: &Path) -> PathBuf {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    dir.join(format!(".{name}.tmp{}", std::process::id()))
}

/// Write `path`'s content: to its temporary (removed again on any failure),
/// or straight into a device or pipe (`/dev/stdout`, `/dev/null`, a FIFO),
/// which a rename would replace instead of writing to.
fn write_pending(path: &Path, fill: impl FnOnce(&mut Output) -> Result<()>) -> Result<Pending> {
    let name = path.display().to_string();
    let err = |e| write_error(&name, e);
    match std::fs::metadata(path) {
        Ok(md) if md.is_dir() => {
            return Err(err(std::io::Error::new(
                std::io::ErrorKind::IsADirectory,
                "is a folder, not a file",
            )));
        }
        Ok(md) if !md.is_file() => {
            let f = std::fs::OpenOptions::new()
                .write(true)
                .open(path)
                .map_err(err)?;
            let mut w = BufWriter::new(f);
            fill(&mut Output::new(&mut w, &name))?;
            w.flush().map_err(err)?;
            return Ok(Pending::Direct);
        }
        _ => {}
    }
    let tmp = temp_path(path);
    let written = (|| {
        let f = File::create(&tmp).map_err(err)?;
        let mut w = BufWriter::with_capacity(1 << 16, f);
        fill(&mut Output::new(&mut w, &name))?;
        w.flush().map_err(err)?;
        Ok(())
    })();
    match written {
        Ok(()) => Ok(Pending::Temp(tmp)),
        Err(e) => {
            let _ = std::fs::remove_file(&tmp);
            Err(e)
        }
    }
}

/// Standard output held back until the text is complete: in memory up to
/// [`Spool::MEMORY`] bytes, beyond that in an unnamed temporary file, so
/// that a long result costs no memory.
pub struct Spool {
    mem: Vec<u8>,
    file: Option<(File, String)>,
}

impl Default for Spool {
    fn default() -> Self {
        Spool::new()
    }
}

impl Spool {
    /// Bytes kept in memory before spilling to a temporary file.
    pub const MEMORY: usize = 64 << 20;

    /// An empty spool.
    pub fn new() -> Spool {
        Spool {
            mem: Vec::new(),
            file: None,
        }
    }

    /// Add `text`.
    pub fn write(&mut self, text: &str) -> Result<()> {
        if self.file.is_none() && self.mem.len() + text.len() > Spool::MEMORY {
            let mut f = spill_file()?;
            f.0.write_all(&self.mem)
                .map_err(|e| write_error(&spill_name(&f.1), e))?;
            self.mem = Vec::new();
            self.file = Some(f);
        }
        match &mut self.file {
            Some((f, name)) => f
                .write_all(text.as_bytes())
                .map_err(|e| write_error(&spill_name(name), e)),
            None => {
                self.mem.extend_from_slice(text.as_bytes());
                Ok(())
            }
        }
    }

    /// Hand everything held to `o` (standard output, named `name` in
    /// errors), checked and flushed.
    pub fn finish_into(self, o: &mut dyn Write, name: &str) -> Result<()> {
        let e = |e| write_error(name, e);
        match self.file {
            None => o.write_all(&self.mem).map_err(e)?,
            Some((mut f, name)) => {
                f.rewind().map_err(|e| write_error(&spill_name(&name), e))?;
                let mut buf = vec![0u8; 1 << 16];
                loop {
                    let n = f.read(&mut buf).map_err(|source| Error::Io {
                        path: spill_name(&name),
                        source,
                    })?;
                    if n == 0 {
                        break;
                    }
                    o.write_all(&buf[..n]).map_err(e)?;
                }
            }
        }
        o.flush().map_err(e)
    }
}

fn spill_name(path: &str) -> String {
    format!("{path} (holding standard output)")
}

/// A new temporary file in the system's temporary folder, removed from the
/// folder at once (it lives as long as the handle).
fn spill_file() -> Result<(File, String)> {
    static COUNT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!("mechplan-stdout-{}-{k}", std::process::id()));
    let name = path.display().to_string();
    let f = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&path)
        .map_err(|e| write_error(&spill_name(&name), e))?;
    let _ = std::fs::remove_file(&path);
    Ok((f, name))
}
