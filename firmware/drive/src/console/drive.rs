//! The drive commands' side of the console: what the firmware provides
//! ([`DriveOps`]) and how replies and errors are written.
use super::{write_err, ErrorCode};
use crate::config::store::SlotState;
use crate::hil::{HilReport, PacedStatus};
use crate::pl::capture::{CapSample, CapStatus, Trigger};
use crate::pl::fault::Faults;
use crate::pl::top::Mode;
use crate::servo::faults::FaultRecord;
use crate::servo::motion::{MotionError, MotionStatus, MoveResult};
use crate::servo::{Measured, ServoConfig, ServoError, StepResult, SweepPoint};
use core::fmt::{self, Write};
use models::motion::law::Impedance;
use models::pmsm::sim_motor::{SimMotor, SimSetError};

/// What is behind the drivers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlKind {
    /// No bitstream: the simulated PL and motor.
    Simulated,
    /// Our bitstream; `VERSION` (major << 16 | minor).
    Bitstream(u32),
    /// A PL the firmware must not drive (foreign or incompatible design).
    Absent,
    /// No bitstream, QEMU with the co-simulation bridge: the Verilated
    /// `pl_top` and the simulated motor in a host process.
    RtlCosim,
}

/// What `status` and the boot banner print after `pl: `.
impl fmt::Display for PlKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlKind::Simulated => f.write_str("simulated"),
            PlKind::Bitstream(v) => {
                let v = regmap::regs::top::VersionValue::from_bits(*v);
                write!(f, "bitstream v{}.{}", v.major(), v.minor())
            }
            PlKind::Absent => f.write_str("absent"),
            PlKind::RtlCosim => f.write_str("rtl co-simulation"),
        }
    }
}

impl PlKind {
    /// The kind for what presence detection selected; `cosim`: the
    /// simulated PL is the co-simulated RTL.
    pub fn of(sel: crate::pl::presence::Selection, cosim: bool) -> Self {
        use crate::pl::presence::Selection;
        match sel {
            Selection::Bitstream { version } => PlKind::Bitstream(version),
            Selection::Simulated if cosim => PlKind::RtlCosim,
            Selection::Simulated => PlKind::Simulated,
            Selection::Absent(_) => PlKind::Absent,
        }
    }
}

/// What the configuration store in flash held at boot and since.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StoreStatus {
    /// Each slot's record.
    pub slots: [SlotState; 2],
    /// The slot the running configuration came from (at boot or the last
    /// `config save`); `None`: the defaults.
    pub loaded: Option<usize>,
}

/// Live drive values for `status`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriveStatus {
    /// Active mode.
    pub mode: Mode,
    /// MPDTC input path: the PL's front end (`true`) or the PS (`false`).
    pub mpdtc_autonomous: bool,
    /// `GATE_EN` read back.
    pub gates_on: bool,
    /// Latched faults.
    pub faults: Faults,
    /// Last control step's measurement.
    pub measured: Measured,
    /// Torque reference, N m.
    pub torque_ref_nm: f64,
    /// Control periods per second, Hz.
    pub control_rate_hz: f64,
    /// Control periods run.
    pub periods: u64,
    /// Control periods missed.
    pub overruns: u64,
    /// Control interrupts (GIC SPI 61) taken.
    pub control_irq: u64,
    /// The control step's start latency after the boundary.
    pub control_latency: crate::pl::irq::Latency,
    /// What drives the registers.
    pub pl: PlKind,
    /// Guest time / simulated time (simulated PL only).
    pub sim_time_scale: Option<f64>,
    /// The configuration store (`None`: no flash access here).
    pub store: Option<StoreStatus>,
    /// `mode mpdcc`: the paced HIL loop's progress (`None` in other modes).
    pub mpdcc: Option<PacedStatus>,
    /// Position, velocity and the outer loop.
    pub motion: MotionStatus,
    /// The MPDTC's rotor alignment runs: the longest it can still take, s
    /// (position, velocity and impedance commands wait for its end).
    pub aligning_left_s: Option<f64>,
}

impl DriveStatus {
    /// `status` without a usable PL: nothing driven, `pl: absent`.
    pub fn absent(mpdcc: Option<PacedStatus>) -> Self {
        Self {
            mode: Mode::Off,
            mpdtc_autonomous: true,
            gates_on: false,
            faults: Faults::default(),
            measured: Default::default(),
            torque_ref_nm: 0.0,
            control_rate_hz: 0.0,
            periods: 0,
            overruns: 0,
            control_irq: 0,
            control_latency: Default::default(),
            pl: PlKind::Absent,
            sim_time_scale: None,
            store: None,
            mpdcc,
            motion: Default::default(),
            aligning_left_s: None,
        }
    }
}

