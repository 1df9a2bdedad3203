//! The sensor check before the first closed loop: open-loop voltage vectors
//! at low duty, current limited, that verify the sign and the order of the
//! three current channels and, when the rotor turns, the encoder's
//! direction.
//!
//! A current channel with the wrong sign or on the wrong phase turns the
//! current loop's negative feedback into positive feedback, so the drive
//! runs this check by itself at the first `enable` after boot and after a
//! change of the motor or sensor configuration ([`super::Servo`]), and on
//! request (`selftest sensors`).
//!
//! Sequence (gates off before and after, the PL in FOC-PWM mode for its
//! duration): for each phase k = a, b, c, its duties written and loaded by
//! the PWM (the gates off until its next period starts), a voltage vector along +k (duty
//! 0.5 + [`DUTY_STEP`] on leg k, 0.5 - `DUTY_STEP`/2 on the others: phase
//! k at +`DUTY_STEP` u_dc, the others at -`DUTY_STEP` u_dc / 2), held until
//! the largest measured phase current reaches [`target_a`] (10 % of the
//! over-current trip, at least 10 ADC counts) or [`VECTOR_MAX_CYCLES`]
//! pass; then the gates off until the currents have decayed (the diodes
//! return them to the DC link in tens of microseconds). At standstill the
//! current follows the voltage vector whatever the rotor angle (no back
//! EMF, equal d/q inductance), so the three readings at the end of vector
//! k should be `(+1, -1/2, -1/2) i` rotated onto channel k.
//!
//! Paper motor (R 0.555 Ohm, L 0.64 mH, u_dc 48 V): phase k at 3.84 V less
//! the dead time's loss (about 0.77 V at 0.5 us per 62.56 us period),
//! di/dt about 4.8 kA/s: the 1.4 A target after about 0.3 ms, the whole
//! check about 1.5 ms of PL time with the duties' loads (`selftest sensors`
//! prints it).
//!
//! Verdict, per channel j: the vector with the largest |reading| on j is
//! the phase channel j measures (must be j: the order), and the sign of
//! that reading must be positive. The encoder's direction is checked when
//! the rotor moved by at least [`ENC_MIN_COUNTS`] during the a, b, c
//! sequence (a positive rotation of the field: the encoder must count up);
//! a rotor that did not move (held, loaded, or too much inertia for the
//! short pulses) leaves the direction unverified, which the report says.
use crate::pl::adc::Adc;
use crate::pl::enc::Encoder;
use crate::pl::fault::{Fault, Faults};
use crate::pl::pwm::Pwm;
use crate::pl::top::{Mode, Top};
use core::fmt;
use regmap::bus::{BusError, RegisterBus};

/// Duty offset of the driven leg (phase voltage `DUTY_STEP * u_dc`).
pub const DUTY_STEP: f64 = 0.08;
/// Longest vector: 1.5 ms of PL time (100 MHz).
pub const VECTOR_MAX_CYCLES: u64 = 150_000;
/// Longest decay after a vector: 0.5 ms.
pub const DECAY_MAX_CYCLES: u64 = 50_000;
/// Encoder movement below which the direction is not judged, counts.
pub const ENC_MIN_COUNTS: i64 = 4;

/// A bus whose PL time the drive can let pass (the sensor check's waits):
/// the simulated PL advances, a bitstream's PL runs while the PS waits.
pub trait PlTime: RegisterBus {
    /// Lets `cycles` PL clock cycles pass.
    fn wait_cycles(&mut self, cycles: u64);
}

/// What is wrong with the sensors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SensorFault {
    /// No vector brought any channel to the target: no current flows or
    /// none is measured (A: the largest |reading|).
    NoCurrent(f64),
    /// Channel `ch` measures phase `phase` (0 = a).
    Order {
        /// The channel.
        ch: usize,
        /// The phase it follows.
        phase: usize,
    },
    /// Channel `ch` reads its phase's current with the wrong sign (A, as
    /// read while its phase carried the positive target).
    Inverted {
        /// The channel.
        ch: usize,
        /// Its reading, A.
        read_a: f64,
    },
    /// The encoder counted down (counts) while the field turned a, b, c.
    EncoderReversed(i64),
    /// A fault latched during the check (gates off by the PL).
    Fault(Faults),
}

fn phase(i: usize) -> char {
    ['a', 'b', 'c'][i.min(2)]
}

