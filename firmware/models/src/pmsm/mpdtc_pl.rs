//! The PL's autonomous torque loop on the host: the averaged measurement as
//! the PL's sensors deliver it (encoder count, speed count, ADC counts),
//! through the front end model [`frontend_fixed::frontend`] and the core
//! model [`mpdtc_fixed::decide`] (the Verilog's oracles, no second copy of
//! their arithmetic), as a [`Controller`] at any control rate; and the
//! inverter's slew bound the results are compared with (docs/mpdtc.md).
//!
//! Sensors (the simulated drive's): encoder [`ENC_CPR`] counts per
//! revolution, speed in counts per [`SPEED_WINDOW_S`] window, ADC
//! [`ADC_A_PER_COUNT`] A per count with zero offset, each rounded to the
//! nearest count (ideal otherwise: the plant and its averaging are exact).

use super::closed_loop::{Actuation, Controller, Measurement};
use super::frontend_fixed::{frontend, FrontendInputs, FrontendParams};
use super::mpdtc_fixed::{self, FixedParams, FixedState};
use super::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use super::params::{MotorParams, ParamError, SamplingParams};
use core::f64::consts::TAU;

/// Encoder counts per mechanical revolution (`ENC_CPR`).
pub const ENC_CPR: u32 = 4096;
/// Window of the encoder speed measurement (`ENC_SPEED`), s.
pub const SPEED_WINDOW_S: f64 = 1e-3;
/// ADC scale, A per count (gain register 8192 = this x 2^20).
pub const ADC_A_PER_COUNT: f64 = 16.0 / 2048.0;
/// ADC samples averaged per control period (the PL's averaging).
pub const ADC_AVERAGE_N: u32 = 4;

/// A control rate of the autonomous loop: the period and the ADC rate
/// ([`ADC_AVERAGE_N`] samples per period, all averaged), and the tuning
/// that goes with it (the rest: `MpdtcParams::default()`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlRate {
    /// Control period, s.
    pub control_period_s: f64,
    /// Torque band T_tol, N m.
    pub t_tol_nm: f64,
    /// Integrator gain K of eq. (13), 1/s.
    pub k_int_per_s: f64,
}

/// The paper's 64 kHz (256 kHz ADC) with the paper's tuning.
pub const RATE_64KHZ: PlRate = PlRate {
    control_period_s: 1.0 / 64_000.0,
    t_tol_nm: 0.08,
    k_int_per_s: 2000.0,
};
/// 1 MHz (4 MHz ADC). The torque moves at most 5 mN m per period here
/// (0.07 at 64 kHz), so the band shrinks with it: T_tol = 0.01 N m. K =
/// 500/s: at 2000/s the integrator winds up during the 0.15 ms reversal and
/// the torque then rides the band edge for 0.4 ms (docs/mpdtc.md).
pub const RATE_1MHZ: PlRate = PlRate {
    control_period_s: 1e-6,
    t_tol_nm: 0.01,
    k_int_per_s: 500.0,
};

impl PlRate {
    /// The MPDTC tuning of this rate on `params` (period, T_tol, K set).
    pub fn params(&self, params: MpdtcParams) -> MpdtcParams {
        MpdtcParams {
            control_period_s: self.control_period_s,
            t_tol_nm: self.t_tol_nm,
            k_int_per_s: self.k_int_per_s,
            ..params
        }
    }

    /// The measurement chain of this rate.
    pub fn drive(&self) -> SamplingParams {
        SamplingParams {
            adc_sample_rate_hz: ADC_AVERAGE_N as f64 / self.control_period_s,
            adc_average_n: ADC_AVERAGE_N,
            control_period_s: self.control_period_s,
            ..SamplingParams::default()
        }
    }
}

