//! Paper 001: induction machine + five-level ANPC inverter, MPDCC.
//!
//! Part A (models, f64 reference, closed loop): `params`, `machine`, `anpc`,
//! `controller` (the interface both implementations share), `reference`,
//! `plant`, `closed_loop`, `stats`. See docs/mpdcc.md.
pub mod anpc;
pub mod controller;
pub mod machine;
pub mod params;
pub mod binsearch;
pub mod fixed;
