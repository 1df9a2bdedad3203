//! The drive on the PS: modes, gates, torque reference, the control step
//! run at every control-period boundary (FOC on the PS, or the inputs of
//! the PL's MPDTC core), the watchdog heartbeat and the `step` recorder.
//!
//! Everything goes through the PL drivers ([`crate::pl`]) over a
//! [`RegisterBus`], so the same code drives a bitstream, the simulated PL
//! and, in the host tests below, a fake one. The firmware calls
//! [`Servo::control_step`] from its control interrupt and the other methods
//! from the console (both under a critical section).
//!
//! Timing (PL clock 100 MHz):
//! - ADC every `ADC_PERIOD` = 391 cycles (255.75 kHz), averaged by 4: a
//!   result every 1564 cycles. MPDTC control period = one averaged result
//!   (63.94 kHz, the paper's 64 kHz within 0.1 %).
//! - FOC: PWM half period 3128 cycles, so one PWM period (6256 cycles,
//!   15.985 kHz, the paper's 16 kHz within 0.1 %) is exactly 4 averaged
//!   ADC results.
use crate::pl::adc::{Adc, AdcScale};
use crate::pl::capture::{CapState, Capture};
use crate::pl::enc::{Encoder, LivePos};
use crate::pl::fault::{Fault, Faults};
use crate::pl::mpdtc::{frontend_params, torque_ref_word, FrontendSetup, Mpdtc};
use crate::pl::pwm::{duty_cycles, Pwm};
use crate::pl::top::{Mode, Top};
use models::pmsm::closed_loop::{Actuation, Controller, Measurement};
use models::pmsm::foc::{Foc, FocParams};
use models::pmsm::frames::{clarke, park};
use models::pmsm::frontend_fixed::FrontendParams;
use models::pmsm::mpdtc_ctrl::{fixed_inputs, inputs_from_measurement};
use models::pmsm::mpdtc_fixed::FixedParams;
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use models::pmsm::mpdtc_tuning;
use models::pmsm::params::MotorParams;
use models::validate::ParamError;
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::top::BoundaryAge;
use regmap::{self, seq_state};

pub mod align;
pub mod faults;
pub mod motion;
mod step;
use align::{AlignAction, AlignSteps};
use faults::{FaultHistory, FaultRecord, Sample, Snapshot};
use models::motion::law::Impedance;
use motion::{LoopKind, Motion, MotionConfig, MotionError, MotionStatus, MoveResult};
pub use step::{StepRecorder, StepResult, STEP_SAMPLES_MAX};
mod sweep;
// Telemetry: the channels of one control period.
mod tel;
pub use sweep::{bandwidth_hz, record_response, tone_response, Sine, SweepPoint};
pub mod calibrate;
pub mod sensors;
use calibrate::{CalReport, CalRun};
use sensors::{PlTime, SensorFault, SensorReport};
pub mod evidence;
use evidence::{EncoderDead, FastTier, FastVerdict, PhaseOpen};

/// Control periods without a new ADC result that latch `ADC_STUCK`: two.
/// A control period holds at least one averaged result (`Config::check`
/// keeps it so), but a step served late (its interrupt held off by the
/// console, or a step that ran past the boundary) can read the result the
/// next step would have read: one stale step is tolerated, as one missed
/// period is for `CONTROL_OVERRUN`. Not so where a period holds two results
/// or more (the FOC's PWM period: four with the paper's timing) and the
/// step before was not that late: the first step without one latches
/// ([`Servo::adc_stale_limit`]).
pub const ADC_STALE_STEPS: u32 = 2;
/// Control periods missed in a row (between two control steps) that latch
/// `CONTROL_OVERRUN`: one late step is tolerated, the PL holds its outputs.
pub const OVERRUN_PERIODS: u64 = 2;

/// Control steps after a start before the checks of [`evidence`] begin:
/// the FOC's measurement pairs with the duties of two steps before, and
/// the one-period checks with the voltage of the period before that.
const EVIDENCE_SKIP: u32 = 3;

/// The one-period dead-encoder check decides only on a torque reference
/// that has stood within this of the step before, N m, for
/// [`REF_STEADY_STEPS`] steps: a current that follows a moving reference
/// (a `sweep` near the current loop's bandwidth: most of its amplitude in
/// a period) carries more `L di/dt` error than the check allows, and the
/// window check decides there.
const REF_STEADY_NM: f64 = 0.01;
/// Steps of a steady reference before the one-period dead-encoder check
/// decides: the FOC's measurement pairs with the duties of two steps
/// before, plus the period judged.
const REF_STEADY_STEPS: u32 = 3;

/// MPDTC alignment, first step: switching state 110 (bits SaSbSc), the
/// voltage vector at +60 electrical degrees. A rotor at its dead point
/// (240 degrees) stays there and is 120 degrees from the second step's
/// vector; any other settles on +60 degrees, 60 degrees from it.
pub const ALIGN_FIRST: u8 = 0b110;
/// MPDTC alignment, second step: 100, the d axis on phase a (angle 0), where
/// `MPDTC_ALIGN_POS` is latched.
pub const ALIGN_D: u8 = 0b100;

/// Configuration of the drive (defaults: the paper's setup).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ServoConfig {
    /// Motor model of the controllers and of the torque estimate.
    pub motor: MotorParams,
    /// Current sensing gain.
    pub adc: AdcScale,
    /// Encoder position of the rotor d axis on phase a, counts (FOC; the
    /// MPDTC uses the position latched by its alignment).
    pub enc_zero: u32,
    /// Largest accepted torque reference magnitude, N m.
    pub torque_limit_nm: f64,
    /// `ADC_PERIOD`, PL clock cycles.
    pub adc_period_cycles: u32,
    /// `PWM_PERIOD` (half period) in FOC mode, PL clock cycles.
    pub foc_half_period_cycles: u32,
    /// `DEAD_TIME`, PL clock cycles.
    pub dead_time_cycles: u32,
    /// `WDG_TIMEOUT`, PL clock cycles.
    pub watchdog_cycles: u32,
    /// `MPDTC_ALIGN_TIME`, PL clock cycles.
    pub align_cycles: u32,
    /// `ENC_CPR`, encoder counts per mechanical revolution.
    pub enc_cpr: u32,
    /// Over-current trip (`OC_LIMIT`, converted with `adc`), A.
    pub current_limit_a: f64,
    /// FOC tuning; its period and measurement lag follow from the PL
    /// timing above ([`Servo::new`] sets them).
    pub foc: FocParams,
    /// MPDTC tuning; its control period follows from `adc_period_cycles`.
    pub mpdtc: MpdtcParams,
    /// The torque integrator's gain K derived from `motor` and the control
    /// period ([`models::pmsm::mpdtc_tuning::integrator_gain_per_s`])
    /// instead of `mpdtc.k_int_per_s`.
    pub mpdtc_k_auto: bool,
    /// MPDTC input path: `false` = the autonomous loop (the PL's front end
    /// computes the core's inputs every period, the PS writes only the
    /// torque reference), `true` = the PS-fed debug path (Park transform and
    /// angles on the PS, `MPDTC_IN_*` and `MPDTC_START` every period).
    pub mpdtc_ps_fed: bool,
    /// Smallest `step` size, N m: its 10 % settling band must stand clear
    /// of the torque estimate's resolution (one ADC count, 10 mA, is about
    /// 1 mN m of q-axis torque) and ripple; a step of zero has no settling
    /// time at all.
    pub step_min_nm: f64,
    /// The outer loops (velocity, position, impedance) and their limits.
    pub motion: MotionConfig,
    /// Largest current magnitude of `calibrate`, A.
    pub calibration_current_a: f64,
    /// Largest voltage vector magnitude of `calibrate`, V.
    pub calibration_voltage_v: f64,
}

impl Default for ServoConfig {
    fn default() -> Self {
        Self {
            motor: MotorParams::default(),
            // 12-bit signed ADC over +-20.48 A: 10 mA per count.
            adc: AdcScale {
                amps_per_count: 0.01,
            },
            enc_zero: 0,
            torque_limit_nm: 1.0,
            adc_period_cycles: 391,
            foc_half_period_cycles: 3128,
            dead_time_cycles: 50,
            // 2 ms: 32 FOC or 128 MPDTC periods without a heartbeat.
            watchdog_cycles: 200_000,
            // At most 0.2 s of rotor alignment before the MPDTC's first
            // decision: two steps (`ALIGN_FIRST` for at most 0.1 s, then
            // `ALIGN_D`), each ending once the rotor is still (`align`;
            // docs/mpdtc.md): the maximum is about 7 of the free rotor's
            // decay times per step.
            align_cycles: 20_000_000,
            enc_cpr: 4096,
            // Below the 16 A full scale of the simulated PL's ADC.
            current_limit_a: 14.0,
            foc: FocParams::default(),
            mpdtc: MpdtcParams::default(),
            mpdtc_k_auto: false,
            mpdtc_ps_fed: false,
            // Band 5 mN m: about 5 ADC counts of i_q.
            step_min_nm: 0.05,
            motion: MotionConfig::default(),
            calibration_current_a: 8.0,
            calibration_voltage_v: 16.0,
        }
    }
}

