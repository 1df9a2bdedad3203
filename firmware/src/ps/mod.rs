//! Drivers of the PS peripherals the firmware uses (Zynq-7000 TRM, UG585).
//!
//! Register blocks are `#[repr(C)]` structs of `volatile-register` cells with
//! a size check; they are reached through `&'static` references built from
//! the documented base address, never `&mut`.
pub mod gem;
pub mod gic;
pub mod l2c;
pub mod mmu;
pub mod qspi;
pub mod slcr;
pub mod timer;
pub mod uart;
