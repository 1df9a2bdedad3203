//! Capture and frequency response on the drive: the capture buffer armed
//! at the mode's control rate, a sine torque reference, and the gain and
//! phase of the measured torque against the reference at one frequency
//! (single-bin DFT over a whole number of periods of both captured
//! channels, so the PS's timing does not enter the phase).
use super::{Servo, ServoError};
use crate::pl::capture::{CapSample, CapStatus, Capture, Trigger};
use crate::pl::top::Mode;
use core::f64::consts::PI;
use regmap::bus::RegisterBus;

/// A sine torque reference `amp sin(2 pi f n T)`, one value per control
/// period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sine {
    amp_nm: f64,
    rad_per_period: f64,
    n: u64,
}

impl Sine {
    /// The reference of the next control period, N m.
    pub fn next_nm(&mut self) -> f64 {
        let x = self.amp_nm * libm::sin(self.rad_per_period * self.n as f64);
        self.n += 1;
        x
    }
}

/// One point of a frequency response.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepPoint {
    /// Frequency, Hz.
    pub f_hz: f64,
    /// |torque / reference| at `f_hz`, dB.
    pub gain_db: f64,
    /// Phase of torque relative to the reference, degrees in (-180, 180].
    pub phase_deg: f64,
}

/// Gain and phase of `out` against `reference` at `f_hz`, both sampled
/// every `ts_s`: a single DFT bin over the longest whole number of periods
/// at the end of the record, means removed. `None` when the record holds
/// less than one period or the reference has no component at `f_hz`.
pub fn tone_response(reference: &[f64], out: &[f64], f_hz: f64, ts_s: f64) -> Option<SweepPoint> {
    let len = reference.len().min(out.len());
    let per_period = 1.0 / (f_hz * ts_s);
    let periods = libm::floor(len as f64 / per_period);
    // NaN (a non-finite frequency) fails too.
    if periods.is_nan() || periods < 1.0 {
        return None;
    }
    let n = (libm::round(periods * per_period) as usize).min(len);
    let (r, o) = (&reference[len - n..len], &out[len - n..len]);
    let mean = |x: &[f64]| x.iter().sum::<f64>() / n as f64;
    let (mr, mo) = (mean(r), mean(o));
    let (mut xr, mut xi, mut yr, mut yi) = (0.0, 0.0, 0.0, 0.0);
    for k in 0..n {
        let a = 2.0 * PI * f_hz * ts_s * k as f64;
        let (s, c) = (libm::sin(a), libm::cos(a));
        xr += (r[k] - mr) * c;
        xi -= (r[k] - mr) * s;
        yr += (o[k] - mo) * c;
        yi -= (o[k] - mo) * s;
    }
    let mag_x = libm::hypot(xr, xi);
    if mag_x.is_nan() || mag_x <= 0.0 {
        return None;
    }
    let gain = libm::hypot(yr, yi) / mag_x;
    let mut phase = (libm::atan2(yi, yr) - libm::atan2(xi, xr)) * 180.0 / PI;
    while phase > 180.0 {
        phase -= 360.0;
    }
    while phase <= -180.0 {
        phase += 360.0;
    }
    Some(SweepPoint {
        f_hz,
        gain_db: 20.0 * libm::log10(gain),
        phase_deg: phase,
    })
}

/// The -3 dB bandwidth: the first crossing of -3 dB, interpolated in log
/// frequency between the points around it (points by increasing
/// frequency). `None` when no point is below -3 dB.
pub fn bandwidth_hz(points: &[SweepPoint]) -> Option<f64> {
    let i = points.iter().position(|p| p.gain_db <= -3.0)?;
    if i == 0 {
        return Some(points[0].f_hz);
    }
    let (a, b) = (&points[i - 1], &points[i]);
    let t = (-3.0 - a.gain_db) / (b.gain_db - a.gain_db);
    let la = libm::log10(a.f_hz);
    let lb = libm::log10(b.f_hz);
    Some(libm::pow(10.0, la + t * (lb - la)))
}

impl Servo {
    /// Averaged ADC results per capture sample, less one: one sample
    /// every `self.cap_every` control periods of the active mode, at most
    /// 256 averaged results per sample (`CAP_DECIM` is 8 bits).
    fn capture_decim(&self) -> u8 {
        let per_result =
            4.0 * f64::from(self.cfg.adc_period_cycles.max(1)) / f64::from(regmap::PL_CLOCK_HZ);
        let k = libm::round(self.control_period_s() / per_result) as i64;
        (k.max(1) * i64::from(self.cap_every.max(1)) - 1).clamp(0, 255) as u8
    }

    /// Time between two capture samples of the record armed last, s.
    pub fn capture_period_s(&self) -> f64 {
        let per_result =
            4.0 * f64::from(self.cfg.adc_period_cycles.max(1)) / f64::from(regmap::PL_CLOCK_HZ);
        per_result * f64::from(self.capture_decim() + 1)
    }