impl ServoConfig {
    /// The MPDTC's control period, s: four ADC averaging periods.
    pub fn mpdtc_period_s(&self) -> f64 {
        period_s(4 * self.adc_period_cycles)
    }

    /// `OC_LIMIT` for [`Self::current_limit_a`]: ADC counts, rounded down
    /// so that the trip is never above the limit; `None` beyond the 11-bit
    /// range.
    pub fn oc_limit_counts(&self) -> Option<u32> {
        let c = libm::floor(self.current_limit_a / self.adc.amps_per_count);
        (c.is_finite() && (0.0..=2047.0).contains(&c)).then_some(c as u32)
    }

    /// The defaults with the `motor` and the current-sensing gain
    /// `adc_amps_per_count` (A per ADC count) of the plant the drive runs:
    /// a board's, or under QEMU the simulated PL's, which the firmware
    /// reads from the simulator when it selects that backend.
    pub fn for_plant(motor: MotorParams, adc_amps_per_count: f64) -> Self {
        Self {
            motor,
            adc: AdcScale {
                amps_per_count: adc_amps_per_count,
            },
            ..Self::default()
        }
    }
}

/// Why a drive command was refused (nothing changed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ServoError {
    /// `enable` in mode off.
    ModeOff,
    /// `enable` while a fault is latched.
    FaultLatched(Faults),
    /// `step` with the gates off.
    GatesOff,
    /// Torque reference not finite or beyond the limit (N m).
    TorqueOutOfRange(f64),
    /// `step` smaller than [`ServoConfig::step_min_nm`] from the present
    /// reference (both N m).
    StepTooSmall {
        /// The present reference, N m.
        from_nm: f64,
        /// The requested one, N m.
        to_nm: f64,
        /// [`ServoConfig::step_min_nm`], N m.
        min_nm: f64,
    },
    /// The PL answered with an error.
    Bus(BusError),
    /// A configuration change that needs the gates off, with them on.
    GatesOn,
    /// A configuration the controllers refuse.
    BadConfig(ParamError),
    /// A sine frequency outside (0, control rate / 4], or too low for one
    /// period in a capture record, Hz.
    BadFrequency(f64),
    /// The sensor check before the first closed loop failed (gates off).
    SensorCheck(SensorFault),
    /// An outer-loop command refused.
    Motion(MotionError),
    /// A position, velocity or impedance command (or `pos zero`) during the
    /// MPDTC's rotor alignment, which still turns the rotor: at most this
    /// long left, s.
    Aligning(f64),
    /// `calibrate` while the rotor turns faster than
    /// [`CAL_REST_REV_S`]: its speed, rev/s.
    RotorTurning(f64),
}

/// The fastest a rotor may turn for `calibrate` to start, rev/s: its
/// phases assume a rotor at rest (the encoder phase turns the field
/// against it, the resistance phase holds a current vector); a coasting
/// rotor's back EMF drives currents they do not command. 0.5 rev/s of the
/// paper's motor (7 pole pairs, 9.29 mWb) is 0.20 V of back EMF.
pub const CAL_REST_REV_S: f64 = 0.5;

impl From<MotionError> for ServoError {
    fn from(e: MotionError) -> Self {
        ServoError::Motion(e)
    }
}

impl From<BusError> for ServoError {
    fn from(e: BusError) -> Self {
        ServoError::Bus(e)
    }
}

/// What the drive measured at the last control step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Measured {
    /// d-axis current, A.
    pub i_d_a: f64,
    /// q-axis current, A.
    pub i_q_a: f64,
    /// Torque from the measured currents, N m.
    pub torque_nm: f64,
    /// Electrical speed, rad/s.
    pub omega_e_rad_s: f64,
}

/// The drive's state on the PS.
pub struct Servo {
    cfg: ServoConfig,
    mode: Mode,
    gates: bool,
    torque_ref_nm: f64,
    foc_params: FocParams,
    foc: Foc,
    mpdtc: MpdtcConfig,
    mpdtc_regs: FixedParams,
    /// MPDTC front-end registers (the autonomous loop).
    fe_regs: FrontendParams,
    /// MPDTC: the encoder zero latched by the alignment of this run.
    align_zero: Option<u32>,
    /// MPDTC: the alignment's progress (when its steps end).
    align: Option<AlignSteps>,
    /// `MPDTC_ALIGN_TIME` was cut to end the alignment early: written back
    /// once the PL has latched the zero (or at the next `enable`).
    align_time_cut: bool,
    /// A `move` during the MPDTC's alignment: its capture record starts
    /// with the alignment's end, where the move starts.
    move_capture_pending: bool,
    /// MPDTC: the decision applied at the last boundary (for transitions).
    last_state: u8,
    /// FOC: the ADC timer was restarted at a PWM period start of this run.
    adc_synced: bool,
    periods: u64,
    overruns: u64,
    beat: u32,
    measured: Measured,
    /// Gate transitions per leg (cumulative, from the commanded switching).
    transitions: [u64; 3],
    rec: StepRecorder,
    /// Faults the PS detected, latched ([`Faults`] bits 3..).
    ps_faults: u32,
    /// Faults (PL and PS) already in the history while latched.
    seen: u32,
    history: FaultHistory,
    snapshot: Snapshot,
    /// Drive time: control periods run and missed, s.
    time_s: f64,
    last_adc_count: Option<u32>,
    adc_stale: u32,
    last_pos: Option<u32>,
    missed: u64,
    /// Sine torque reference (`sweep`), while the gates are on.
    sine: Option<Sine>,
    /// FOC: the duties of the last step (telemetry).
    duties: [f64; 3],
    /// FOC: the duties of the step before (applied in the period the
    /// present step measured).
    duties_old: [f64; 3],
    /// `BOUNDARY_AGE` of the present step and of the one before, PL cycles
    /// (`None`: not known).
    step_age: Option<u32>,
    prev_step_age: Option<u32>,
    /// The motion limits (`pos_min`, `pos_max`, `vel_limit`) before
    /// [`Self::tighten_limit`] moved them.
    saved_limits: Option<(f64, f64, f64)>,
    /// The dead-encoder check.
    enc_dead: EncoderDead,
    /// The open-phase check.
    phase_open: PhaseOpen,
    /// The one-period checks of both, and their last verdict.
    fast: FastTier,
    fast_last: FastVerdict,
    /// The live encoder count at the end of the last step (gates on), if
    /// read before the next boundary.
    pos_at_end: Option<LivePos>,
    /// The torque reference of the last step, N m, and the steps it has
    /// stood within [`REF_STEADY_NM`] of the one before.
    ref_last: f64,
    ref_steady: u32,
    /// The MPDTC's motor model at the FOC's period (the one-period checks
    /// in FOC).
    foc_model: MpdtcConfig,
    /// Steps before the checks over a window start again (the voltage of
    /// the first steps after a start is not yet this run's).
    evidence_skip: u32,
    /// The sensor check passed with this configuration's motor and sensors.
    sensors_ok: bool,
    /// The outer loops and the multi-turn position.
    motion: Motion,
    /// Control periods per capture sample of the record armed last.
    cap_every: u32,
}

/// A configuration checked and its controllers built ([`Servo::rebuild`]).
pub struct Rebuilt {
    cfg: ServoConfig,
    foc_params: FocParams,
    foc: Foc,
    mpdtc: MpdtcConfig,
    mpdtc_regs: FixedParams,
    fe_regs: FrontendParams,
    foc_model: MpdtcConfig,
    motion: Motion,
}

/// A configuration's PL registers (timing, trip levels, MPDTC parameters),
/// written with the gates off and the core held.
#[derive(Debug, Clone, Copy)]
pub struct PlConfig {
    cfg: ServoConfig,
    mpdtc_regs: FixedParams,
    fe_regs: FrontendParams,
}

