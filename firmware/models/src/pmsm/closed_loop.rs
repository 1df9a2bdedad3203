//! Closed-loop simulation: the [`Controller`] trait both FOC and MPDTC
//! implement, and the runner that connects a controller to the [`Plant`]
//! through the paper's measurement chain and computation delay.
//!
//! Timeline (period `T` = `controller.period_s()`, control instants `t_k = k T`):
//! 1. at `t_k` the controller gets the mean of the last `adc_average_n` ADC
//!    samples (256 kHz; the newest taken at `t_k`) and the torque reference
//!    `r(t_k)`, and returns an [`Actuation`];
//! 2. with `computation_delay_periods = 1` (paper) that actuation is applied
//!    during `[t_{k+1}, t_{k+2})`; during `[t_k, t_{k+1})` the decision of
//!    `t_{k-1}` acts. Before the first decision takes effect,
//!    [`Controller::initial_actuation`] acts (default 000, zero voltage);
//! 3. the plant is advanced exactly, sampled at every ADC instant, and each
//!    sample is reported to the `record` callback as a [`TracePoint`].
//!
//! Nothing here allocates: traces go to a callback (collect them into a `Vec`
//! on the host). See `metrics` for settling time, switching frequency and
//! ripple helpers over such traces.

use super::measure::Averager;
pub use super::measure::Measurement;
use super::params::{samples_per_period, ParamError, SamplingParams};
pub use super::plant::Actuation;
use super::plant::Plant;

/// A torque controller running at a fixed period.
pub trait Controller {
    /// Control period, s (must be an integer multiple of the ADC period).
    fn period_s(&self) -> f64;
    /// One control decision from the measurement of this instant and the
    /// torque reference, N m. Applied after the computation delay.
    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation;
    /// What the inverter does before the first decision takes effect.
    fn initial_actuation(&self) -> Actuation {
        Actuation::SwitchState(0)
    }
}

/// One ADC sample of a closed-loop run (all values exact plant values, not
/// the averaged measurement).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TracePoint {
    /// Time, s.
    pub t_s: f64,
    /// Index k of the control period `[t_k, t_{k+1})` this sample ends in.
    pub period: u64,
    /// `true` for the last sample of the period (at `t_{k+1}`).
    pub end_of_period: bool,
    /// d-axis current, A.
    pub i_d_a: f64,
    /// q-axis current, A.
    pub i_q_a: f64,
    /// Electromagnetic torque, N m.
    pub torque_nm: f64,
    /// Torque reference given to the controller at `t_k`, N m.
    pub torque_ref_nm: f64,
    /// Electrical angle, rad.
    pub theta_e_rad: f64,
    /// Electrical speed, rad/s.
    pub omega_e_rad_s: f64,
    /// Gate state (index `4 Sa + 2 Sb + Sc`) at this instant.
    pub switch_state: u8,
    /// Actuation applied during this period.
    pub applied: Actuation,
    /// Gate transitions per leg since the start of the run (cumulative).
    pub transitions: [u64; 3],
}

/// Totals of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSummary {
    /// Control periods simulated.
    pub periods: u64,
    /// Simulated duration, s.
    pub duration_s: f64,
    /// Gate transitions per leg during the run.
    pub transitions: [u64; 3],
}

/// Maximum computation delay supported (periods).
const MAX_DELAY: usize = 2;

