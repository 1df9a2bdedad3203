//! The PL as the PS sees it: devcfg (is it configured?) and the AXI GP0
//! register pages (docs/register-map.md) as a `RegisterBus`.
//!
//! GP0 is touched only after `drive::pl::presence` found our bitstream:
//! on a real Zynq an access to an unconfigured PL (or with the level
//! shifters off, or the PL in reset) hangs the bus. The one exception is
//! [`gates_safe`], which writes `GATE_CTRL` = 0 whenever the GP0 guard
//! passes, also before detection (first thing at boot).
use core::sync::atomic::{AtomicBool, Ordering};
use drive::pl::presence::{self, Guard, Presence};
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::pwm::{GateCtrl, GateCtrlValue};
use volatile_register::RW;

/// Set once presence detection found our bitstream behind GP0.
static GP0_OK: AtomicBool = AtomicBool::new(false);

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: callers pass the address of a 32-bit device register.
    unsafe { &*(addr as *const RW<u32>) }
}

/// devcfg `INT_STS` (a PS register: always safe to read).
pub fn devcfg_int_sts() -> u32 {
    reg(presence::DEVCFG_INT_STS).read()
}

/// SLCR `PSS_IDCODE` (a PS register: always safe to read); tells a Zynq
/// from QEMU (`drive::pl::presence::platform`).
pub fn pss_idcode() -> u32 {
    reg(presence::SLCR_PSS_IDCODE).read()
}

/// The GP0 guard's words: devcfg `INT_STS`, SLCR `LVL_SHFTR_EN` and
/// `FPGA_RST_CTRL` (PS registers: always safe to read).
pub fn guard() -> Guard {
    Guard {
        int_sts: devcfg_int_sts(),
        lvl_shftr_en: reg(presence::SLCR_LVL_SHFTR_EN).read(),
        fpga_rst_ctrl: reg(presence::SLCR_FPGA_RST_CTRL).read(),
    }
}

/// Decides what is in the PL; GP0 is read only when the guard passes.
/// Remembers whether GP0 may be used from now on.
pub fn detect() -> Presence {
    let p = presence::detect(&guard(), &mut Gp0);
    GP0_OK.store(p.usable(), Ordering::Release);
    p
}

/// GP0 as a register bus (volatile 32-bit accesses).
pub struct Gp0;

impl RegisterBus for Gp0 {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        if regmap::lookup(addr).is_none() {
            return Err(BusError::SlaveError);
        }
        Ok(reg(addr).read())
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        if regmap::lookup(addr).is_none() {
            return Err(BusError::SlaveError);
        }
        // SAFETY: a register of the map; the drivers decide the values.
        unsafe { reg(addr).write(value) };
        Ok(())
    }
}

/// Turns every gate of a configured PL off (clears `GATE_EN`): one store, no
/// read-modify-write, safe from any context including the panic and abort
/// handlers. With our bitstream found, at once; otherwise (before detection,
/// or a design detection did not recognise) only when the GP0 guard passes,
/// so that the store cannot hang the bus. A foreign design may see a 0
/// written at `GATE_CTRL`'s offset: the price of not waiting for `ID`.
pub fn gates_safe() {
    if GP0_OK.load(Ordering::Acquire) || guard().check().is_ok() {
        // Only GATE_EN is writable in GATE_CTRL: all gates off.
        let _ = GateCtrl::write(&mut Gp0, GateCtrlValue::ZERO.with_gate_en(false));
        // GP0 is device memory: the store may wait in the write buffer;
        // the barrier makes it reach the PL before anything else.
        // SAFETY: a barrier only.
        unsafe { core::arch::asm!("dsb", options(nostack)) };
    }
}
