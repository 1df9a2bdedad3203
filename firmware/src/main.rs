//! Bare-metal PS application of the predictive servo drive.
//!
//! Boot: VBAR, UART0 (defmt log, 115200 8N1) and UART1 (console, 921600 8N1), GIC,
//! private timer tick at [`TICK_HZ`], then the console loop. Everything that
//! can be tested on the host lives in the `drive` crate; this crate only
//! moves bytes and touches registers.
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
mod irq;
#[cfg(target_os = "none")]
mod log;
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
