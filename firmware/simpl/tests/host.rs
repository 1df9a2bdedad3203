//! The simulated PL and the drive on it, on the host: one module per file of this
//! directory, in one test binary (one compilation and one link instead of
//! one per file; docs/ARCHITECTURE.md, "Tests and their budget"). A test is `<module>::<name>`: run one file's
//! tests with `cargo test -p simpl --test host <module>::`. The
//! system tests check that no file of the directory is left out.
mod alignment;
mod calibration;
mod cia402;
mod evidence;
mod hil;
mod ps_can;
mod servo;
mod servo_faults;
mod telemetry;
