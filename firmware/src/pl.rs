//! The PL as the PS sees it: AXI GP0 register pages (see docs/register-map.md),
//! reached through the typed accessors of `drive::regs` over [`Mmio`].
//!
//! Under QEMU the PL window reads 0 and drops writes, so the gates read as
//! off (the safe state), which is also the reset state of the real PL.
use drive::bus::{BusError, RegisterBus};
use drive::regs::{pwm, top};

/// The PL window on GP0: one volatile 32-bit load or store per access.
pub struct Mmio;

impl RegisterBus for Mmio {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        // SAFETY: every caller passes an address generated from the register
        // map: a word-aligned 32-bit register inside the PL window.
        Ok(unsafe { core::ptr::read_volatile(addr as *const u32) })
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        // SAFETY: as for `read`.
        unsafe { core::ptr::write_volatile(addr as *mut u32, value) };
        Ok(())
    }
}

/// Turns every gate off (clears `GATE_EN`). Safe to call from any context,
/// including the panic handler: one store, no read-modify-write.
pub fn gates_safe() {
    // Writing 0 disables all gates; no other bit has a side effect. `Mmio`
    // cannot fail.
    let _ = pwm::GateCtrl::write(&mut Mmio, pwm::GateCtrlValue::ZERO);
}

/// Whether the gate-enable bit is set.
pub fn gates_enabled() -> bool {
    pwm::GateCtrl::read(&mut Mmio).is_ok_and(|v| v.gate_en())
}

/// The PL's `ID` and `VERSION` registers (both read 0 without a bitstream).
pub fn id_and_version() -> (u32, u32) {
    let id = top::Id::read(&mut Mmio).map_or(0, |v| v.bits());
    let version = top::Version::read(&mut Mmio).map_or(0, |v| v.bits());
    (id, version)
}
