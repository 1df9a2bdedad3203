//! The PS side of the two control loops when the PL does the switching:
//! register readings -> [`Measurement`] -> controller -> register writes,
//! over any [`RegisterBus`] (the PL on a board, the simulated PL under QEMU
//! and in host tests). The controllers are the ones of the host experiments
//! ([`super::foc::Foc`], and for the MPDTC the PL's `mpdtc_core` fed with
//! [`inputs_from_measurement`] / [`fixed_inputs`], as
//! `pl-bitstream-src/sim/tests/closed_loop.rs` does).
//!
//! Units: ADC counts -> A by [`PlScaling::adc_amps_per_count`]; encoder
//! counts -> electrical angle by `(ENC_POS - align_pos) pole_pairs 2 pi /
//! encoder_cpr`; ENC_SPEED (counts per ENC_WINDOW cycles) -> rad/s
//! electrical.

use super::measure::Measurement;
use super::mpdtc_ctrl::{fixed_inputs, inputs_from_measurement};
use super::mpdtc_fixed::FixedParams;
use super::mpdtc_ref::MpdtcConfig;
use super::plant::wrap_2pi;
use crate::bus::{BusError, RegisterBus};
use crate::regmap::{self as rm, Block, Register, ADC, ENC, MPDTC, PWM};
use core::f64::consts::PI;

/// How the board's sensors map to physical units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlScaling {
    /// Phase current per ADC count, A.
    pub adc_amps_per_count: f64,
    /// Encoder counts per mechanical revolution (as written to ENC_CPR).
    pub encoder_cpr: u32,
    /// Motor pole pairs.
    pub pole_pairs: u32,
}

fn rd<B: RegisterBus>(bus: &mut B, b: &Block, r: &Register) -> Result<u32, BusError> {
    bus.read(b.addr(r))
}

fn wr<B: RegisterBus>(bus: &mut B, b: &Block, r: &Register, v: u32) -> Result<(), BusError> {
    bus.write(b.addr(r), v)
}

/// Reads the averaged phase currents and the encoder: the measurement of
/// this control period. `align_pos` is MPDTC_ALIGN_POS (or the position of
/// the rotor's d axis on phase a found otherwise).
pub fn read_measurement<B: RegisterBus>(
    bus: &mut B,
    sc: &PlScaling,
    align_pos: u32,
) -> Result<Measurement, BusError> {
    let mut i = [0.0; 3];
    for (x, r) in i.iter_mut().zip([&rm::ADC_IA, &rm::ADC_IB, &rm::ADC_IC]) {
        let counts = rd(bus, &ADC, r)? as u16 as i16;
        *x = f64::from(counts) * sc.adc_amps_per_count;
    }
    let cpr = f64::from(sc.encoder_cpr.max(1));
    let pp = f64::from(sc.pole_pairs);
    let pos = rd(bus, &ENC, &rm::ENC_POS)?;
    let rel = (pos as i64 - align_pos as i64).rem_euclid(sc.encoder_cpr.max(1) as i64);
    let speed = rd(bus, &ENC, &rm::ENC_SPEED)? as u16 as i16;
    let window_s = f64::from(rd(bus, &ENC, &rm::ENC_WINDOW)?.max(1)) / f64::from(rm::PL_CLOCK_HZ);
    Ok(Measurement {
        i_abc_a: i,
        theta_e_rad: wrap_2pi(rel as f64 / cpr * 2.0 * PI * pp),
        omega_e_rad_s: f64::from(speed) / window_s / cpr * 2.0 * PI * pp,
    })
}

/// Writes a (possibly negative) value to an MPDTC-page register: its
/// two's complement, masked to the register width.
fn wr_mp<B: RegisterBus>(bus: &mut B, r: &Register, v: i32) -> Result<(), BusError> {
    wr(bus, &MPDTC, r, v as u32 & r.mask())
}

