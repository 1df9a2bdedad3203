//! Motor calibration: the methods that measure a PMSM on the drive (encoder
//! direction, electrical offset and pole pairs; R; L; flux linkage; inertia
//! and friction) as one pure state machine, [`Calibrator`], fed one
//! [`Measurement`] per control period and answering the voltage vector to
//! apply ([`Command`]). No bus and no clock: the drive's driver
//! (`drive::servo::calibrate`) turns the commands into duties and the PL's
//! readings into measurements, and a host test runs the same machine
//! against the simulated PL. The methods, their equations, error sources
//! and uncertainties are written down in `docs/calibration.md`.
//!
//! Timing contract with the driver: the measurement handed to step `k` is
//! the mean of the phase currents over PWM period `k` and the encoder
//! position at its end; the command returned by step `k` is applied (as
//! PWM period means) during period `k + 2` ([`DELAY_PERIODS`]).
mod fit;
mod machine;
mod mech;

pub use fit::{Lsq, Mean, Solution};
pub use machine::Calibrator;

use crate::pmsm::params::MotorParams;
use crate::validate::ParamError;

/// Periods from the step that returns a command to the period it is
/// applied in (the driver writes the duties just after a PWM period ends;
/// the PWM loads them at the next counter bottom).
pub const DELAY_PERIODS: usize = 2;

/// Phases of a calibration, as bits of [`Phases`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Encoder direction, electrical offset and pole pairs.
    Encoder,
    /// Stator resistance.
    Resistance,
    /// Stator inductance.
    Inductance,
    /// Permanent-magnet flux linkage.
    Flux,
    /// Inertia, viscous and Coulomb friction.
    Mechanics,
}

impl Phase {
    /// All, in the order a calibration runs them.
    pub const ALL: [Phase; 5] = [
        Phase::Encoder,
        Phase::Resistance,
        Phase::Inductance,
        Phase::Flux,
        Phase::Mechanics,
    ];

    /// The console's name.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Encoder => "encoder",
            Phase::Resistance => "resistance",
            Phase::Inductance => "inductance",
            Phase::Flux => "flux",
            Phase::Mechanics => "mechanics",
        }
    }

    /// The phase named `s`.
    pub fn parse(s: &str) -> Option<Phase> {
        Phase::ALL.into_iter().find(|p| p.name() == s)
    }

    /// What it does (the progress line).
    pub fn what(self) -> &'static str {
        match self {
            Phase::Encoder => {
                "current vector turned forwards then backwards, encoder fitted to its angle"
            }
            Phase::Resistance => "d-axis current at four levels, voltage over current slope",
            Phase::Inductance => "voltage steps at standstill, current time constant",
            Phase::Flux => "q-axis voltage balance at three speeds under velocity control",
            Phase::Mechanics => {
                "torque steps between three speeds, i_d reversed: inertia and friction from a momentum balance over nine windows"
            }
        }
    }

    /// Whether the rotor must turn.
    pub fn needs_motion(self) -> bool {
        matches!(self, Phase::Encoder | Phase::Flux | Phase::Mechanics)
    }

    const fn bit(self) -> u8 {
        1 << self as u8
    }
}

/// A set of phases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Phases(pub u8);

impl Phases {
    /// Every phase.
    pub const ALL: Phases = Phases(0x1F);
    /// Just `p`.
    pub fn only(p: Phase) -> Self {
        Phases(p.bit())
    }
    /// Whether `p` is in the set.
    pub fn has(self, p: Phase) -> bool {
        self.0 & p.bit() != 0
    }
}

/// What the calibration starts from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setup {
    /// Largest current magnitude the calibration drives, A.
    pub current_a: f64,
    /// Largest voltage vector magnitude it applies, V.
    pub voltage_v: f64,
    /// Control (PWM) period, s.
    pub period_s: f64,
    /// Encoder counts per mechanical revolution.
    pub cpr: u32,
    /// The configured motor: the starting point of the loops' gains and
    /// what a phase not run keeps.
    pub motor: MotorParams,
    /// The configured encoder zero, counts.
    pub enc_zero: u32,
    /// The phases to run.
    pub phases: Phases,
}

