//! [`Controller`] adapters of the MPDTC for the closed-loop runner: the
//! measurement front end (Clarke/Park of the averaged phase currents, angle
//! advance for the measurement age) in front of [`mpdtc_ref::decide`].

use super::frames::{clarke, park};
use super::mpdtc_ref::{self, MpdtcConfig, MpdtcInputs, MpdtcOutputs, MpdtcState};
use super::sim::{Actuation, Controller, Measurement};

/// Age of the averaged measurement at the control instant, in control periods:
/// the mean of `n` samples spaced `T / m` (newest at `t_k`) describes the
/// instant `t_k - (n - 1) T / (2 m)` (paper: n = 4, m = 4 -> 0.375).
pub fn measurement_age_periods(adc_average_n: u32, samples_per_period: u32) -> f64 {
    (adc_average_n.max(1) as f64 - 1.0) / (2.0 * samples_per_period.max(1) as f64)
}

/// Front end: averaged measurement -> MPDTC inputs. The angle is advanced
/// by the measurement age so that `theta_e_rad` is the angle at `t_k`.
pub fn inputs_from_measurement(
    m: &Measurement,
    torque_ref_nm: f64,
    age_periods: f64,
    ts_s: f64,
) -> MpdtcInputs {
    let (ia, ib) = clarke(m.i_abc_a);
    let (i_d_a, i_q_a) = park(ia, ib, m.theta_e_rad);
    MpdtcInputs {
        i_d_a,
        i_q_a,
        theta_e_rad: m.theta_e_rad + age_periods * m.omega_e_rad_s * ts_s,
        omega_e_rad_s: m.omega_e_rad_s,
        t_ref_nm: torque_ref_nm,
    }
}

/// The `f64` reference MPDTC as a [`Controller`].
#[derive(Debug, Clone)]
pub struct MpdtcRef {
    /// Model and tuning.
    pub cfg: MpdtcConfig,
    /// Controller state.
    pub state: MpdtcState,
    /// Outputs of the last period (diagnostics).
    pub last: Option<MpdtcOutputs>,
}

impl MpdtcRef {
    /// A controller at rest (000 applied, integrator and observers zero).
    pub fn new(cfg: MpdtcConfig) -> Self {
        Self {
            cfg,
            state: MpdtcState::default(),
            last: None,
        }
    }
}

impl Controller for MpdtcRef {
    fn period_s(&self) -> f64 {
        self.cfg.params.control_period_s
    }

    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation {
        let ts = self.period_s();
        let inp = inputs_from_measurement(m, torque_ref_nm, self.cfg.params.meas_age_periods, ts);
        let out = mpdtc_ref::decide(&self.state, &inp, &self.cfg);
        self.state = out.next;
        self.last = Some(out);
        Actuation::SwitchState(out.s_next)
    }
}