/// Loads the parameter registers of `mpdtc_core`.
pub fn mpdtc_load_params<B: RegisterBus>(bus: &mut B, p: &FixedParams) -> Result<(), BusError> {
    wr_mp(bus, &rm::MPDTC_P_A, p.a)?;
    wr_mp(bus, &rm::MPDTC_P_LAMBDA, p.lambda)?;
    wr_mp(bus, &rm::MPDTC_P_U0, p.u0)?;
    wr_mp(bus, &rm::MPDTC_P_U0_HALF, p.u0_half)?;
    wr_mp(bus, &rm::MPDTC_P_U0_H, p.u0_h)?;
    wr_mp(bus, &rm::MPDTC_P_PSI_L, p.psi_l)?;
    wr_mp(bus, &rm::MPDTC_P_KINV_T, p.kinv_t)?;
    wr_mp(bus, &rm::MPDTC_P_TOL, p.tol)?;
    wr_mp(bus, &rm::MPDTC_P_K_INT, p.k_int)?;
    wr_mp(bus, &rm::MPDTC_P_INT_LIM, p.int_lim)?;
    wr_mp(bus, &rm::MPDTC_P_INT_COND, i32::from(p.int_conditional))?;
    wr_mp(bus, &rm::MPDTC_P_KP_O, p.kp_o)?;
    wr_mp(bus, &rm::MPDTC_P_KI_O, p.ki_o)?;
    wr_mp(bus, &rm::MPDTC_P_ETA_LIM, p.eta_lim)?;
    let w2 = [
        &rm::MPDTC_P_W2_0,
        &rm::MPDTC_P_W2_1,
        &rm::MPDTC_P_W2_2,
        &rm::MPDTC_P_W2_3,
    ];
    for (r, v) in w2.into_iter().zip(p.w2) {
        wr_mp(bus, r, v)?;
    }
    Ok(())
}

/// One MPDTC control period on the PS (in the sequence's SAMPLE state):
/// the core's inputs from the measurement and the torque reference, N m,
/// then MPDTC_START. The PL decides and applies S[k+1] at the next boundary.
pub fn mpdtc_period<B: RegisterBus>(
    bus: &mut B,
    m: &Measurement,
    torque_ref_nm: f64,
    cfg: &MpdtcConfig,
) -> Result<(), BusError> {
    let ts = cfg.params.control_period_s;
    let inp = inputs_from_measurement(m, torque_ref_nm, cfg.params.meas_age_periods, ts);
    let f = fixed_inputs(&inp, ts);
    wr_mp(bus, &rm::MPDTC_IN_ID, f.i_dq.0)?;
    wr_mp(bus, &rm::MPDTC_IN_IQ, f.i_dq.1)?;
    wr_mp(bus, &rm::MPDTC_IN_COS0, f.trig[0].0)?;
    wr_mp(bus, &rm::MPDTC_IN_SIN0, f.trig[0].1)?;
    wr_mp(bus, &rm::MPDTC_IN_COS1, f.trig[1].0)?;
    wr_mp(bus, &rm::MPDTC_IN_SIN1, f.trig[1].1)?;
    wr_mp(bus, &rm::MPDTC_IN_COS2, f.trig[2].0)?;
    wr_mp(bus, &rm::MPDTC_IN_SIN2, f.trig[2].1)?;
    wr_mp(bus, &rm::MPDTC_IN_W_TS, f.w_ts)?;
    wr_mp(bus, &rm::MPDTC_IN_T_REF, f.t_ref)?;
    wr(bus, &MPDTC, &rm::MPDTC_START, 1)
}

/// Compare value of a duty `d` (0..=1, clamped; NaN counts as 0) for the
/// centre-aligned PWM with half period `pwm_period` cycles: upper switch on
/// while the counter < DUTY, i.e. for `DUTY / PWM_PERIOD` of the period.
pub fn duty_counts(d: f64, pwm_period: u32) -> u32 {
    let d = if d.is_nan() { 0.0 } else { d.clamp(0.0, 1.0) };
    libm::round(d * f64::from(pwm_period)) as u32
}

/// Writes the duties of legs a, b, c (loaded by the PWM at its next bottom).
pub fn write_duties<B: RegisterBus>(
    bus: &mut B,
    d: [f64; 3],
    pwm_period: u32,
) -> Result<(), BusError> {
    for (r, x) in [&rm::DUTY_A, &rm::DUTY_B, &rm::DUTY_C].into_iter().zip(d) {
        wr(bus, &PWM, r, duty_counts(x, pwm_period))?;
    }
    Ok(())
}

/// Restarts the ADC's sample timer (ADC_CTRL.ENABLE 0 then 1), so that its
/// conversions take a fixed phase to the PWM when called right after a PWM
/// period start: the PL has no ADC trigger from the PWM counter, and the
/// FOC wants its samples at a known instant of the period.
pub fn restart_adc_timer<B: RegisterBus>(bus: &mut B) -> Result<(), BusError> {
    wr(bus, &ADC, &rm::ADC_CTRL, 0)?;
    wr(bus, &ADC, &rm::ADC_CTRL, 1)
}

