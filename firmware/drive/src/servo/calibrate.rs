//! The calibration on the PL: runs [`models::calibration::Calibrator`]
//! period by period through the PWM (voltage vectors as duties) and the
//! ADC and encoder (its measurements), with the gates on for its duration
//! and off afterwards whatever happened.
//!
//! Timing (the calibrator's contract): each step starts just after a PWM
//! period ends; the four averaged ADC results read during the period (at
//! fixed phases of the PWM counter, one per quarter period) are its 16
//! samples, spread evenly over it, so their mean is the period's mean
//! current whatever the ripple. The duties written right after the step
//! are loaded at the next counter bottom: applied in period `k + 2`.
use super::sensors::PlTime;
use crate::pl::adc::Adc;
use crate::pl::enc::Encoder;
use crate::pl::fault::{Fault, Faults};
use crate::pl::pwm::Pwm;
use crate::pl::top::{Mode, Top};
use models::calibration::{Calibrator, Command, Measurement, Phase, Results, Setup};
use models::frames::inv_clarke;
use regmap::bus::BusError;

/// How a calibration ended early.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CalStop {
    /// A fault latched (gates off by the PL).
    Fault(Faults),
    /// Stopped on request (Ctrl-C).
    Interrupted,
}

/// What a calibration run returns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalReport {
    /// The estimates.
    pub results: Results,
    /// Set when it stopped early (the results are then not to be applied).
    pub stopped: Option<CalStop>,
    /// PL cycles it took.
    pub cycles: u64,
}

/// Cycles from the counter bottom at which the step runs.
const STEP_PHASE: u32 = 100;

pub(super) struct CalRun<'a, B> {
    pub bus: &'a mut B,
    pub beat: &'a mut u32,
    pub half: u32,
    pub u_dc_v: f64,
    pub amps_per_count: f64,
    pub cycles: u64,
}

impl<B: PlTime> CalRun<'_, B> {
    /// Waits until the PWM counter is `target` cycles past its bottom.
    fn wait_phase(&mut self, target: u32) -> Result<(), BusError> {
        let period = 2 * self.half;
        let now = Pwm(&mut *self.bus).phase(self.half)?;
        let w = (target + period - now) % period;
        let w = if w == 0 { period } else { w };
        self.bus.wait_cycles(u64::from(w));
        self.cycles += u64::from(w);
        Ok(())
    }

    fn currents(&mut self) -> Result<[f64; 3], BusError> {
        let c = Adc(&mut *self.bus).currents_counts()?;
        Ok(c.map(|x| f64::from(x) * self.amps_per_count))
    }

    fn duties(&mut self, alpha: f64, beta: f64) -> Result<(), BusError> {
        let v = inv_clarke(alpha, beta);
        let d = v.map(|x| 0.5 + x / self.u_dc_v);
        Pwm(&mut *self.bus).set_duties(d, self.half)
    }

    /// The whole calibration; the caller turns the gates off and restores
    /// the mode. `on_phase` sees each new phase; `stop` is asked every
    /// period whether to stop now (Ctrl-C).
    pub fn run(
        &mut self,
        setup: &Setup,
        on_phase: &mut dyn FnMut(Option<Phase>),
        stop: &mut dyn FnMut() -> bool,
    ) -> Result<CalReport, BusError> {
        let mut cal = Calibrator::new(setup);
        let mut report = CalReport {
            results: *cal.results(),
            stopped: None,
            cycles: 0,
        };
        Top(&mut *self.bus).set_mode(Mode::Foc)?;
        Pwm(&mut *self.bus).set_duties([0.5; 3], self.half)?;
        Pwm(&mut *self.bus).set_gates(true)?;
        let quarter = self.half / 2;
        // The ADC's samples at fixed phases of the PWM period (as the FOC
        // restarts it): the four results read below are its 16 samples.
        self.wait_phase(2)?;
        Adc(&mut *self.bus).restart()?;
        self.wait_phase(STEP_PHASE)?;
        let mut phase = None;
        loop {
            let mut sum = [0.0; 3];
            for q in 1..=4 {
                let target = (STEP_PHASE + q * quarter) % (2 * self.half);
                self.wait_phase(target)?;
                let i = self.currents()?;
                for (s, x) in sum.iter_mut().zip(i) {
                    *s += 0.25 * x;
                }
            }
            *self.beat = self.beat.wrapping_add(1);
            Top(&mut *self.bus).heartbeat(*self.beat)?;
            let f = Fault(&mut *self.bus).latched()?;
            if !f.none() {
                Pwm(&mut *self.bus).set_gates(false)?;
                report.stopped = Some(CalStop::Fault(f));
                break;
            }
            let enc = Encoder(&mut *self.bus).read()?;
            let cmd = cal.step(&Measurement {
                i_abc_a: sum,
                enc_pos: enc.pos,
            });
            if cal.phase() != phase {
                phase = cal.phase();
                on_phase(phase);
            }
            if stop() {
                Pwm(&mut *self.bus).set_gates(false)?;
                report.stopped = Some(CalStop::Interrupted);
                break;
            }
            match cmd {
                Command::Voltage { alpha_v, beta_v } => self.duties(alpha_v, beta_v)?,
                Command::Done => break,
            }
        }
        Pwm(&mut *self.bus).set_gates(false)?;
        report.results = *cal.results();
        report.cycles = self.cycles;
        Ok(report)
    }
}
