//! The `step` command's recorder: the measured torque sampled once per
//! control period from the step on, and its metrics by the one definition
//! in [`models::pmsm::metrics`] (10 % settling band).
//!
//! The metrics assume the plant starts at rest at the step's start value.
//! Right after `enable` (or a mode change) the current of the previous run
//! may still be decaying through the diodes: 0.37 N m one FOC period after
//! leaving a 0.4 N m MPDTC run, gone after three (`simpl`'s test
//! `tests/servo.rs`). A step started then is scored from the wrong start
//! (its first sample can already be in the band: a settling time of 0). So an armed step waits
//! until the measured torque is within the settling band of its start
//! value, at most one window (a steady offset larger than the band is not
//! a transient), and only then applies the new reference.
use models::pmsm::metrics::{
    overshoot_percent, settling_band, settling_time_s, transitions_per_leg_per_s,
};

/// Most samples one step records (20 ms at 64 kHz).
pub const STEP_SAMPLES_MAX: usize = 1280;

/// Metrics of one recorded step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepResult {
    /// Reference before the step, N m.
    pub from_nm: f64,
    /// Reference after the step, N m.
    pub to_nm: f64,
    /// Settling time (10 % band), s; `None` if not settled in the window.
    pub settling_s: Option<f64>,
    /// Overshoot, percent of the step size.
    pub overshoot_percent: f64,
    /// Gate transitions per leg per second over the window.
    pub switching_per_leg_per_s: f64,
    /// Mean measured torque over the last quarter of the window, N m.
    pub final_nm: f64,
    /// Window, s.
    pub window_s: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum State {
    Idle,
    /// Waiting for the first running control step.
    Armed,
    Recording,
    Done,
}

/// Samples of one step.
pub struct StepRecorder {
    state: State,
    from_nm: f64,
    to_nm: f64,
    n: usize,
    len: usize,
    /// Periods spent armed, waiting for the plant to be at the start value.
    waited: usize,
    torque: [f32; STEP_SAMPLES_MAX],
    transitions_start: [u64; 3],
    transitions_end: [u64; 3],
}

impl Default for StepRecorder {
    fn default() -> Self {
        Self::new()
    }
}