/// Guest instructions of the control code, measured by `debug bench`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bench {
    /// One FOC step (`models::pmsm::foc`), instructions.
    pub foc_step: u32,
    /// One MPDTC-mode control period on the PS (measurement, inputs, START), instructions.
    pub mpdtc_period: u32,
    /// One boundary of `mode mpdcc`'s HIL loop on the PS (decision, plant
    /// step from the transition-matrix cache, inputs, START), instructions.
    pub mpdcc_boundary: u32,
    /// A transition matrix the plant's cache misses (9 x 9 matrix
    /// exponential), instructions.
    pub mpdcc_expm: u32,
    /// One `defmt` frame of a console line's size encoded into the log's
    /// RAM ring: the logger's interrupts-off window, instructions.
    pub log_frame: u32,
    /// Repetitions each figure is the minimum of.
    pub runs: u32,
}

/// What `debug mmu` reads back from the CPU.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MmuReport {
    /// SCTLR.
    pub sctlr: u32,
    /// PL310 `CACHE_ID` (0: no PL310, as under QEMU 7.2).
    pub l2_id: u32,
    /// PL310 `CTRL` (bit 0: L2 on).
    pub l2_ctrl: u32,
    /// TTBR0.
    pub ttbr0: u32,
    /// For each of [`crate::mmu::USED`]: the table entry and the MMU's
    /// translation of the address (PAR, bit 0 set: fault).
    pub regions: [(u32, u32); crate::mmu::USED.len()],
}

impl MmuReport {
    /// MMU, L1 caches and branch prediction on, and the L2 on where there
    /// is one.
    pub fn caches_on(&self) -> bool {
        self.sctlr & crate::mmu::SCTLR_ON == crate::mmu::SCTLR_ON
            && (self.l2_id == 0 || self.l2_ctrl & 1 != 0)
    }
}

/// A fault `debug fault` makes happen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Injection {
    /// The external fault input asserted for 10 us (simulated PL only).
    External,
    /// The ADC stopped (`ADC_CTRL.ENABLE` = 0; `fault clear` restarts it).
    AdcStuck,
    /// Two control periods pass without a control step (simulated PL only).
    Overrun,
    /// Current channels a and b swapped in the simulated PL's ADC path
    /// (until reboot).
    AdcSwap,
    /// Current channel a inverted in the simulated PL's ADC path (until
    /// reboot).
    AdcInvert,
    /// `OC_LIMIT` set to 0 counts: the next raw sample with current trips
    /// (`fault clear` restores the limit).
    Overcurrent,
    /// The heartbeat stops for 3 ms (`WDG_TIMEOUT` is 2 ms).
    Watchdog,
    /// The encoder's lines freeze (`sim set enc_dead 1`).
    EncoderDead,
    /// Phase b disconnected (`sim set phase_open 2`).
    PhaseOpen,
    /// A soft limit moved to one count behind the present position
    /// (`fault clear` restores it).
    PositionLimit,
    /// `vel_limit` lowered below the present speed (`fault clear`
    /// restores it).
    Overspeed,
    /// The encoder's A and B lines change in the same instant, an illegal
    /// quadrature step (`sim set enc_invert 1`; `sim reset` ends it).
    EncoderLoss,
}

/// Control periods `debug fault` waits, with the gates on, for a
/// [`Injection::prompt_fault`] to latch: the PL latches either at its next
/// raw ADC sample or pin sample, well inside one period.
pub const LATCH_WAIT_PERIODS: u32 = 4;

impl Injection {
    /// The fault the PL latches within a period of this injection with the
    /// gates on (current flows, the pin is sampled), so that `debug fault`
    /// waits for it and reports it; `None` for the injections whose fault
    /// comes later or not at all.
    pub fn prompt_fault(self) -> Option<u32> {
        match self {
            Injection::Overcurrent => Some(Faults::OVERCURRENT),
            Injection::External => Some(Faults::EXTERNAL),
            _ => None,
        }
    }

