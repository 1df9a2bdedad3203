//! The PL310 L2 cache controller of the A9 MPCore (UG585 ch. 3.4, PL310
//! TRM r3p2), at 0xF8F0_2000.
//!
//! QEMU 7.2's `xilinx-zynq-a9` has no PL310: its registers are unassigned
//! (reads 0, writes dropped), so `CACHE_ID` tells a real controller apart
//! and the L2 reports itself absent there.
use volatile_register::RW;

const BASE: usize = 0xF8F0_2000;
const CACHE_ID: usize = 0x000;
const CTRL: usize = 0x100;
const AUX: usize = 0x104;
const TAG_RAM: usize = 0x108;
const DATA_RAM: usize = 0x10C;
const INT_CLEAR: usize = 0x220;
const CACHE_SYNC: usize = 0x730;
const INV_WAY: usize = 0x77C;
const CLEAN_INV_WAY: usize = 0x7FC;

/// SLCR `L2C_RAM` (UG585 B.28).
const SLCR_L2C_RAM: usize = 0xF800_0A1C;
/// The value UG585 requires in `L2C_RAM` before the L2 is used.
const L2C_RAM_VALUE: u32 = 0x0002_0202;
/// RAM latencies (setup, read, write, cycles - 1) of the Zynq-7000's L2
/// RAMs: tag 2/2/2, data 2/3/2 (UG585 3.4.7).
const TAG_LATENCY: u32 = 0x0111;
const DATA_LATENCY: u32 = 0x0121;
/// `AUX` bits set: data prefetch (28), instruction prefetch (29), early
/// BRESP (30); the rest (8 ways of 64 KiB) as the reset value has it.
const AUX_SET: u32 = (1 << 28) | (1 << 29) | (1 << 30);
/// All eight ways.
const WAYS: u32 = 0xFF;

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: callers pass a documented PL310 or SLCR register address.
    unsafe { &*(addr as *const RW<u32>) }
}

/// `CACHE_ID`: implementer ARM (0x41, bits 31:24), part L2C-310 (0b0011,
/// bits 9:6); the Zynq-7000's reads 0x4100_00C8 (r3p2).
pub fn present() -> bool {
    let id = cache_id();
    id >> 24 == 0x41 && (id >> 6) & 0xF == 0b0011
}

/// `CACHE_ID` as read.
pub fn cache_id() -> u32 {
    reg(BASE + CACHE_ID).read()
}

/// Invalidates all ways and enables the L2, from known values whatever it
/// was: one left on (a core reset without a system reset) is switched off
/// first and its lines dropped, not written back (they are the previous
/// run's: this image's start-up ran with the L1 off, uncached, so nothing
/// of it is there; after a start-up with the caches on the caller has
/// cleaned it with [`disable`]). Nothing without a PL310.
pub fn enable() {
    if !present() {
        return;
    }
    // SAFETY: documented values, written with the L2 disabled.
    unsafe {
        reg(BASE + CTRL).write(0);
        super::slcr::unlocked(|| reg(SLCR_L2C_RAM).write(L2C_RAM_VALUE));
        reg(BASE + AUX).modify(|a| a | AUX_SET);
        reg(BASE + TAG_RAM).write(TAG_LATENCY);
        reg(BASE + DATA_RAM).write(DATA_LATENCY);
        reg(BASE + INV_WAY).write(WAYS);
    }
    while reg(BASE + INV_WAY).read() & WAYS != 0 {}
    // SAFETY: as above; then on.
    unsafe {
        reg(BASE + CACHE_SYNC).write(0);
        reg(BASE + INT_CLEAR).write(0x1FF);
        reg(BASE + CTRL).write(1);
    }
}

/// Cleans, invalidates and switches off an L2 left on (a warm restart);
/// nothing when it is off or absent. [`enable`] then sets it up afresh.
pub fn disable() {
    if !present() || ctrl() & 1 == 0 {
        return;
    }
    // SAFETY: the PL310's maintenance by way with the L1 already cleaned.
    unsafe { reg(BASE + CLEAN_INV_WAY).write(WAYS) };
    while reg(BASE + CLEAN_INV_WAY).read() & WAYS != 0 {}
    // SAFETY: as above; then off.
    unsafe {
        reg(BASE + CACHE_SYNC).write(0);
        reg(BASE + CTRL).write(0);
    }
}

/// `CTRL` (bit 0: the L2 is on).
pub fn ctrl() -> u32 {
    reg(BASE + CTRL).read()
}