/// Front end registers for `model` at period `ts_s` with the measurement
/// age `age_periods` (the three instants are `age -+ 1/2`, `age + 3/2`
/// periods after the sample, COEF). Errors: a scale that does not fit its
/// register.
pub fn frontend_params(
    model: &MotorParams,
    ts_s: f64,
    age_periods: f64,
) -> Result<FrontendParams, ParamError> {
    let cpr = ENC_CPR as f64;
    let pp = model.pole_pairs as f64;
    let spd = libm::round(pp * ts_s * libm::exp2(40.0) / (cpr * SPEED_WINDOW_S));
    if !(1.0..=u32::MAX as f64).contains(&spd) {
        return Err(ParamError {
            field: "control_period_s",
            reason: "speed scale (spd_scale) out of its 32-bit register",
        });
    }
    let coef = |x: f64| mpdtc_fixed::quantize_sat(x, mpdtc_fixed::FRAC, 18);
    Ok(FrontendParams {
        cpr: ENC_CPR,
        align_pos: 0,
        ang_scale: libm::round(pp * libm::exp2(32.0) / cpr) as u64 as u32,
        spd_scale: spd as u32,
        age: [
            coef(age_periods - 0.5),
            coef(age_periods + 0.5),
            coef(age_periods + 1.5),
        ],
        adc_off: [0; 3],
        adc_gain: [libm::round(ADC_A_PER_COUNT * libm::exp2(20.0)) as i32; 3],
    })
}

/// The PL's loop (front end + core models) as a [`Controller`].
#[derive(Debug, Clone)]
pub struct MpdtcPl {
    /// Configuration the registers come from (its period is the loop's).
    pub cfg: MpdtcConfig,
    /// Front end registers.
    pub fe: FrontendParams,
    /// Core registers.
    pub regs: FixedParams,
    /// Core state.
    pub state: FixedState,
}

impl MpdtcPl {
    /// Registers from `cfg` (errors: [`frontend_params`],
    /// [`FixedParams::from_config`]).
    pub fn new(cfg: MpdtcConfig) -> Result<Self, ParamError> {
        let ts = cfg.params.control_period_s;
        Ok(Self {
            fe: frontend_params(&cfg.model, ts, cfg.params.meas_age_periods)?,
            regs: FixedParams::from_config(&cfg)?,
            cfg,
            state: FixedState::default(),
        })
    }

    /// What the sensors deliver for the averaged measurement `m`.
    pub fn sensor_inputs(&self, m: &Measurement, torque_ref_nm: f64) -> FrontendInputs {
        let cpr = ENC_CPR as f64;
        let pp = self.cfg.model.pole_pairs as f64;
        // Position within one pole pair's sector: the angle the PL derives
        // from it is the electrical angle (cpr and 2^32 make ang_scale exact).
        let pos = libm::round(m.theta_e_rad / TAU * cpr / pp) as i64;
        let speed = libm::round(m.omega_e_rad_s / pp / TAU * cpr * SPEED_WINDOW_S);
        let adc = |i: f64| libm::round(i / ADC_A_PER_COUNT).clamp(-32768.0, 32767.0) as i32;
        FrontendInputs {
            pos: pos.rem_euclid(ENC_CPR as i64) as u32,
            speed: speed.clamp(-32768.0, 32767.0) as i32,
            adc: [adc(m.i_abc_a[0]), adc(m.i_abc_a[1]), adc(m.i_abc_a[2])],
            t_ref: mpdtc_fixed::quantize_sat(torque_ref_nm, mpdtc_fixed::TRQ_FRAC, 18),
        }
    }
}

impl Controller for MpdtcPl {
    fn period_s(&self) -> f64 {
        self.cfg.params.control_period_s
    }

    fn step(&mut self, m: &Measurement, torque_ref_nm: f64) -> Actuation {
        let fe = frontend(&self.sensor_inputs(m, torque_ref_nm), &self.fe);
        let out = mpdtc_fixed::decide(&self.state, &fe.core, &self.regs);
        self.state = out.next;
        Actuation::SwitchState(out.s_next)
    }
}

/// Mean of the largest q-axis voltage the inverter can apply, V: the best
/// of the six active vectors projected on the q axis, averaged over the
/// rotor angle, `2/3 U_dc x 3 / pi` (30.6 V at 48 V).
pub fn mean_q_voltage_v(model: &MotorParams) -> f64 {
    2.0 / 3.0 * model.u_dc_v * 3.0 / core::f64::consts::PI
}

/// Torque slew bound at standstill and zero current, N m/s:
/// `k_T u / L` with `u` [`mean_q_voltage_v`] (4.66 kN m/s on the
/// paper's motor; resistance and back-EMF only lower it).
pub fn slew_bound_nm_per_s(model: &MotorParams) -> f64 {
    model.k_t_nm_per_a() * mean_q_voltage_v(model) / model.l_q_h
}

/// Settling bound of a step of `step_nm` into the 10 % band
/// (`metrics::SETTLING_BAND_FRACTION`), s: pure slewing over 90 % of the
/// step plus one period of computation delay.
pub fn settling_bound_s(model: &MotorParams, step_nm: f64, ts_s: f64) -> f64 {
    (1.0 - super::metrics::SETTLING_BAND_FRACTION) * libm::fabs(step_nm)
        / slew_bound_nm_per_s(model)
        + ts_s
}