    /// From the console word.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "external" => Some(Injection::External),
            "adc-stuck" => Some(Injection::AdcStuck),
            "overrun" => Some(Injection::Overrun),
            "adc-swap" => Some(Injection::AdcSwap),
            "adc-invert" => Some(Injection::AdcInvert),
            "overcurrent" => Some(Injection::Overcurrent),
            "watchdog" => Some(Injection::Watchdog),
            "encoder-dead" => Some(Injection::EncoderDead),
            "phase-open" => Some(Injection::PhaseOpen),
            "position-limit" => Some(Injection::PositionLimit),
            "overspeed" => Some(Injection::Overspeed),
            "encoder-loss" => Some(Injection::EncoderLoss),
            _ => None,
        }
    }
}

/// Why a drive command failed (nothing changed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DriveError {
    /// Refused by the drive.
    Servo(ServoError),
    /// No usable PL.
    Absent,
    /// A step did not complete in time.
    Timeout,
    /// Not available in this build or setup.
    Unsupported,
    /// The configuration flash did not answer as expected.
    Flash,
    /// Refused in `mode mpdcc` (the HIL loop uses the MPDCC page, the PMSM
    /// gates stay off).
    MpdccMode,
    /// `debug fault`: the fault (bits) did not latch within
    /// [`LATCH_WAIT_PERIODS`] control periods.
    NotLatched(u32),
    /// A command that moves the motor while a CANopen master owns it
    /// (NMT operational, CiA 402 operation enabled or quick stop active).
    CanopenOwns,
}

impl From<ServoError> for DriveError {
    fn from(e: ServoError) -> Self {
        DriveError::Servo(e)
    }
}

