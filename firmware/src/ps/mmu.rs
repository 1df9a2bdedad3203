//! MMU and caches of the A9: the flat translation table of `drive::mmu`,
//! L1 instruction and data caches, branch prediction and the PL310 L2
//! (`l2c`), switched on once at boot; and the read-backs `debug mmu` prints.
//!
//! Order (ARMv7-A ARM B2.2 "Caches and branch predictors", B3.10 "TLB
//! maintenance"; Cortex-A9 TRM r4p1): with the MMU and caches still off,
//! invalidate the L1 data cache by set/way (its contents are not defined
//! after a reset on every part, and the FSBL ran with it on), the
//! instruction cache, the branch predictor and the TLBs; load DACR, TTBCR
//! and TTBR0; invalidate and enable the L2; then write SCTLR whole
//! (`drive::mmu::SCTLR_BOOT`). The code runs at its own (flat) address
//! throughout.
//!
//! A warm restart (a debugger's reset of the core without a system reset,
//! or a download and run) may find the MMU and caches on: the L1 data
//! cache then holds this image's own start-up writes (`.data`, `.bss`, the
//! stack), so it is cleaned and invalidated, not just invalidated, and
//! switched off before the sequence above; an L2 left on is cleaned,
//! invalidated and switched off before it is set up again (`l2c`).
use super::l2c;
use drive::mmu::{self, ENTRIES};

/// The translation table: 16 KiB aligned (TTBR0 with TTBCR.N = 0).
#[repr(C, align(16384))]
struct Table([u32; ENTRIES]);

/// Written once, before the MMU is on, then only read (by the walker and
/// `entry`).
static mut TABLE: Table = Table([0; ENTRIES]);

/// Invalidates (`clean` false: DCISW) or cleans and invalidates (DCCISW)
/// the L1 data cache by set/way, with the geometry from CCSIDR.
fn l1d_by_set_way(clean: bool) {
    let ccsidr: u32;
    // SAFETY: CSSELR = 0 selects the L1 data cache; reading CCSIDR.
    unsafe {
        core::arch::asm!(
            "mcr p15, 2, {z}, c0, c0, 0",
            "isb",
            "mrc p15, 1, {c}, c0, c0, 0",
            z = in(reg) 0u32,
            c = out(reg) ccsidr,
            options(nostack)
        );
    }
    let line_shift = (ccsidr & 0x7) + 4;
    let ways = ((ccsidr >> 3) & 0x3FF) + 1;
    let sets = ((ccsidr >> 13) & 0x7FFF) + 1;
    let way_shift = (ways - 1).leading_zeros() % 32;
    for way in 0..ways {
        for set in 0..sets {
            let sw = (way.checked_shl(way_shift).unwrap_or(0)) | (set << line_shift);
            if clean {
                // SAFETY: DCCISW: dirty lines are written back first.
                unsafe {
                    core::arch::asm!("mcr p15, 0, {}, c7, c14, 2", in(reg) sw, options(nostack))
                };
            } else {
                // SAFETY: DCISW with caches off: nothing dirty to lose.
                unsafe {
                    core::arch::asm!("mcr p15, 0, {}, c7, c6, 2", in(reg) sw, options(nostack))
                };
            }
        }
    }
    // SAFETY: barrier only.
    unsafe { core::arch::asm!("dsb", options(nostack)) };
}

