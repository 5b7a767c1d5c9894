//! Writing results: every write checked, a failure reported with the path
//! (or "standard output") as [`Error::Write`] (exit status 3 in the
//! binary), and never half a file: a file is written to a temporary beside
//! it and renamed into place; on any failure the temporary is removed.
//! A text for standard output is held back ([`Spool`]: in memory, then in
//! a temporary file for long texts) until the whole text is ready, so that
//! a run refused at a late position prints nothing; the command prints it.
//!
//! Every temporary this process is writing (a file's `.NAME.tmpPID`, a
//! sheet folder's staging folder and lock file) is listed in a
//! process-wide register ([`remove_temporaries`]), so that the command's
//! signal handler can remove them before it exits; the temporaries of a
//! process that died anyway (SIGKILL, a power cut) are removed by the next
//! run writing into that folder ([`remove_stale`]).

use crate::error::{Error, Result};
use std::fs::File;
use std::io::{BufWriter, Read, Seek, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

/// The temporaries this process is writing, removed by
/// [`remove_temporaries`].
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Held while files are renamed into place ([`committing`]).
static COMMIT: Mutex<()> = Mutex::new(());

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// Note `path` (a file or a folder) as a temporary of this process, before
/// it is made: a signal handler's [`remove_temporaries`] removes it.
pub(crate) fn track(path: &Path) {
    lock(&TEMPORARIES).push(path.to_path_buf());
}

/// `path` is no temporary any more (renamed into place, or removed).
pub(crate) fn untrack(path: &Path) {
    let mut t = lock(&TEMPORARIES);
    if let Some(k) = t.iter().rposition(|p| p == path) {
        t.swap_remove(k);
    }
}

/// Remove `path`, a temporary file or folder, and forget it.
pub(crate) fn discard(path: &Path) {
    remove_any(path);
    untrack(path);
}

fn remove_any(path: &Path) {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.is_dir() => {
            // A writer may still be putting a file into it (a signal's
            // thread removes it while the run draws on): removed again
            // until it is gone, or for at most a second.
            for _ in 0..100 {
                if std::fs::remove_dir_all(path).is_ok() || !path.exists() {
                    break;
                }
                std::thread::sleep(std::time::Duration::from_millis(10));
            }
        }
        Ok(_) => {
            let _ = std::fs::remove_file(path);
        }
        Err(_) => {}
    }
}

/// The renames that put a run's files into place, in progress: held by
/// the writer while it renames, taken by a signal handler before
/// [`remove_temporaries`], so that a run interrupted then finishes its
/// renames first (and leaves the new set, not a mix).
pub fn committing() -> MutexGuard<'static, ()> {
    lock(&COMMIT)
}

/// Remove every temporary this process is writing (for a signal handler
/// about to exit). The register stays locked as long as the guard is
/// held: hold it until the process exits, so that no new temporary is
/// made meanwhile (a temporary is noted before it is made).
pub fn remove_temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    let mut t = lock(&TEMPORARIES);
    for p in t.drain(..).rev() {
        remove_any(&p);
    }
    t
}

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
        Pending::Temp(tmp) => {
            let _commit = committing();
            let renamed = std::fs::rename(&tmp, path);
            match renamed {
                Ok(()) => {
                    untrack(&tmp);
                    Ok(())
                }
                Err(e) => {
                    discard(&tmp);
                    Err(write_error(&path.display().to_string(), e))
                }
            }
        }
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
        let _commit = committing();
        for (k, (tmp, path)) in temps.iter().enumerate() {
            if let Err(e) = std::fs::rename(tmp, path) {
                for (t, _) in &temps[k..] {
                    discard(t);
                }
                return Err(write_error(&path.display().to_string(), e));
            }
            untrack(tmp);
        }
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        for (tmp, _) in &self.temps {
            discard(tmp);
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
    if let Some(dir) = tmp.parent() {
        remove_stale_once(dir);
    }
    track(&tmp);
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
            discard(&tmp);
            Err(e)
        }
    }
}

/// Whether process `pid` is alive; `None` where the system does not list
/// its processes (no /proc).
fn alive(pid: &str) -> Option<bool> {
    let proc = Path::new("/proc");
    proc.is_dir().then(|| proc.join(pid).exists())
}

/// [`remove_stale`] of `dir`, once in a process.
fn remove_stale_once(dir: &Path) {
    static SWEPT: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
    let mut swept = lock(&SWEPT);
    if !swept.iter().any(|d| d == dir) {
        swept.push(dir.to_path_buf());
        drop(swept);
        remove_stale(dir);
    }
}

