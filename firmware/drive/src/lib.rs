//! `drive`: every model and algorithm of the predictive servo drive, in a
//! `no_std` crate that `cargo test` runs on the host and the firmware links
//! on the target.
//!
//! Modules, one job each:
//! - [`bus`]: the `RegisterBus` trait every PL driver talks through.
//! - [`console`]: the UART console line editor and command grammar.
//! - [`pl`]: PL drivers (one per register block) over `RegisterBus`.
//! - [`servo`]: the drive on the PS: modes, gates, control step, `step`.
//! - [`pmsm`]: paper 000 (PMSM + 2-level inverter, FOC baseline, MPDTC).
//! - [`mpdcc`]: paper 001 (induction machine + 5L-ANPC, MPDCC).
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

#[cfg(feature = "std")]
extern crate std;

pub mod bus;
pub mod console;
pub mod gates;
pub mod mpdcc;
pub mod pl;
pub mod pmsm;
pub mod regmap;
pub mod servo;
pub mod simpl;
pub mod validate;
pub mod zynq;