/// Builds the table and turns on the MMU, L1 caches, branch prediction and
/// the L2. Call once, first thing at boot, IRQs masked.
pub fn enable() {
    // SAFETY: single core, before anything else runs; the only write.
    let table = unsafe { &mut *core::ptr::addr_of_mut!(TABLE) };
    mmu::fill(&mut table.0);
    let base = table.0.as_ptr() as u32;
    let at_entry = sctlr();
    if at_entry & (mmu::SCTLR_M | mmu::SCTLR_C) != 0 {
        // A warm restart: write back what the start-up wrote, then off.
        l1d_by_set_way(true);
        // SAFETY: the flat table maps this code at its own address, so
        // execution continues with the MMU off.
        unsafe {
            core::arch::asm!(
                "mcr p15, 0, {t}, c1, c0, 0",
                "dsb",
                "isb",
                t = in(reg) at_entry & !mmu::SCTLR_ON,
                options(nostack)
            );
        }
        l2c::disable();
    }
    l1d_by_set_way(false);
    // SAFETY: the sequence of the module comment; the table maps this code
    // and its data at their own addresses, so execution continues.
    unsafe {
        core::arch::asm!(
            "dsb",
            "mcr p15, 0, {z}, c7, c5, 0", // ICIALLU
            "mcr p15, 0, {z}, c7, c5, 6", // BPIALL
            "mcr p15, 0, {z}, c8, c7, 0", // TLBIALL
            "mcr p15, 0, {dacr}, c3, c0, 0",
            "mcr p15, 0, {z}, c2, c0, 2", // TTBCR = 0: TTBR0 only
            "mcr p15, 0, {ttbr}, c2, c0, 0",
            "dsb",
            "isb",
            z = in(reg) 0u32,
            // Domain 0 client: the entries' AP bits are checked.
            dacr = in(reg) 0b01u32,
            ttbr = in(reg) mmu::ttbr0(base),
            options(nostack)
        );
    }
    l2c::enable();
    // SAFETY: as above; the whole register, not ORed into.
    unsafe {
        core::arch::asm!(
            "mcr p15, 0, {t}, c1, c0, 0",
            "dsb",
            "isb",
            t = in(reg) mmu::SCTLR_BOOT,
            options(nostack)
        );
    }
}

/// SCTLR as the CPU has it.
pub fn sctlr() -> u32 {
    let v: u32;
    // SAFETY: reading SCTLR has no side effect.
    unsafe { core::arch::asm!("mrc p15, 0, {}, c1, c0, 0", out(reg) v, options(nomem, nostack)) };
    v
}

/// TTBR0 as the CPU has it.
pub fn ttbr0() -> u32 {
    let v: u32;
    // SAFETY: reading TTBR0 has no side effect.
    unsafe { core::arch::asm!("mrc p15, 0, {}, c2, c0, 0", out(reg) v, options(nomem, nostack)) };
    v
}

/// The table entry of `addr` as the walker reads it (from the table TTBR0
/// points at).
pub fn entry(addr: u32) -> u32 {
    let t = (ttbr0() & !0x3FFF) as *const u32;
    // SAFETY: TTBR0 holds `TABLE`'s address (mapped, cached normal memory);
    // the index is below 4096.
    unsafe { t.add((addr >> 20) as usize).read_volatile() }
}

/// The MMU's own translation of `addr` for a privileged read (ATS1CPR):
/// PAR, bit 0 set on a fault (no abort is taken).
pub fn translate(addr: u32) -> u32 {
    let par: u32;
    // SAFETY: an address translation operation has no memory effect.
    unsafe {
        core::arch::asm!(
            "mcr p15, 0, {a}, c7, c8, 0",
            "isb",
            "mrc p15, 0, {p}, c7, c4, 0",
            a = in(reg) addr,
            p = out(reg) par,
            options(nostack)
        );
    }
    par
}

/// What `debug mmu` prints.
pub fn report() -> drive::console::MmuReport {
    let mut regions = [(0, 0); mmu::USED.len()];
    for (r, &(_, addr)) in regions.iter_mut().zip(mmu::USED) {
        *r = (entry(addr), translate(addr));
    }
    drive::console::MmuReport {
        sctlr: sctlr(),
        l2_id: l2c::cache_id(),
        l2_ctrl: l2c::ctrl(),
        ttbr0: ttbr0(),
        regions,
    }
}

/// An address the table leaves unmapped (GP1, which the design does not
/// use).
pub const UNMAPPED: usize = 0x8000_0000;

/// Reads [`UNMAPPED`]: a translation fault, taken as a data abort.
pub fn read_unmapped() {
    // SAFETY: the read cannot reach the bus (the MMU faults it); the data
    // abort handler takes over and halts.
    let _ = unsafe { core::ptr::read_volatile(UNMAPPED as *const u32) };
}
