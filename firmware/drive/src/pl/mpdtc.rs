//! MPDTC block: the core's parameters, the per-period inputs the PS
//! computes on the PS-fed path (Park transform, angles), the front end's
//! registers for the autonomous loop (`MPDTC_CTRL.AUTO`: the PL computes the
//! inputs itself, the PS writes only the torque reference), the core status
//! and the control sequence (`mpdtc_seq`).
//!
//! Signed values are written as two's complement masked to the register
//! width, as the register map says (formats in docs/mpdtc-fixed.md).
use models::pmsm::frontend_fixed::FrontendParams;
use models::pmsm::mpdtc_fixed::{quantize_sat, FixedInputs, FixedParams, FRAC, TRQ_FRAC};
use models::validate::ParamError;
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::mpdtc::*;

/// What the front end's registers are computed from (the drive's facts).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrontendSetup {
    /// Motor pole pairs.
    pub pole_pairs: u32,
    /// `ENC_CPR`, counts per mechanical revolution.
    pub enc_cpr: u32,
    /// Control period (`ADC_PERIOD x 2^ADC_AVG_LOG2`), PL clock cycles.
    pub period_cycles: u32,
    /// `ENC_WINDOW`, PL clock cycles.
    pub window_cycles: u32,
    /// Age of the averaged measurement at the control instant, periods
    /// (the instants are this minus 1/2, plus 1/2, plus 3/2).
    pub meas_age_periods: f64,
    /// Current per ADC count, A (all three phases).
    pub amps_per_count: f64,
    /// ADC offsets, counts.
    pub adc_offset: [i32; 3],
}

fn param_err(field: &'static str, reason: &'static str) -> ParamError {
    ParamError { field, reason }
}

/// The `MPDTC_FE_*` register values of `s` (formats in
/// `models::pmsm::frontend_fixed`); errors for values outside the formats.
/// `cpr` and `align_pos` of the result are `ENC_CPR` and 0: the PL takes
/// them from `ENC_CPR` and its own alignment.
pub fn frontend_params(s: &FrontendSetup) -> Result<FrontendParams, ParamError> {
    if !(4..=65_535).contains(&s.enc_cpr) {
        return Err(param_err("enc_cpr", "must be in 4..=65535"));
    }
    if !(1..=64).contains(&s.pole_pairs) {
        return Err(param_err("pole_pairs", "must be in 1..=64"));
    }
    if s.period_cycles == 0 || s.window_cycles == 0 {
        return Err(param_err("period_cycles", "periods must be > 0"));
    }
    let pp = f64::from(s.pole_pairs);
    let cpr = f64::from(s.enc_cpr);
    let ang = libm::round(pp * 4_294_967_296.0 / cpr) as u64 as u32;
    let spd = libm::round(
        pp * f64::from(s.period_cycles) * 1_099_511_627_776.0 / (cpr * f64::from(s.window_cycles)),
    );
    if spd > f64::from(u32::MAX) {
        return Err(param_err(
            "period_cycles",
            "speed scale beyond 32 bits (period too long for the window)",
        ));
    }
    let lam = s.meas_age_periods;
    if !(lam.is_finite() && (0.0..=0.5).contains(&lam)) {
        return Err(param_err(
            "meas_age_periods",
            "must be in [0, 0.5] (age + 3/2 periods within COEF)",
        ));
    }
    let gain = s.amps_per_count * f64::from(1u32 << 20);
    if !(gain.is_finite() && libm::fabs(gain) < 131_071.5) {
        return Err(param_err(
            "amps_per_count",
            "must be within +-0.125 A per count (s18, 2^-20 A)",
        ));
    }
    if s.adc_offset.iter().any(|o| !(-32_768..=32_767).contains(o)) {
        return Err(param_err("adc_offset", "must fit 16 bits"));
    }
    let gain = libm::round(gain) as i32;
    Ok(FrontendParams {
        cpr: s.enc_cpr,
        align_pos: 0,
        ang_scale: ang,
        spd_scale: spd as u32,
        age: [lam - 0.5, lam + 0.5, lam + 1.5].map(|a| quantize_sat(a, FRAC, 18)),
        adc_off: s.adc_offset,
        adc_gain: [gain; 3],
    })
}