/// The drive as the console sees it; the firmware implements it over the
/// `Servo` it shares with the control interrupt.
pub trait DriveOps {
    /// Active mode.
    fn mode(&mut self) -> Mode;
    /// Sets the mode (gates off first).
    fn set_mode(&mut self, m: Mode) -> Result<(), DriveError>;
    /// Gates on.
    fn enable(&mut self) -> Result<(), DriveError>;
    /// Gates off.
    fn disable(&mut self) -> Result<(), DriveError>;
    /// Torque reference, N m.
    fn torque_ref(&mut self) -> f64;
    /// Sets the torque reference, N m (checked against the limit).
    fn set_torque_ref(&mut self, nm: f64) -> Result<(), DriveError>;
    /// Runs a step to `nm` and records it for `window_s`; blocks until done.
    fn step(&mut self, nm: f64, window_s: f64) -> Result<StepResult, DriveError>;
    /// Latched faults.
    fn faults(&mut self) -> Result<Faults, DriveError>;
    /// Clears the faults; returns what is still latched.
    fn clear_faults(&mut self) -> Result<Faults, DriveError>;
    /// Stops the control loop and heartbeat for `ms` milliseconds.
    fn stall(&mut self, ms: u32) -> Result<(), DriveError>;
    /// Live values.
    fn status(&mut self) -> DriveStatus;
    /// Counts the control code's guest instructions.
    fn bench(&mut self) -> Result<Bench, DriveError>;
    /// The `k`-th fault of the history (oldest first) and the number of
    /// faults recorded since boot.
    fn fault_record(&mut self, _k: usize) -> Result<(Option<FaultRecord>, u32), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Makes a fault happen (`debug fault`), to test the drive's reaction.
    /// With the gates on, an injection with a [`Injection::prompt_fault`]
    /// returns once that fault has latched, with the latched faults
    /// (`Some`), or [`DriveError::NotLatched`]; otherwise `None` at once.
    fn inject(&mut self, _f: Injection) -> Result<Option<Faults>, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// The last injection's cause and the gates-off instant, PL cycles
    /// (`debug fault-time`): (cause, gates off since, `None` while on).
    fn fault_time(&mut self) -> Result<(u64, Option<u64>), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Holds each flash erase and program of later saves `ms` longer
    /// (`debug flash-pace`; 0 ends it).
    fn flash_pace(&mut self, _ms: u32) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Saves the running configuration to flash; returns the slot.
    fn save_config(&mut self) -> Result<usize, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// The drive's configuration.
    fn config(&mut self) -> Result<ServoConfig, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Replaces the configuration (`Servo::reconfigure`).
    fn reconfigure(&mut self, _cfg: &ServoConfig) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Arms the capture buffer with `pre` samples before the trigger and
    /// one sample every `every` control periods.
    fn capture_arm(&mut self, _t: Trigger, _pre: u32, _every: u32) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Manual capture trigger.
    fn capture_trigger(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Capture state.
    fn capture_status(&mut self) -> Result<CapStatus, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Sample `i` of the record.
    fn capture_sample(&mut self, _i: u32) -> Result<CapSample, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Time between capture samples in the active mode, s.
    fn capture_period_s(&mut self) -> f64 {
        0.0
    }
    /// One frequency of `sweep`: the sine reference at `f_hz` (kept
    /// running), a capture of it, gain and phase.
    fn sweep_point(&mut self, _f_hz: f64, _amp_nm: f64) -> Result<SweepPoint, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Ends a sweep: the sine stops, the reference returns to 0 N m.
    fn sweep_end(&mut self) {}
    /// `mpdcc run`: paper 001's hardware-in-the-loop run on the PL's MPDCC
    /// page ([`crate::hil`]), one warm-up and `periods` measured
    /// fundamental periods.
    fn mpdcc_run(&mut self, _periods: u32) -> Result<HilReport, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// The last `mpdcc run`'s report.
    fn mpdcc_report(&mut self) -> Option<HilReport> {
        None
    }
    /// `mode mpdcc`: the PMSM gates off and the PL in mode off, then the
    /// HIL loop paced by the control periods ([`crate::hil::Paced`]).
    fn set_mpdcc_mode(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// The paced HIL loop's progress while `mode mpdcc` is active.
    fn mpdcc_live(&mut self) -> Option<PacedStatus> {
        None
    }
    /// Runs the sensor check (`selftest sensors`; gates off, no fault).
    fn sensor_check(&mut self) -> Result<crate::servo::sensors::SensorReport, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Runs a calibration of `phases` with the configuration's limits
    /// (gates off, no fault); `on_phase` prints the progress. Ctrl-C stops
    /// it (the firmware watches the console for it).
    fn calibrate(
        &mut self,
        _phases: models::calibration::Phases,
        _on_phase: &mut dyn FnMut(Option<models::calibration::Phase>),
    ) -> Result<crate::servo::calibrate::CalReport, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Whether the next `enable` runs the sensor check (`status`); `None`
    /// where there is no drive.
    fn sensor_check_due(&mut self) -> Option<bool> {
        None
    }
    /// MMU and cache state (`debug mmu`).
    fn mmu(&mut self) -> Result<MmuReport, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Reads an address the translation table leaves unmapped: a data
    /// abort on purpose (`debug abort`); returns only where unsupported.
    fn provoke_abort(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// The GP0 guard's words (`status`), if the firmware reads them.
    fn gp0_guard(&mut self) -> Option<crate::pl::presence::Guard> {
        None
    }
    /// The CANopen device's state (`status`), if the firmware has one.
    fn canopen(&mut self) -> Option<crate::fieldbus::LinkStatus> {
        None
    }
    /// The telemetry stream's owner, if the build has one.
    fn telemetry(&mut self) -> Option<&mut dyn super::TelOps> {
        None
    }
    /// The simulated motor's parameters (simulated PL only).
    fn sim_motor(&mut self) -> Result<SimMotor, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Sets one of them: the inner error when the value is refused.
    fn sim_set(&mut self, _name: &str, _v: f64) -> Result<Result<(), SimSetError>, DriveError> {
        Err(DriveError::Unsupported)
    }
    /// Their defaults.
    fn sim_reset(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// `vel`.
    fn set_velocity(&mut self, _v: f64) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// `pos <rev>`.
    fn set_position(&mut self, _p: f64) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// `pos zero`.
    fn zero_position(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// `imp`.
    fn set_impedance(&mut self, _c: &Impedance) -> Result<(), DriveError> {
        Err(DriveError::Unsupported)
    }
    /// `move`: blocks until the window after the trajectory is over.
    fn run_move(&mut self, _distance_rev: f64, _window_s: f64) -> Result<MoveResult, DriveError> {
        Err(DriveError::Unsupported)
    }
}

/// Writes the final `ERR` line of a failed drive command.
pub fn write_error<W: Write>(out: &mut W, cmd: &str, e: DriveError) -> fmt::Result {
    match e {
        DriveError::Servo(ServoError::ModeOff) => write_err(
            out,
            ErrorCode::ModeOff,
            format_args!("{cmd}: mode is off (set `mode foc` or `mode mpdtc` first)"),
        ),
        DriveError::Servo(ServoError::FaultLatched(f)) => {
            write!(
                out,
                "ERR {} {cmd}: fault latched: ",
                ErrorCode::FaultLatched.as_str()
            )?;
            f.write_names(out)?;
            out.write_str(" (`fault clear` first)\r\n")
        }
        DriveError::Servo(ServoError::GatesOff) => write_err(
            out,
            ErrorCode::GatesOff,
            format_args!("{cmd}: gates are off (`enable` first)"),
        ),
        DriveError::Servo(ServoError::TorqueOutOfRange(x)) => write_err(
            out,
            ErrorCode::BadArgs,
            format_args!("{cmd}: {x} Nm is beyond the torque limit"),
        ),
        DriveError::Servo(ServoError::StepTooSmall {
            from_nm,
            to_nm,
            min_nm,
        }) => write_err(
            out,
            ErrorCode::BadArgs,
            format_args!(
                "{cmd}: the reference is already {from_nm:.4} Nm; a step to {to_nm:.4} Nm \
                 is smaller than {min_nm:.4} Nm and has no settling time"
            ),
        ),
        DriveError::Servo(ServoError::GatesOn) => write_err(
            out,
            ErrorCode::GatesOn,
            format_args!("{cmd}: needs the gates off (`disable` first)"),
        ),
        DriveError::Servo(ServoError::BadConfig(e)) => {
            write_err(out, ErrorCode::BadArgs, format_args!("{cmd}: {e}"))
        }
        DriveError::Servo(ServoError::BadFrequency(f)) => write_err(
            out,
            ErrorCode::BadArgs,
            format_args!(
                "{cmd}: {f} Hz is outside (0, control rate / 4] or below one period per \
                 capture record"
            ),
        ),
        DriveError::Servo(ServoError::SensorCheck(f)) => write_err(
            out,
            ErrorCode::SensorCheck,
            format_args!("{cmd}: {f}; gates off"),
        ),
        // A state of the drive, not the arguments: retry once it changed.
        DriveError::Servo(ServoError::Motion(e @ MotionError::Holding)) => {
            write_err(out, ErrorCode::Holding, format_args!("{cmd}: {e}"))
        }
        DriveError::Servo(ServoError::Motion(e)) => {
            write_err(out, ErrorCode::BadArgs, format_args!("{cmd}: {e}"))
        }
        DriveError::Servo(ServoError::Aligning(left_s)) => write_err(
            out,
            ErrorCode::Aligning,
            format_args!(
                "{cmd}: the MPDTC's rotor alignment still turns the rotor (at most {:.0} ms \
                 left, less once it is still); nothing changed, retry after it",
                libm::ceil(left_s * 1e3)
            ),
        ),
        DriveError::Servo(ServoError::RotorTurning(v)) => write_err(
            out,
            ErrorCode::RotorTurning,
            format_args!(
                "{cmd}: the rotor turns at {v:.2} rev/s (at most {} rev/s to start): \
                 stop it first (`enable`, `vel 0`, then `disable`); nothing changed",
                crate::servo::CAL_REST_REV_S
            ),
        ),
        DriveError::Servo(ServoError::Bus(b)) => write_err(
            out,
            ErrorCode::BusError,
            format_args!("{cmd}: PL register access failed ({b:?})"),
        ),
        DriveError::Absent => write_err(
            out,
            ErrorCode::PlAbsent,
            format_args!(
                "{cmd}: no usable PL: nothing is driven without our bitstream \
                 (boot a BOOT.BIN with it, see docs/board.md; `status` shows devcfg)"
            ),
        ),
        DriveError::NotLatched(bits) => {
            write!(out, "ERR {} {cmd}: ", ErrorCode::Timeout.as_str())?;
            Faults(bits).write_names(out)?;
            write!(
                out,
                " did not latch within {LATCH_WAIT_PERIODS} control periods of the \
                 injection (gates still on)\r\n"
            )
        }
        DriveError::Timeout => write_err(
            out,
            ErrorCode::Timeout,
            format_args!("{cmd}: the control loop did not complete it in time"),
        ),
        DriveError::Unsupported => write_err(
            out,
            ErrorCode::Unsupported,
            format_args!("{cmd}: not available here"),
        ),
        DriveError::Flash => write_err(
            out,
            ErrorCode::FlashError,
            format_args!("{cmd}: the configuration flash failed (nothing loaded or changed)"),
        ),
        DriveError::CanopenOwns => write_err(
            out,
            ErrorCode::CanopenOwns,
            format_args!(
                "{cmd}: a CANopen master commands the motor (NMT operational, CiA 402 operation \
                 enabled); `status`, `tel`, `capture`, `config get` and `disable` still work"
            ),
        ),
        DriveError::MpdccMode => write_err(
            out,
            ErrorCode::MpdccMode,
            format_args!(
                "{cmd}: refused in mode mpdcc (its HIL loop uses the MPDCC page, the PMSM \
                 gates stay off; `mode off`, `mode foc` or `mode mpdtc` first)"
            ),
        ),
    }
}
