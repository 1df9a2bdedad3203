//! The PL as the PS sees it: AXI GP0 register pages (see docs/register-map.md).
//!
//! Under QEMU the PL window reads 0 and drops writes, so the gates read as
//! off (the safe state), which is also the reset state of the real PL.
use drive::regmap;
use volatile_register::RW;

fn gate_ctrl() -> &'static RW<u32> {
    // SAFETY: GATE_CTRL is a 32-bit register of the PWM/gates page.
    unsafe { &*(regmap::PWM.addr(&regmap::GATE_CTRL) as *const RW<u32>) }
}

/// Turns every gate off (clears `GATE_EN`). Safe to call from any context,
/// including the panic handler: one store, no read-modify-write.
pub fn gates_safe() {
    // SAFETY: writing 0 disables all gates; no other bit has a side effect.
    unsafe { gate_ctrl().write(0) };
}

/// Whether the gate-enable bit is set.
pub fn gates_enabled() -> bool {
    gate_ctrl().read() & regmap::GATE_CTRL_GATE_EN != 0
}

fn top_reg(reg: &regmap::Register) -> u32 {
    // SAFETY: a 32-bit register of the top/ID page.
    unsafe { (*(regmap::TOP.addr(reg) as *const RW<u32>)).read() }
}

/// The PL's `ID` and `VERSION` registers (both read 0 without a bitstream).
pub fn id_and_version() -> (u32, u32) {
    (top_reg(&regmap::ID), top_reg(&regmap::VERSION))
}
