//! ARM semihosting: file I/O on the host under QEMU
//! `-semihosting-config enable=on,target=native` (ARM "Semihosting for
//! AArch32 and AArch64", operations SYS_OPEN, SYS_WRITE, SYS_READ,
//! SYS_GET_CMDLINE, SYS_ERRNO), called with `SVC 0x123456` in A32 state.
//!
//! Without semihosting that SVC is an ordinary supervisor call: the
//! handler here only notes it and returns, so [`probe`] can ask once at
//! boot whether the host answers; every other call must follow a
//! successful probe. A board never enables it, so the firmware boots
//! unchanged without it.
use core::sync::atomic::{AtomicBool, Ordering};

const SYS_OPEN: u32 = 0x01;
const SYS_WRITE: u32 = 0x05;
const SYS_READ: u32 = 0x06;
const SYS_ERRNO: u32 = 0x13;
const SYS_GET_CMDLINE: u32 = 0x15;

/// `SYS_OPEN` modes (the C `fopen` modes "rb" and "wb").
const MODE_RB: usize = 1;
const MODE_WB: usize = 5;

/// A supervisor call reached the firmware instead of the host.
static TRAPPED: AtomicBool = AtomicBool::new(false);
/// The probe found the host answering.
static PRESENT: AtomicBool = AtomicBool::new(false);

#[cortex_a_rt::exception(SupervisorCall)]
fn svc(_arg: u32) {
    TRAPPED.store(true, Ordering::SeqCst);
}

/// One semihosting call: `op` with the parameter block at `arg`.
///
/// # Safety
/// `arg` must point to the parameter block `op` expects, valid for the
/// buffers it names; semihosting must be present (or this is the probe).
unsafe fn call(op: u32, arg: usize) -> isize {
    let r: u32;
    // SAFETY: the host (or the SVC handler above) reads and writes only
    // the memory the block names; lr is banked per mode but clobbered in
    // case the trap is taken from SVC mode.
    unsafe {
        core::arch::asm!(
            "svc 0x123456",
            inout("r0") op => r,
            in("r1") arg,
            out("lr") _,
            options(nostack),
        );
    }
    r as i32 as isize
}

/// Asks once whether the host answers semihosting calls (call it at boot,
/// in a privileged mode other than SVC).
pub fn probe() -> bool {
    TRAPPED.store(false, Ordering::SeqCst);
    // SAFETY: SYS_ERRNO takes no parameter block.
    unsafe { call(SYS_ERRNO, 0) };
    let present = !TRAPPED.load(Ordering::SeqCst);
    PRESENT.store(present, Ordering::SeqCst);
    present
}

fn present() -> bool {
    PRESENT.load(Ordering::Relaxed)
}

/// The host's command line for the guest (QEMU: the `arg=` values of
/// `-semihosting-config`, joined by spaces) into `buf`; its length.
pub fn cmdline(buf: &mut [u8]) -> Option<usize> {
    if !present() {
        return None;
    }
    let mut block = [buf.as_mut_ptr() as usize, buf.len()];
    // SAFETY: the block names `buf` and its length; the host writes at most
    // that many bytes and the length back into the block.
    let r = unsafe { call(SYS_GET_CMDLINE, block.as_mut_ptr() as usize) };
    (r == 0).then_some(block[1].min(buf.len()))
}

/// A host file opened through semihosting.
pub struct HostFile(usize);

impl HostFile {
    /// Opens `path` (NUL-terminated) for reading or writing.
    pub fn open(path: &[u8], write: bool) -> Option<Self> {
        if !present() || path.last() != Some(&0) {
            return None;
        }
        let mode = if write { MODE_WB } else { MODE_RB };
        let block = [path.as_ptr() as usize, mode, path.len() - 1];
        // SAFETY: the block names the NUL-terminated path.
        let fd = unsafe { call(SYS_OPEN, block.as_ptr() as usize) };
        (fd >= 0).then_some(Self(fd as usize))
    }

    /// Writes all of `data`; `false` if the host could not.
    pub fn write_all(&mut self, data: &[u8]) -> bool {
        let block = [self.0, data.as_ptr() as usize, data.len()];
        // SAFETY: the block names `data`; the host only reads it.
        unsafe { call(SYS_WRITE, block.as_ptr() as usize) == 0 }
    }

    /// Fills `buf` (a pipe may deliver it in pieces); `false` at the end
    /// of the file or on an error.
    pub fn read_exact(&mut self, buf: &mut [u8]) -> bool {
        let mut done = 0;
        while done < buf.len() {
            let rest = &mut buf[done..];
            let block = [self.0, rest.as_mut_ptr() as usize, rest.len()];
            // SAFETY: the block names `rest`; the host writes at most its
            // length and returns how many bytes it did not read.
            let left = unsafe { call(SYS_READ, block.as_ptr() as usize) };
            if left < 0 || left as usize >= rest.len() {
                return false;
            }
            done += rest.len() - left as usize;
        }
        true
    }
}
