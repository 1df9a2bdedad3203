//! Paper 001: induction machine + five-level ANPC inverter, MPDCC.
//!
//! Models, `f64` reference and closed loop: `params`, `machine`, `anpc`,
//! `controller` (the interface both implementations share), `reference`,
//! `plant`, `closed_loop`, `stats`. See docs/mpdcc.md.
//! The 16-bit FPGA model: `fixed`, `fpga`, `binsearch`, `scheduler`,
//! `cycles`, `fpga_eval` (tests). See docs/mpdcc-fpga.md.
//! `horizon`, `horizon_fixed`: longer switching horizons (SSE, SESE) for
//! both implementations (docs/mpdcc-horizons.md). The
//! hardware-in-the-loop run of the core on its register page is the
//! product's (`drive::hil`).
pub mod anpc;
pub mod binsearch;
pub mod closed_loop;
pub mod controller;
pub mod cycles;
pub mod fixed;
pub mod fpga;
pub mod fpga_eval;
pub mod horizon;
pub mod horizon_fixed;
pub mod machine;
pub mod params;
pub mod plant;
pub mod reference;
pub mod scheduler;
pub mod stats;