/// The text after `ERR sensor-check`.
impl fmt::Display for SensorFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            SensorFault::NoCurrent(a) => write!(
                f,
                "no current measured (largest {a:.3} A): DC link, gate drivers or current sensing"
            ),
            SensorFault::Order { ch, phase: p } => write!(
                f,
                "current channel {} measures phase {} (channels swapped)",
                phase(ch),
                phase(p)
            ),
            SensorFault::Inverted { ch, read_a } => write!(
                f,
                "current channel {} inverted (read {read_a:.3} A with its phase positive)",
                phase(ch)
            ),
            SensorFault::EncoderReversed(n) => write!(
                f,
                "encoder counts backwards ({n} counts while the field turned a-b-c)"
            ),
            SensorFault::Fault(faults) => {
                f.write_str("fault latched during the check: ")?;
                faults.write_names(f)?;
                if faults.0 & Faults::ADC_STUCK != 0 {
                    f.write_str(" (no ADC result: is the converter card fitted and powered?)")?;
                }
                Ok(())
            }
        }
    }
}

/// What the check measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorReport {
    /// Channel readings a, b, c at the end of the vector along phase a, b,
    /// c, A.
    pub readings_a: [[f64; 3]; 3],
    /// PL cycles each vector was applied.
    pub vector_cycles: [u64; 3],
    /// The current each vector was held for, A.
    pub target_a: f64,
    /// Encoder movement over the sequence, counts (shortest way round).
    pub enc_counts: i64,
    /// PL cycles the check took.
    pub cycles: u64,
    /// The verdict.
    pub result: Result<(), SensorFault>,
}

impl SensorReport {
    /// Whether the encoder moved enough for its direction to be judged.
    pub fn encoder_judged(&self) -> bool {
        self.enc_counts.abs() >= ENC_MIN_COUNTS
    }
}

/// The current each vector is held for: 10 % of the trip level, at least
/// 10 ADC counts, A.
pub fn target_a(current_limit_a: f64, amps_per_count: f64) -> f64 {
    (0.1 * current_limit_a).max(10.0 * amps_per_count)
}

/// The verdict on the readings (`r[k][j]`: channel j at the end of the
/// vector along phase k) and the encoder movement.
pub fn judge(r: &[[f64; 3]; 3], target: f64, enc_counts: i64) -> Result<(), SensorFault> {
    let largest = r.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest < 0.5 * target {
        return Err(SensorFault::NoCurrent(largest));
    }
    // Row `ch` is the vector along phase `ch`; its own reading is `row[ch]`.
    for (ch, row) in r.iter().enumerate() {
        let k = (0..3)
            .max_by(|&x, &y| r[x][ch].abs().total_cmp(&r[y][ch].abs()))
            .unwrap_or(ch);
        if k != ch {
            return Err(SensorFault::Order { ch, phase: k });
        }
        if row[ch] <= 0.0 {
            return Err(SensorFault::Inverted {
                ch,
                read_a: row[ch],
            });
        }
    }
    if enc_counts <= -ENC_MIN_COUNTS {
        return Err(SensorFault::EncoderReversed(enc_counts));
    }
    Ok(())
}

/// Duties of the vector along phase `k`.
fn vector(k: usize) -> [f64; 3] {
    let mut d = [0.5 - DUTY_STEP / 2.0; 3];
    d[k] = 0.5 + DUTY_STEP;
    d
}

/// The check's state while it runs.
pub(super) struct Run<'a, B> {
    pub bus: &'a mut B,
    pub beat: &'a mut u32,
    pub cycles: u64,
    pub amps_per_count: f64,
}

