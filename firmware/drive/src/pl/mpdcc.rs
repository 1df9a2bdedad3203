//! MPDCC block: the constants and per-period state of `mpdcc_core` (the
//! words of `models::mpdcc::mpdcc_fixed::Coeffs` and `Inputs`), start, status and
//! the decision. Formats: docs/mpdcc-fpga.md; the page: docs/register-map.md.
//!
//! A decision is `write_inputs`, `start`, then `wait` (polls `MPDCC_STATUS`
//! until `BUSY = 0` and `DONE = 1`) and the result registers. `START`
//! snapshots the page, so the next inputs may be written while a decision
//! runs.
use models::mpdcc::controller::{Decision, DecisionKind};
use models::mpdcc::mpdcc_fixed::{Coeffs, Inputs};
use regmap::bus::{BusError, RegisterBus};
use regmap::mpdcc_kind;
use regmap::regs::mpdcc::*;

/// Why a driver call failed; nothing was started by a call that failed
/// before its `START`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MpdccError {
    /// The register access failed.
    Bus(BusError),
    /// No decision came within the allowed status polls.
    Timeout,
    /// A value does not fit the page (the name says which).
    Format(&'static str),
    /// The constants are not for the core in the PL (`MPDCC_CONFIG`).
    Config(&'static str),
}

impl From<BusError> for MpdccError {
    fn from(e: BusError) -> Self {
        Self::Bus(e)
    }
}

impl core::fmt::Display for MpdccError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Bus(e) => write!(f, "bus error {e:?}"),
            Self::Timeout => write!(f, "no MPDCC decision in time"),
            Self::Format(w) => write!(f, "{w} out of the register format"),
            Self::Config(w) => write!(f, "{w} differs from the core's build (MPDCC_CONFIG)"),
        }
    }
}

/// `MPDCC_CONFIG` decoded: what the core was built with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CoreConfig {
    /// Explorer units instantiated.
    pub explorers: u32,
    /// `lambda = log2 L`.
    pub lambda: u32,
    /// `M = log2 N_bar`.
    pub m_bits: u32,
    /// Interpolation nodes.
    pub nodes: u32,
}

/// `MPDCC_STATUS` decoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Status {
    /// A decision runs.
    pub busy: bool,
    /// The result registers hold the decision of the last START.
    pub done: bool,
    /// Decisions completed (wraps at 65536).
    pub count: u32,
}

/// One decision as the page reports it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PageDecision {
    /// Position, kind, `L*` and candidate count.
    pub decision: Decision,
    /// `J` of the chosen candidate, UQ15.17 (kept: 0).
    pub cost: u32,
    /// `J_dl` of the chosen candidate, Q2.13 pu (kept: 0).
    pub j_dl: i32,
    /// PL clock cycles of the core, start to done strobe.
    pub cycles: u32,
}

/// Writes each listed word (two's complement, 16 bits).
macro_rules! write_words {
    ($bus:expr, $(($reg:ident, $val:ident, $v:expr)),+ $(,)?) => {
        $( $reg::write($bus, $val::ZERO.with_value(u32::from($v as u16)))?; )+
    };
}

/// The MPDCC block.
pub struct Mpdcc<B>(pub B);

impl<B: RegisterBus> Mpdcc<B> {
    /// The core's build constants.
    pub fn config(&mut self) -> Result<CoreConfig, MpdccError> {
        let v = MpdccConfig::read(&mut self.0)?;
        Ok(CoreConfig {
            explorers: v.explorers(),
            lambda: v.lambda(),
            m_bits: v.m_bits(),
            nodes: v.nodes(),
        })
    }

    /// Writes every constant register from `k`; refuses (writing nothing)
    /// constants of another structure or build than the core's, or a
    /// negative bound.
    pub fn load_coeffs(&mut self, k: &Coeffs) -> Result<(), MpdccError> {
        let c = self.config()?;
        if !k.is_core_structure() {
            return Err(MpdccError::Config("structure"));
        }
        if k.lambda != c.lambda {
            return Err(MpdccError::Config("lambda"));
        }
        if k.m_bits != c.m_bits {
            return Err(MpdccError::Config("m_bits"));
        }
        if k.nodes != c.nodes {
            return Err(MpdccError::Config("nodes"));
        }
        if k.bnd.iter().any(|&b| b < 0) {
            return Err(MpdccError::Format("bnd"));
        }
        let bus = &mut self.0;
        write_words!(
            bus,
            (MpdccCTau, MpdccCTauValue, k.c_tau),
            (MpdccCR, MpdccCRValue, k.c_r),
            (MpdccCW, MpdccCWValue, k.c_w),
            (MpdccCP, MpdccCPValue, k.c_p),
            (MpdccCS, MpdccCSValue, k.c_s),
            (MpdccC3, MpdccC3Value, k.c_3),
            (MpdccCD, MpdccCDValue, k.c_d),
            (MpdccCN, MpdccCNValue, k.c_n),
            (MpdccCPh, MpdccCPhValue, k.c_ph),
            (MpdccS3h, MpdccS3hValue, k.s3h),
            (MpdccVPhRef, MpdccVPhRefValue, k.v_ph_ref),
            (MpdccCTau1, MpdccCTau1Value, k.c_tau1),
            (MpdccCR1, MpdccCR1Value, k.c_r1),
            (MpdccCW1, MpdccCW1Value, k.c_w1),
            (MpdccCS1, MpdccCS1Value, k.c_s1),
            (MpdccVdcHalf, MpdccVdcHalfValue, k.v_dc_half),
            (MpdccG3, MpdccG3Value, k.g3),
            (MpdccGd, MpdccGdValue, k.gd),
            (MpdccG31, MpdccG31Value, k.g3_1),
            (MpdccBndIa, MpdccBndIaValue, k.bnd[0]),
            (MpdccBndIb, MpdccBndIbValue, k.bnd[1]),
            (MpdccBndIc, MpdccBndIcValue, k.bnd[2]),
            (MpdccBndVn, MpdccBndVnValue, k.bnd[3]),
            (MpdccBndVpa, MpdccBndVpaValue, k.bnd[4]),
            (MpdccBndVpb, MpdccBndVpbValue, k.bnd[5]),
            (MpdccBndVpc, MpdccBndVpcValue, k.bnd[6]),
            (MpdccLambdaN, MpdccLambdaNValue, k.lambda_n),
        );
        Ok(())
    }

