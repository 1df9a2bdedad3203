//! MPDTC block: the core's parameters, the per-period inputs the PS
//! computes (Park transform, angles: the PL has no Park transform yet), the
//! core status and the control sequence (`mpdtc_seq`).
//!
//! Signed values are written as two's complement masked to the register
//! width, as the register map says (formats in docs/mpdtc-fixed.md).
use crate::bus::{BusError, RegisterBus};
use crate::pmsm::mpdtc_fixed::{FixedInputs, FixedParams};
use crate::regs::mpdtc::*;

/// Writes signed `v` to each listed register, two's complement masked to
/// the register's width (its `with_value_i32`).
macro_rules! write_signed {
    ($bus:expr, $(($reg:ident, $val:ident, $v:expr)),+ $(,)?) => {
        $( $reg::write($bus, $val::ZERO.with_value_i32($v))?; )+
    };
}

/// `MPDTC_SEQ_STATUS` decoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SeqStatus {
    /// `regmap::seq_state` value.
    pub state: u32,
    /// SAMPLE holds this period's averaged sample.
    pub sampled: bool,
    /// The alignment of this run finished (`MPDTC_ALIGN_POS` valid).
    pub aligned: bool,
    /// Boundaries that found no decision ready (wraps at 256).
    pub overruns: u32,
    /// Periods completed (wraps at 65536).
    pub periods: u32,
}

impl SeqStatus {
    /// Decodes the register value.
    pub fn from_reg(v: u32) -> Self {
        let s = MpdtcSeqStatusValue::from_bits(v);
        Self {
            state: s.state(),
            sampled: s.sampled(),
            aligned: s.aligned(),
            overruns: s.overruns(),
            periods: s.periods(),
        }
    }
}

/// The MPDTC block.
pub struct Mpdtc<B>(pub B);