impl Setup {
    /// Checks the setup: finite positive limits and period, a valid motor,
    /// at least one phase.
    pub fn validate(&self) -> Result<(), ParamError> {
        let e = |field, reason| Err(ParamError { field, reason });
        if !(self.current_a.is_finite() && self.current_a > 0.0) {
            return e("calibration_current", "must be finite and > 0");
        }
        if !(self.voltage_v.is_finite() && self.voltage_v > 0.0) {
            return e("calibration_voltage", "must be finite and > 0");
        }
        if !(self.period_s.is_finite() && self.period_s > 0.0) {
            return e("period_s", "must be finite and > 0");
        }
        if self.cpr < 4 {
            return e("enc_cpr", "must be at least 4");
        }
        if self.phases.0 == 0 || self.phases.0 & !Phases::ALL.0 != 0 {
            return e("phases", "no phase selected");
        }
        self.motor.validate()
    }
}

/// One control period's readings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// Phase currents averaged over the PWM period, A.
    pub i_abc_a: [f64; 3],
    /// Encoder position at the end of the period, counts in `0..cpr`.
    pub enc_pos: u32,
}

/// What to apply.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Command {
    /// This voltage vector (stationary frame, amplitude invariant), V.
    Voltage {
        /// alpha component, V.
        alpha_v: f64,
        /// beta component, V.
        beta_v: f64,
    },
    /// Finished: gates off, read [`Calibrator::results`].
    Done,
}

/// An estimate and its one-sigma uncertainty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Value (SI unit of the parameter).
    pub value: f64,
    /// Standard uncertainty, same unit.
    pub sigma: f64,
}

impl Estimate {
    /// Relative uncertainty.
    pub fn rel(&self) -> f64 {
        libm::fabs(self.sigma / self.value)
    }
}

/// The encoder phase's findings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EncoderEst {
    /// +1: the encoder counts up when the field turns a-b-c.
    pub dir: i32,
    /// Pole pairs.
    pub pole_pairs: u32,
    /// Encoder count with the rotor d axis on phase a (0..cpr/p).
    pub zero_counts: u32,
    /// The offset before rounding to counts, counts.
    pub zero_exact: f64,
    /// Uncertainty of the offset, electrical degrees.
    pub sigma_deg: f64,
    /// Electrical turns per mechanical turn before rounding.
    pub pole_pairs_exact: f64,
}

/// The mechanics phase's findings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MechEst {
    /// Inertia, kg m^2.
    pub j: Estimate,
    /// Viscous friction, N m s/rad.
    pub b: Estimate,
    /// Coulomb friction, N m.
    pub coulomb: Estimate,
}

/// How a phase ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outcome<T> {
    /// Not asked for.
    NotRun,
    /// Refused or impossible (why).
    Refused(&'static str),
    /// Measured, but the fit is beyond its bound (why): not to be applied.
    Poor(T, &'static str),
    /// Measured.
    Done(T),
}

impl<T> Outcome<T> {
    /// The estimate when measured with a good fit.
    pub fn good(&self) -> Option<&T> {
        match self {
            Outcome::Done(t) => Some(t),
            _ => None,
        }
    }
}

/// Everything a calibration found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Results {
    /// Encoder.
    pub encoder: Outcome<EncoderEst>,
    /// Resistance, ohm.
    pub resistance: Outcome<Estimate>,
    /// Inductance, H.
    pub inductance: Outcome<Estimate>,
    /// Flux linkage, Wb.
    pub flux: Outcome<Estimate>,
    /// Mechanics.
    pub mechanics: Outcome<MechEst>,
    /// Dead-time voltage along the current (the R fit's intercept), V.
    pub dead_time_v: f64,
    /// The resistance fit's points: (current A, voltage V) per level.
    pub r_points: [(f64, f64); 4],
    /// The flux fit's points: (electrical speed rad/s, q-axis voltage less
    /// the R, L and dead-time terms V) per speed.
    pub flux_points: [(f64, f64); 3],
    /// The friction fit's points: (mechanical speed rad/s, torque N m) per
    /// speed.
    pub friction_points: [(f64, f64); 3],
    /// Control periods the calibration took.
    pub periods: u64,
}

