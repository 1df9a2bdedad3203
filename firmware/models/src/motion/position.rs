//! Multi-turn position and velocity from an encoder that counts modulo its
//! counts per revolution.
//!
//! Position: an `i64` count of every step of the encoder since the last
//! zero, each step taken the shortest way round (the encoder must move by
//! less than half a turn between two updates), so nothing drifts or wraps:
//! 10^6 revolutions of a 65535-count encoder are 6.6e10 counts, exact in
//! an `i64` and in the `f64` of the reading.
//!
//! Velocity: a tracking observer on the count with three states, the
//! estimate `p^`, its velocity `v^` and an acceleration `d^` that the
//! drive's expectation does not explain (a load, friction, an inertia
//! error): `e = p - p^`, `p^' = v^ + 3 w_n e`, `v^' = a_exp + d^ + 3 w_n^2 e`,
//! `d^' = w_n^3 e` (a triple pole at `-w_n`), stepped by forward Euler at
//! the update rate. `a_exp` is the acceleration the drive expects from its
//! torque reference. It has no velocity error at constant speed (standstill
//! to no-load speed) nor under a constant acceleration, whether expected or
//! not (a constant load under a torque that holds it reads 0 rev/s), and it
//! smooths the count's quantisation (a difference of two counts over one
//! period would be 4096 x 16 kHz = 3.9 rev/s per count at 16 kHz). The
//! estimate is kept relative to the count (`p^ - p`), so it stays small
//! however far the rotor turns.
use crate::validate::{check_pos, ParamError};

/// Tracking bandwidth `w_n`, rad/s: 2 pi 250 Hz. At 16 kHz its Euler step
/// is stable with margin (`3 w_n dt` = 0.29).
pub const TRACKING_BANDWIDTH_RAD_S: f64 = 2.0 * core::f64::consts::PI * 250.0;

/// Multi-turn position and tracking-loop velocity of one encoder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionEstimator {
    cpr: u32,
    last: Option<u32>,
    /// Counts since the last zero.
    total: i64,
    /// Estimate minus count, counts.
    lead: f64,
    /// Velocity estimate, counts/s.
    v: f64,
    /// Unexplained acceleration, counts/s^2.
    d: f64,
    w_n: f64,
}

impl PositionEstimator {
    /// An estimator for `cpr` counts per revolution (`cpr` >= 4) with
    /// tracking bandwidth `w_n_rad_s` (damping 1).
    pub fn new(cpr: u32, w_n_rad_s: f64) -> Result<Self, ParamError> {
        check_pos("w_n_rad_s", w_n_rad_s)?;
        if cpr < 4 {
            return Err(ParamError {
                field: "cpr",
                reason: "must be at least 4",
            });
        }
        Ok(Self {
            cpr,
            last: None,
            total: 0,
            lead: 0.0,
            v: 0.0,
            d: 0.0,
            w_n: w_n_rad_s,
        })
    }

    /// Takes the encoder reading `pos` (`0..cpr`) after `dt_s` seconds.
    /// The first reading only sets the reference.
    pub fn update(&mut self, pos: u32, dt_s: f64) {
        self.update_with_accel(pos, dt_s, 0.0);
    }

    /// [`Self::update`] with the acceleration the drive expects over the
    /// step, rev/s^2 (its torque over the inertia): a right expectation
    /// leaves the observer's third state nothing to learn, so a change of
    /// acceleration shows in the velocity without the observer's lag.
    pub fn update_with_accel(&mut self, pos: u32, dt_s: f64, accel_rev_s2: f64) {
        let cpr = i64::from(self.cpr);
        let pos = i64::from(pos % self.cpr);
        let Some(last) = self.last else {
            self.last = Some(pos as u32);
            return;
        };
        let mut d = (pos - i64::from(last)).rem_euclid(cpr);
        if d > cpr / 2 {
            d -= cpr;
        }
        self.last = Some(pos as u32);
        self.total += d;
        self.lead -= d as f64;
        if !(dt_s.is_finite() && dt_s > 0.0) {
            return;
        }
        let e = -self.lead;
        let a = if accel_rev_s2.is_finite() {
            accel_rev_s2 * f64::from(self.cpr)
        } else {
            0.0
        };
        let w = self.w_n;
        self.lead += dt_s * (self.v + 3.0 * w * e);
        self.v += dt_s * (a + self.d + 3.0 * w * w * e);
        self.d += dt_s * w * w * w * e;
    }

    /// Counts since the last zero.
    pub fn counts(&self) -> i64 {
        self.total
    }

    /// Position, rev.
    pub fn position_rev(&self) -> f64 {
        self.total as f64 / f64::from(self.cpr)
    }

    /// Velocity estimate, rev/s.
    pub fn velocity_rev_s(&self) -> f64 {
        self.v / f64::from(self.cpr)
    }

    /// Counts per revolution.
    pub fn cpr(&self) -> u32 {
        self.cpr
    }

    /// Makes the present position 0 (the velocity estimate stays).
    pub fn zero(&mut self) {
        self.total = 0;
    }