impl StepRecorder {
    /// Nothing armed.
    pub const fn new() -> Self {
        Self {
            state: State::Idle,
            from_nm: 0.0,
            to_nm: 0.0,
            n: 0,
            len: 0,
            waited: 0,
            torque: [0.0; STEP_SAMPLES_MAX],
            transitions_start: [0; 3],
            transitions_end: [0; 3],
        }
    }
    /// Arms a step to `to_nm` over `n` control periods.
    pub fn arm(&mut self, to_nm: f64, n: usize) {
        self.state = State::Armed;
        self.to_nm = to_nm;
        self.n = n.clamp(1, STEP_SAMPLES_MAX);
        self.len = 0;
        self.waited = 0;
    }
    /// Drops an armed or running step.
    pub fn cancel(&mut self) {
        if matches!(self.state, State::Armed | State::Recording) {
            self.state = State::Idle;
        }
    }
    /// Copies `other`'s state and recorded samples (only those, not the
    /// whole buffer: a copy under a critical section stays short).
    pub fn copy_from(&mut self, other: &Self) {
        self.state = other.state;
        self.from_nm = other.from_nm;
        self.to_nm = other.to_nm;
        self.n = other.n;
        self.len = other.len;
        self.waited = other.waited;
        self.torque[..other.len].copy_from_slice(&other.torque[..other.len]);
        self.transitions_start = other.transitions_start;
        self.transitions_end = other.transitions_end;
    }
    /// The window is full: [`StepRecorder::result`] has its metrics.
    pub fn done(&self) -> bool {
        self.state == State::Done
    }
    /// Armed or recording.
    pub fn pending(&self) -> bool {
        matches!(self.state, State::Armed | State::Recording)
    }
    /// One control period with the controller running: `torque_nm` is the
    /// torque measured at this boundary (before the controller acts on the
    /// new reference), `transitions` the cumulative gate transitions per leg.
    /// Returns the new reference when the step starts at this boundary.
    pub fn on_period(&mut self, torque_nm: f64, transitions: [u64; 3]) -> Option<f64> {
        let mut started = None;
        if self.state == State::Armed {
            let band = settling_band(self.from_nm, self.to_nm);
            if libm::fabs(torque_nm - self.from_nm) > band && self.waited < self.n {
                self.waited += 1;
                return None;
            }
            self.state = State::Recording;
            self.transitions_start = transitions;
            started = Some(self.to_nm);
        }
        if self.state == State::Recording {
            self.torque[self.len] = torque_nm as f32;
            self.len += 1;
            if self.len >= self.n {
                self.state = State::Done;
                self.transitions_end = transitions;
            }
        }
        started
    }
    /// Periods the last armed step waited for the plant to reach its start
    /// value.
    pub fn waited_periods(&self) -> usize {
        self.waited
    }
    /// The recorded torque samples, N m, one per control period.
    pub fn samples(&self) -> &[f32] {
        &self.torque[..self.len]
    }
    /// Sets the step's start value (the reference before it), N m.
    pub fn start_from(&mut self, from_nm: f64) {
        self.from_nm = from_nm;
    }
    /// The metrics, once the window is full; `period_s` is the spacing of
    /// the samples.
    pub fn result(&self, period_s: f64) -> Option<StepResult> {
        if self.state != State::Done {
            return None;
        }
        let samples = || {
            self.torque[..self.len]
                .iter()
                .enumerate()
                .map(move |(k, y)| (k as f64 * period_s, f64::from(*y)))
        };
        let t_end = (self.len - 1) as f64 * period_s;
        let (y0, y1) = (self.from_nm, self.to_nm);
        let tail = &self.torque[self.len - self.len.div_ceil(4)..self.len];
        let final_nm = tail.iter().map(|y| f64::from(*y)).sum::<f64>() / tail.len() as f64;
        let window_s = self.len as f64 * period_s;
        Some(StepResult {
            from_nm: y0,
            to_nm: y1,
            settling_s: settling_time_s(samples(), 0.0, t_end, y1, settling_band(y0, y1)),
            overshoot_percent: overshoot_percent(samples(), 0.0, t_end, y0, y1),
            switching_per_leg_per_s: transitions_per_leg_per_s(
                self.transitions_start,
                self.transitions_end,
                window_s,
            ),
            final_nm,
            window_s,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order response sampled every 10 us, by hand: it enters the
    /// 10 % band of a 0 -> 1 step when 1 - e^{-t/tau} >= 0.9, t = tau ln 10.
    #[test]
    fn metrics_of_a_first_order_step() {
        let mut r = StepRecorder::new();
        r.start_from(0.0);
        r.arm(1.0, 100);
        let tau = 50e-6;
        let mut started = None;
        for k in 0..100u64 {
            let t = k as f64 * 10e-6;
            let y = 1.0 - libm::exp(-t / tau);
            let s = r.on_period(y, [2 * k, 2 * k, 2 * k]);
            started = started.or(s);
            assert_eq!(r.pending(), k < 99);
        }
        assert_eq!(started, Some(1.0));
        let m = r.result(10e-6).unwrap();
        // tau ln 10 = 115.1 us -> first sample at or after it: 120 us.
        assert!((m.settling_s.unwrap() - 120e-6).abs() < 1e-9, "{m:?}");
        assert_eq!(m.overshoot_percent, 0.0);
        // 2 transitions per leg per 10 us period = 200 k/s (99 periods / 1 ms).
        assert!(
            (m.switching_per_leg_per_s - 198.0 / 1e-3).abs() < 1e-6,
            "{m:?}"
        );
        assert!((m.final_nm - 1.0).abs() < 1e-3);
        assert!((m.window_s - 1e-3).abs() < 1e-12);
    }

    #[test]
    fn overshoot_and_no_settling() {
        let mut r = StepRecorder::new();
        r.start_from(0.4);
        r.arm(-0.4, 4);
        for y in [0.4, -0.5, -0.4, 0.0] {
            r.on_period(y, [0; 3]);
        }
        let m = r.result(1e-4).unwrap();
        assert!((m.overshoot_percent - 12.5).abs() < 1e-4, "{m:?}");
        assert_eq!(m.settling_s, None, "the last sample is out of the band");
        // Cancel drops a pending step; nothing without arming.
        let mut r = StepRecorder::new();
        assert_eq!(r.on_period(1.0, [0; 3]), None);
        assert!(r.result(1e-4).is_none());
        r.arm(1.0, 3);
        r.cancel();
        assert!(!r.pending());
    }

    /// An armed step waits while the plant is away from the start value
    /// (a decaying current), then starts at the first sample in the band.
    #[test]
    fn an_armed_step_waits_for_the_start_value() {
        let mut r = StepRecorder::new();
        r.start_from(0.0);
        r.arm(0.4, 3);
        // Band 0.04 N m around 0: 0.37 and 0.12 wait, 0.03 starts.
        assert_eq!(r.on_period(0.37, [0; 3]), None);
        assert_eq!(r.on_period(0.12, [0; 3]), None);
        assert_eq!(r.on_period(0.03, [0; 3]), Some(0.4));
        assert_eq!(r.waited_periods(), 2);
        r.on_period(0.3, [0; 3]);
        r.on_period(0.4, [0; 3]);
        assert_eq!(r.samples(), [0.03f32, 0.3, 0.4]);
        assert!(r.result(1e-4).unwrap().settling_s.unwrap() > 0.0);
        // A steady offset beyond the band: it starts after one window.
        r.arm(0.4, 2);
        assert_eq!(r.on_period(0.1, [0; 3]), None);
        assert_eq!(r.on_period(0.1, [0; 3]), None);
        assert_eq!(r.on_period(0.1, [0; 3]), Some(0.4));
    }
}
