//! MPDTC block: the core's parameters, the per-period inputs the PS
//! computes (Park transform, angles: the PL has no Park transform yet), the
//! core status and the control sequence (`mpdtc_seq`).
//!
//! Signed values are written as two's complement masked to the register
//! width, as the register map says (formats in docs/mpdtc-fixed.md).
use super::{rd, wr};
use crate::bus::{BusError, RegisterBus};
use crate::pmsm::mpdtc_fixed::{FixedInputs, FixedParams};
use crate::regmap::{self, Register, MPDTC};

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
        Self {
            state: v & 7,
            sampled: v & 8 != 0,
            aligned: v & 16 != 0,
            overruns: v >> 8 & 0xFF,
            periods: v >> 16,
        }
    }
}

/// The MPDTC block.
pub struct Mpdtc<B>(pub B);

impl<B: RegisterBus> Mpdtc<B> {
    fn w(&mut self, r: &Register, v: i32) -> Result<(), BusError> {
        wr(&mut self.0, &MPDTC, r, v as u32 & r.mask())
    }
    /// Writes every `MPDTC_P_*` register.
    pub fn load_params(&mut self, p: &FixedParams) -> Result<(), BusError> {
        use regmap::*;
        for (r, v) in [
            (&MPDTC_P_A, p.a),
            (&MPDTC_P_LAMBDA, p.lambda),
            (&MPDTC_P_U0, p.u0),
            (&MPDTC_P_U0_HALF, p.u0_half),
            (&MPDTC_P_U0_H, p.u0_h),
            (&MPDTC_P_PSI_L, p.psi_l),
            (&MPDTC_P_KINV_T, p.kinv_t),
            (&MPDTC_P_TOL, p.tol),
            (&MPDTC_P_K_INT, p.k_int),
            (&MPDTC_P_INT_LIM, p.int_lim),
            (&MPDTC_P_INT_COND, i32::from(p.int_conditional)),
            (&MPDTC_P_KP_O, p.kp_o),
            (&MPDTC_P_KI_O, p.ki_o),
            (&MPDTC_P_ETA_LIM, p.eta_lim),
            (&MPDTC_P_W2_0, p.w2[0]),
            (&MPDTC_P_W2_1, p.w2[1]),
            (&MPDTC_P_W2_2, p.w2[2]),
            (&MPDTC_P_W2_3, p.w2[3]),
        ] {
            self.w(r, v)?;
        }
        Ok(())
    }
    /// Writes the period's `MPDTC_IN_*` registers.
    pub fn write_inputs(&mut self, f: &FixedInputs) -> Result<(), BusError> {
        use regmap::*;
        for (r, v) in [
            (&MPDTC_IN_ID, f.i_dq.0),
            (&MPDTC_IN_IQ, f.i_dq.1),
            (&MPDTC_IN_COS0, f.trig[0].0),
            (&MPDTC_IN_SIN0, f.trig[0].1),
            (&MPDTC_IN_COS1, f.trig[1].0),
            (&MPDTC_IN_SIN1, f.trig[1].1),
            (&MPDTC_IN_COS2, f.trig[2].0),
            (&MPDTC_IN_SIN2, f.trig[2].1),
            (&MPDTC_IN_W_TS, f.w_ts),
            (&MPDTC_IN_T_REF, f.t_ref),
        ] {
            self.w(r, v)?;
        }
        Ok(())
    }
    /// `MPDTC_START`: in SAMPLE, "this period's inputs are written".
    pub fn start(&mut self, tag: u32) -> Result<(), BusError> {
        wr(&mut self.0, &MPDTC, &regmap::MPDTC_START, tag)
    }
    /// `MPDTC_CTRL`: `manual` (gates follow `SW_STATE`) and `state_clr`
    /// (core state held at zero).
    pub fn set_ctrl(&mut self, manual: bool, state_clr: bool) -> Result<(), BusError> {
        let v = u32::from(manual) | u32::from(state_clr) << 1;
        wr(&mut self.0, &MPDTC, &regmap::MPDTC_CTRL, v)
    }
    /// Duration of the rotor alignment, PL clock cycles.
    pub fn set_align_time(&mut self, cycles: u32) -> Result<(), BusError> {
        wr(&mut self.0, &MPDTC, &regmap::MPDTC_ALIGN_TIME, cycles)
    }
    /// Encoder position latched at the end of the alignment.
    pub fn align_pos(&mut self) -> Result<u32, BusError> {
        rd(&mut self.0, &MPDTC, &regmap::MPDTC_ALIGN_POS)
    }
    /// The control sequence's status.
    pub fn seq_status(&mut self) -> Result<SeqStatus, BusError> {
        Ok(SeqStatus::from_reg(rd(
            &mut self.0,
            &MPDTC,
            &regmap::MPDTC_SEQ_STATUS,
        )?))
    }
    /// `S[k+1]` of the last decision (bits SaSbSc).
    pub fn last_decision(&mut self) -> Result<u8, BusError> {
        Ok((rd(&mut self.0, &MPDTC, &regmap::MPDTC_STATUS)? >> 1 & 7) as u8)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;

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
