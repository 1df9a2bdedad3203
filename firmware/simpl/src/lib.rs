//! The simulated PL: a register-accurate model of `pl_top`
//! (`pl-bitstream-src/rtl/`) behind [`regmap::bus::RegisterBus`], coupled to
//! the PMSM plant. See `docs/ARCHITECTURE.md` (simulated PL).

pub mod adc;
pub mod capture;
pub mod core;
pub mod cosim;
pub mod enc;
pub mod fault;
pub mod frontend;
pub mod gates;
pub mod inverter;
pub mod mpdcc;
pub mod pl;
pub mod pwm;
pub mod regs;
pub mod seq;
pub mod simdrive;

pub use simdrive::{Advance, PlModel, SimConfig, SimDrive, Truth, Work};

/// "No event ahead" for the closed-form spans (any span is capped by the
/// cycles asked for).
pub(crate) const NEVER: u64 = u64::MAX;

#[cfg(test)]
mod tests;