impl<B: RegisterBus> Mpdtc<B> {
    /// Writes every `MPDTC_P_*` register.
    pub fn load_params(&mut self, p: &FixedParams) -> Result<(), BusError> {
        let bus = &mut self.0;
        write_signed!(
            bus,
            (MpdtcPA, MpdtcPAValue, p.a),
            (MpdtcPLambda, MpdtcPLambdaValue, p.lambda),
            (MpdtcPU0, MpdtcPU0Value, p.u0),
            (MpdtcPU0Half, MpdtcPU0HalfValue, p.u0_half),
            (MpdtcPU0H, MpdtcPU0HValue, p.u0_h),
            (MpdtcPPsiL, MpdtcPPsiLValue, p.psi_l),
            (MpdtcPKinvT, MpdtcPKinvTValue, p.kinv_t),
            (MpdtcPKInt, MpdtcPKIntValue, p.k_int),
            (MpdtcPKpO, MpdtcPKpOValue, p.kp_o),
            (MpdtcPKiO, MpdtcPKiOValue, p.ki_o),
            (MpdtcPW20, MpdtcPW20Value, p.w2[0]),
            (MpdtcPW21, MpdtcPW21Value, p.w2[1]),
            (MpdtcPW22, MpdtcPW22Value, p.w2[2]),
            (MpdtcPW23, MpdtcPW23Value, p.w2[3]),
        );
        // Non-negative formats: the low bits of the word, as the signed ones.
        MpdtcPTol::write(bus, MpdtcPTolValue::ZERO.with_value(p.tol as u32))?;
        MpdtcPIntLim::write(bus, MpdtcPIntLimValue::ZERO.with_value(p.int_lim as u32))?;
        MpdtcPEtaLim::write(bus, MpdtcPEtaLimValue::ZERO.with_value(p.eta_lim as u32))?;
        MpdtcPIntCond::write(bus, MpdtcPIntCondValue::ZERO.with_value(p.int_conditional))
    }
    /// Writes the period's `MPDTC_IN_*` registers.
    pub fn write_inputs(&mut self, f: &FixedInputs) -> Result<(), BusError> {
        let bus = &mut self.0;
        write_signed!(
            bus,
            (MpdtcInId, MpdtcInIdValue, f.i_dq.0),
            (MpdtcInIq, MpdtcInIqValue, f.i_dq.1),
            (MpdtcInCos0, MpdtcInCos0Value, f.trig[0].0),
            (MpdtcInSin0, MpdtcInSin0Value, f.trig[0].1),
            (MpdtcInCos1, MpdtcInCos1Value, f.trig[1].0),
            (MpdtcInSin1, MpdtcInSin1Value, f.trig[1].1),
            (MpdtcInCos2, MpdtcInCos2Value, f.trig[2].0),
            (MpdtcInSin2, MpdtcInSin2Value, f.trig[2].1),
            (MpdtcInWTs, MpdtcInWTsValue, f.w_ts),
            (MpdtcInTRef, MpdtcInTRefValue, f.t_ref),
        );
        Ok(())
    }
    /// `MPDTC_START`: in SAMPLE, "this period's inputs are written".
    pub fn start(&mut self, tag: u32) -> Result<(), BusError> {
        MpdtcStart::write(&mut self.0, MpdtcStartValue::ZERO.with_value(tag))
    }
    /// `MPDTC_CTRL`: `manual` (gates follow `SW_STATE`) and `state_clr`
    /// (core state held at zero).
    pub fn set_ctrl(&mut self, manual: bool, state_clr: bool) -> Result<(), BusError> {
        MpdtcCtrl::write(
            &mut self.0,
            MpdtcCtrlValue::ZERO
                .with_manual(manual)
                .with_state_clr(state_clr),
        )
    }
    /// Duration of the rotor alignment, PL clock cycles.
    pub fn set_align_time(&mut self, cycles: u32) -> Result<(), BusError> {
        MpdtcAlignTime::write(&mut self.0, MpdtcAlignTimeValue::ZERO.with_value(cycles))
    }
    /// Encoder position latched at the end of the alignment.
    pub fn align_pos(&mut self) -> Result<u32, BusError> {
        Ok(MpdtcAlignPos::read(&mut self.0)?.value())
    }
    /// The control sequence's status.
    pub fn seq_status(&mut self) -> Result<SeqStatus, BusError> {
        Ok(SeqStatus::from_reg(
            MpdtcSeqStatus::read(&mut self.0)?.bits(),
        ))
    }
    /// `S[k+1]` of the last decision (bits SaSbSc).
    pub fn last_decision(&mut self) -> Result<u8, BusError> {
        Ok(MpdtcStatus::read(&mut self.0)?.s_next() as u8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use crate::regmap::{self, Register, MPDTC};

    #[test]
    fn negative_values_are_masked_two_complement() {
        let mut pl = FakePl::new();
        let f = FixedInputs {
            i_dq: (-1, 65536),
            trig: [(65536, 0), (0, -65536), (-1, 1)],
            w_ts: -2,
            t_ref: -16384,
        };
        Mpdtc(&mut pl).write_inputs(&f).unwrap();
        let g = |r: &Register| pl.get(MPDTC.addr(r));
        assert_eq!(g(&regmap::MPDTC_IN_ID), 0x1FF_FFFF);
        assert_eq!(g(&regmap::MPDTC_IN_IQ), 65536);
        assert_eq!(g(&regmap::MPDTC_IN_SIN1), 0x3_0000);
        assert_eq!(g(&regmap::MPDTC_IN_W_TS), 0x3_FFFE);
        assert_eq!(g(&regmap::MPDTC_IN_T_REF), 0x3_C000);
    }

    #[test]
    fn params_from_the_paper_configuration() {
        use crate::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
        use crate::pmsm::params::MotorParams;
        let cfg = MpdtcConfig::new(MotorParams::default(), MpdtcParams::default()).unwrap();
        let p = FixedParams::from_config(&cfg).unwrap();
        let mut pl = FakePl::new();
        Mpdtc(&mut pl).load_params(&p).unwrap();
        let g = |r: &Register| pl.get(MPDTC.addr(r));
        assert_eq!(g(&regmap::MPDTC_P_A), p.a as u32 & 0x3_FFFF);
        assert_eq!(g(&regmap::MPDTC_P_TOL), p.tol as u32);
        assert_eq!(g(&regmap::MPDTC_P_W2_3), p.w2[3] as u32 & 0x3_FFFF);
        assert_eq!(g(&regmap::MPDTC_P_INT_COND), u32::from(p.int_conditional));
    }

    #[test]
    fn sequence_status_fields() {
        let s = SeqStatus::from_reg(0x0102_031A);
        assert_eq!(
            s,
            SeqStatus {
                state: 2,
                sampled: true,
                aligned: true,
                overruns: 3,
                periods: 0x0102
            }
        );
        let mut pl = FakePl::new();
        Mpdtc(&mut pl).set_ctrl(false, false).unwrap();
        assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_CTRL)), 0);
    }
}
