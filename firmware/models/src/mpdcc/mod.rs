//! Paper 001: induction machine + five-level ANPC inverter, MPDCC.
//!
//! The same roles under the same names as paper 000's [`crate::pmsm`]:
//! `params`, `plant` (with `machine`, `anpc`), the [`controller::Controller`]
//! trait both implementations share, the `f64` reference `mpdcc_ref`, the
//! bit-exact model of the PL core `mpdcc_fixed` (16-bit formats in
//! `formats`; `binsearch`, `scheduler`, `cycles` its parts and timing),
//! `closed_loop` and `metrics`; `mpdcc_tests` checks the bit-exact model
//! against independent `f64` computations. See docs/mpdcc.md and
//! docs/mpdcc-fpga.md. `horizon_ref`, `horizon_fixed`: longer switching
//! horizons (SSE, SESE) for both implementations (docs/mpdcc-horizons.md).
//! The hardware-in-the-loop run of the core on its register page is the
//! product's (`drive::hil`).
pub mod anpc;
pub mod binsearch;
pub mod closed_loop;
pub mod controller;
pub mod cycles;
pub mod formats;
pub mod horizon_fixed;
pub mod horizon_ref;
pub mod machine;
pub mod metrics;
pub mod mpdcc_fixed;
pub mod mpdcc_ref;
#[cfg(test)]
mod mpdcc_tests;
pub mod params;
pub mod plant;
pub mod scheduler;
