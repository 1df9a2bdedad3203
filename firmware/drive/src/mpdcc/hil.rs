//! Paper 001's hardware-in-the-loop arrangement (Sec. VII): the induction
//! machine and 5L-ANPC plant ([`super::closed_loop`], exact model) runs on
//! the processor and feeds the MPDCC core on its register page
//! ([`crate::pl::mpdcc`]) each `T_s`; the core's decision switches the
//! plant. One warm-up fundamental period, then `periods` measured ones
//! (f_sw and THD over those, as the host experiments).
//!
//! The page is reached through a caller's function, so the same run works
//! on the simulated PL, the co-simulated RTL or a bitstream; its decisions
//! must be the FPGA model's ([`super::fpga::FpgaMpdcc`]) one for one.
use super::closed_loop::{self, LoopConfig, LoopError};
use super::controller::{CtrlState, Decision, DecisionKind, MpdccController, StateError};
use super::fpga::{FpgaConfig, FpgaError, FpgaMpdcc, Inputs};
use super::params::DriveParams;
use crate::pl::mpdcc::{MpdccError, PageDecision};

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
pub fn default_core() -> Result<(DriveParams, FpgaMpdcc), HilError> {
    let p = DriveParams::default();
    let f = FpgaMpdcc::new(&p, FpgaConfig::core(&p.machine)).map_err(HilError::Core)?;
    Ok((p, f))
}

/// The page as the loop's controller.
struct Page<'a> {
    decide: &'a mut dyn FnMut(&Inputs) -> Result<PageDecision, MpdccError>,
    err: Option<MpdccError>,
    r: HilReport,
    sum_cycles: u64,
}

impl MpdccController for Page<'_> {
    fn name(&self) -> &'static str {
        "page"
    }
    fn decide(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let x = Inputs::quantize(st)?;
        match (self.decide)(&x) {
            Ok(d) => {
                self.r.decisions += 1;
                self.r.kinds[match d.decision.kind {
                    DecisionKind::Kept => 0,
                    DecisionKind::Optimal => 1,
                    DecisionKind::Deadlock => 2,
                }] += 1;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::{BusError, RegisterBus};
    use crate::mpdcc::closed_loop::LoopResult;
    use crate::pl::mpdcc::Mpdcc;
    use crate::simpl::pl::SimPl;

    struct Bus(SimPl);

    impl RegisterBus for Bus {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            self.0.read(addr).0
        }
        fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
            self.0.write(addr, value).0
        }
    }

    /// On the simulated PL the run is the FPGA-model loop: the same
    /// statistics (so the same decisions and trajectory), the cycle counts
    /// of the pipelined core (at most 173 at N = 2, 216 candidates).
    #[test]
    fn simulated_pl_run_is_the_model_loop() {
        let (p, f) = default_core().unwrap();
        let mut model = f.clone();
        let want: LoopResult = closed_loop::run(
            &p,
            &LoopConfig {
                warmup_periods: 1,
                measure_periods: 1,
            },
            &mut model,
            None,
            &mut |_| {},
        )
        .unwrap();
        let mut m = Mpdcc(Bus(SimPl::new(10)));
        m.load_coeffs(f.coeffs()).unwrap();
        let r = run(&p, 1, &mut |x| m.decide(x, 400)).unwrap();
        assert_eq!(r.fsw_hz, want.fsw_hz);
        assert_eq!(r.thd_percent, want.thd_percent);
        assert_eq!(r.max_i_err_pu, want.max_i_err_pu);
        assert_eq!(r.decisions, 2 * want.steps);
        assert!(r.kinds[1] > 10 && r.kinds[0] > 10, "{r:?}");
        // Common terms 20, 108 issue cycles at N = 2, explorer 41, arg-min
        // tree 3, the last fold 1.
        assert_eq!(r.worst_cycles, 20 + 108 + 41 + 3 + 1);
        assert!(r.mean_cycles > 59.0 && r.mean_cycles < 173.0, "{r:?}");
        assert_eq!(m.deadlocks().unwrap() as u64, r.kinds[2]);
    }

    #[test]
    fn bad_periods_and_page_errors_stop_the_run() {
        let (p, _) = default_core().unwrap();
        let mut never = |_: &Inputs| -> Result<PageDecision, MpdccError> { unreachable!() };
        assert_eq!(run(&p, 0, &mut never), Err(HilError::Periods));
        assert_eq!(run(&p, MAX_PERIODS + 1, &mut never), Err(HilError::Periods));
        let mut fail = |_: &Inputs| Err(MpdccError::Timeout);
        assert_eq!(
            run(&p, 1, &mut fail),
            Err(HilError::Page(MpdccError::Timeout))
        );
    }
}
