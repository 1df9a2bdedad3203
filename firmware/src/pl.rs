//! The PL as the PS sees it: devcfg (is it configured?) and the AXI GP0
//! register pages (docs/register-map.md) as a `RegisterBus`.
//!
//! GP0 is touched only after `drive::pl::presence` found our bitstream:
//! on a real Zynq an access to an unconfigured PL hangs the bus. The panic
//! handler's gate write obeys the same rule ([`gates_safe`]).
use core::sync::atomic::{AtomicBool, Ordering};
use drive::pl::presence::{self, Presence};
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

/// Decides what is in the PL; GP0 is read only when devcfg says the PL is
/// configured. Remembers whether GP0 may be used from now on.
pub fn detect() -> Presence {
    let p = presence::detect(devcfg_int_sts(), &mut Gp0);
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
/// read-modify-write, safe from any context including the panic handler.
/// Does nothing before presence detection or without our bitstream.
pub fn gates_safe() {
    if GP0_OK.load(Ordering::Acquire) {
        // Only GATE_EN is writable in GATE_CTRL: all gates off.
        let _ = GateCtrl::write(&mut Gp0, GateCtrlValue::ZERO.with_gate_en(false));
    }
}