    /// Arms a record with one sample every `every` control periods of the
    /// active mode (1: the control rate; clamped to 256 averaged ADC
    /// results per sample, [`Self::capture_period_s`] says what it is).
    pub fn capture_arm<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        trigger: Trigger,
        pre: u32,
        every: u32,
    ) -> Result<(), ServoError> {
        self.cap_every = every.max(1);
        let decim = self.capture_decim();
        Ok(Capture(bus).arm(trigger, pre, decim)?)
    }

    /// Manual trigger.
    pub fn capture_trigger<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        Ok(Capture(bus).trigger()?)
    }

    /// Capture state.
    pub fn capture_status<B: RegisterBus>(&mut self, bus: &mut B) -> Result<CapStatus, ServoError> {
        Ok(Capture(bus).status()?)
    }

    /// Sample `i` of the record.
    pub fn capture_sample<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        i: u32,
    ) -> Result<CapSample, ServoError> {
        Ok(Capture(bus).sample(i)?)
    }

    /// Starts a sine torque reference of `amp_nm` at `f_hz` (gates on,
    /// 0 < amp <= the limit, 0 < f <= a quarter of the control rate).
    pub fn sine_start<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        f_hz: f64,
        amp_nm: f64,
    ) -> Result<(), ServoError> {
        let amp = self.check_torque(amp_nm)?;
        if amp <= 0.0 {
            return Err(ServoError::TorqueOutOfRange(amp_nm));
        }
        if !(f_hz > 0.0 && f_hz <= 0.25 * self.control_rate_hz()) {
            return Err(ServoError::BadFrequency(f_hz));
        }
        if self.mode == Mode::Off {
            return Err(ServoError::ModeOff);
        }
        if !(self.gates && self.gates_on(bus)?) {
            return Err(ServoError::GatesOff);
        }
        self.motion.to_torque();
        self.sine = Some(Sine {
            amp_nm: amp,
            rad_per_period: 2.0 * PI * f_hz * self.control_period_s(),
            n: 0,
        });
        Ok(())
    }

    /// Ends the sine reference; the reference returns to 0 N m.
    pub fn sine_stop(&mut self) {
        if self.sine.take().is_some() {
            self.torque_ref_nm = 0.0;
        }
    }

    /// Whether a sine reference is running (a fault or `disable` ends it).
    pub fn sine_running(&self) -> bool {
        self.sine.is_some()
    }

    /// Gain and phase at `f_hz` of the measured torque against the
    /// reference in the complete capture record (`None`: no complete
    /// record, or less than one period in it).
    pub fn record_response<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        f_hz: f64,
    ) -> Result<Option<SweepPoint>, ServoError> {
        let st = self.capture_status(bus)?;
        if st.state != crate::pl::capture::CapState::Done {
            return Ok(None);
        }
        let ts = self.capture_period_s();
        record_response(st.count, f_hz, ts, |i| self.capture_sample(bus, i))
    }

    /// PL time to let a new sine settle before its capture, s: two of its
    /// periods, at least 1 ms.
    pub fn sine_settle_s(f_hz: f64) -> f64 {
        (2.0 / f_hz).max(1e-3)
    }
}

/// Gain and phase at `f_hz` of the torque against the reference over the
/// first `count` samples (at most the ring's depth) of a complete capture
/// record, one sample every `ts_s`, read one at a time by `sample` (so that
/// the firmware can let the control interrupt run between two reads: the
/// PL keeps running while a record is read).
pub fn record_response<E>(
    count: u32,
    f_hz: f64,
    ts_s: f64,
    mut sample: impl FnMut(u32) -> Result<crate::pl::capture::CapSample, E>,
) -> Result<Option<SweepPoint>, E> {
    const N: usize = crate::pl::capture::DEPTH as usize;
    let n = (count as usize).min(N);
    let mut r = [0.0; N];
    let mut o = [0.0; N];
    for i in 0..n {
        let x = sample(i as u32)?;
        r[i] = x.torque_ref_nm;
        o[i] = x.torque_nm;
    }
    Ok(tone_response(&r[..n], &o[..n], f_hz, ts_s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// A first-order lag 1 / (1 + s tau) sampled exactly: gain and phase
    /// from the DFT must equal the analytic ones.
    #[test]
    fn tone_response_of_a_known_filter() {
        let ts = 1.0 / 64_000.0;
        let tau = 1.0 / (2.0 * PI * 1000.0);
        for f in [100.0, 1000.0, 3000.0] {
            let w = 2.0 * PI * f;
            let g = 1.0 / libm::sqrt(1.0 + (w * tau) * (w * tau));
            let ph = -libm::atan(w * tau);
            let n = 1024;
            let r: Vec<f64> = (0..n).map(|k| 0.3 * libm::sin(w * ts * k as f64)).collect();
            let o: Vec<f64> = (0..n)
                .map(|k| 0.3 * g * libm::sin(w * ts * k as f64 + ph) + 0.01)
                .collect();
            let p = tone_response(&r, &o, f, ts).unwrap();
            assert!(
                (p.gain_db - 20.0 * libm::log10(g)).abs() < 0.02,
                "{f} {p:?}"
            );
            assert!((p.phase_deg - ph * 180.0 / PI).abs() < 0.5, "{f} {p:?}");
        }
        // Less than one period: no point.
        assert!(tone_response(&[0.0; 10], &[0.0; 10], 100.0, ts).is_none());
        // No reference: no point.
        assert!(tone_response(&[0.0; 1024], &[1.0; 1024], 1000.0, ts).is_none());
    }

    #[test]
    fn bandwidth_interpolates_the_crossing() {
        let p = |f_hz, gain_db| SweepPoint {
            f_hz,
            gain_db,
            phase_deg: 0.0,
        };
        // -3 dB halfway (in log f) between 100 and 10000 Hz: 1000 Hz.
        let pts = [p(10.0, 0.0), p(100.0, -2.0), p(10_000.0, -4.0)];
        assert!((bandwidth_hz(&pts).unwrap() - 1000.0).abs() < 1e-6);
        assert_eq!(bandwidth_hz(&[p(10.0, -0.1), p(20.0, -1.0)]), None);
        assert_eq!(bandwidth_hz(&[p(10.0, -5.0)]), Some(10.0));
    }
}
