//! A9 MPCore global timer (uptime) and private timer (periodic tick).
use volatile_register::RW;

const GLOBAL: usize = 0xF8F0_0200;
const PRIVATE: usize = 0xF8F0_0600;

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: only called with timer register addresses.
    unsafe { &*(addr as *const RW<u32>) }
}

/// Clock of both timers (PERIPHCLK = CPU_6x4x / 2), from the board file:
/// 333.333 MHz with the ZedBoard's 666.667 MHz CPU clock.
pub const PERIPHCLK_HZ: u32 = crate::board::PERIPHCLK_HZ;

/// Starts the 64-bit global timer, prescaler 1.
pub fn start_global() {
    // SAFETY: enable bit only.
    unsafe { reg(GLOBAL + 0x08).write(1) };
}

/// Global timer count (PERIPHCLK cycles since it started).
pub fn global_count() -> u64 {
    loop {
        let hi = reg(GLOBAL + 0x04).read();
        let lo = reg(GLOBAL).read();
        if reg(GLOBAL + 0x04).read() == hi {
            return (u64::from(hi) << 32) | u64::from(lo);
        }
    }
}

/// Microseconds since the global timer started.
pub fn uptime_us() -> u64 {
    global_count() / u64::from(PERIPHCLK_HZ / 1_000_000)
}

/// Raises the global timer's interrupt (IRQ 27) once the count reaches
/// `count` (at once if it already has): comparator mode, no auto-increment.
pub fn set_compare(count: u64) {
    // SAFETY: documented sequence: comparator off, value, stale event
    // cleared, then timer enable | comparator enable | IRQ enable.
    unsafe {
        reg(GLOBAL + 0x08).write(1);
        reg(GLOBAL + 0x10).write(count as u32);
        reg(GLOBAL + 0x14).write((count >> 32) as u32);
        reg(GLOBAL + 0x0C).write(1);
        reg(GLOBAL + 0x08).write(0b111);
    }
}

/// Stops the comparator and clears its event flag. The comparator must be
/// off first: while the count is past the comparator the event flag sets
/// again at once (QEMU re-evaluates on the clear), and the interrupt would
/// fire back to back.
pub fn ack_compare() {
    // SAFETY: comparator off (timer stays enabled), then write-one-to-clear.
    unsafe {
        reg(GLOBAL + 0x08).write(1);
        reg(GLOBAL + 0x0C).write(1);
    }
}

/// Starts the private timer: auto-reload, interrupt every `load + 1` cycles.
pub fn start_private(load: u32) {
    // SAFETY: documented values: load, then enable | auto-reload | IRQ enable.
    unsafe {
        reg(PRIVATE + 0x08).write(0);
        reg(PRIVATE).write(load);
        reg(PRIVATE + 0x0C).write(1);
        reg(PRIVATE + 0x08).write(0b111);
    }
}

/// Clears the private timer's event flag.
pub fn ack_private() {
    // SAFETY: write-one-to-clear.
    unsafe { reg(PRIVATE + 0x0C).write(1) };
}