/// Runs `n_periods` control periods of `ctrl` on `plant`.
///
/// `torque_ref(t_s)` gives the reference at each control instant; `record` is
/// called at every ADC sample. `drive` supplies the ADC rate, the averaging
/// length and the computation delay (`drive.control_period_s` is not used:
/// the controller's own period is).
///
/// Errors (nothing simulated): invalid `drive`, or a controller period that is
/// not an integer multiple (>= averaging length) of the ADC period.
pub fn run<C: Controller + ?Sized>(
    plant: &mut Plant,
    ctrl: &mut C,
    drive: &SamplingParams,
    n_periods: u64,
    mut torque_ref: impl FnMut(f64) -> f64,
    mut record: impl FnMut(&TracePoint),
) -> Result<RunSummary, ParamError> {
    let period_s = ctrl.period_s();
    let d = SamplingParams {
        control_period_s: period_s,
        ..*drive
    };
    d.validate()?;
    let n_sub = samples_per_period(period_s, d.adc_sample_rate_hz).ok_or(ParamError {
        field: "period_s",
        reason: "controller period is not an integer multiple of the ADC period",
    })?;
    let delay = d.computation_delay_periods as usize;
    let mut avg = Averager::new(d.adc_average_n as usize, plant);
    // Delay line: queue[0] acts next; decisions enter at index `delay`.
    let mut queue = [ctrl.initial_actuation(); MAX_DELAY + 1];
    let t0 = plant.state().t_s;
    let tr0 = plant.transitions();
    for k in 0..n_periods {
        let t_k = t0 + k as f64 * period_s;
        let m = avg.measurement();
        let r = torque_ref(t_k);
        queue[delay] = ctrl.step(&m, r);
        let applied = queue[0];
        queue.copy_within(1..=MAX_DELAY, 0);
        let mut j = 0;
        plant.step(&applied, period_s, n_sub, |p| {
            j += 1;
            avg.push(p);
            let (i_d_a, i_q_a) = p.i_dq_a();
            let s = p.state();
            let tr = p.transitions();
            record(&TracePoint {
                t_s: s.t_s,
                period: k,
                end_of_period: j == n_sub,
                i_d_a,
                i_q_a,
                torque_nm: p.motor().torque_nm(i_d_a, i_q_a),
                torque_ref_nm: r,
                theta_e_rad: s.theta_e_rad,
                omega_e_rad_s: s.omega_e_rad_s,
                switch_state: p.gate_state(),
                applied,
                transitions: [tr[0] - tr0[0], tr[1] - tr0[1], tr[2] - tr0[2]],
            });
        })?;
    }
    let tr = plant.transitions();
    Ok(RunSummary {
        periods: n_periods,
        duration_s: n_periods as f64 * period_s,
        transitions: [tr[0] - tr0[0], tr[1] - tr0[1], tr[2] - tr0[2]],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pmsm::params::MotorParams;
    use crate::pmsm::plant::MechanicalMode;
    use std::vec::Vec;

    /// Returns 100 at its first decision and 000 afterwards; logs measurements.
    struct Pulse {
        k: u64,
        seen: Vec<Measurement>,
    }

    impl Controller for Pulse {
        fn period_s(&self) -> f64 {
            1.0 / 64_000.0
        }
        fn step(&mut self, m: &Measurement, _r: f64) -> Actuation {
            self.seen.push(*m);
            self.k += 1;
            Actuation::SwitchState(if self.k == 1 { 0b100 } else { 0b000 })
        }
    }

    fn run_pulse(delay: u32, w: f64) -> (Vec<TracePoint>, Pulse) {
        let mut plant = Plant::new(
            &MotorParams::default(),
            0.0,
            MechanicalMode::ConstantSpeed,
            w,
        )
        .unwrap();
        let mut c = Pulse {
            k: 0,
            seen: Vec::new(),
        };
        let d = SamplingParams {
            computation_delay_periods: delay,
            ..Default::default()
        };
        let mut tr = Vec::new();
        let s = run(&mut plant, &mut c, &d, 4, |_| 0.0, |p| tr.push(*p)).unwrap();
        assert_eq!(s.periods, 4);
        (tr, c)
    }

    #[test]
    fn computation_delay_shifts_the_decision_by_one_period() {
        let (tr, _) = run_pulse(1, 0.0);
        assert_eq!(tr.len(), 16); // 4 ADC samples per 64 kHz period
        let ends: Vec<&TracePoint> = tr.iter().filter(|p| p.end_of_period).collect();
        assert_eq!(ends.len(), 4);
        // Period 0 runs the initial 000: no current; period 1 runs 100.
        assert_eq!(ends[0].i_d_a, 0.0);
        assert_eq!(ends[0].applied, Actuation::SwitchState(0));
        assert_eq!(ends[1].applied, Actuation::SwitchState(0b100));
        // 32 V on the d axis (angle 0) for 15.625 us: i = u/R (1 - e^{-R T/L}).
        let want = 32.0 / 0.555 * (1.0 - (-0.555 * 15.625e-6 / 0.64e-3f64).exp());
        assert!((ends[1].i_d_a - want).abs() < 1e-9, "{}", ends[1].i_d_a);
        assert_eq!(ends[1].transitions, [1, 0, 0]);
        assert_eq!(ends[2].transitions, [2, 0, 0]);
        let (tr0, _) = run_pulse(0, 0.0);
        assert!((tr0[3].i_d_a - want).abs() < 1e-9);
        let (tr2, _) = run_pulse(2, 0.0);
        assert_eq!(tr2[7].i_d_a, 0.0);
        assert!((tr2[11].i_d_a - want).abs() < 1e-9);
    }

    #[test]
    fn measurement_is_the_mean_of_the_last_four_samples() {
        let (tr, c) = run_pulse(1, 3000.0);
        // Decision k sees the samples of period k-1 (indices 4(k-1)..4k).
        for k in 1..4 {
            let w = &tr[4 * (k - 1)..4 * k];
            let mut i_a = 0.0;
            for p in w {
                let (al, _) = crate::pmsm::frames::inv_park(p.i_d_a, p.i_q_a, p.theta_e_rad);
                i_a += al / 4.0;
            }
            let m = &c.seen[k];
            assert!((m.i_abc_a[0] - i_a).abs() < 1e-12, "{k}");
            // The mean angle lags the newest sample by 1.5 ADC periods.
            let lag = w[3].theta_e_rad - m.theta_e_rad;
            assert!((lag - 1.5 * 3000.0 / 256e3).abs() < 1e-9, "{lag}");
        }
        // The first decision sees the initial state.
        assert_eq!(c.seen[0].i_abc_a, [0.0; 3]);
    }

    #[test]
    fn bad_controller_period_is_rejected() {
        struct Odd;
        impl Controller for Odd {
            fn period_s(&self) -> f64 {
                1.0 / 60_000.0
            }
            fn step(&mut self, _: &Measurement, _: f64) -> Actuation {
                Actuation::SwitchState(0)
            }
        }
        let mut plant = Plant::new(
            &MotorParams::default(),
            0.0,
            MechanicalMode::ConstantSpeed,
            0.0,
        )
        .unwrap();
        let r = run(
            &mut plant,
            &mut Odd,
            &SamplingParams::default(),
            3,
            |_| 0.0,
            |_| {},
        );
        assert!(r.is_err());
        assert_eq!(plant.state().t_s, 0.0);
    }
}