/// A torque reference in the core's format (TRQ sQ3.14), N m.
pub fn torque_ref_word(nm: f64) -> i32 {
    quantize_sat(nm, TRQ_FRAC, 18)
}

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
    /// Writes every `MPDTC_FE_*` register (the autonomous loop's front end).
    pub fn load_frontend(&mut self, p: &FrontendParams) -> Result<(), BusError> {
        let bus = &mut self.0;
        MpdtcFeAngScale::write(bus, MpdtcFeAngScaleValue::ZERO.with_value(p.ang_scale))?;
        MpdtcFeSpdScale::write(bus, MpdtcFeSpdScaleValue::ZERO.with_value(p.spd_scale))?;
        write_signed!(
            bus,
            (MpdtcFeAge0, MpdtcFeAge0Value, p.age[0]),
            (MpdtcFeAge1, MpdtcFeAge1Value, p.age[1]),
            (MpdtcFeAge2, MpdtcFeAge2Value, p.age[2]),
            (MpdtcFeOffA, MpdtcFeOffAValue, p.adc_off[0]),
            (MpdtcFeOffB, MpdtcFeOffBValue, p.adc_off[1]),
            (MpdtcFeOffC, MpdtcFeOffCValue, p.adc_off[2]),
            (MpdtcFeGainA, MpdtcFeGainAValue, p.adc_gain[0]),
            (MpdtcFeGainB, MpdtcFeGainBValue, p.adc_gain[1]),
            (MpdtcFeGainC, MpdtcFeGainCValue, p.adc_gain[2]),
        );
        Ok(())
    }
    /// The autonomous loop's only per-period write: `MPDTC_IN_T_REF`
    /// (TRQ, see [`torque_ref_word`]).
    pub fn write_torque_ref(&mut self, t_ref: i32) -> Result<(), BusError> {
        let bus = &mut self.0;
        write_signed!(bus, (MpdtcInTRef, MpdtcInTRefValue, t_ref));
        Ok(())
    }
    /// The front end's last (i_d, i_q), CUR (2^-16 A).
    pub fn frontend_currents(&mut self) -> Result<(i32, i32), BusError> {
        let d = MpdtcFeId::read(&mut self.0)?.value_i32();
        let q = MpdtcFeIq::read(&mut self.0)?.value_i32();
        Ok((d, q))
    }
    /// `MPDTC_START`: in SAMPLE, "this period's inputs are written".
    pub fn start(&mut self, tag: u32) -> Result<(), BusError> {
        MpdtcStart::write(&mut self.0, MpdtcStartValue::ZERO.with_value(tag))
    }
    /// `MPDTC_CTRL`: `manual` (gates follow `SW_STATE`) and `state_clr`
    /// (core state held at zero).
    pub fn set_ctrl(&mut self, manual: bool, state_clr: bool) -> Result<(), BusError> {
        self.set_ctrl_path(manual, state_clr, false)
    }
    /// `MPDTC_CTRL` with the input path: `auto` = the PL's front end
    /// computes the core's inputs (the autonomous loop).
    pub fn set_ctrl_path(
        &mut self,
        manual: bool,
        state_clr: bool,
        auto: bool,
    ) -> Result<(), BusError> {
        MpdtcCtrl::write(
            &mut self.0,
            MpdtcCtrlValue::ZERO
                .with_manual(manual)
                .with_state_clr(state_clr)
                .with_auto(auto),
        )
    }
    /// Duration of the rotor alignment, PL clock cycles.
    pub fn set_align_time(&mut self, cycles: u32) -> Result<(), BusError> {
        MpdtcAlignTime::write(&mut self.0, MpdtcAlignTimeValue::ZERO.with_value(cycles))
    }
    /// Switching state of the rotor alignment (bits SaSbSc).
    pub fn set_align_vec(&mut self, state: u8) -> Result<(), BusError> {
        MpdtcAlignVec::write(
            &mut self.0,
            MpdtcAlignVecValue::ZERO.with_value(u32::from(state)),
        )
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
    use regmap::{self, Register, MPDTC};

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
        use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
        use models::pmsm::params::MotorParams;
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

    /// Hand-computed: 7 pole pairs over 4096 counts = 7 2^20 per count;
    /// Ts 1564 cycles, window 100,000: 7 x 1564 x 2^40 / 409.6e6 =
    /// 29,388,313.7; 16 A over 2048 counts = 2^13 in 2^-20 A.
    #[test]
    fn frontend_registers_by_hand_and_refusals() {
        let s = FrontendSetup {
            pole_pairs: 7,
            enc_cpr: 4096,
            period_cycles: 1564,
            window_cycles: 100_000,
            meas_age_periods: 0.375,
            amps_per_count: 16.0 / 2048.0,
            adc_offset: [1, -2, 0],
        };
        let p = frontend_params(&s).unwrap();
        assert_eq!(p.ang_scale, 7 << 20);
        assert_eq!(p.spd_scale, 29_388_314);
        assert_eq!(p.age, [-8192, 57_344, 122_880]);
        assert_eq!(p.adc_gain, [8192; 3]);
        // The reset values of the table are this setup.
        assert_eq!(regmap::MPDTC_FE_ANG_SCALE.reset, p.ang_scale);
        assert_eq!(regmap::MPDTC_FE_SPD_SCALE.reset, p.spd_scale);
        assert_eq!(regmap::MPDTC_FE_AGE0.reset, p.age[0] as u32 & 0x3_FFFF);
        assert_eq!(regmap::MPDTC_FE_AGE2.reset, p.age[2] as u32);
        let mut pl = FakePl::new();
        Mpdtc(&mut pl).load_frontend(&p).unwrap();
        let g = |r: &Register| pl.get(MPDTC.addr(r));
        assert_eq!(g(&regmap::MPDTC_FE_OFF_B), 0xFFFE);
        assert_eq!(g(&regmap::MPDTC_FE_GAIN_C), 8192);
        for bad in [
            FrontendSetup { enc_cpr: 3, ..s },
            FrontendSetup { pole_pairs: 0, ..s },
            FrontendSetup {
                meas_age_periods: 0.6,
                ..s
            },
            FrontendSetup {
                meas_age_periods: f64::NAN,
                ..s
            },
            FrontendSetup {
                amps_per_count: 0.2,
                ..s
            },
            FrontendSetup {
                adc_offset: [40_000, 0, 0],
                ..s
            },
            FrontendSetup {
                period_cycles: 60_000_000,
                window_cycles: 100,
                ..s
            },
        ] {
            assert!(frontend_params(&bad).is_err(), "{bad:?}");
        }
        assert_eq!(torque_ref_word(0.4), 6554);
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
