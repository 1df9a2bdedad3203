//! The processes `drivectl` starts (QEMU, `pl-cosim`): how they are
//! spawned so that they end with it.
use std::os::unix::process::CommandExt as _;
use std::process::Command;
use std::sync::atomic::{AtomicBool, Ordering};

/// Whether the processes this one starts (QEMU, `pl-cosim`) end when it
/// ends, whatever ends it (a signal, a panic, SIGKILL): `drivectl` sets it
/// at start; a library user (the system tests) starts its children from
/// threads that end before the child should, so it stays off there.
static END_CHILDREN_WITH_PARENT: AtomicBool = AtomicBool::new(false);

/// Children spawned from now on get SIGTERM when the thread that spawned
/// them ends (Linux `PR_SET_PDEATHSIG`); call it from the main thread,
/// which lives as long as the process. SIGTERM, not SIGKILL: QEMU's clean
/// exit on SIGTERM keeps the flash writes the firmware finished.
pub fn end_children_with_parent() {
    END_CHILDREN_WITH_PARENT.store(true, Ordering::Relaxed);
}

/// Prepares `cmd` as a child of this tool: it starts with no signal
/// blocked (a server blocks SIGTERM in all its threads to take it in one,
/// and a blocked mask survives exec: QEMU would ignore the SIGTERM that
/// asks it to end cleanly), and with [`end_children_with_parent`] it ends
/// with this process.
pub(crate) fn end_with_parent(cmd: &mut Command) {
    let die_with_parent = END_CHILDREN_WITH_PARENT.load(Ordering::Relaxed);
    let parent = std::process::id();
    // SAFETY: the closure runs in the forked child before exec and calls
    // only async-signal-safe functions (sigemptyset, pthread_sigmask,
    // prctl, getppid, kill).
    unsafe {
        cmd.pre_exec(move || {
            let mut none: libc::sigset_t = std::mem::zeroed();
            libc::sigemptyset(&mut none);
            libc::pthread_sigmask(libc::SIG_SETMASK, &none, std::ptr::null_mut());
            if !die_with_parent {
                return Ok(());
            }
            if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGTERM) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            // The parent may have ended between fork and prctl.
            if libc::getppid() as u32 != parent {
                libc::kill(libc::getpid(), libc::SIGTERM);
            }
            Ok(())
        });
    }
}
