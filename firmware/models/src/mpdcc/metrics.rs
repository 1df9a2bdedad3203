//! Steady-state statistics of the closed loop: stator current THD and the
//! average switching frequency per semiconductor. One definition of each,
//! used by every experiment.
//!
//! **THD** (percent): over a window of an integer number of fundamental
//! periods, sampled at `T_s` (the controller's sampling instants), per phase
//! `x` the fundamental is the DFT component at exactly `omega_s`,
//! `I1_x^2 = (a^2 + b^2)/2` with `a = 2/N sum i cos(theta)`,
//! `b = 2/N sum i sin(theta)`; the distortion is everything else,
//! `rms(i_x)^2 - I1_x^2` (DC, harmonics and interharmonics up to the
//! sampling Nyquist frequency, 20 kHz at 25 us). Pooled over the three
//! phases: `THD = 100 sqrt(sum_x (rms_x^2 - I1_x^2) / sum_x I1_x^2)`.
//! Equivalently, the total rms of `i - i_fundamental` over the rms of the
//! fundamental.
//!
//! **Switching frequency per semiconductor** (Hz): device turn-ons in the
//! window (`f_s` of [`super::anpc::switch_transitions`]) divided by the
//! number of devices (24) and the window length. A device that turns on
//! and off once per fundamental period counts as 50 Hz.
#![allow(clippy::needless_range_loop)] // index loops mirror the matrix equations

use super::anpc::DEVICES_TOTAL;

/// Streaming THD accumulator (no allocation).
#[derive(Debug, Clone)]
pub struct ThdAccumulator {
    dtheta: f64,
    n: u64,
    sum_sq: [f64; 3],
    sum_c: [f64; 3],
    sum_s: [f64; 3],
}

impl ThdAccumulator {
    /// `dtheta_rad` = fundamental angle advance per sample, `omega_s T_s`.
    pub fn new(dtheta_rad: f64) -> Self {
        Self {
            dtheta: dtheta_rad,
            n: 0,
            sum_sq: [0.0; 3],
            sum_c: [0.0; 3],
            sum_s: [0.0; 3],
        }
    }

    /// Adds one sample of the three phase currents.
    pub fn push(&mut self, i_abc: [f64; 3]) {
        let th = self.dtheta * self.n as f64;
        let (c, s) = (libm::cos(th), libm::sin(th));
        for x in 0..3 {
            self.sum_sq[x] += i_abc[x] * i_abc[x];
            self.sum_c[x] += i_abc[x] * c;
            self.sum_s[x] += i_abc[x] * s;
        }
        self.n += 1;
    }

    /// Samples so far.
    pub fn samples(&self) -> u64 {
        self.n
    }

    /// Fundamental rms per phase, same unit as the samples.
    pub fn fundamental_rms(&self) -> [f64; 3] {
        let n = self.n.max(1) as f64;
        core::array::from_fn(|x| {
            let a = 2.0 * self.sum_c[x] / n;
            let b = 2.0 * self.sum_s[x] / n;
            libm::sqrt(0.5 * (a * a + b * b))
        })
    }

    /// THD in percent (0 with no samples or no fundamental).
    pub fn thd_percent(&self) -> f64 {
        if self.n == 0 {
            return 0.0;
        }
        let n = self.n as f64;
        let f = self.fundamental_rms();
        let (mut dist, mut fund) = (0.0, 0.0);
        for x in 0..3 {
            let f2 = f[x] * f[x];
            dist += (self.sum_sq[x] / n - f2).max(0.0);
            fund += f2;
        }
        if fund <= 0.0 {
            return 0.0;
        }
        100.0 * libm::sqrt(dist / fund)
    }
}

/// Switching frequency per semiconductor, Hz, from the device turn-ons
/// counted over `duration_s`.
pub fn fsw_per_device_hz(turn_ons: u64, duration_s: f64) -> f64 {
    if duration_s <= 0.0 {
        return 0.0;
    }
    turn_ons as f64 / (DEVICES_TOTAL as f64 * duration_s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pure sinusoid plus a known 5th harmonic: THD = 100 * h5 / i1.
    #[test]
    fn thd_of_known_harmonic_content() {
        let n_per = 800; // 50 Hz at 25 us
        let dth = 2.0 * core::f64::consts::PI / n_per as f64;
        let mut acc = ThdAccumulator::new(dth);
        for n in 0..(10 * n_per) {
            let t = dth * n as f64;
            let i: [f64; 3] = core::array::from_fn(|x| {
                let ph = -2.0 * core::f64::consts::PI / 3.0 * x as f64;
                1.0 * libm::cos(t + ph + 0.3) + 0.05 * libm::cos(5.0 * (t + ph))
            });
            acc.push(i);
        }
        assert!(
            (acc.thd_percent() - 5.0).abs() < 1e-9,
            "{}",
            acc.thd_percent()
        );
        let f = acc.fundamental_rms();
        assert!((f[1] - core::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12);
    }

    #[test]
    fn fsw_by_hand() {
        // 24 devices each turning on 10 times in 0.2 s: 50 Hz.
        assert!((fsw_per_device_hz(240, 0.2) - 50.0).abs() < 1e-12);
        assert_eq!(fsw_per_device_hz(5, 0.0), 0.0);
    }
}
