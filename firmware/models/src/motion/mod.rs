//! The servo's outer loops over a torque loop, in revolutions: multi-turn
//! position and a tracking-loop velocity estimate from the encoder count
//! ([`position`]), the velocity PI with anti-windup behind an acceleration
//! limit ([`velocity`]), the trapezoidal trajectory ([`trajectory`]), the
//! position loop with velocity and acceleration feedforward and the
//! impedance law ([`law`]). Units: rev, rev/s, rev/s^2, N m; every function
//! takes the step `dt_s` it runs at (the drive runs them at its control
//! rate).
pub mod law;
pub mod position;
pub mod trajectory;
pub mod velocity;

/// Radians per revolution.
pub const RAD_PER_REV: f64 = core::f64::consts::TAU;
