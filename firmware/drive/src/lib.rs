//! `drive`: the product code of the predictive servo drive that runs on the
//! PS, in a `no_std` crate that `cargo test` runs on the host and the
//! firmware links on the target. It talks to the PL only through the
//! register map's `RegisterBus` and computes with the paper models; it may
//! depend on `regmap` (registers, bus), `models` (plants, controllers,
//! fixed-point models) and `canopen` (the CAN frame), never on the
//! simulated PL (`simpl`): the firmware binary chooses the backend a
//! `RegisterBus` is answered by.
//!
//! Modules, one job each:
//! - [`pl`]: PL drivers (one per register block) over `RegisterBus`.
//! - [`can`]: the PS CAN controller's driver, the link for `canopen`.
//! - [`servo`]: the drive on the PS: modes, gates, control step, `step`.
//! - [`hil`]: paper 001's hardware-in-the-loop run of the MPDCC core on
//!   its register page.
//! - [`config`]: the parameter table, its values and their flash store.
//! - [`console`]: the UART console line editor and command grammar.
//! - [`zynq`]: arithmetic of the Zynq-7000 PS peripherals (UART divisors,
//!   timer loads), tested on the host.
//! - [`telemetry`]: the live channel stream on the console UART.
//! - [`mmu`]: the flat translation table (memory types of the address map).
//! - [`logring`]: the log's RAM ring (whole frames, drained to the UART).
//! - [`gem`]: the Ethernet MAC's register fields and descriptor rings.
//! - [`can_gateway`]: the CANopen node behind a socketcand connection.
//! - [`fieldbus`]: the drive as a CANopen device: its dictionary, EDS and
//!   the CiA 402 modes on the servo.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

pub mod can;
pub mod can_gateway;
pub mod config;
pub mod console;
#[cfg(test)]
mod doc_figures;
pub mod fieldbus;
pub mod gem;
pub mod hil;
pub mod logring;
pub mod mmu;
pub mod pl;
pub mod servo;
pub mod telemetry;
pub mod zynq;
