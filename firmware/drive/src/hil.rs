//! Paper 001's hardware-in-the-loop arrangement (Sec. VII): the induction
//! machine and 5L-ANPC plant ([`models::mpdcc::closed_loop`], exact model) runs on
//! the processor and feeds the MPDCC core on its register page
//! ([`crate::pl::mpdcc`]) each `T_s`; the core's decision switches the
//! plant. One warm-up fundamental period, then `periods` measured ones
//! (f_sw and THD over those, as the host experiments).
//!
//! Two ways to run it: [`run`] (`mpdcc run`) takes its decisions as fast as
//! the page answers, through a caller's function; [`Paced`] (`mode mpdcc`)
//! takes one per control period of the drive and runs until stopped. Both
//! work on the simulated PL, the co-simulated RTL or a bitstream; their
//! decisions must be the FPGA model's ([`models::mpdcc::mpdcc_fixed::MpdccFixed`]) one for
//! one.
use crate::pl::mpdcc::{Mpdcc, MpdccError, PageDecision};
use models::mpdcc::closed_loop::{self, LoopConfig, LoopError, Stepper};
use models::mpdcc::controller::{Controller, CtrlState, Decision, DecisionKind, StateError};
use models::mpdcc::mpdcc_fixed::{FpgaConfig, FpgaError, Inputs, MpdccFixed};
use models::mpdcc::params::DriveParams;
use regmap::bus::RegisterBus;

/// Most measured periods of one run.
pub const MAX_PERIODS: u32 = 20;

/// What a run measured.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HilReport {
    /// Measured fundamental periods (after one warm-up period).
    pub periods: u32,
    /// Decisions, warm-up included (one per `T_s`).
    pub decisions: u64,
    /// Kept, optimal, deadlock decisions (warm-up included).
    pub kinds: [u64; 3],
    /// Mean core cycles per decision (`MPDCC_CYCLES`), PL clock cycles.
    pub mean_cycles: f64,
    /// Largest core cycle count, PL clock cycles.
    pub worst_cycles: u32,
    /// Average switching frequency per semiconductor, Hz (measured periods).
    pub fsw_hz: f64,
    /// Stator current THD, percent (measured periods).
    pub thd_percent: f64,
    /// Largest `|i* - i|` of any phase, pu (measured periods).
    pub max_i_err_pu: f64,
}

/// Why a run stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HilError {
    /// `periods` outside `1..=MAX_PERIODS`.
    Periods,
    /// The default drive's core could not be built.
    Core(FpgaError),
    /// The register page failed.
    Page(MpdccError),
    /// The loop stopped (plant diverged, inadmissible position).
    Loop(LoopError),
}

/// The default drive and its frozen core (the constants the page gets).
pub fn default_core() -> Result<(DriveParams, MpdccFixed), HilError> {
    let p = DriveParams::default();
    let f = MpdccFixed::new(&p, FpgaConfig::core(&p.machine)).map_err(HilError::Core)?;
    Ok((p, f))
}

/// The page as the loop's controller.
struct Page<'a> {
    decide: &'a mut dyn FnMut(&Inputs) -> Result<PageDecision, MpdccError>,
    err: Option<MpdccError>,
    r: HilReport,
    sum_cycles: u64,
}

impl Controller for Page<'_> {
    fn name(&self) -> &'static str {
        "page"
    }
    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let x = Inputs::quantize(st)?;
        match (self.decide)(&x) {
            Ok(d) => {
                self.r.decisions += 1;
                self.r.kinds[kind_index(d.decision.kind)] += 1;
                self.sum_cycles += u64::from(d.cycles);
                self.r.worst_cycles = self.r.worst_cycles.max(d.cycles);
                Ok(d.decision)
            }
            Err(e) => {
                // The loop only knows state errors: remember the real one.
                self.err = Some(e);
                Err(StateError::BadPosition)
            }
        }
    }
}

/// Runs the default drive for one warm-up and `periods` measured
/// fundamental periods with `decide` (constants already on the page).
pub fn run(
    p: &DriveParams,
    periods: u32,
    decide: &mut dyn FnMut(&Inputs) -> Result<PageDecision, MpdccError>,
) -> Result<HilReport, HilError> {
    if !(1..=MAX_PERIODS).contains(&periods) {
        return Err(HilError::Periods);
    }
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: periods,
    };
    let mut page = Page {
        decide,
        err: None,
        r: HilReport {
            periods,
            ..HilReport::default()
        },
        sum_cycles: 0,
    };
    let res = closed_loop::run(p, &cfg, &mut page, None, &mut |_| {});
    if let Some(e) = page.err {
        return Err(HilError::Page(e));
    }
    let l = res.map_err(HilError::Loop)?;
    let mut r = page.r;
    r.mean_cycles = page.sum_cycles as f64 / r.decisions.max(1) as f64;
    r.fsw_hz = l.fsw_hz;
    r.thd_percent = l.thd_percent;
    r.max_i_err_pu = l.max_i_err_pu;
    Ok(r)
}

