//! `simpl`: the simulated PL, a register-accurate model of `pl_top`
//! (`pl-bitstream-src/rtl/`) behind [`regmap::bus::RegisterBus`], coupled to
//! the PMSM plant; the gate-driver model ([`gates`]) and the co-simulation
//! wire format ([`cosim`]) between the firmware under QEMU and the
//! Verilated PL. Its PL cores compute with the bit-exact models of
//! `models`, never a copy of their arithmetic. It may depend on `regmap` and
//! `models` only, never on the product (`drive`): the firmware binary picks
//! it as one backend of `RegisterBus`, and `rtl-sim` checks the RTL against
//! it. Its tests drive it through the product's drivers and servo (a
//! dev-dependency). `no_std`. See `docs/ARCHITECTURE.md` (simulated PL).
//!
//! Modules: [`pl`] (`SimPl`: the register file [`regs`] and the blocks
//! [`adc`], [`capture`], [`core`], [`enc`], [`fault`], [`frontend`],
//! [`irq`], [`mpdcc`], [`pwm`], [`seq`]), [`inverter`] (leg potentials),
//! [`simdrive`] (`SimDrive`: `SimPl`, inverter and PMSM plant), [`gates`],
//! [`cosim`]; [`ps_can`], a register model of the PS CAN controller (a PS
//! peripheral, outside `SimPl`) and the bus between such models.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

pub mod adc;
pub mod capture;
pub mod core;
pub mod cosim;
pub mod enc;
pub mod fault;
pub mod frontend;
pub mod gates;
pub mod inverter;
pub mod irq;
pub mod mpdcc;
pub mod pl;
pub mod ps_can;
pub mod pwm;
pub mod regs;
pub mod seq;
pub mod simdrive;

pub use simdrive::{AdcWiring, Advance, PlModel, SimConfig, SimDrive, Truth, Work};

/// "No event ahead" for the closed-form spans (any span is capped by the
/// cycles asked for).
pub(crate) const NEVER: u64 = u64::MAX;

#[cfg(test)]
mod tests;