impl Default for Results {
    fn default() -> Self {
        Self {
            encoder: Outcome::NotRun,
            resistance: Outcome::NotRun,
            inductance: Outcome::NotRun,
            flux: Outcome::NotRun,
            mechanics: Outcome::NotRun,
            dead_time_v: 0.0,
            r_points: [(0.0, 0.0); 4],
            flux_points: [(0.0, 0.0); 3],
            friction_points: [(0.0, 0.0); 3],
            periods: 0,
        }
    }
}

/// Relative uncertainty bounds beyond which a fit is poor (not applied).
pub mod bounds {
    /// R.
    pub const R_REL: f64 = 0.02;
    /// L.
    pub const L_REL: f64 = 0.02;
    /// psi.
    pub const PSI_REL: f64 = 0.01;
    /// J.
    pub const J_REL: f64 = 0.10;
    /// Encoder offset, electrical degrees.
    pub const ZERO_DEG: f64 = 2.0;
    /// Pole pairs: distance of the fitted ratio from a whole number.
    pub const POLE_PAIRS_FRAC: f64 = 0.1;
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup() -> Setup {
        Setup {
            current_a: 8.0,
            voltage_v: 16.0,
            period_s: 62.56e-6,
            cpr: 4096,
            motor: MotorParams::default(),
            enc_zero: 0,
            phases: Phases::ALL,
        }
    }

    #[test]
    fn phases_parse_and_sets() {
        for p in Phase::ALL {
            assert_eq!(Phase::parse(p.name()), Some(p));
            assert!(Phases::ALL.has(p));
            assert!(Phases::only(p).has(p));
        }
        assert_eq!(Phase::parse("all"), None);
        assert!(!Phases::only(Phase::Flux).has(Phase::Encoder));
        assert!(Phase::Flux.needs_motion() && !Phase::Inductance.needs_motion());
    }

    #[test]
    fn bad_setups_are_refused() {
        assert!(setup().validate().is_ok());
        for bad in [
            Setup {
                current_a: f64::NAN,
                ..setup()
            },
            Setup {
                current_a: 0.0,
                ..setup()
            },
            Setup {
                voltage_v: -1.0,
                ..setup()
            },
            Setup {
                period_s: f64::INFINITY,
                ..setup()
            },
            Setup { cpr: 2, ..setup() },
            Setup {
                phases: Phases(0),
                ..setup()
            },
            Setup {
                phases: Phases(0x20),
                ..setup()
            },
        ] {
            assert!(bad.validate().is_err(), "{bad:?}");
        }
    }

    /// A current beyond twice the limit stops everything at once, and a
    /// NaN measurement too: every phase refused, `Done`.
    #[test]
    fn an_over_current_or_nan_measurement_stops_it() {
        for i in [[17.0, -8.5, -8.5], [f64::NAN, 0.0, 0.0]] {
            let mut c = Calibrator::new(&setup());
            let m = Measurement {
                i_abc_a: [0.0; 3],
                enc_pos: 0,
            };
            assert!(matches!(c.step(&m), Command::Voltage { .. }));
            let m = Measurement {
                i_abc_a: i,
                enc_pos: 0,
            };
            assert_eq!(c.step(&m), Command::Done);
            assert_eq!(c.step(&m), Command::Done);
            let r = c.results();
            assert!(matches!(r.encoder, Outcome::Refused(_)), "{r:?}");
            assert!(matches!(r.resistance, Outcome::Refused(_)), "{r:?}");
            assert!(matches!(r.mechanics, Outcome::Refused(_)), "{r:?}");
        }
    }

    /// A rotor that never moves: the encoder phase is refused after its
    /// first turn and the voltage stays within the limit throughout.
    #[test]
    fn a_still_encoder_is_a_locked_rotor() {
        let s = Setup {
            phases: Phases::only(Phase::Encoder),
            ..setup()
        };
        let mut c = Calibrator::new(&s);
        let m = Measurement {
            i_abc_a: [0.0; 3],
            enc_pos: 100,
        };
        let mut n = 0;
        while let Command::Voltage { alpha_v, beta_v } = c.step(&m) {
            assert!(alpha_v.hypot(beta_v) <= s.voltage_v + 1e-9);
            n += 1;
            assert!(n < 10_000, "does not end");
        }
        assert!(
            matches!(c.results().encoder, Outcome::Refused(w) if w.starts_with("rotor locked")),
            "{:?}",
            c.results()
        );
    }
}
