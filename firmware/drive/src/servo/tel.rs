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
        // The position and velocity `status` prints, in its units (rev,
        // rev/s), so that a stream and `status` agree; speed is `status`'s
        // electrical speed.
        let mo = self.motion.status();
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
            mo.position_rev,
            mo.velocity_rev_s,
            m.omega_e_rad_s,
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
