//! The process's ends the binary owns: a signal (SIGINT, SIGTERM) or a
//! reader of standard output gone ends the run with its temporaries
//! removed, on a thread of its own. `main` only calls these.

/// SIGINT and SIGTERM end the run on a thread of their own (not in the
/// asynchronous handler): renames into place in progress are let finish,
/// every temporary being written is removed, and the process exits with
/// 128 + the signal's number (130, 143). SIGXFSZ (a file-size limit,
/// `ulimit -f`) is caught and ignored, so the write past the limit fails
/// with EFBIG and the run's own error path removes its temporary (exit 3).
pub fn handle() {
    use signal_hook::consts::signal::{SIGINT, SIGTERM, SIGXFSZ};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGXFSZ]) else {
        return;
    };
    std::thread::spawn(move || {
        for signo in signals.forever() {
            if signo == SIGXFSZ {
                continue;
            }
            let _commit = mechplan::study::files::committing();
            // Held until the exit: no temporary is made meanwhile.
            let _held = mechplan::study::files::remove_temporaries();
            std::process::exit(128 + signo);
        }
    });
}

/// A result held back for standard output, whose reader is gone (`solve |
/// head -1` once `head` has its line): the sweep is stopped at once, the
/// run ends quietly with status 0 as a filter's does (the write would fail
/// with a broken pipe, which ends it the same way). Watched on a thread
/// polling standard output when it is a pipe.
pub fn stop_when_stdout_closes() {
    use rustix::event::{PollFd, PollFlags, poll};
    use std::os::fd::AsFd;
    let out = std::io::stdout();
    let is_pipe = rustix::fs::fstat(out.as_fd()).is_ok_and(|st| {
        rustix::fs::FileType::from_raw_mode(st.st_mode) == rustix::fs::FileType::Fifo
    });
    if !is_pipe {
        return;
    }
    std::thread::spawn(move || {
        let fd = out.as_fd();
        loop {
            // No events asked: poll returns on an error or hang-up only,
            // which a pipe whose reader closed reports.
            let mut fds = [PollFd::from_borrowed_fd(fd, PollFlags::empty())];
            match poll(&mut fds, None) {
                Ok(_) if fds[0].revents().intersects(PollFlags::ERR | PollFlags::HUP) => break,
                Ok(_) => continue,
                Err(rustix::io::Errno::INTR) => continue,
                Err(_) => return,
            }
        }
        let _commit = mechplan::study::files::committing();
        let _held = mechplan::study::files::remove_temporaries();
        std::process::exit(0);
    });
}
