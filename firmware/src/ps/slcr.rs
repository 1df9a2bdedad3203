//! SLCR write protection (UG585 4.3 and B.28): its registers take writes
//! only between an unlock and the next lock.
use volatile_register::RW;

const SLCR_LOCK: usize = 0xF800_0004;
const SLCR_UNLOCK: usize = 0xF800_0008;
const LOCK_KEY: u32 = 0x767B;
const UNLOCK_KEY: u32 = 0xDF0D;

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: callers pass a documented SLCR register address.
    unsafe { &*(addr as *const RW<u32>) }
}

/// Runs `f` with the SLCR unlocked and locks it again (as the FSBL leaves
/// it). Call with the interrupts masked or before they are on: a handler
/// writing the SLCR in between would lock it under `f`.
pub fn unlocked<T>(f: impl FnOnce() -> T) -> T {
    // SAFETY: the documented unlock key.
    unsafe { reg(SLCR_UNLOCK).write(UNLOCK_KEY) };
    let r = f();
    // SAFETY: the documented lock key.
    unsafe { reg(SLCR_LOCK).write(LOCK_KEY) };
    r
}
