//! Measurement chain of paper 000 (Section 4): phase currents and rotor angle
//! sampled at 256 kHz, each measurement the mean of the last `n` samples
//! ("each four sampled phase current and motor angles are averaged").
//!
//! Decisions:
//! - Samples are ideal (no noise, no quantisation): the paper averages to
//!   suppress noise, which a noise-free model does not have; what the averaging
//!   does to the *dynamics* (a lag of `(n-1)/2` ADC periods, 5.9 us for n = 4)
//!   is kept.
//! - The angle is averaged on the circle: `theta_avg = theta_newest +
//!   mean(wrap(theta_j - theta_newest))`, so a wrap at 2 pi does not corrupt it.
//! - The speed is averaged the same way as the currents (an encoder-derived
//!   speed is outside the paper's chain; we give the controller the plant speed).
//! - The window is the last `n` samples before the control instant, the
//!   newest one taken at the instant itself. Before `n` samples exist, the
//!   missing ones are copies of the initial state.

use super::plant::{wrap_2pi, Plant};
use core::f64::consts::PI;

/// Maximum averaging length supported (matches `SamplingParams::validate`).
pub const MAX_AVERAGE_N: usize = 64;

/// What a controller receives at a control instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Phase currents a, b, c, A (averaged).
    pub i_abc_a: [f64; 3],
    /// Electrical rotor angle, rad, in `[0, 2 pi)` (averaged on the circle).
    pub theta_e_rad: f64,
    /// Electrical speed, rad/s (averaged).
    pub omega_e_rad_s: f64,
}

#[derive(Debug, Clone, Copy, Default)]
struct Sample {
    i_abc_a: [f64; 3],
    theta_e_rad: f64,
    omega_e_rad_s: f64,
}

/// Moving average over the last `n` ADC samples.
#[derive(Debug, Clone)]
pub struct Averager {
    buf: [Sample; MAX_AVERAGE_N],
    n: usize,
    head: usize,
}

impl Averager {
    /// An averager of length `n` (clamped to 1..=[`MAX_AVERAGE_N`]) prefilled
    /// with the plant's present state.
    pub fn new(n: usize, plant: &Plant) -> Self {
        let s = sample_of(plant);
        Self {
            buf: [s; MAX_AVERAGE_N],
            n: n.clamp(1, MAX_AVERAGE_N),
            head: 0,
        }
    }

    /// Records one ADC sample of the plant.
    pub fn push(&mut self, plant: &Plant) {
        self.head = (self.head + 1) % self.n;
        self.buf[self.head] = sample_of(plant);
    }

    /// The mean of the last `n` samples.
    pub fn measurement(&self) -> Measurement {
        let newest = self.buf[self.head].theta_e_rad;
        let mut i = [0.0; 3];
        let (mut dth, mut w) = (0.0, 0.0);
        for s in &self.buf[..self.n] {
            for (acc, v) in i.iter_mut().zip(s.i_abc_a) {
                *acc += v;
            }
            dth += wrap_pi(s.theta_e_rad - newest);
            w += s.omega_e_rad_s;
        }
        let k = 1.0 / self.n as f64;
        Measurement {
            i_abc_a: [i[0] * k, i[1] * k, i[2] * k],
            theta_e_rad: wrap_2pi(newest + dth * k),
            omega_e_rad_s: w * k,
        }
    }
}

fn sample_of(p: &Plant) -> Sample {
    Sample {
        i_abc_a: p.i_abc_a(),
        theta_e_rad: p.state().theta_e_rad,
        omega_e_rad_s: p.state().omega_e_rad_s,
    }
}

/// Wraps an angle into `[-pi, pi)`.
pub fn wrap_pi(x: f64) -> f64 {
    let y = wrap_2pi(x + PI) - PI;
    if y >= PI {
        y - 2.0 * PI
    } else {
        y
    }
}
