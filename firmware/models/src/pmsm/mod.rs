//! Paper 000: PMSM + 2-level inverter, FOC baseline, MPDTC.
//!
//! - [`params`]: motor and drive parameters (paper defaults, validation).
//! - [`frames`]: Clarke/Park transforms and switch states `SaSbSc`.
//! - [`plant`]: exact (zero-order hold) surface PMSM + inverter model.
//! - [`mechanics`]: rotor and joint mechanics (inertia, friction, load, spring).
//! - [`measure`]: 256 kHz sampling and averaging (the measurement chain).
//! - [`sim_motor`]: the simulated motor's own parameters as one table.
//! - [`closed_loop`]: the `Controller` trait and the closed-loop runner.
//! - [`svpwm`], [`foc`]: the FOC baseline (PI + centre-aligned SVPWM).
//! - [`metrics`]: settling time, overshoot, switching frequency, ripple.
//! - [`mpdtc_ref`]: the MPDTC `f64` reference (interpretations of the paper
//!   in its module doc); [`observer`]: eqs. (14)-(16) and their stability
//!   test; [`mpdtc_fixed`]: the bit-accurate model of the PL core;
//!   [`mpdtc_ctrl`]: both as [`closed_loop::Controller`]s; [`frontend_fixed`]: the
//!   bit-accurate model of the PL front end (encoder, ADC -> core inputs);
//!   [`mpdtc_pl`]: both in one [`closed_loop::Controller`] (the PL's autonomous
//!   loop at any rate) and the inverter's slew bound.
pub mod closed_loop;
pub mod foc;
pub mod frames;
pub mod frontend_fixed;
pub mod measure;
pub mod mechanics;
pub mod metrics;
pub mod mpdtc_ctrl;
pub mod mpdtc_fixed;
pub mod mpdtc_pl;
pub mod mpdtc_ref;
#[cfg(test)]
mod mpdtc_tests;
pub mod mpdtc_tuning;
pub mod observer;
pub mod params;
pub mod plant;
pub mod sim_motor;
pub mod svpwm;
