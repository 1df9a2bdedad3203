//! The servo's values of one control period for the telemetry stream
//! ([`crate::telemetry`]).
use super::Servo;
use crate::pl::top::Mode;
use crate::telemetry::{Point, CHANNEL_COUNT};

impl Servo {
    /// The channels of [`crate::telemetry::CHANNELS`] after the last
    /// control step; `step_time_us` is that step's duration, measured by
    /// the caller.
    pub fn tel_point(&self, step_time_us: f64) -> Point {
        let m = self.measured;
        let velocity = m.omega_e_rad_s / f64::from(self.cfg.motor.pole_pairs.max(1));
        let cpr = f64::from(self.cfg.enc_cpr.max(1));
        let position = self
            .last_pos
            .map_or(0.0, |p| f64::from(p) / cpr * core::f64::consts::TAU);
        let state = self.last_state;
        let (duties, switching) = match self.mode {
            Mode::Foc if self.gates => (self.duties, 0),
            Mode::Mpdtc if self.gates => (
                core::array::from_fn(|leg| f64::from(state >> (2 - leg) & 1)),
                state,
            ),
            _ => ([0.0; 3], 0),
        };
        let v: [f64; CHANNEL_COUNT] = [
            m.i_d_a,
            m.i_q_a,
            m.torque_nm,
            self.torque_ref_nm,
            position,
            velocity,
            velocity * 60.0 / core::f64::consts::TAU,
            duties[0],
            duties[1],
            duties[2],
            f64::from(switching),
            f64::from(self.seen | self.ps_faults),
            step_time_us,
        ];
        Point {
            time_s: self.time_s,
            values: v.map(|x| x as f32),
        }
    }
}