/// Remove the temporaries `.NAME.tmpPID` in `dir` of processes that are
/// gone (killed before they could remove them): the number removed.
/// Those of live processes (and everything, where the system does not
/// list its processes) are left alone.
pub fn remove_stale(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let own = std::process::id().to_string();
    let mut removed = 0;
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some((stem, pid)) = name.strip_prefix('.').and_then(|n| n.rsplit_once(".tmp")) else {
            continue;
        };
        if stem.is_empty()
            || pid.is_empty()
            || !pid.bytes().all(|b| b.is_ascii_digit())
            || pid == own
            || alive(pid) != Some(false)
            || !e.file_type().is_ok_and(|t| t.is_file())
        {
            continue;
        }
        if std::fs::remove_file(e.path()).is_ok() {
            removed += 1;
        }
    }
    removed
}

/// Check, before any work, that files can be made in `dir` (a folder to
/// write into, made later if missing): a probe file is made and removed in
/// it, or in the nearest folder above it that exists. The error names
/// `shown`, the path the user gave.
pub fn check_writable(dir: &Path, shown: &Path) -> Result<()> {
    let err = |e| write_error(&shown.display().to_string(), e);
    let mut at = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    loop {
        match std::fs::metadata(at) {
            Ok(m) if m.is_dir() => break,
            Ok(_) => {
                return Err(err(std::io::Error::new(
                    std::io::ErrorKind::NotADirectory,
                    format!("{} is a file, not a folder", at.display()),
                )));
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                match at.parent().filter(|p| !p.as_os_str().is_empty()) {
                    Some(p) => at = p,
                    None => {
                        at = Path::new(".");
                        break;
                    }
                }
            }
            Err(e) => return Err(err(e)),
        }
    }
    let probe = at.join(format!(".mechplan-probe.tmp{}", std::process::id()));
    track(&probe);
    let made = std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(true)
        .open(&probe);
    discard(&probe);
    made.map(|_| ()).map_err(err)
}

/// The lock file of a folder written by a run ([`FolderLock`]).
pub const LOCK: &str = ".mechplan.lock";

/// What a run waiting for another's folder is told (set by the command:
/// a note on standard error); a library caller is told nothing.
static WAITING: std::sync::OnceLock<fn(&str)> = std::sync::OnceLock::new();

/// Say `f(text)` when a run waits for a folder another run is writing.
pub fn on_waiting(f: fn(&str)) {
    let _ = WAITING.set(f);
}

/// An output folder locked for this run: an advisory lock on the file
/// [`LOCK`] in it. A second run into the folder waits for the first to
/// finish (told through [`on_waiting`]); the lock goes with the process,
/// however it ends, and the file is removed when the run is done.
pub struct FolderLock {
    file: File,
    path: PathBuf,
}

impl FolderLock {
    /// Lock `dir` (which exists), waiting for any other run.
    pub fn acquire(dir: &Path) -> Result<FolderLock> {
        let path = dir.join(LOCK);
        let err = |e| write_error(&path.display().to_string(), e);
        let mut told = false;
        loop {
            // Not noted as a temporary until locked: until then it may be
            // another run's (an empty lock file left by a kill between
            // these lines is harmless: the next run locks and removes it).
            let file = std::fs::OpenOptions::new()
                .read(true)
                .write(true)
                .create(true)
                .truncate(false)
                .open(&path)
                .map_err(err)?;
            match file.try_lock() {
                Ok(()) => {}
                Err(std::fs::TryLockError::WouldBlock) => {
                    if !told {
                        told = true;
                        if let Some(f) = WAITING.get() {
                            f(&format!(
                                "waiting for another run writing into {} (its lock: {})",
                                dir.display(),
                                path.display()
                            ));
                        }
                    }
                    file.lock().map_err(err)?;
                }
                Err(std::fs::TryLockError::Error(e)) => return Err(err(e)),
            }
            // The run before us may have removed the file it locked: the
            // lock holds only if the file locked is still the one there.
            if same_file(&file, &path) {
                track(&path);
                return Ok(FolderLock { file, path });
            }
        }
    }
}

/// Whether the open `file` is the one at `path` now.
#[cfg(unix)]
fn same_file(file: &File, path: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (file.metadata(), std::fs::metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn same_file(_: &File, path: &Path) -> bool {
    path.exists()
}

impl Drop for FolderLock {
    /// The lock file removed while still locked, then unlocked.
    fn drop(&mut self) {
        discard(&self.path);
        let _ = self.file.unlock();
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
