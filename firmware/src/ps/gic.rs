//! GIC (PL390) distributor and CPU interface of the Cortex-A9 MPCore.
use volatile_register::RW;

const DIST: usize = 0xF8F0_1000;
const CPU: usize = 0xF8F0_0100;

// Distributor offsets.
const ICDDCR: usize = 0x000;
const ICDICTR: usize = 0x004;
const ICDISER: usize = 0x100;
const ICDICER: usize = 0x180;
const ICDISPR: usize = 0x200;
const ICDICPR: usize = 0x280;
const ICDABR: usize = 0x300;
const ICDIPR: usize = 0x400;
const ICDIPTR: usize = 0x800;
const ICDICFR: usize = 0xC00;
// CPU interface offsets.
const ICCICR: usize = 0x00;
const ICCPMR: usize = 0x04;
const ICCIAR: usize = 0x0C;
const ICCEOIR: usize = 0x10;

/// Interrupt IDs (UG585 table 7-3).
pub const IRQ_PRIVATE_TIMER: u32 = 29;
/// Global timer comparator.
pub const IRQ_GLOBAL_TIMER: u32 = 27;
pub const IRQ_UART1: u32 = 82;
/// `IRQ_F2P[0]` from the PL (UG585 table 7-4): the control interrupt.
/// Level-sensitive, as after reset (`ICDICFR`).
pub const IRQ_F2P0: u32 = 61;
/// What ICCIAR returns when nothing is pending.
pub const SPURIOUS: u32 = 1023;

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: only called with GIC register addresses; MMIO lives forever.
    unsafe { &*(addr as *const RW<u32>) }
}

fn reg8(addr: usize) -> &'static RW<u8> {
    // SAFETY: the priority and target registers are byte-accessible.
    unsafe { &*(addr as *const RW<u8>) }
}

/// Starts the distributor and CPU interface from known values, whatever
/// the last run left (a warm restart: a debugger's reset of the core, or a
/// download and run, keeps the GIC's state): forwarding off, the active
/// interrupts ended, every interrupt disabled and its pending state
/// cleared; then both on with all priorities passing. Interrupts come on
/// one by one ([`enable_at`]).
pub fn init() {
    // SAFETY: documented registers and values (PL390 / Cortex-A9 MPCore
    // TRM), with IRQs masked.
    unsafe {
        reg(DIST + ICDDCR).write(0);
        let regs = (reg(DIST + ICDICTR).read() as usize & 0x1F) + 1;
        for r in 0..regs {
            // An interrupt still active (its handler cut short by the
            // restart) would hold off every one of its priority and below.
            let active = reg(DIST + ICDABR + 4 * r).read();
            for b in 0..32 {
                if active & (1 << b) != 0 {
                    reg(CPU + ICCEOIR).write((32 * r + b) as u32);
                }
            }
            reg(DIST + ICDICER + 4 * r).write(u32::MAX);
            reg(DIST + ICDICPR + 4 * r).write(u32::MAX);
        }
        reg(CPU + ICCICR).write(0);
        reg(DIST + ICDDCR).write(1);
        reg(CPU + ICCPMR).write(0xF0);
        reg(CPU + ICCICR).write(1);
    }
}

/// The priority of [`enable`]: the middle of the range.
pub const PRIORITY_DEFAULT: u8 = 0xA0;
/// A priority above [`PRIORITY_DEFAULT`] (a lower value is taken first).
pub const PRIORITY_HIGH: u8 = 0x90;

/// Routes `id` to CPU0 at a middle priority and enables it.
pub fn enable(id: u32) {
    enable_at(id, PRIORITY_DEFAULT);
}

/// Routes `id` to CPU0 at `priority` and enables it. Handlers do not nest:
/// the priority only decides which of two pending interrupts is taken
/// first (at equal priority, the lower ID).
pub fn enable_at(id: u32, priority: u8) {
    let id = id as usize;
    // SAFETY: per-interrupt configuration registers of a valid ID.
    unsafe {
        reg8(DIST + ICDIPR + id).write(priority);
        if id >= 32 {
            reg8(DIST + ICDIPTR + id).write(0x01);
            // The boot ROM leaves the sensitivity to software (UG585 7.2.4):
            // ours are level-high (the PL's `irq_o` stays up until cleared).
            let cfg = reg(DIST + ICDICFR + 4 * (id / 16));
            cfg.write(drive::zynq::icdicfr_level_high(cfg.read(), id as u32));
        }
        reg(DIST + ICDISER + 4 * (id / 32)).write(1 << (id % 32));
    }
}

/// Acknowledges the highest pending interrupt: its ICCIAR value.
pub fn acknowledge() -> u32 {
    reg(CPU + ICCIAR).read()
}

/// The interrupt ID of an acknowledged `iar` (ICCIAR bits 9:0; bits 12:10
/// name the requesting CPU of an SGI).
pub const fn interrupt_id(iar: u32) -> u32 {
    iar & 0x3ff
}

/// Signals the end of the interrupt acknowledged as `iar`.
pub fn end(iar: u32) {
    // SAFETY: writing back the acknowledged value.
    unsafe { reg(CPU + ICCEOIR).write(iar) };
}

/// Sets interrupt `id` pending in the distributor (`GICD_ISPENDR`), as a
/// peripheral's line would: the same acknowledge and handler follow.
pub fn set_pending(id: u32) {
    let id = id as usize;
    // SAFETY: the set-pending register of a valid ID; writing 1 sets only it.
    unsafe { reg(DIST + ICDISPR + 4 * (id / 32)).write(1 << (id % 32)) };
}

/// Whether interrupt `id` is pending in the distributor (`GICD_ISPENDR`
/// reads the pending bits).
pub fn is_pending(id: u32) -> bool {
    let id = id as usize;
    // A read of the set-pending register has no side effect.
    reg(DIST + ICDISPR + 4 * (id / 32)).read() & (1 << (id % 32)) != 0
}