impl PlConfig {
    /// Writes the registers: [`PlConfig::write_adc`], then
    /// [`PlConfig::write_rest`].
    pub fn write<B: RegisterBus>(&self, bus: &mut B) -> Result<(), BusError> {
        self.write_adc(bus)?;
        self.write_rest(bus)
    }
    /// The ADC's period: a change stops and restarts the conversions
    /// ([`Adc::set_period`]), accesses that belong together (no control
    /// step between them: it would find no result).
    pub fn write_adc<B: RegisterBus>(&self, bus: &mut B) -> Result<(), BusError> {
        Adc(&mut *bus).set_period(self.cfg.adc_period_cycles)
    }
    /// The other registers, each access on its own.
    pub fn write_rest<B: RegisterBus>(&self, bus: &mut B) -> Result<(), BusError> {
        Encoder(&mut *bus).set_cpr(self.cfg.enc_cpr)?;
        // `Config::check` refuses a limit beyond the ADC's range; any other
        // `ServoConfig` gets the largest trip level.
        let oc = self.cfg.oc_limit_counts().unwrap_or(2047);
        Fault(&mut *bus).set_oc_limit(oc)?;
        let mut pwm = Pwm(&mut *bus);
        pwm.set_dead_time(self.cfg.dead_time_cycles)?;
        pwm.set_half_period(self.cfg.foc_half_period_cycles)?;
        pwm.set_duties([0.5; 3], self.cfg.foc_half_period_cycles)?;
        Fault(&mut *bus).set_watchdog_timeout(self.cfg.watchdog_cycles)?;
        let mut m = Mpdtc(&mut *bus);
        m.set_ctrl_path(false, true, !self.cfg.mpdtc_ps_fed)?;
        m.load_params(&self.mpdtc_regs)?;
        m.load_frontend(&self.fe_regs)?;
        m.set_align_time(self.cfg.align_cycles)
    }
}

impl Servo {
    /// A drive in mode off with the gates off; nothing touches the PL
    /// until [`Servo::init`].
    pub fn new(cfg: &ServoConfig) -> Result<Self, ParamError> {
        let Rebuilt {
            cfg: _,
            foc_params,
            foc,
            mpdtc,
            mpdtc_regs,
            fe_regs,
            foc_model,
            motion,
        } = Self::rebuild(cfg)?;
        Ok(Self {
            fe_regs,
            cfg: *cfg,
            mode: Mode::Off,
            gates: false,
            torque_ref_nm: 0.0,
            foc,
            foc_params,
            mpdtc_regs,
            mpdtc,
            align_zero: None,
            align: None,
            align_time_cut: false,
            move_capture_pending: false,
            last_state: 0,
            adc_synced: false,
            periods: 0,
            overruns: 0,
            beat: 0,
            measured: Measured::default(),
            transitions: [0; 3],
            rec: StepRecorder::new(),
            ps_faults: 0,
            seen: 0,
            history: FaultHistory::default(),
            snapshot: Snapshot::default(),
            time_s: 0.0,
            last_adc_count: None,
            adc_stale: 0,
            last_pos: None,
            missed: 0,
            sine: None,
            duties: [0.0; 3],
            duties_old: [0.0; 3],
            step_age: None,
            prev_step_age: None,
            saved_limits: None,
            enc_dead: EncoderDead::default(),
            phase_open: PhaseOpen::default(),
            fast: FastTier::default(),
            fast_last: FastVerdict::default(),
            pos_at_end: None,
            ref_last: 0.0,
            ref_steady: 0,
            foc_model,
            evidence_skip: EVIDENCE_SKIP,
            sensors_ok: false,
            motion,
            cap_every: 1,
        })
    }

    /// Checks `cfg` and builds its controllers and PL register values:
    /// the arithmetic of a reconfiguration, done before it and away from
    /// the control loop (the firmware builds it outside the control
    /// interrupt's critical section, then [`Servo::adopt`]s it).
    pub fn rebuild(cfg: &ServoConfig) -> Result<Rebuilt, ParamError> {
        if !(cfg.torque_limit_nm.is_finite() && cfg.torque_limit_nm > 0.0) {
            return Err(ParamError {
                field: "torque_limit_nm",
                reason: "must be finite and > 0",
            });
        }
        let foc_params = FocParams {
            period_s: period_s(2 * cfg.foc_half_period_cycles),
            measurement_lag_s: foc_measurement_lag_s(cfg),
            ..cfg.foc
        };
        let ts = period_s(4 * cfg.adc_period_cycles);
        let mp = MpdtcParams {
            control_period_s: ts,
            k_int_per_s: if cfg.mpdtc_k_auto {
                mpdtc_tuning::integrator_gain_per_s(&cfg.motor, ts)
            } else {
                cfg.mpdtc.k_int_per_s
            },
            ..cfg.mpdtc
        };
        let mpdtc = MpdtcConfig::new(cfg.motor, mp)?;
        let foc_model = MpdtcConfig::prediction_model(cfg.motor, foc_params.period_s)?;
        cfg.motion.validate()?;
        let fe_regs = frontend_params(&FrontendSetup {
            pole_pairs: cfg.motor.pole_pairs,
            enc_cpr: cfg.enc_cpr,
            period_cycles: 4 * cfg.adc_period_cycles,
            window_cycles: regmap::ENC_WINDOW.reset,
            meas_age_periods: cfg.mpdtc.meas_age_periods,
            amps_per_count: cfg.adc.amps_per_count,
            adc_offset: [0; 3],
        });
        // The PS-fed path does not use the front end: its limits do not apply.
        let fe_regs = match (fe_regs, cfg.mpdtc_ps_fed) {
            (Ok(f), _) => f,
            (Err(_), true) => FrontendParams::default(),
            (Err(e), false) => return Err(e),
        };
        Ok(Rebuilt {
            cfg: *cfg,
            foc: Foc::new(&cfg.motor, &foc_params)?,
            foc_params,
            mpdtc_regs: FixedParams::from_config(&mpdtc)?,
            mpdtc,
            fe_regs,
            foc_model,
            motion: Motion::new(cfg.enc_cpr)?,
        })
    }