/// Control boundaries in a row at which a started decision may still be
/// running before the paced loop stops with a timeout (the core needs at
/// most 281 PL cycles at N = 1, a control period is 1,564).
pub const MAX_LATE_IN_A_ROW: u32 = 64;

/// What the paced loop has done (`status` in `mode mpdcc`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PacedStatus {
    /// Decisions, kinds, cycles since the mode started; `periods` counts
    /// the measured fundamental periods, `fsw_hz`, `thd_percent` and
    /// `max_i_err_pu` are the last one's (0 before the first).
    pub report: HilReport,
    /// Control boundaries at which the running decision was not done yet
    /// (the plant waited a boundary for it).
    pub late: u64,
    /// Plant time simulated, s (one `T_s` per decision).
    pub plant_time_s: f64,
    /// Why the loop stopped, if it did.
    pub stopped: Option<HilError>,
}

/// The HIL loop paced by the drive's control periods (`mode mpdcc`): at
/// each boundary the decision started at the last one is read, applied to
/// the plant for one `T_s`, and the next state starts the next decision.
/// The plant's time and the core's decisions are those of [`run`] (one
/// warm-up period, then one measured window per fundamental period); only
/// the wall-clock pacing differs.
pub struct Paced {
    stepper: Stepper,
    /// Steps per fundamental period: the warm-up and each window.
    period: u64,
    started: bool,
    late_in_a_row: u32,
    sum_cycles: u64,
    st: PacedStatus,
}

impl Paced {
    /// The default drive's plant at its steady state; the page must hold
    /// the core's constants ([`default_core`]).
    pub fn new(p: &DriveParams) -> Result<Self, HilError> {
        let stepper = Stepper::new(p).map_err(HilError::Loop)?;
        Ok(Self {
            period: stepper.steps_in(1).max(1),
            stepper,
            started: false,
            late_in_a_row: 0,
            sum_cycles: 0,
            st: PacedStatus::default(),
        })
    }

    /// Progress so far.
    pub fn status(&self) -> PacedStatus {
        self.st
    }

    /// One control boundary. After an error the loop stays stopped (the
    /// error is in [`Paced::status`]) and touches the page no more.
    pub fn tick<B: RegisterBus>(&mut self, m: &mut Mpdcc<B>) -> Result<(), HilError> {
        if let Some(e) = self.st.stopped {
            return Err(e);
        }
        let r = self.advance(m);
        if let Err(e) = r {
            self.st.stopped = Some(e);
        }
        r
    }

    fn advance<B: RegisterBus>(&mut self, m: &mut Mpdcc<B>) -> Result<(), HilError> {
        if self.started {
            let s = m.status().map_err(HilError::Page)?;
            if s.busy || !s.done {
                self.st.late += 1;
                self.late_in_a_row += 1;
                if self.late_in_a_row >= MAX_LATE_IN_A_ROW {
                    return Err(HilError::Page(MpdccError::Timeout));
                }
                return Ok(());
            }
            self.late_in_a_row = 0;
            let d = m.read_decision().map_err(HilError::Page)?;
            let r = &mut self.st.report;
            r.decisions += 1;
            r.kinds[kind_index(d.decision.kind)] += 1;
            self.sum_cycles += u64::from(d.cycles);
            r.worst_cycles = r.worst_cycles.max(d.cycles);
            r.mean_cycles = self.sum_cycles as f64 / r.decisions as f64;
            if !self.stepper.measuring() && self.stepper.step() >= self.period {
                self.stepper.measure(self.period);
            }
            let closed = self
                .stepper
                .apply(&d.decision, None)
                .map_err(HilError::Loop)?;
            self.st.plant_time_s = self.stepper.step() as f64 * self.stepper.ts_s();
            if let Some(w) = closed {
                r.periods += 1;
                r.fsw_hz = w.fsw_hz;
                r.thd_percent = w.thd_percent;
                r.max_i_err_pu = w.max_i_err_pu;
            }
        }
        let x = Inputs::quantize(&self.stepper.state())
            .map_err(|e| HilError::Loop(LoopError::State(e)))?;
        m.write_inputs(&x).map_err(HilError::Page)?;
        m.start().map_err(HilError::Page)?;
        self.started = true;
        Ok(())
    }
}

fn kind_index(k: DecisionKind) -> usize {
    match k {
        DecisionKind::Kept => 0,
        DecisionKind::Optimal => 1,
        DecisionKind::Deadlock => 2,
    }
}
