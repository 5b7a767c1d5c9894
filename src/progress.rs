//! Long sweeps: parallel over positions (rayon), and how far they have
//! come, told to whoever watches ([`Progress`]: the command draws a bar on
//! a terminal; the library itself never prints). Results never depend on
//! either: each position's work is independent once the positions
//! themselves are found in order, and the results are gathered in the
//! order of the positions.

use rayon::prelude::*;

/// From this many items a sweep runs in parallel: fewer do not pay for
/// waking the thread pool.
pub const PARALLEL_FROM: usize = 32;

/// A watcher of a long sweep: told its length once, then each item done.
/// The library calls it from several threads at once.
pub trait Progress: Sync {
    /// The sweep of `len` items of `what` (e.g. "positions") begins.
    fn start(&self, _len: usize, _what: &str) {}
    /// `n` more items are done.
    fn advance(&self, n: usize);
    /// The sweep is over (done or stopped by an error).
    fn finish(&self) {}
}

/// No watcher: the default of every library call.
#[derive(Clone, Copy, Debug, Default)]
pub struct Silent;

impl Progress for Silent {
    fn advance(&self, _n: usize) {}
}

/// `f` over `items`, in parallel for long sweeps, results in the items'
/// order, told to `progress` as one sweep of `what`.
pub fn map<T: Sync, R: Send>(
    items: &[T],
    what: &str,
    progress: &dyn Progress,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    progress.start(items.len(), what);
    let out = map_on(items, progress, f);
    progress.finish();
    out
}

/// As [`map`], counting on a sweep begun by the caller (one sweep done a
/// part at a time).
pub fn map_on<T: Sync, R: Send>(
    items: &[T],
    progress: &dyn Progress,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    let mut out = Vec::new();
    map_into(items, progress, f, &mut out);
    out
}

/// As [`map_on`], into `out` (emptied first; its room kept: a sweep done
/// a part at a time reuses one buffer instead of asking for a new one a
/// part).
pub fn map_into<T: Sync, R: Send>(
    items: &[T],
    progress: &dyn Progress,
    f: impl Fn(&T) -> R + Sync,
    out: &mut Vec<R>,
) {
    map_into_with(items, progress, || (), |(), x| f(x), out);
}

/// As [`map_into`], `f` given a scratch of its own made by `init` (once
/// for each part of the work a thread takes, not once an item: a sweep's
/// positions reuse one state instead of making a new one each).
pub fn map_into_with<T: Sync, S, R: Send>(
    items: &[T],
    progress: &dyn Progress,
    init: impl Fn() -> S + Sync + Send,
    f: impl Fn(&mut S, &T) -> R + Sync + Send,
    out: &mut Vec<R>,
) {
    let one = |s: &mut S, x: &T| {
        let r = f(s, x);
        progress.advance(1);
        r
    };
    if items.len() >= PARALLEL_FROM {
        items.par_iter().map_init(&init, one).collect_into_vec(out);
    } else {
        out.clear();
        let mut s = init();
        out.extend(items.iter().map(|x| one(&mut s, x)));
    }
}
