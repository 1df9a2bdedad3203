//! Bare-metal PS application of the predictive servo drive.
//!
//! Boot: VBAR, UART0 (defmt log, 115200 8N1) and UART1 (console, 921600
//! 8N1), GIC,
//! private timer tick at [`TICK_HZ`], GEM0 Ethernet, then the console loop,
//! which also polls the network (the socketcand server, `net`). This crate only
//! moves bytes, touches registers and chooses the backend the drive's
//! `RegisterBus` is answered by (`control`: GP0 with a bitstream, else the
//! co-simulated RTL over `cosim`, else the simulated PL). Everything that
//! can be tested on the host lives in the library crates:
//! - `drive` (`firmware/drive`): the product: PL drivers, servo, the MPDCC
//!   HIL loop, configuration and its flash store, console grammar;
//! - `models` (`firmware/models`): the papers' plants, controllers and
//!   bit-exact fixed-point models;
//! - `simpl` (`firmware/simpl`): the simulated PL, the gate-driver model,
//!   the co-simulation wire format;
//! - `regmap` (`firmware/regmap`): the PL register map, its typed accessors
//!   and the `RegisterBus` trait.
//!
//! Only this crate may depend on both `drive` and `simpl`.
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

#[cfg(target_os = "none")]
mod app;
#[cfg(target_os = "none")]
mod bench;
#[cfg(target_os = "none")]
mod board;
#[cfg(target_os = "none")]
mod control;
#[cfg(target_os = "none")]
mod cosim;
#[cfg(target_os = "none")]
mod fieldbus;
#[cfg(target_os = "none")]
mod irq;
#[cfg(target_os = "none")]
mod log;
#[cfg(target_os = "none")]
mod net;
#[cfg(target_os = "none")]
mod panic;
#[cfg(target_os = "none")]
mod pl;
#[cfg(target_os = "none")]
mod ps;
#[cfg(target_os = "none")]
mod rx;
#[cfg(target_os = "none")]
mod semihosting;
#[cfg(target_os = "none")]
mod telemetry;

/// The firmware only runs on the target; on the host this crate is an empty
/// binary so that `cargo build --workspace` and clippy work everywhere.
#[cfg(not(target_os = "none"))]
fn main() {}