    /// Explorers the next decisions use (1..=6; the core takes at most its
    /// own count).
    pub fn set_explorers(&mut self, n: u32) -> Result<(), MpdccError> {
        if !(1..=6).contains(&n) {
            return Err(MpdccError::Format("explorers"));
        }
        MpdccNUse::write(&mut self.0, MpdccNUseValue::ZERO.with_value(n))?;
        Ok(())
    }

    /// Writes the period's state registers; refuses (writing nothing) a
    /// switch position above 7.
    pub fn write_inputs(&mut self, x: &Inputs) -> Result<(), MpdccError> {
        if x.s_prev.iter().any(|&p| p > 7) {
            return Err(MpdccError::Format("s_prev"));
        }
        let bus = &mut self.0;
        MpdccSPrev::write(
            bus,
            MpdccSPrevValue::ZERO
                .with_a(u32::from(x.s_prev[0]))
                .with_b(u32::from(x.s_prev[1]))
                .with_c(u32::from(x.s_prev[2])),
        )?;
        write_words!(
            bus,
            (MpdccIA, MpdccIAValue, x.i_ab[0]),
            (MpdccIB, MpdccIBValue, x.i_ab[1]),
            (MpdccPsiA, MpdccPsiAValue, x.psi_ab[0]),
            (MpdccPsiB, MpdccPsiBValue, x.psi_ab[1]),
            (MpdccVN, MpdccVNValue, x.v_n),
            (MpdccVPhA, MpdccVPhAValue, x.v_ph[0]),
            (MpdccVPhB, MpdccVPhBValue, x.v_ph[1]),
            (MpdccVPhC, MpdccVPhCValue, x.v_ph[2]),
            (MpdccIrefA, MpdccIrefAValue, x.i_ref_ab[0]),
            (MpdccIrefB, MpdccIrefBValue, x.i_ref_ab[1]),
            (MpdccOmegaR, MpdccOmegaRValue, x.omega_r),
            (MpdccOmegaS, MpdccOmegaSValue, x.omega_s),
        );
        Ok(())
    }

    /// `MPDCC_START` (ignored by the PL while a decision runs).
    pub fn start(&mut self) -> Result<(), MpdccError> {
        MpdccStart::write(&mut self.0, MpdccStartValue::ZERO.with_value(true))?;
        Ok(())
    }

    /// `MPDCC_STATUS`.
    pub fn status(&mut self) -> Result<Status, MpdccError> {
        let v = MpdccStatus::read(&mut self.0)?;
        Ok(Status {
            busy: v.busy(),
            done: v.done(),
            count: v.count(),
        })
    }

    /// Polls `MPDCC_STATUS` at most `max_polls` times for the end of the
    /// decision, then reads it; returns it and the polls used.
    pub fn wait(&mut self, max_polls: u32) -> Result<(PageDecision, u32), MpdccError> {
        for n in 1..=max_polls {
            let s = self.status()?;
            if !s.busy && s.done {
                return Ok((self.read_decision()?, n));
            }
        }
        Err(MpdccError::Timeout)
    }

    /// The result registers.
    pub fn read_decision(&mut self) -> Result<PageDecision, MpdccError> {
        let d = MpdccDecision::read(&mut self.0)?;
        let kind = match d.kind() {
            mpdcc_kind::KEPT => DecisionKind::Kept,
            mpdcc_kind::OPTIMAL => DecisionKind::Optimal,
            mpdcc_kind::DEADLOCK => DecisionKind::Deadlock,
            _ => return Err(MpdccError::Format("kind")),
        };
        let cyc = MpdccCycles::read(&mut self.0)?;
        Ok(PageDecision {
            decision: Decision {
                s: [d.s_a() as u8, d.s_b() as u8, d.s_c() as u8],
                kind,
                horizon_steps: d.l_star(),
                candidates: cyc.candidates(),
            },
            cost: MpdccCost::read(&mut self.0)?.value(),
            j_dl: MpdccJDl::read(&mut self.0)?.value() as i32,
            cycles: cyc.cycles(),
        })
    }

    /// Deadlock decisions since reset (wraps at 65536).
    pub fn deadlocks(&mut self) -> Result<u32, MpdccError> {
        Ok(MpdccDeadlocks::read(&mut self.0)?.value())
    }

    /// One decision: inputs, START, wait.
    pub fn decide(&mut self, x: &Inputs, max_polls: u32) -> Result<PageDecision, MpdccError> {
        self.write_inputs(x)?;
        self.start()?;
        Ok(self.wait(max_polls)?.0)
    }
}
