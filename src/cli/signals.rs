//! Signals. SIGPIPE: a closed pipe on stdout (`bidir info SCENE | head -1`) ends the process
//! quietly, as it does every Unix tool, instead of a panic in `println!`. SIGINT (Ctrl-C):
//! [`on_interrupt`] decides what the first one does; a second always aborts at once, removing
//! the temporary files of writes in progress, with nothing written (exit status 130).

use signal_hook::consts::SIGINT;
use signal_hook::iterator::Signals;

/// Restores the default action of SIGPIPE (Rust ignores it, so writes to a closed pipe fail
/// and `println!` panics). One of the two `unsafe` blocks outside `src/vk` (the binary denies
/// it elsewhere; the other is `exit_now`): std offers no safe way to set a signal's
/// disposition.
#[allow(unsafe_code)]
pub fn default_sigpipe() {
    // SAFETY: sets a signal's disposition to the default action; called first thing in
    // `main`, before any other thread exists, and installs no handler of ours.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

/// Ends the process with `code` at once, without exit handlers or static destructors: the
/// main thread may be inside the Vulkan driver, and `std::process::exit` from this thread ran
/// the driver's teardown under it (seen once in CI on lavapipe: the process died of a signal
/// after "aborted: nothing written" instead of exiting 130). Partial files are removed before.
#[allow(unsafe_code)]
fn exit_now(code: i32) -> ! {
    use std::io::Write;
    std::io::stderr().flush().ok();
    // SAFETY: _exit takes no pointers and never returns; nothing is left to clean up here.
    unsafe { libc::_exit(code) }
}

/// What the first Ctrl-C does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FirstInterrupt {
    /// Ends the render after the current pass; the command then writes what it has.
    FinishPass,
    /// Aborts at once, as the second one does.
    Abort,
}

/// Installs the Ctrl-C handler for a command that writes files. Without it SIGINT would kill
/// the process mid-write and leave a temporary file behind.
pub fn on_interrupt(first: FirstInterrupt) -> anyhow::Result<()> {
    let mut signals = Signals::new([SIGINT])?;
    std::thread::Builder::new().name("sigint".into()).spawn(move || {
        let mut count = 0;
        for _ in signals.forever() {
            count += 1;
            if count == 1 && first == FirstInterrupt::FinishPass {
                bidir::render::request_stop();
                eprintln!(
                    "\ninterrupted: finishing the current pass, then writing what was rendered (Ctrl-C again aborts without writing)"
                );
            } else {
                let removed = bidir::imaging::abort_writes();
                let note = if removed > 0 { format!(" ({removed} partial file(s) removed)") } else { String::new() };
                eprintln!("\naborted: nothing written{note}");
                exit_now(130);
            }
        }
    })?;
    Ok(())
}