    /// Puts the PL in the drive's start state: gates off, mode off, timing,
    /// watchdog, MPDTC parameters (core state held cleared).
    pub fn init<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), BusError> {
        Pwm(&mut *bus).set_gates(false)?;
        Top(&mut *bus).set_mode(Mode::Off)?;
        self.write_pl_config(bus)?;
        Top(&mut *bus).heartbeat(0)
    }

    /// Writes the configuration's PL registers (gates off, core held).
    fn write_pl_config<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), BusError> {
        self.pl_config().write(bus)
    }

    /// The PL registers of the present configuration.
    fn pl_config(&self) -> PlConfig {
        PlConfig {
            cfg: self.cfg,
            mpdtc_regs: self.mpdtc_regs,
            fe_regs: self.fe_regs,
        }
    }

    /// Replaces the configuration. With the gates on only a change of the
    /// torque limit is accepted (and not below the present reference);
    /// with them off the controllers are rebuilt and the PL registers
    /// written, the mode stays. On an error nothing changed.
    pub fn reconfigure<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        cfg: &ServoConfig,
    ) -> Result<(), ServoError> {
        let next = Servo::rebuild(cfg).map_err(ServoError::BadConfig)?;
        if let Some(pl) = self.adopt(bus, next)? {
            pl.write_rest(bus)?;
        }
        Ok(())
    }

    /// Installs a configuration [`Servo::rebuild`] built: no arithmetic
    /// beyond copies and the ADC period's accesses
    /// ([`PlConfig::write_adc`]), so a caller may hold the control loop off
    /// around it. The ADC period goes with the installation: the MPDTC's
    /// and mode off's control period is four ADC results, and a control
    /// step or PL tick between the two would wait for a boundary of the new
    /// period on the PL's old one (a period shortened from 1,500 to 391
    /// cycles: no result within two new periods, the PS's `ADC_STUCK`).
    /// Returns the PL registers still to write ([`PlConfig::write_rest`])
    /// when the gates are off (`None` with them on: only the torque limit
    /// changed). Those writes may be interleaved with control steps: the
    /// gates stay off until the console enables them, and the steps of a
    /// drive with the gates off only measure. On a configuration error
    /// nothing changed.
    pub fn adopt<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        next: Rebuilt,
    ) -> Result<Option<PlConfig>, ServoError> {
        let cfg = &next.cfg;
        if libm::fabs(self.torque_ref_nm) > cfg.torque_limit_nm {
            return Err(ServoError::TorqueOutOfRange(self.torque_ref_nm));
        }
        if self.gates {
            let live_only = ServoConfig {
                torque_limit_nm: cfg.torque_limit_nm,
                ..self.cfg
            };
            if live_only != *cfg {
                return Err(ServoError::GatesOn);
            }
            self.cfg.torque_limit_nm = cfg.torque_limit_nm;
            return Ok(None);
        }
        // New motor or sensor facts: the next `enable` checks the sensors.
        let sensed = |c: &ServoConfig| (c.motor, c.adc, c.enc_cpr, c.enc_zero, c.current_limit_a);
        if sensed(&next.cfg) != sensed(&self.cfg) {
            self.sensors_ok = false;
        }
        if next.cfg.enc_cpr != self.motion.estimator().cpr() {
            self.motion = next.motion;
        }
        self.cfg = next.cfg;
        self.foc_params = next.foc_params;
        self.foc = next.foc;
        self.mpdtc = next.mpdtc;
        self.mpdtc_regs = next.mpdtc_regs;
        self.fe_regs = next.fe_regs;
        self.foc_model = next.foc_model;
        // The writes below include MPDTC_ALIGN_TIME.
        self.align_time_cut = false;
        let pl = self.pl_config();
        pl.write_adc(bus)?;
        Ok(Some(pl))
    }

    /// The configuration.
    pub fn config(&self) -> &ServoConfig {
        &self.cfg
    }
    /// The active mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }
    /// The torque reference, N m.
    pub fn torque_ref_nm(&self) -> f64 {
        self.torque_ref_nm
    }
    /// Control periods run.
    pub fn periods(&self) -> u64 {
        self.periods
    }
    /// Control periods missed (the control step did not run in time).
    pub fn overruns(&self) -> u64 {
        self.overruns
    }
    /// What the last control step measured.
    pub fn measured(&self) -> Measured {
        self.measured
    }
    /// Control periods per second of the active mode (FOC: the PWM period;
    /// MPDTC and off: one averaged ADC result), Hz.
    pub fn control_rate_hz(&self) -> f64 {
        1.0 / self.control_period_s()
    }
    /// The control period of the active mode in PL clock cycles (10 ns),
    /// the whole number the PL's timers count (MPDTC: 4 ADC periods, FOC:
    /// 2 PWM half periods): rounded, as `1 / control_rate_hz` in cycles
    /// lands a hair below it (1563.99... for 1,564) and truncates one short.
    pub fn control_period_cycles(&self) -> u64 {
        libm::round(self.control_period_s() * f64::from(regmap::PL_CLOCK_HZ)) as u64
    }
    /// The control period of the active mode, s.
    pub fn control_period_s(&self) -> f64 {
        match self.mode {
            Mode::Foc => self.foc_params.period_s,
            _ => self.mpdtc.params.control_period_s,
        }
    }

    /// Switches the mode; the gates go off first (any mode change).
    pub fn set_mode<B: RegisterBus>(&mut self, bus: &mut B, m: Mode) -> Result<(), ServoError> {
        self.gates_off(bus)?;
        Top(&mut *bus).set_mode(m)?;
        self.mode = m;
        // The next boundary may come sooner than a period of the new mode
        // (without a new ADC result in between).
        self.note_skipped();
        Ok(())
    }

    /// Gates on: refused in mode off and while a fault is latched.
    pub fn enable<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        if self.mode == Mode::Off {
            return Err(ServoError::ModeOff);
        }
        let f = self.faults(bus)?;
        if !f.none() {
            return Err(ServoError::FaultLatched(f));
        }
        // Fresh controller state for this run.
        self.foc = Foc::new(&self.cfg.motor, &self.foc_params).map_err(|_| ServoError::ModeOff)?;
        self.align_zero = None;
        self.move_capture_pending = false;
        self.last_state = 0;
        self.adc_synced = false;
        let half = self.cfg.foc_half_period_cycles;
        Pwm(&mut *bus).set_duties([0.5; 3], half)?;
        if self.mode == Mode::Mpdtc {
            // The sequence aligns the rotor, then takes the decisions. The
            // alignment in two steps: on the vector 60 electrical degrees
            // ahead of the d axis, then on the d axis (`control_step`
            // switches), so no starting angle is the dead point (180
            // degrees off) of both. Each step ends once the rotor is still
            // (`align`), the first at the latest at the half of
            // MPDTC_ALIGN_TIME, the second at its end; the early end of the
            // second cuts MPDTC_ALIGN_TIME, written back at its end (or
            // here, if a run ended before the PL latched).
            let mut m = Mpdtc(&mut *bus);
            if core::mem::take(&mut self.align_time_cut) {
                m.set_align_time(self.cfg.align_cycles)?;
            }
            m.set_align_vec(ALIGN_FIRST)?;
            m.set_ctrl_path(false, false, !self.cfg.mpdtc_ps_fed)?;
            let clock = f64::from(regmap::PL_CLOCK_HZ);
            let period = self.mpdtc.params.control_period_s * clock;
            self.align = Some(AlignSteps::new(period, self.cfg.align_cycles, clock));
        }
        Pwm(&mut *bus).set_gates(true)?;
        self.gates = true;
        Ok(())
    }

    /// Whether the next [`Servo::enable_checked`] runs the sensor check
    /// (none passed since boot or since the motor or sensor configuration
    /// changed).
    pub fn sensor_check_due(&self) -> bool {
        !self.sensors_ok
    }

    /// Runs the sensor check ([`sensors`]): refused with the gates on and
    /// while a fault is latched. The gates are off and the mode restored
    /// afterwards whatever happened; a pass is remembered until the motor or
    /// sensor configuration changes.
    pub fn check_sensors<B: PlTime>(&mut self, bus: &mut B) -> Result<SensorReport, ServoError> {
        if self.gates {
            return Err(ServoError::GatesOn);
        }
        let f = self.faults(bus)?;
        if !f.none() {
            return Err(ServoError::FaultLatched(f));
        }
        let half = self.cfg.foc_half_period_cycles;
        let target = sensors::target_a(self.cfg.current_limit_a, self.cfg.adc.amps_per_count);
        let mut run = sensors::Run {
            bus: &mut *bus,
            beat: &mut self.beat,
            cycles: 0,
            amps_per_count: self.cfg.adc.amps_per_count,
        };
        let r = run.sequence(half, target, u64::from(4 * self.cfg.adc_period_cycles));
        let restored = self.end_open_loop(bus, half);
        let r = r?;
        restored?;
        self.sensors_ok = r.result.is_ok();
        Ok(r)
    }

    /// Runs a calibration ([`calibrate`]): refused with the gates on and
    /// while a fault is latched. The gates are off and the mode restored
    /// afterwards whatever happened; the configuration is not touched (the
    /// caller applies the results).
    pub fn calibrate<B: PlTime>(
        &mut self,
        bus: &mut B,
        setup: &models::calibration::Setup,
        on_phase: &mut dyn FnMut(Option<models::calibration::Phase>),
        stop: &mut dyn FnMut() -> bool,
    ) -> Result<CalReport, ServoError> {
        if self.gates || self.gates_on(bus)? {
            return Err(ServoError::GatesOn);
        }
        let f = self.faults(bus)?;
        if !f.none() {
            return Err(ServoError::FaultLatched(f));
        }
        let v = self.motion_status().velocity_rev_s;
        // A NaN estimate is no proof of rest either.
        if v.is_nan() || libm::fabs(v) > CAL_REST_REV_S {
            return Err(ServoError::RotorTurning(v));
        }
        setup.validate().map_err(ServoError::BadConfig)?;
        let bad = |field, reason| Err(ServoError::BadConfig(ParamError { field, reason }));
        if setup.current_a >= self.cfg.current_limit_a {
            return bad("calibration_current", "must be below current_limit");
        }
        if setup.voltage_v > 0.5 * self.cfg.motor.u_dc_v {
            return bad(
                "calibration_voltage",
                "must be at most u_dc / 2 (the PWM's linear range)",
            );
        }
        let half = self.cfg.foc_half_period_cycles;
        let mut run = CalRun {
            bus: &mut *bus,
            beat: &mut self.beat,
            half,
            u_dc_v: self.cfg.motor.u_dc_v,
            amps_per_count: self.cfg.adc.amps_per_count,
            cycles: 0,
        };
        let r = run.run(setup, on_phase, stop);
        let restored = self.end_open_loop(bus, half);
        let r = r?;
        restored?;
        Ok(r)
    }

    /// After a sequence that drove the inverter itself (sensor check,
    /// calibration), whatever happened: gates off, duties neutral, the
    /// mode back; every write is tried, the first error returned.
    fn end_open_loop<B: RegisterBus + ?Sized>(
        &mut self,
        bus: &mut B,
        half: u32,
    ) -> Result<(), ServoError> {
        let off = Pwm(&mut *bus).set_gates(false);
        let duties = Pwm(&mut *bus).set_duties([0.5; 3], half);
        let mode = Top(&mut *bus).set_mode(self.mode);
        self.note_skipped();
        off?;
        duties?;
        mode?;
        Ok(())
    }

    /// The calibration's starting point from this configuration: its
    /// motor, encoder and PWM period, with the given limits and phases.
    pub fn calibration_setup(
        &self,
        current_a: f64,
        voltage_v: f64,
        phases: models::calibration::Phases,
    ) -> models::calibration::Setup {
        models::calibration::Setup {
            current_a,
            voltage_v,
            period_s: period_s(2 * self.cfg.foc_half_period_cycles),
            cpr: self.cfg.enc_cpr,
            motor: MotorParams {
                j_kg_m2: self
                    .cfg
                    .motion
                    .load_inertia_kg_m2
                    .max(self.cfg.motor.j_kg_m2),
                ..self.cfg.motor
            },
            enc_zero: self.cfg.enc_zero,
            phases,
        }
    }

    /// [`Servo::enable`], after the sensor check when one is due; a failed
    /// check leaves the gates off and answers [`ServoError::SensorCheck`].
    pub fn enable_checked<B: PlTime>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        if self.mode == Mode::Off {
            return Err(ServoError::ModeOff);
        }
        if self.sensor_check_due() && !self.gates {
            if let Err(e) = self.check_sensors(bus)?.result {
                return Err(ServoError::SensorCheck(e));
            }
        }
        self.enable(bus)
    }

    /// Gates off (always allowed).
    pub fn disable<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        self.gates_off(bus)
    }

    /// Gates off; the torque reference returns to 0 N m, so that every run
    /// starts from rest (a `step` after `enable` is a step from 0).
    fn gates_off<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        if self.gates {
            self.torque_ref_nm = 0.0;
        }
        self.gates = false;
        self.rec.cancel();
        self.sine = None;
        self.motion.to_torque();
        Pwm(&mut *bus).set_gates(false)?;
        let mut m = Mpdtc(&mut *bus);
        m.set_ctrl_path(false, true, !self.cfg.mpdtc_ps_fed)?;
        // The next run starts from 0 N m in the PL too.
        m.write_torque_ref(0)?;
        Ok(())
    }

    /// Whether the gates are on (`GATE_EN` read back: a fault clears it).
    pub fn gates_on<B: RegisterBus>(&mut self, bus: &mut B) -> Result<bool, BusError> {
        Pwm(bus).gates_enabled()
    }

    /// The faults the control loop has recorded while they are latched (no
    /// register read: the last step's view).
    pub fn faults_recorded(&self) -> Faults {
        Faults(self.seen)
    }

    /// The latched faults and then `GATE_EN`, for a report that never
    /// shows a latched PL fault with the gates on: the PL holds `GATE_EN`
    /// at 0 from the latch on, so a fault read first is seen off by the
    /// gate read after it. (Gates first, a fault that latched between the
    /// two reads showed as `fault: ENCODER_LOSS` with `gates: on`; on the
    /// simulated PL, which runs only on accesses between its ticks, that
    /// was a `status` right after `debug fault encoder-loss`.)
    pub fn faults_then_gates<B: RegisterBus>(
        &mut self,
        bus: &mut B,
    ) -> Result<(Faults, bool), BusError> {
        let faults = self.faults(bus)?;
        Ok((faults, self.gates_on(bus)?))
    }

    /// The controller runs: the gates are on and, in MPDTC, the rotor
    /// alignment is over (the checks over a window run only then).
    pub fn controlling(&self) -> bool {
        self.gates && (self.mode != Mode::Mpdtc || self.align_zero.is_some())
    }

    /// Checks a torque reference: finite and within the limit.
    pub fn check_torque(&self, nm: f64) -> Result<f64, ServoError> {
        if nm.is_finite() && libm::fabs(nm) <= self.cfg.torque_limit_nm {
            Ok(nm)
        } else {
            Err(ServoError::TorqueOutOfRange(nm))
        }
    }

    /// Sets the torque reference, N m.
    pub fn set_torque_ref(&mut self, nm: f64) -> Result<(), ServoError> {
        self.torque_ref_nm = self.check_torque(nm)?;
        self.motion.to_torque();
        Ok(())
    }

    /// Refused unless the gates are on.
    fn need_gates<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), ServoError> {
        if self.gates && self.gates_on(bus)? {
            Ok(())
        } else {
            Err(ServoError::GatesOff)
        }
    }

    /// The MPDTC's rotor alignment runs (gates on, zero not latched yet):
    /// the longest it can still take, s.
    pub fn aligning_left_s(&self) -> Option<f64> {
        if self.gates && self.mode == Mode::Mpdtc && self.align_zero.is_none() {
            Some(self.align.as_ref().map_or(0.0, AlignSteps::left_s))
        } else {
            None
        }
    }

    /// Refuses a command that needs the rotor's position while the
    /// alignment still turns it: a zero taken then, or a loop closed on
    /// the position, would be off by the alignment's motion.
    fn not_aligning(&self) -> Result<(), ServoError> {
        match self.aligning_left_s() {
            Some(left) => Err(ServoError::Aligning(left)),
            None => Ok(()),
        }
    }

    /// `vel <rev/s>`: the velocity loop (gates on, alignment over).
    pub fn set_velocity<B: RegisterBus>(&mut self, bus: &mut B, v: f64) -> Result<(), ServoError> {
        self.need_gates(bus)?;
        self.not_aligning()?;
        Ok(self.motion.set_velocity(&self.cfg.motion, v)?)
    }

    /// `pos <rev>`: a trajectory to `target` (gates on, alignment over).
    pub fn set_position<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        target: f64,
    ) -> Result<(), ServoError> {
        // The argument before the drive's state: a target out of range is
        // refused as such whatever the gates.
        Motion::check_position(&self.cfg.motion, target)?;
        self.need_gates(bus)?;
        self.not_aligning()?;
        Ok(self.motion.set_position(&self.cfg.motion, target)?)
    }

    /// `imp ...`: the impedance law (gates on, alignment over).
    pub fn set_impedance<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        imp: &Impedance,
    ) -> Result<(), ServoError> {
        self.need_gates(bus)?;
        self.not_aligning()?;
        let lim = self.cfg.torque_limit_nm;
        Ok(self.motion.set_impedance(&self.cfg.motion, imp, lim)?)
    }

    /// `move <rev>`: a recorded move by `distance` (gates on).
    pub fn begin_move<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        distance: f64,
        window_s: f64,
    ) -> Result<(), ServoError> {
        // The arguments first, before the gates and before anything is
        // cancelled: a refused move changes nothing.
        self.motion
            .check_move(&self.cfg.motion, distance, window_s)?;
        self.need_gates(bus)?;
        self.rec.cancel();
        self.sine = None;
        self.motion
            .begin_move(&self.cfg.motion, distance, window_s)?;
        // An armed capture record starts with the move: re-armed (the ring
        // empties, the decimation counter restarts) and triggered, so that
        // sample j of the record is taken at the (j + 1) x every-th
        // sample strobe after this command, a fixed offset from the move.
        // During the MPDTC's alignment that is at its end (the move starts
        // there).
        self.move_capture_pending = self.mode == Mode::Mpdtc && self.align_zero.is_none();
        if !self.move_capture_pending {
            Self::start_move_capture(bus)?;
        }
        Ok(())
    }

    /// An armed capture record restarts and triggers.
    fn start_move_capture<B: RegisterBus>(bus: &mut B) -> Result<(), BusError> {
        let mut cap = Capture(&mut *bus);
        if cap.status()?.state == CapState::Armed {
            cap.restart()?;
            cap.trigger()?;
        }
        Ok(())
    }

    /// The watchdog's heartbeat without a control step, written only while
    /// the gates are off; returns whether it wrote. The firmware calls it
    /// when no control step has fed the watchdog for a quarter of its
    /// timeout: in mode off only the ADC's averages raise control-period
    /// boundaries, so a board without its ADC card has none, and WATCHDOG
    /// would latch with nothing to protect, hiding the real problem from
    /// the next `enable` (the sensor check's `ADC_STUCK`). With the gates
    /// on only the control step feeds it: a control loop that stops still
    /// trips it.
    pub fn keep_alive<B: RegisterBus>(&mut self, bus: &mut B) -> Result<bool, BusError> {
        if self.gates {
            return Ok(false);
        }
        self.beat = self.beat.wrapping_add(1);
        Top(&mut *bus).heartbeat(self.beat)?;
        Ok(true)
    }

    /// `pos zero` (refused during the MPDTC's alignment).
    pub fn zero_position(&mut self) -> Result<(), ServoError> {
        self.not_aligning()?;
        Ok(self.motion.zero()?)
    }

    /// The `move` figures once done.
    pub fn move_result(&self) -> Option<MoveResult> {
        self.motion.move_result()
    }

    /// Whether a `move` is still waiting or running.
    pub fn move_pending(&self) -> bool {
        self.motion.move_pending()
    }

    /// Position, velocity and the outer loop for `status`.
    pub fn motion_status(&self) -> MotionStatus {
        self.motion.status()
    }

    /// The active loop.
    pub fn loop_kind(&self) -> LoopKind {
        self.motion.kind()
    }

    /// Latched faults: the PL's and the PS's.
    pub fn faults<B: RegisterBus>(&mut self, bus: &mut B) -> Result<Faults, BusError> {
        Ok(Faults(Fault(bus).latched()?.0 | self.ps_faults))
    }

    /// Clears the latched faults whose condition is gone; the gates stay
    /// off until `enable`. Returns what is still latched. The watchdog is
    /// fed and the ADC started first (their conditions are the drive's to
    /// end); the PS's checks start afresh.
    pub fn clear_faults<B: RegisterBus>(&mut self, bus: &mut B) -> Result<Faults, ServoError> {
        self.gates_off(bus)?;
        self.beat = self.beat.wrapping_add(1);
        Top(&mut *bus).heartbeat(self.beat)?;
        Adc(&mut *bus).set_enabled(true)?;
        // The configured trip level (`debug fault overcurrent` lowers it).
        let oc = self.cfg.oc_limit_counts().unwrap_or(2047);
        Fault(&mut *bus).set_oc_limit(oc)?;
        // The configured motion limits (`debug fault position-limit` or
        // `overspeed` moved them).
        if let Some((lo, hi, v)) = self.saved_limits.take() {
            let m = &mut self.cfg.motion;
            (m.pos_min, m.pos_max, m.vel_limit) = (lo, hi, v);
        }
        let left = Fault(&mut *bus).clear()?;
        self.ps_faults = 0;
        self.seen = left.0;
        self.note_skipped();
        Ok(left)
    }

    /// Makes the next control step latch `POSITION_LIMIT` (`speed` false:
    /// a soft limit moved to one count behind the present position) or
    /// `OVERSPEED` (`vel_limit` lowered to half the present speed over the
    /// trip margin: a rotor at rest does not trip), for `debug fault`;
    /// `fault clear` restores them. The checks run with the gates on only
    /// ([`ServoError::GatesOff`] otherwise, nothing changed).
    pub fn tighten_limit(&mut self, speed: bool) -> Result<(), ServoError> {
        if !self.gates {
            return Err(ServoError::GatesOff);
        }
        let st = self.motion.status();
        let m = self.cfg.motion;
        self.saved_limits
            .get_or_insert((m.pos_min, m.pos_max, m.vel_limit));
        let m = &mut self.cfg.motion;
        if speed {
            m.vel_limit = libm::fabs(st.velocity_rev_s) / (2.0 * motion::OVERSPEED_MARGIN);
        } else {
            let count = 1.0 / f64::from(self.cfg.enc_cpr.max(1));
            if st.position_rev - count >= m.pos_min {
                m.pos_max = st.position_rev - count;
            } else {
                m.pos_min = st.position_rev + count;
            }
        }
        Ok(())
    }

    /// The fault history, oldest first.
    pub fn fault_history(&self) -> &FaultHistory {
        &self.history
    }

    /// The one-period checks' verdict of the last step (their margins).
    pub fn fast_verdict(&self) -> FastVerdict {
        self.fast_last
    }

    /// Drive time: control periods run and missed, s.
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The control steps were skipped for a while (`debug stall`): the
    /// period-to-period checks start afresh.
    pub fn note_skipped(&mut self) {
        self.last_adc_count = None;
        self.adc_stale = 0;
        self.last_pos = None;
        self.enc_dead.reset();
        self.phase_open.reset();
        self.fast.reset();
        self.ref_steady = 0;
        self.evidence_skip = EVIDENCE_SKIP;
    }

    /// The PL gave no control-period boundary for `periods` control periods
    /// (the MPDTC period and mode off are paced by the ADC's results): after
    /// [`ADC_STALE_STEPS`] of them with the gates on the ADC is stuck. With
    /// the gates off (mode off, a board without its ADC card) it is judged
    /// as the PL's own ADC result timer judges it: only once the drive runs.
    pub fn note_no_boundary<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        periods: u32,
    ) -> Result<(), BusError> {
        self.time_s += f64::from(periods) * self.control_period_s();
        if self.mode == Mode::Foc || !self.gates {
            return Ok(());
        }
        self.adc_stale += periods;
        if self.adc_stale >= ADC_STALE_STEPS {
            self.latch_ps(bus, Faults::ADC_STUCK)?;
        }
        Ok(())
    }

    /// Records the PL's newly latched faults between control steps: a
    /// period without a boundary (MPDTC and mode off are paced by the
    /// ADC's results, which a stuck ADC stops) has no step to see them.
    pub fn note_pl_faults<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), BusError> {
        let pl = Fault(&mut *bus).latched()?.0;
        if pl & !self.seen != 0 {
            self.record_new(pl | self.ps_faults);
        }
        Ok(())
    }

    /// Records the faults in `latched` not yet in the history.
    fn record_new(&mut self, latched: u32) {
        for bit in Faults(latched & !self.seen).bits() {
            self.history.push(FaultRecord {
                bit,
                time_s: self.time_s,
                snapshot: self.snapshot,
            });
        }
        self.seen = latched;
    }

    /// Latches PS-detected faults: recorded, gates off at once.
    fn latch_ps<B: RegisterBus>(&mut self, bus: &mut B, bits: u32) -> Result<(), BusError> {
        self.ps_faults |= bits;
        let pl = Fault(&mut *bus).latched()?.0;
        self.record_new(pl | self.ps_faults);
        self.gates_off(bus).map_err(|e| match e {
            ServoError::Bus(b) => b,
            _ => BusError::SlaveError,
        })
    }

    /// Steps without a new ADC result that latch `ADC_STUCK`: one where a
    /// control period holds two averaged results or more (FOC) and the step
    /// before was served at most a period less one result period after its
    /// boundary (its count read then leaves at least one result to this
    /// one), else [`ADC_STALE_STEPS`].
    pub fn adc_stale_limit(&self) -> u32 {
        let p = 2 * self.cfg.foc_half_period_cycles;
        let r = (4 * self.cfg.adc_period_cycles).max(1);
        let on_time = self.prev_step_age.is_some_and(|a| a.saturating_add(r) <= p);
        if self.mode == Mode::Foc && p >= 2 * r && on_time {
            1
        } else {
            ADC_STALE_STEPS
        }
    }

    /// The PL cycles from its boundary to the present step's interrupt
    /// (`BOUNDARY_AGE`), before [`Self::control_step`].
    pub fn note_step_age(&mut self, cycles: u32) {
        self.step_age = Some(cycles);
    }

    /// The PS's checks of one control period: no new ADC result, an
    /// impossible encoder jump, control periods missed. Returns the faults
    /// they found.
    fn ps_checks(&mut self, adc_count: u32, pos: u32, cpr: u32) -> u32 {
        let mut f = 0;
        // A stuck ADC is judged while the drive runs, as the PL's own ADC
        // result timer judges it: with the gates off there is nothing to
        // protect, and a board without its ADC card in FOC would latch
        // ADC_STUCK again after every `fault clear`, before the sensor
        // check of `enable` could name it.
        if self.last_adc_count == Some(adc_count) && self.gates {
            self.adc_stale += 1;
        } else {
            self.adc_stale = 0;
        }
        self.last_adc_count = Some(adc_count);
        if self.adc_stale >= self.adc_stale_limit() {
            f |= Faults::ADC_STUCK;
        }
        self.prev_step_age = self.step_age.take();
        // The shortest way round from the last position: more than an
        // eighth of a turn in one control period (> 30000 rpm at 16 kHz)
        // is no motor's motion.
        if let Some(last) = self.last_pos {
            let cpr = cpr.max(1);
            let d = (pos + cpr - last % cpr) % cpr;
            if d.min(cpr - d) > cpr / 8 {
                f |= Faults::ENCODER_LOSS;
            }
        }
        self.last_pos = Some(pos);
        if self.missed >= OVERRUN_PERIODS {
            f |= Faults::CONTROL_OVERRUN;
        }
        self.missed = 0;
        f
    }

    /// Arms a step to `nm` recorded over `window_s` (at most
    /// [`STEP_SAMPLES_MAX`] control periods); it starts at the first control
    /// step where the controller is running (after the MPDTC alignment).
    pub fn begin_step<B: RegisterBus>(
        &mut self,
        bus: &mut B,
        nm: f64,
        window_s: f64,
    ) -> Result<(), ServoError> {
        let nm = self.check_torque(nm)?;
        let from_nm = if self.motion.kind() == LoopKind::Torque {
            self.torque_ref_nm
        } else {
            0.0
        };
        // Both finite (checked above and when set).
        if libm::fabs(nm - from_nm) < self.cfg.step_min_nm {
            return Err(ServoError::StepTooSmall {
                from_nm,
                to_nm: nm,
                min_nm: self.cfg.step_min_nm,
            });
        }
        if !(self.gates && self.gates_on(bus)?) {
            return Err(ServoError::GatesOff);
        }
        let n = libm::ceil(window_s / self.control_period_s()) as usize;
        self.motion.to_torque();
        self.torque_ref_nm = from_nm;
        self.rec.start_from(from_nm);
        self.rec.arm(nm, n.clamp(1, STEP_SAMPLES_MAX));
        Ok(())
    }

    /// The step's metrics once its window is full.
    pub fn step_result(&self) -> Option<StepResult> {
        self.rec.result(self.control_period_s())
    }

    /// The step's recording once its window is full. The metrics take
    /// longer than a control period on the PS: the console computes them
    /// from a copy, outside the control loop's critical section.
    pub fn step_recording(&self) -> Option<&StepRecorder> {
        self.rec.done().then_some(&self.rec)
    }

    /// Whether an armed step is still waiting or recording.
    pub fn step_pending(&self) -> bool {
        self.rec.pending()
    }

    /// Notes `n` control periods that passed without a control step.
    pub fn note_overruns(&mut self, n: u64) {
        self.overruns += n;
        self.missed += n;
        self.time_s += n as f64 * self.control_period_s();
    }

    /// One control period: heartbeat, measurement, then the active
    /// controller. Called at every control-period boundary.
    pub fn control_step<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), BusError> {
        if self.mode == Mode::Foc && self.gates && !self.adc_synced {
            // First thing after a PWM period start: restart the ADC timer so
            // that its samples take the fixed phase the FOC's measurement
            // lag assumes (the PL has no ADC trigger from the PWM counter).
            Adc(&mut *bus).restart()?;
            self.adc_synced = true;
        }
        // The step's start after the boundary: the interrupt handler's
        // reading, else read here (a step that is not the interrupt's).
        let start_age = match self.step_age {
            Some(a) => a,
            None => BoundaryAge::read(&mut *bus)?.bits(),
        };
        self.beat = self.beat.wrapping_add(1);
        Top(&mut *bus).heartbeat(self.beat)?;
        self.periods += 1;
        // The result count first: a late step can run past the next
        // boundary, and a count read after it would make the step that
        // serves that boundary see no new result.
        let (adc_count, i_abc) = Adc(&mut *bus).count_and_currents_a(&self.cfg.adc)?;
        // The period's currents belong to its voltage only if one period's
        // results came since the last step's read.
        let results_regular = self.last_adc_count.is_none_or(|l| {
            let result = 4 * self.cfg.adc_period_cycles;
            let period = match self.mode {
                Mode::Foc => 2 * self.cfg.foc_half_period_cycles,
                _ => result,
            };
            evidence::results_regular(adc_count.wrapping_sub(l), period, result)
        });
        // The autonomous loop: the PL computes the core's inputs itself.
        let auto = self.mode == Mode::Mpdtc && !self.cfg.mpdtc_ps_fed;
        // The position of the boundary's instant, as the currents: a live
        // read would move with how long the step took to get here.
        let enc = Encoder(&mut *bus).read_sampled()?;
        let pp = self.cfg.motor.pole_pairs;
        let gates = self.gates && Pwm(&mut *bus).gates_enabled()?;
        // The reference this period ran with: the snapshot keeps it, not the
        // 0 N m a fault's gates-off sets below.
        let torque_ref_nm = self.torque_ref_nm;
        if self.gates && !gates {
            // A fault turned the gates off: the drive follows.
            self.gates_off(bus).map_err(|e| match e {
                ServoError::Bus(b) => b,
                _ => BusError::SlaveError,
            })?;
        }
        let mut running = gates;
        let zero = match self.mode {
            Mode::Mpdtc => {
                if self.align_zero.is_none() && gates {
                    let mut m = Mpdtc(&mut *bus);
                    let action = match &mut self.align {
                        Some(a) => a.next(enc.pos, enc.cpr),
                        None => AlignAction::Hold,
                    };
                    match action {
                        AlignAction::SecondStep => m.set_align_vec(ALIGN_D)?,
                        // INITIAL ends at the next PL cycle and latches the
                        // encoder: the rotor has been still for the settle
                        // time.
                        AlignAction::End => {
                            m.set_align_time(1)?;
                            self.align_time_cut = true;
                        }
                        AlignAction::Hold => {}
                    }
                    if m.seq_status()?.aligned {
                        self.align_zero = Some(m.align_pos()?);
                        if core::mem::take(&mut self.move_capture_pending) {
                            Self::start_move_capture(&mut *bus)?;
                        }
                        if core::mem::take(&mut self.align_time_cut) {
                            Mpdtc(&mut *bus).set_align_time(self.cfg.align_cycles)?;
                        }
                    }
                }
                running &= self.align_zero.is_some();
                self.align_zero.unwrap_or(self.cfg.enc_zero)
            }
            _ => self.cfg.enc_zero,
        };
        let m = Measurement {
            i_abc_a: i_abc,
            theta_e_rad: enc.theta_e_rad(pp, zero),
            omega_e_rad_s: enc.omega_e_rad_s(pp),
        };
        // The measurement for status, `step` and the capture: from the ADC
        // averages on the PS in both MPDTC paths (the front end's own
        // i_d, i_q are ready 9 cycles after the boundary, after this read).
        let (al, be) = clarke(i_abc);
        let (i_d, i_q) = park(al, be, m.theta_e_rad);
        self.measured = Measured {
            i_d_a: i_d,
            i_q_a: i_q,
            torque_nm: self.cfg.motor.torque_nm(i_d, i_q),
            omega_e_rad_s: m.omega_e_rad_s,
        };
        self.time_s += self.control_period_s();
        self.snapshot.push(Sample {
            measured: self.measured,
            torque_ref_nm,
        });
        // The torque the last period asked for (0 with the gates off).
        let t_last = if gates { self.torque_ref_nm } else { 0.0 };
        let j = self.cfg.motion.load_inertia_kg_m2;
        self.motion
            .measure(enc.pos, self.control_period_s(), t_last, j);
        let mut ps = self.ps_checks(adc_count, enc.pos, enc.cpr);
        if gates {
            let (pos, speed) = self.motion.limits_violated(&self.cfg.motion);
            if pos {
                ps |= Faults::POSITION_LIMIT;
            }
            if speed {
                ps |= Faults::OVERSPEED;
            }
        }
        // The checks of `evidence` last: a fault already found latches
        // without waiting for their arithmetic.
        if gates && running && !results_regular {
            // A period left out or taken from the next: the one-period
            // checks and the window start afresh, and judge again once the
            // voltage applied is again that of the steps seen (as after a
            // start).
            self.enc_dead.reset();
            self.fast.reset();
            self.evidence_skip = EVIDENCE_SKIP;
        }
        if gates && running && ps & !self.ps_faults == 0 {
            ps |= self.evidence_checks(enc.pos, i_abc, &m, torque_ref_nm);
        } else if !(gates && running) {
            self.enc_dead.reset();
            self.phase_open.reset();
            self.fast.reset();
            self.ref_steady = 0;
            self.evidence_skip = EVIDENCE_SKIP;
        }
        let pl = Fault(&mut *bus).latched()?.0;
        if ps & !self.ps_faults != 0 {
            self.latch_ps(bus, ps)?;
            running = false;
        } else if pl & !self.seen != 0 {
            self.record_new(pl | self.ps_faults);
        } else {
            // Cleared by hand or by the PL: forget them.
            self.seen &= pl | self.ps_faults;
        }
        if running {
            let (lim, dt) = (self.cfg.torque_limit_nm, self.control_period_s());
            if let Some(t) = self.motion.step(&self.cfg.motion, lim, dt) {
                self.torque_ref_nm = t;
            }
            if let Some(r) = self
                .rec
                .on_period(self.measured.torque_nm, self.transitions)
            {
                self.torque_ref_nm = r;
            }
            if let Some(sine) = &mut self.sine {
                self.torque_ref_nm = sine.next_nm();
            }
        }
        match (self.mode, running) {
            (Mode::Foc, true) => self.foc_step(bus, &m)?,
            (Mode::Mpdtc, true) if auto => self.mpdtc_auto_step(bus)?,
            (Mode::Mpdtc, true) => self.mpdtc_step(bus, &m)?,
            _ => {}
        }
        // The capture channels of this period (after the controller, so
        // that the MPDTC core's inputs go out first).
        let me = self.measured;
        Capture(&mut *bus).write_channels(me.i_d_a, me.i_q_a, me.torque_nm, self.torque_ref_nm)?;
        let ms = self.motion.status();
        Capture(&mut *bus).write_motion(ms.counts, ms.velocity_rev_s, ms.following_error_counts)?;
        // The last count the PS sees in this period: a dead encoder's
        // still count is judged from here (a cause after this step may
        // follow an edge since the boundary's sample).
        self.pos_at_end = None;
        if gates && running {
            let l = Encoder(&mut *bus).live_pos_aged()?;
            if l.age >= start_age {
                self.pos_at_end = Some(l);
            } else {
                // The age restarted: the step ran past the next boundary
                // (it started late), and any of its reads may have found
                // the next period's sample, which the next step then finds
                // again, a still count of a moving rotor. The one-period
                // checks start afresh there.
                self.fast.reset();
            }
        }
        Ok(())
    }

    /// The checks over a window ([`evidence`]) of one period with the
    /// controller running: the voltage applied while `i_abc` was measured
    /// (FOC: the duties of two steps ago, loaded at the period start before
    /// last; MPDTC: the switching state of the last step's boundary).
    fn evidence_checks(&mut self, pos: u32, i_abc: [f64; 3], m: &Measurement, t_ref: f64) -> u32 {
        let theta_e = m.theta_e_rad;
        let mo = self.cfg.motor;
        let ts = self.control_period_s();
        let win = evidence::window_periods(ts);
        let u = match self.mode {
            Mode::Foc => models::pmsm::frames::leg_voltage_alpha_beta(self.duties_old, mo.u_dc_v),
            _ => models::pmsm::frames::switch_state_alpha_beta(self.last_state, mo.u_dc_v),
        };
        // The fast tier first: one period's evidence.
        let (model, age, allow) = match self.mode {
            Mode::Foc => (&self.foc_model, FOC_VOLTAGE_AGE, evidence::FOC_ALLOWANCE),
            _ => (
                &self.mpdtc,
                self.mpdtc.params.meas_age_periods,
                evidence::MPDTC_ALLOWANCE,
            ),
        };
        let now = evidence::Period {
            pos,
            i_abc,
            theta_e_rad: theta_e,
            omega_e_rad_s: m.omega_e_rad_s,
            u_ab: u,
        };
        // The first steps of a run carry the start's voltage: no verdict.
        let skip = self.evidence_skip > 0;
        // The still interval from the end of the last step's read: the
        // share of the period after it (its age is at least the count's).
        let period_cycles = ts * f64::from(regmap::PL_CLOCK_HZ);
        let since = self.pos_at_end.map(|l| evidence::Since {
            pos: l.pos,
            share: (1.0 - f64::from(l.age) / period_cycles).clamp(0.0, 1.0),
        });
        let v = self
            .fast
            .step(model, now, since, age, self.cfg.enc_cpr, allow);
        if libm::fabs(t_ref - self.ref_last) <= REF_STEADY_NM {
            self.ref_steady = self.ref_steady.saturating_add(1);
        } else {
            self.ref_steady = 0;
        }
        self.ref_last = t_ref;
        self.fast_last = if skip { FastVerdict::default() } else { v };
        if skip {
            self.evidence_skip -= 1;
            return 0;
        }
        if v.open.is_some() {
            return Faults::PHASE_OPEN;
        }
        if v.dead && self.ref_steady >= REF_STEADY_STEPS {
            return Faults::ENCODER_DEAD;
        }
        // Voltage without any current is an open circuit, not back-EMF.
        let flowing = i_abc.iter().any(|&x| libm::fabs(x) > evidence::ZERO_MAX_A);
        if !flowing {
            self.enc_dead.reset();
        }
        // The reference current: i_d = 0, i_q from the torque (L_d = L_q
        // or not, the reluctance term is 0 at i_d = 0).
        let kt = 1.5 * f64::from(mo.pole_pairs) * mo.psi_pm_wb;
        let (ra, rb) = models::pmsm::frames::inv_park(0.0, t_ref / kt, theta_e);
        let i_ref = models::pmsm::frames::inv_clarke(ra, rb);
        // The MPDTC controls the torque only: its d-axis current is free,
        // so the reference above (i_d = 0) does not say which phase must
        // carry current, and a healthy phase can stay at zero for a
        // window while the d-axis current makes the vector turn with the
        // rotor (a 1 rev move on ten times the inertia: phase b at -0.04 A
        // for 0.5 ms against -1.32 A of reference, i_d -1.4 A). In MPDTC
        // the one-period check, against the model's prediction from the
        // voltage applied, judges an open phase alone.
        let open = self.phase_open.step(i_ref, i_abc, win).is_some() && self.mode == Mode::Foc;
        // A period where a phase looks open voids the voltage equation.
        let suspect = self.phase_open.suspect();
        let dead = flowing
            && self.enc_dead.step(
                pos,
                u,
                clarke(i_abc),
                suspect,
                mo.r_s_ohm,
                mo.l_d_h,
                ts,
                win,
            );
        if open {
            Faults::PHASE_OPEN
        } else if dead {
            Faults::ENCODER_DEAD
        } else {
            0
        }
    }

    fn foc_step<B: RegisterBus>(&mut self, bus: &mut B, m: &Measurement) -> Result<(), BusError> {
        let half = self.cfg.foc_half_period_cycles;
        self.duties_old = self.duties;
        if let Actuation::DutyAbc(d) = self.foc.step(m, self.torque_ref_nm) {
            self.duties = d;
            Pwm(&mut *bus).set_duties(d, half)?;
            // Centre-aligned PWM: a leg strictly between 0 and 100 % makes
            // two transitions per period.
            for (t, x) in self.transitions.iter_mut().zip(d) {
                let c = duty_cycles(x, half);
                if c > 0 && c < half {
                    *t += 2;
                }
            }
        }
        Ok(())
    }

    /// Counts the gate transitions of the decision applied at this boundary:
    /// the gate driver's state (`GATE_STATUS`) in the autonomous loop, whose
    /// next decision may already be in `MPDTC_STATUS` 21 cycles after the
    /// boundary; the last decision on the PS-fed path (the core waits for
    /// `MPDTC_START`).
    fn note_decision<B: RegisterBus>(&mut self, bus: &mut B, auto: bool) -> Result<(), BusError> {
        let s = if auto {
            Pwm(&mut *bus).gate_status()?.2
        } else {
            Mpdtc(&mut *bus).last_decision()?
        };
        if s != self.last_state {
            for (leg, t) in self.transitions.iter_mut().enumerate() {
                *t += u64::from((s ^ self.last_state) >> (2 - leg) & 1);
            }
            self.last_state = s;
        }
        Ok(())
    }

    /// The autonomous loop's period: the torque reference is the only write
    /// (the PL's front end takes it with the next averaged sample).
    fn mpdtc_auto_step<B: RegisterBus>(&mut self, bus: &mut B) -> Result<(), BusError> {
        self.note_decision(bus, true)?;
        Mpdtc(&mut *bus).write_torque_ref(torque_ref_word(self.torque_ref_nm))
    }

    fn mpdtc_step<B: RegisterBus>(&mut self, bus: &mut B, m: &Measurement) -> Result<(), BusError> {
        self.note_decision(bus, false)?;
        let mut core = Mpdtc(&mut *bus);
        let seq = core.seq_status()?;
        if seq.state != seq_state::SAMPLE {
            return Ok(());
        }
        let ts = self.mpdtc.params.control_period_s;
        let inp = inputs_from_measurement(
            m,
            self.torque_ref_nm,
            self.mpdtc.params.meas_age_periods,
            ts,
        );
        core.write_inputs(&fixed_inputs(&inp, ts))?;
        core.start(self.beat)
    }
}