    /// Forgets the last reading (after a pause in the updates): the next
    /// one sets the reference again; position and velocity stay.
    pub fn resync(&mut self) {
        self.last = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The count of a rotor at `rev` revolutions, `0..cpr`.
    fn count(rev: f64, cpr: u32) -> u32 {
        (libm::floor(rev * f64::from(cpr)) as i64).rem_euclid(i64::from(cpr)) as u32
    }

    #[test]
    fn a_million_revolutions_of_counting_neither_drift_nor_wrap() {
        // 2047 counts per update (just under half a turn, the largest step
        // the shortest-way rule reads right), forward then back.
        let cpr = 4096;
        let mut e = PositionEstimator::new(cpr, TRACKING_BANDWIDTH_RAD_S).unwrap();
        let steps = 1_000_000u64 * u64::from(cpr) / 2047 + 1;
        let mut c: i64 = 0;
        e.update(0, 1e-4);
        for _ in 0..steps {
            c += 2047;
            e.update(c.rem_euclid(4096) as u32, 1e-4);
        }
        assert_eq!(e.counts(), c);
        assert!(e.position_rev() >= 1_000_000.0);
        assert_eq!(e.position_rev(), c as f64 / 4096.0);
        for _ in 0..steps {
            c -= 2047;
            e.update(c.rem_euclid(4096) as u32, 1e-4);
        }
        assert_eq!(e.counts(), 0);
    }

    #[test]
    fn velocity_tracks_from_standstill_to_no_load_speed() {
        // The paper's motor turns at most about 68 rev/s at 48 V; at 16 kHz
        // that is 17 counts per period.
        let (cpr, dt) = (4096, 1.0 / 16_000.0);
        for want in [0.0, 0.05, -1.0, 10.0, -68.0] {
            let mut e = PositionEstimator::new(cpr, TRACKING_BANDWIDTH_RAD_S).unwrap();
            let (mut worst, mut sum): (f64, f64) = (0.0, 0.0);
            for k in 0..16_000 {
                e.update(count(want * k as f64 * dt, cpr), dt);
                if k >= 8000 {
                    worst = worst.max((e.velocity_rev_s() - want).abs());
                    sum += e.velocity_rev_s() - want;
                }
            }
            // Quantisation ripple: a count (1/4096 rev) seen by a 250 Hz
            // observer is at most about 3 w_n / 4096 = 1.2 rev/s; measured
            // well under that (largest where the counts come slowest), and
            // no mean error.
            assert!(worst < 0.35, "{want} rev/s: worst error {worst} rev/s");
            let mean = sum / 8000.0;
            assert!(mean.abs() < 2e-3, "{want} rev/s: mean error {mean} rev/s");
            let p = want * 15_999.0 * dt;
            assert!((e.position_rev() - p).abs() <= 1.0 / 4096.0 + 1e-12);
        }
    }

    /// Constant acceleration from rest at 64 kHz for 0.1 s: the velocity
    /// at the end within quantisation, with the acceleration expected, not
    /// expected, or expected wrongly by a constant (a load the torque holds).
    fn accelerate(expected: f64) -> f64 {
        let (cpr, dt, a) = (4096, 1.0 / 64_000.0, 500.0);
        let mut e = PositionEstimator::new(cpr, TRACKING_BANDWIDTH_RAD_S).unwrap();
        let n = 6400;
        for k in 0..=n {
            let t = k as f64 * dt;
            e.update_with_accel(count(0.5 * a * t * t, cpr), dt, expected);
        }
        e.velocity_rev_s() - a * n as f64 * dt
    }

    #[test]
    fn no_velocity_error_under_constant_acceleration() {
        for expected in [500.0, 0.0, 893.0] {
            let err = accelerate(expected);
            assert!(
                err.abs() < 0.05,
                "expected {expected} rev/s^2: error {err} rev/s"
            );
        }
    }

    #[test]
    fn a_held_load_reads_standstill() {
        // The torque holds a load: the drive expects 393 rev/s^2 that never
        // comes; the rotor stays at count 100.
        let mut e = PositionEstimator::new(4096, TRACKING_BANDWIDTH_RAD_S).unwrap();
        for _ in 0..16_000 {
            e.update_with_accel(100, 1.0 / 16_000.0, 393.0);
        }
        assert!(e.velocity_rev_s().abs() < 1e-6, "{}", e.velocity_rev_s());
        assert_eq!(e.counts(), 0);
    }

    #[test]
    fn zero_and_bad_arguments() {
        assert!(PositionEstimator::new(3, 100.0).is_err());
        assert!(PositionEstimator::new(4096, f64::NAN).is_err());
        let mut e = PositionEstimator::new(4096, 100.0).unwrap();
        e.update(4000, 1e-4);
        e.update(100, 1e-4); // 196 counts forward through the wrap
        assert_eq!(e.counts(), 196);
        e.zero();
        assert_eq!(e.counts(), 0);
        e.update(90, f64::NAN); // bad time step: counted, no estimate step
        assert_eq!(e.counts(), -10);
    }
}
