//! Ctrl-C on the command line: the first press asks the long work in progress (a run, a sweep, an IDA, a
//! separation, a spectrum) to stop; it stops within one progress report and says what it kept. A second
//! press ends the process at once.

use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};

static PRESSED: AtomicBool = AtomicBool::new(false);

/// Exit code of a command stopped by Ctrl-C (128 + SIGINT, as a shell reports it).
pub const EXIT_CODE: u8 = 130;

/// Installs the handler. Without one (the OS refused it), Ctrl-C ends the process as it would by default.
pub fn install() {
    let _ = ctrlc::set_handler(|| {
        if PRESSED.swap(true, Ordering::SeqCst) {
            std::process::exit(i32::from(EXIT_CODE));
        }
    });
}

/// Whether Ctrl-C was pressed.
pub fn pressed() -> bool {
    PRESSED.load(Ordering::Relaxed)
}

/// `Break` once Ctrl-C was pressed: the answer for the library's progress callbacks.
pub fn go_on() -> ControlFlow<()> {
    if pressed() {
        ControlFlow::Break(())
    } else {
        ControlFlow::Continue(())
    }
}