/// Age of the FOC's averaged measurement at the PWM period start, s, with
/// the ADC timer restarted [`ADC_RESTART_CYCLES`] (`r`) after a period
/// start `B`: conversions at `B + r + j P_adc`; the newest before the next
/// start `B + P_pwm` is `P_pwm - r - j_max P_adc` old, and the mean of the
/// last 4 is 1.5 ADC periods older. Paper timing: 387 + 586.5 cycles = 9.7 us.
fn foc_measurement_lag_s(cfg: &ServoConfig) -> f64 {
    let pwm = 2 * cfg.foc_half_period_cycles;
    let adc = cfg.adc_period_cycles.max(1);
    let j_max = pwm.saturating_sub(ADC_RESTART_CYCLES + 1) / adc;
    let newest = pwm.saturating_sub(ADC_RESTART_CYCLES + j_max * adc);
    (f64::from(newest) + 1.5 * f64::from(adc)) / f64::from(regmap::PL_CLOCK_HZ)
}

/// FOC: the share of the period before's voltage in the change of current
/// between two steps' measurements, periods. Measured on the simulated PL
/// (`cargo test -p simpl --test host evidence::`): after a current step from zero
/// the measured current was 0.69 of the one-period prediction with the
/// last period's duties alone, 0.82 with the measurement's lag (0.156
/// periods), 1.00 with 0.31.
const FOC_VOLTAGE_AGE: f64 = 0.31;

/// PL cycles from the PWM period start to the ADC timer restart: the
/// boundary is reported one cycle after it, and the two `ADC_CTRL` writes
/// take one cycle each.
pub const ADC_RESTART_CYCLES: u32 = 4;

/// Seconds of `cycles` PL clock cycles.
fn period_s(cycles: u32) -> f64 {
    f64::from(cycles) / f64::from(regmap::PL_CLOCK_HZ)
}

#[cfg(test)]
mod fault_tests;
#[cfg(test)]
mod tests;
