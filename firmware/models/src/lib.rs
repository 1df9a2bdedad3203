//! `models`: the mathematics of the predictive servo drive's two papers,
//! with no hardware in it. The plants (PMSM + two-level inverter,
//! induction machine + five-level ANPC), the controllers (FOC, MPDTC,
//! MPDCC) as `f64` references and as the bit-exact models of the PL cores
//! (the RTL's oracle, the simulated PL's arithmetic and the host
//! controller at once), closed-loop runners and their metrics. It is
//! `no_std`, host-testable and depends on no crate of the project: no
//! register map, no bus, no drivers; the product (`drive`), the simulated
//! PL (`simpl`), the generator (`regmap-gen`), the RTL simulation
//! (`rtl-sim`) and the host tool depend on it.
//!
//! Modules, one job each:
//! - [`pmsm`]: paper 000 (PMSM + two-level inverter, FOC baseline, MPDTC),
//!   with its frames (Clarke/Park), measurement chain and metrics.
//! - [`mpdcc`]: paper 001 (induction machine + five-level ANPC, MPDCC) and
//!   its 16-bit FPGA model.
//! - [`motion`]: the servo's outer loops (position and velocity from the
//!   encoder, velocity PI, trajectory, position loop, impedance).
//! - [`frames`]: the Clarke and Park transforms both papers use.
//! - [`fixedpoint`]: the rounding shift shared by every fixed-point model.
//! - [`validate`]: the parameter error type and checks every model's
//!   `validate()` uses.
//! - [`testrng`]: the one seeded generator of every randomized test.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

#[cfg(feature = "std")]
extern crate std;

pub mod calibration;
pub mod fixedpoint;
pub mod frames;
pub mod motion;
pub mod mpdcc;
pub mod pmsm;
pub mod testrng;
pub mod validate;
