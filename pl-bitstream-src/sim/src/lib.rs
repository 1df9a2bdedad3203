//! Verilator harnesses of the PL RTL, driven from Rust.
//!
//! `build.rs` verilates each top and links a small C++ shim per top
//! (`csrc/*_shim.cpp`); this crate wraps the shim's `extern "C"` functions in
//! safe types. Tests in `tests/` drive them against the cycle-exact Rust
//! models in the `drive` crate.

pub mod gate_driver;
pub mod mpdtc_core;
pub mod mpdtc_vectors;
pub mod pl_top;
