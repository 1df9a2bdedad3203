//! PL drivers: one module per register block of `pl_top`
//! (docs/register-map.md), each generic over [`RegisterBus`], so the same
//! driver talks to GP0 on a board, to the simulated PL under QEMU and to a
//! fake bus in host tests.
//!
//! - [`presence`]: is our bitstream there? (devcfg `INT_STS.PCFG_DONE`, then
//!   `ID`/`VERSION`) - decided before any GP0 access.
//! - [`top`]: mode, status, access errors, watchdog heartbeat.
//! - [`pwm`]: gate enable, dead time, PWM period and duties
//!   (`embedded_hal::pwm::SetDutyCycle` per leg).
//! - [`adc`]: averaged phase currents.
//! - [`enc`]: encoder position and speed, converted to the electrical angle.
//! - [`fault`]: latched faults, over-current limit, watchdog timeout.
//! - [`mpdtc`]: parameters, per-period inputs and status of the MPDTC core
//!   and its control sequence.
//!
//! Register addresses come from `crate::regmap` inside these modules only.
use crate::bus::{BusError, RegisterBus};
use crate::regmap::{Block, Register};

pub mod adc;
pub mod enc;
pub mod fault;
pub mod mpdtc;
pub mod presence;
pub mod pwm;
pub mod top;

#[cfg(test)]
pub(crate) mod fake;

/// Reads `reg` of `block`.
fn rd<B: RegisterBus>(bus: &mut B, block: &Block, reg: &Register) -> Result<u32, BusError> {
    bus.read(block.addr(reg))
}

/// Writes `value` to `reg` of `block`.
fn wr<B: RegisterBus>(
    bus: &mut B,
    block: &Block,
    reg: &Register,
    value: u32,
) -> Result<(), BusError> {
    bus.write(block.addr(reg), value)
}

/// Sign-extends the low `bits` bits of `v`.
fn sext(v: u32, bits: u32) -> i32 {
    let sh = 32 - bits;
    ((v << sh) as i32) >> sh
}