/// Timing of the PL for the two loops, PL clock cycles.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlTiming {
    /// ADC_PERIOD: 391 = 255.75 kHz (the paper's 256 kHz within 0.1 %); the
    /// MPDTC control period is 4 of them (63.94 kHz).
    pub adc_period: u32,
    /// PWM_PERIOD (half period): 3128 = 15.985 kHz, exactly 16 ADC periods,
    /// so the ADC keeps its phase to the PWM (the paper's FOC: 16 kHz).
    pub pwm_period: u32,
    /// DEAD_TIME: 10 = 100 ns.
    pub dead_time: u32,
}

impl Default for PlTiming {
    fn default() -> Self {
        Self {
            adc_period: 391,
            pwm_period: 3128,
            dead_time: 10,
        }
    }
}

impl PlTiming {
    /// MPDTC control period (4 ADC periods), s.
    pub fn mpdtc_period_s(&self) -> f64 {
        4.0 * f64::from(self.adc_period) / f64::from(rm::PL_CLOCK_HZ)
    }

    /// FOC control (= PWM) period, s.
    pub fn foc_period_s(&self) -> f64 {
        2.0 * f64::from(self.pwm_period) / f64::from(rm::PL_CLOCK_HZ)
    }

    /// Age, at a PWM period start, of the mean of the 4 ADC samples averaged
    /// last, s, after [`restart_adc_timer`] at a period start: conversions
    /// at start + 4 + j ADC_PERIOD (2 register writes, then the timer's
    /// pulse), the newest of the period's last 4 is
    /// `2 PWM_PERIOD - 4 - (n - 1) ADC_PERIOD` cycles old at the next start
    /// (n = samples per PWM period), their mean 1.5 ADC periods older. The
    /// FOC propagates its measurement over this lag.
    pub fn foc_measurement_lag_s(&self) -> f64 {
        let per = 2 * self.pwm_period;
        let n = (per / self.adc_period.max(1)).max(1);
        let newest = per.saturating_sub(4 + (n - 1) * self.adc_period);
        (f64::from(newest) + 1.5 * f64::from(self.adc_period)) / f64::from(rm::PL_CLOCK_HZ)
    }
}

/// Prepares mode MPDTC with the control sequence (gates still off): core
/// parameters, ADC period, dead time, alignment time (cycles), core state
/// released, MANUAL off, CTRL.MODE = MPDTC. `GATE_CTRL` = 1 then starts
/// the sequence (alignment, then one decision per ADC average).
pub fn setup_mpdtc<B: RegisterBus>(
    bus: &mut B,
    p: &FixedParams,
    t: &PlTiming,
    align_time_cycles: u32,
) -> Result<(), BusError> {
    mpdtc_load_params(bus, p)?;
    wr(bus, &ADC, &rm::ADC_PERIOD, t.adc_period)?;
    wr(bus, &PWM, &rm::DEAD_TIME, t.dead_time)?;
    wr(bus, &MPDTC, &rm::MPDTC_ALIGN_TIME, align_time_cycles)?;
    wr(bus, &MPDTC, &rm::MPDTC_CTRL, 0)?;
    wr(bus, &rm::TOP, &rm::CTRL, rm::mode::MPDTC)
}

/// Prepares mode FOC-PWM (gates still off): ADC and PWM periods, 50 %
/// duties, dead time, CTRL.MODE = FOC-PWM. Call [`restart_adc_timer`] right
/// after a PWM period start before the first FOC step.
pub fn setup_foc<B: RegisterBus>(bus: &mut B, t: &PlTiming) -> Result<(), BusError> {
    wr(bus, &ADC, &rm::ADC_PERIOD, t.adc_period)?;
    wr(bus, &PWM, &rm::PWM_PERIOD, t.pwm_period)?;
    write_duties(bus, [0.5; 3], t.pwm_period)?;
    wr(bus, &PWM, &rm::DEAD_TIME, t.dead_time)?;
    wr(bus, &rm::TOP, &rm::CTRL, rm::mode::FOC_PWM)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duty_counts_by_hand() {
        assert_eq!(duty_counts(0.5, 3128), 1564);
        assert_eq!(duty_counts(1.2, 3128), 3128);
        assert_eq!(duty_counts(-0.1, 3128), 0);
        assert_eq!(duty_counts(f64::NAN, 3128), 0);
        assert_eq!(duty_counts(0.25, 2), 1);
    }

    #[test]
    fn default_timing_by_hand() {
        let t = PlTiming::default();
        assert!((t.mpdtc_period_s() - 15.64e-6).abs() < 1e-12);
        assert!((t.foc_period_s() - 62.56e-6).abs() < 1e-12);
        // 16 samples per PWM period; newest 6256 - 4 - 15 x 391 = 387
        // cycles old, mean 586.5 cycles older: 973.5 cycles.
        assert!((t.foc_measurement_lag_s() - 9.735e-6).abs() < 1e-12);
    }
}