impl<B: PlTime> Run<'_, B> {
    /// One averaged ADC result of PL time, the watchdog fed.
    fn wait(&mut self, cycles: u64) -> Result<(), BusError> {
        *self.beat = self.beat.wrapping_add(1);
        Top(&mut *self.bus).heartbeat(*self.beat)?;
        self.bus.wait_cycles(cycles);
        self.cycles += cycles;
        Ok(())
    }

    fn currents(&mut self) -> Result<[f64; 3], BusError> {
        let c = Adc(&mut *self.bus).currents_counts()?;
        Ok(c.map(|x| f64::from(x) * self.amps_per_count))
    }

    fn largest(&mut self) -> Result<f64, BusError> {
        Ok(self.currents()?.iter().fold(0.0f64, |m, x| m.max(x.abs())))
    }

    fn faults(&mut self) -> Result<Faults, BusError> {
        Fault(&mut *self.bus).latched()
    }

    /// The sequence; the caller restores mode and gates whatever happens.
    /// `step`: PL cycles between readings (one averaged ADC result).
    pub fn sequence(
        &mut self,
        half_period: u32,
        target: f64,
        step: u64,
    ) -> Result<SensorReport, BusError> {
        let mut report = SensorReport {
            readings_a: [[0.0; 3]; 3],
            vector_cycles: [0; 3],
            target_a: target,
            enc_counts: 0,
            cycles: 0,
            result: Ok(()),
        };
        Top(&mut *self.bus).set_mode(Mode::Foc)?;
        let enc0 = Encoder(&mut *self.bus).read()?;
        for k in 0..3 {
            // The PWM loads its duties at the start of each of its periods:
            // gates turned on right after the write would apply the
            // previous vector's duties for up to a period, and with a
            // residue of its current a reading in that period can reach
            // the target on the previous phase (read as channels swapped;
            // where in the PWM period the averaged results fall decides
            // it, so a restart of the ADC's sample timer did). The gates
            // go on once the PWM has started its next period.
            Pwm(&mut *self.bus).set_duties(vector(k), half_period)?;
            let phase = Pwm(&mut *self.bus).phase(half_period)?;
            self.wait(u64::from(2 * half_period - phase.min(2 * half_period)) + 2)?;
            Pwm(&mut *self.bus).set_gates(true)?;
            let t0 = self.cycles;
            loop {
                self.wait(step)?;
                let f = self.faults()?;
                if !f.none() {
                    Pwm(&mut *self.bus).set_gates(false)?;
                    report.cycles = self.cycles;
                    report.result = Err(SensorFault::Fault(f));
                    return Ok(report);
                }
                let i = self.currents()?;
                let big = i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                if big >= target || self.cycles - t0 >= VECTOR_MAX_CYCLES {
                    report.readings_a[k] = i;
                    break;
                }
            }
            Pwm(&mut *self.bus).set_gates(false)?;
            report.vector_cycles[k] = self.cycles - t0;
            let t1 = self.cycles;
            while self.cycles - t1 < DECAY_MAX_CYCLES {
                self.wait(step)?;
                if self.largest()? < 0.05 * target {
                    break;
                }
            }
        }
        let enc1 = Encoder(&mut *self.bus).read()?;
        let cpr = i64::from(enc1.cpr.max(1));
        let d = (i64::from(enc1.pos) - i64::from(enc0.pos)).rem_euclid(cpr);
        report.enc_counts = if d > cpr / 2 { d - cpr } else { d };
        report.cycles = self.cycles;
        report.result = judge(&report.readings_a, target, report.enc_counts);
        Ok(report)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ideal readings: +i on the driven phase, -i/2 on the others.
    fn ideal(i: f64) -> [[f64; 3]; 3] {
        let mut r = [[-i / 2.0; 3]; 3];
        for (k, row) in r.iter_mut().enumerate() {
            row[k] = i;
        }
        r
    }

    #[test]
    fn correct_wiring_passes() {
        assert_eq!(judge(&ideal(1.4), 1.4, 0), Ok(()));
        // The rotor turned forwards with the field.
        assert_eq!(judge(&ideal(1.4), 1.4, 37), Ok(()));
    }

    #[test]
    fn a_swapped_pair_names_the_first_wrong_channel() {
        let mut r = ideal(1.4);
        for row in r.iter_mut() {
            row.swap(0, 1);
        }
        assert_eq!(
            judge(&r, 1.4, 0),
            Err(SensorFault::Order { ch: 0, phase: 1 })
        );
        let mut r = ideal(1.4);
        for row in r.iter_mut() {
            row.swap(1, 2);
        }
        assert_eq!(
            judge(&r, 1.4, 0),
            Err(SensorFault::Order { ch: 1, phase: 2 })
        );
    }

    #[test]
    fn an_inverted_channel_is_named() {
        let mut r = ideal(1.4);
        for row in r.iter_mut() {
            row[2] = -row[2];
        }
        assert_eq!(
            judge(&r, 1.4, 0),
            Err(SensorFault::Inverted {
                ch: 2,
                read_a: -1.4
            })
        );
        let text = std::format!("{}", judge(&r, 1.4, 0).unwrap_err());
        assert!(text.starts_with("current channel c inverted"), "{text}");
    }

    #[test]
    fn no_current_and_a_reversed_encoder_fail() {
        let r = [[0.01, -0.004, 0.0]; 3];
        assert_eq!(judge(&r, 1.4, 0), Err(SensorFault::NoCurrent(0.01)));
        assert_eq!(
            judge(&ideal(1.4), 1.4, -ENC_MIN_COUNTS),
            Err(SensorFault::EncoderReversed(-ENC_MIN_COUNTS))
        );
        // Below the threshold the direction is not judged.
        assert_eq!(judge(&ideal(1.4), 1.4, -(ENC_MIN_COUNTS - 1)), Ok(()));
        // NaN readings are no current, not a pass.
        assert!(judge(&[[f64::NAN; 3]; 3], 1.4, 0).is_err());
    }

    #[test]
    fn vectors_and_target() {
        // Phase a at +DUTY_STEP u_dc, b and c at -DUTY_STEP/2: zero mean.
        let d = vector(0);
        for (x, want) in d.iter().zip([0.58, 0.46, 0.46]) {
            assert!((x - want).abs() < 1e-12, "{d:?}");
        }
        assert!((d.iter().sum::<f64>() - 1.5).abs() < 1e-12);
        assert!((target_a(14.0, 0.01) - 1.4).abs() < 1e-12);
        // A small trip level: ten counts at least.
        assert_eq!(target_a(0.5, 0.01), 0.1);
    }
}