/// Gain of the fundamental, dB, of an ideal slew-rate limiter (rate
/// `slew`, N m/s) following `amp sin(2 pi f t)`: the best any loop with this
/// inverter can do (evaluated over 4 periods after 4 of settling, 4096
/// steps per period).
pub fn slew_limited_gain_db(amp_nm: f64, f_hz: f64, slew: f64) -> f64 {
    const N: usize = 4096;
    let dt = 1.0 / (f_hz * N as f64);
    let dy = slew * dt;
    let (mut y, mut re, mut im) = (0.0, 0.0, 0.0);
    for k in 0..8 * N {
        let t = k as f64 * dt;
        let r = amp_nm * libm::sin(TAU * f_hz * t);
        y += (r - y).clamp(-dy, dy);
        if k >= 4 * N {
            re += y * libm::cos(TAU * f_hz * t);
            im += y * libm::sin(TAU * f_hz * t);
        }
    }
    let a = 2.0 * libm::sqrt(re * re + im * im) / (4 * N) as f64;
    20.0 * libm::log10(a / amp_nm)
}

/// -3 dB frequency of [`slew_limited_gain_db`] for `amp_nm` on `model`, Hz
/// (bisection to 1 Hz).
pub fn slew_bandwidth_bound_hz(model: &MotorParams, amp_nm: f64) -> f64 {
    let s = slew_bound_nm_per_s(model);
    // Below s / (2 pi amp) the limiter follows exactly (0 dB).
    let (mut lo, mut hi) = (s / (TAU * amp_nm), 100e3);
    while hi - lo > 1.0 {
        let mid = 0.5 * (lo + hi);
        if slew_limited_gain_db(amp_nm, mid, s) >= -3.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pmsm::closed_loop;
    use crate::pmsm::metrics;
    use crate::pmsm::mpdtc_ctrl::MpdtcFixed;
    use crate::pmsm::plant::{MechanicalMode, Plant};
    use std::vec::Vec;

    fn cfg(rate: PlRate) -> MpdtcConfig {
        MpdtcConfig::new(MotorParams::default(), rate.params(MpdtcParams::default())).unwrap()
    }

    /// Fig. 10 toggle (-0.4 -> +0.4 N m every 10 ms, from rest, free
    /// rotor) for 30 ms: settling times of the two toggles at 10 and 20 ms
    /// on the plant torque averaged over one control period.
    fn toggle<C: Controller>(c: &mut C, rate: PlRate) -> [Option<f64>; 2] {
        let mut plant = Plant::new(
            &MotorParams::default(),
            0.0,
            MechanicalMode::Inertia {
                load_torque_nm: 0.0,
            },
            0.0,
        )
        .unwrap();
        let r = |t: f64| {
            if ((t / 10e-3) as i64) % 2 == 0 {
                -0.4
            } else {
                0.4
            }
        };
        let n = libm::round(30e-3 / rate.control_period_s) as u64;
        let mut w: Vec<(f64, f64)> = Vec::new();
        let (mut acc, mut k) = (0.0, 0);
        closed_loop::run(&mut plant, c, &rate.drive(), n, r, |p| {
            acc += p.torque_nm;
            k += 1;
            if k == ADC_AVERAGE_N {
                w.push((p.t_s, acc / ADC_AVERAGE_N as f64));
                acc = 0.0;
                k = 0;
            }
        })
        .unwrap();
        [10e-3, 20e-3].map(|t0| {
            let (y0, y1) = (r(t0 - 1e-6), r(t0 + 1e-6));
            metrics::settling_time_s(
                w.iter().copied(),
                t0,
                t0 + 2e-3,
                y1,
                metrics::settling_band(y0, y1),
            )
        })
    }

    /// The slew bound by hand: k_T = 1.5 x 7 x 0.0092879 = 0.09752 N m/A,
    /// u = 32 V x 3 / pi = 30.56 V, L = 0.64 mH: 4657 N m/s; 0.72 N m of
    /// the 0.8 N m toggle take 0.1546 ms. A slew limiter's fundamental is
    /// 0 dB while it follows (f <= S / (2 pi A) = 2.47 kHz at 0.3 N m) and
    /// the bound lies above that.
    #[test]
    fn slew_bound_by_hand() {
        let m = MotorParams::default();
        let s = slew_bound_nm_per_s(&m);
        assert!((s - 4657.0).abs() < 2.0, "{s}");
        let b = settling_bound_s(&m, 0.8, 1e-6);
        assert!((b - (0.72 / s + 1e-6)).abs() < 1e-12, "{b}");
        assert!(slew_limited_gain_db(0.3, 2000.0, s).abs() < 0.01);
        let f3 = slew_bandwidth_bound_hz(&m, 0.3);
        assert!(f3 > 2470.0 && f3 < 6000.0, "{f3}");
        assert!((slew_limited_gain_db(0.3, f3, s) + 3.0).abs() < 0.01);
    }

    /// The sensors of the PL: count of the electrical angle within one
    /// pole pair, speed counts per window, ADC counts (hand-computed).
    #[test]
    fn sensor_inputs_by_hand() {
        let c = MpdtcPl::new(cfg(RATE_1MHZ)).unwrap();
        let m = Measurement {
            i_abc_a: [1.0, -0.5, -0.5],
            theta_e_rad: core::f64::consts::PI,
            omega_e_rad_s: 700.0,
        };
        let s = c.sensor_inputs(&m, 0.25);
        // half an electrical turn = 4096 / 7 / 2 = 292.57 counts
        assert_eq!(s.pos, 293);
        // 700 / 7 rad/s mechanical x 1 ms x 4096 / 2 pi = 65.19 counts
        assert_eq!(s.speed, 65);
        assert_eq!(s.adc, [128, -64, -64]);
        assert_eq!(s.t_ref, 4096);
        // 7 x 1 us x 2^40 / (4096 x 1 ms) = 1,879,048.2
        assert_eq!(c.fe.spd_scale, 1_879_048);
        assert_eq!(c.fe.age, [-8192, 57_344, 122_880]);
    }

    /// Fig. 10 at 64 kHz with the paper's tuning: the PL loop settles
    /// within 10 % of the slew bound (measured 0.172 ms against 0.170)
    /// and as the fixed core fed by the f64 front end does.
    #[test]
    fn pl_loop_at_64khz_settles_at_the_bound() {
        let c = cfg(RATE_64KHZ);
        let b = settling_bound_s(&MotorParams::default(), 0.8, RATE_64KHZ.control_period_s);
        let pl = toggle(&mut MpdtcPl::new(c).unwrap(), RATE_64KHZ);
        let fx = toggle(&mut MpdtcFixed::new(c).unwrap(), RATE_64KHZ);
        for (a, f) in pl.iter().zip(&fx) {
            let a = a.expect("settles");
            assert!(a <= 1.1 * b && a >= 0.9 * b, "{a} vs bound {b}");
            assert!((a - f.unwrap()).abs() <= 2.0 * RATE_64KHZ.control_period_s);
        }
    }

    /// Fig. 10 at 1 MHz (T_tol 0.01 N m, K 500/s): both toggles settle
    /// within 5 % of the slew bound (measured 0.146 / 0.152 ms, bound
    /// 0.156 ms); with the 64 kHz tuning (T_tol 0.08, K 2000) the same
    /// loop takes over 1 ms (the integrator winds up: the reason for the
    /// 1 MHz tuning).
    #[test]
    fn pl_loop_at_1mhz_settles_within_5_percent_of_the_bound() {
        let b = settling_bound_s(&MotorParams::default(), 0.8, 1e-6);
        let st = toggle(&mut MpdtcPl::new(cfg(RATE_1MHZ)).unwrap(), RATE_1MHZ);
        let fx = toggle(&mut MpdtcFixed::new(cfg(RATE_1MHZ)).unwrap(), RATE_1MHZ);
        for (s, f) in st.iter().zip(&fx) {
            let s = s.expect("settles");
            assert!(s <= 1.05 * b && s >= 0.85 * b, "{s} vs bound {b}");
            // The integer front end costs no settling against the f64 one.
            let f = f.expect("settles");
            assert!((s - f).abs() <= 5e-6, "{s} vs {f}");
        }
        let slow = PlRate {
            t_tol_nm: 0.08,
            k_int_per_s: 2000.0,
            ..RATE_1MHZ
        };
        let st = toggle(&mut MpdtcPl::new(cfg(slow)).unwrap(), slow);
        assert!(st.iter().any(|s| s.is_none_or(|s| s > 1e-3)), "{st:?}");
    }
}
