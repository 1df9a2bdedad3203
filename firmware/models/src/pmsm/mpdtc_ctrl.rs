//! [`Controller`] adapters of the MPDTC for the closed-loop runner: the
//! measurement front end (Clarke/Park of the averaged phase currents, angle
//! advance for the measurement age) in front of [`mpdtc_ref::decide`].

use super::closed_loop::{Actuation, Controller, Measurement};
use super::frames::{clarke, park};
use super::mpdtc_fixed::{self, FixedInputs, FixedParams, FixedState};
use super::mpdtc_ref::{self, MpdtcConfig, MpdtcInputs, MpdtcOutputs, MpdtcState};
use super::params::ParamError;

/// Age of the averaged measurement at the control instant, in control periods:
/// the mean of `n` samples spaced `T / m` (newest at `t_k`) describes the
/// instant `t_k - (n - 1) T / (2 m)` (paper: n = 4, m = 4 -> 0.375).
pub fn measurement_age_periods(adc_average_n: u32, samples_per_period: u32) -> f64 {
    (adc_average_n.max(1) as f64 - 1.0) / (2.0 * samples_per_period.max(1) as f64)
}

/// Front end: averaged measurement -> MPDTC inputs. The angle is advanced
/// by the measurement age so that `theta_e_rad` is the angle at `t_k`.
pub fn inputs_from_measurement(
    m: &Measurement,
    torque_ref_nm: f64,
    age_periods: f64,
    ts_s: f64,
) -> MpdtcInputs {
    let (ia, ib) = clarke(m.i_abc_a);
    let (i_d_a, i_q_a) = park(ia, ib, m.theta_e_rad);
    MpdtcInputs {
        i_d_a,
        i_q_a,
        theta_e_rad: m.theta_e_rad + age_periods * m.omega_e_rad_s * ts_s,
        omega_e_rad_s: m.omega_e_rad_s,
        t_ref_nm: torque_ref_nm,
    }
}

/// The `f64` reference MPDTC as a [`Controller`].
#[derive(Debug, Clone)]
pub struct MpdtcRef {
    /// Model and tuning.
    pub cfg: MpdtcConfig,
    /// Controller state.
    pub state: MpdtcState,
    /// Outputs of the last period (diagnostics).
    pub last: Option<MpdtcOutputs>,
}

impl MpdtcRef {
    /// A controller at rest (000 applied, integrator and observers zero).
    pub fn new(cfg: MpdtcConfig) -> Self {
        Self {
            cfg,
            state: MpdtcState::default(),
            last: None,
        }
    }
}

impl Controller for MpdtcRef {
    fn period_s(&self) -> f64 {
        self.cfg.params.control_period_s
    }

    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation {
        let ts = self.period_s();
        let inp = inputs_from_measurement(m, torque_ref_nm, self.cfg.params.meas_age_periods, ts);
        let out = mpdtc_ref::decide(&self.state, &inp, &self.cfg);
        self.state = out.next;
        self.last = Some(out);
        Actuation::SwitchState(out.s_next)
    }
}

/// Front end of the fixed-point core (modelled on the host in `f64` and
/// quantized at the core boundary, as the ADC/encoder blocks deliver it):
/// currents to CUR, `(cos, sin)` of the three mid-period angles and `w Ts` to
/// COEF, the reference to TRQ. Out-of-range values saturate, NaN reads 0.
pub fn fixed_inputs(inp: &MpdtcInputs, ts_s: f64) -> FixedInputs {
    use super::mpdtc_fixed::{quantize_sat, CUR_BITS, FRAC, TRQ_FRAC};
    let w_ts = inp.omega_e_rad_s * ts_s;
    let trig = |k: f64| {
        let th = inp.theta_e_rad + k * w_ts;
        (
            quantize_sat(libm::cos(th), FRAC, 18),
            quantize_sat(libm::sin(th), FRAC, 18),
        )
    };
    FixedInputs {
        i_dq: (
            quantize_sat(inp.i_d_a, FRAC, CUR_BITS),
            quantize_sat(inp.i_q_a, FRAC, CUR_BITS),
        ),
        trig: [trig(-0.5), trig(0.5), trig(1.5)],
        w_ts: quantize_sat(w_ts, FRAC, 18),
        t_ref: quantize_sat(inp.t_ref_nm, TRQ_FRAC, 18),
    }
}

/// The fixed-point core model as a [`Controller`].
#[derive(Debug, Clone)]
pub struct MpdtcFixed {
    /// Reference configuration the registers were derived from.
    pub cfg: MpdtcConfig,
    /// Parameter registers.
    pub regs: FixedParams,
    /// State registers.
    pub state: FixedState,
}

impl MpdtcFixed {
    /// Registers from `cfg` (errors: see [`FixedParams::from_config`]).
    pub fn new(cfg: MpdtcConfig) -> Result<Self, ParamError> {
        Ok(Self {
            regs: FixedParams::from_config(&cfg)?,
            cfg,
            state: FixedState::default(),
        })
    }
}

impl Controller for MpdtcFixed {
    fn period_s(&self) -> f64 {
        self.cfg.params.control_period_s
    }

    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation {
        let ts = self.period_s();
        let inp = inputs_from_measurement(m, torque_ref_nm, self.cfg.params.meas_age_periods, ts);
        let out = mpdtc_fixed::decide(&self.state, &fixed_inputs(&inp, ts), &self.regs);
        self.state = out.next;
        Actuation::SwitchState(out.s_next)
    }
}

/// The reference drives the plant; the fixed-point core runs in its shadow on
/// the same measurements and command (its `S[k]`, `S[k-1]` forced to what is
/// really applied; its integrator and observer evolve on their own) and the
/// decisions are compared every period.
#[derive(Debug, Clone)]
pub struct MpdtcShadow {
    /// The reference (in the loop).
    pub reference: MpdtcRef,
    /// The fixed-point core (shadow).
    pub fixed: MpdtcFixed,
    /// Periods compared.
    pub periods: u64,
    /// Periods with the same decision.
    pub agree: u64,
}

impl MpdtcShadow {
    /// Both controllers from one configuration.
    pub fn new(cfg: MpdtcConfig) -> Result<Self, ParamError> {
        Ok(Self {
            reference: MpdtcRef::new(cfg),
            fixed: MpdtcFixed::new(cfg)?,
            periods: 0,
            agree: 0,
        })
    }
}

impl Controller for MpdtcShadow {
    fn period_s(&self) -> f64 {
        self.reference.period_s()
    }

    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation {
        self.fixed.state.s_applied = self.reference.state.s_applied;
        self.fixed.state.s_prev = self.reference.state.s_prev;
        // Both get the command as the core's TRQ register holds it: a
        // quantization offset of the command (0.4 N m is not dyadic) would
        // otherwise be integrated open-loop by the shadow's eq. (13)
        // integrator and drift it away from the reference's.
        let t = mpdtc_fixed::quantize_sat(torque_ref_nm, mpdtc_fixed::TRQ_FRAC, 18) as f64
            / (1u32 << mpdtc_fixed::TRQ_FRAC) as f64;
        let a = self.reference.step(m, t);
        let f = self.fixed.step(m, t);
        self.periods += 1;
        if a == f {
            self.agree += 1;
        }
        a
    }
}
