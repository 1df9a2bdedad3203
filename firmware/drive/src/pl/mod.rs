//! PL drivers: one module per register block of `pl_top`
//! (docs/register-map.md), each generic over [`RegisterBus`], so the same
//! driver talks to GP0 on a board, to the simulated PL under QEMU and to a
//! fake bus in host tests.
//!
//! - [`presence`]: is our bitstream there? (devcfg `INT_STS.PCFG_DONE`, the
//!   EMIO GPIO signature, then `ID`/`VERSION`) - GP0 touched only once the
//!   first two say ours.
//! - [`top`]: mode, status, access errors, watchdog heartbeat.
//! - [`pwm`]: gate enable, dead time, PWM period and duties
//!   (`embedded_hal::pwm::SetDutyCycle` per leg).
//! - [`adc`]: averaged phase currents.
//! - [`enc`]: encoder position and speed, converted to the electrical angle.
//! - [`fault`]: latched faults, over-current limit, watchdog timeout.
//! - [`capture`]: the triggered capture buffer (arm, channels, read-back).
//! - [`mpdcc`]: constants, per-period state, start and decision of the
//!   MPDCC core.
//! - [`mpdtc`]: parameters, per-period inputs and status of the MPDTC core
//!   and its control sequence.
//!
//! Every access goes through the typed accessors of `regmap::regs` (generated
//! from the register table) by named field; no driver spells an address,
//! shift or mask.

pub mod adc;
pub mod capture;
pub mod enc;
pub mod fault;
pub mod irq;
pub mod mpdcc;
pub mod mpdtc;
pub mod presence;
pub mod pwm;
pub mod top;

#[cfg(test)]
pub(crate) mod fake;
