//! Motor and drive parameters of paper 000, with validation.
//!
//! Every field carries its unit in its name. With feature `std` the structs
//! derive serde so that `drivectl` loads them from TOML: missing keys take the
//! paper's default, unknown keys are an error (catches typos).
//!
//! Conventions written down here because the paper leaves them open:
//! - `r_s_ohm`, `l_d_h`, `l_q_h` are *per-phase star-equivalent* values:
//!   terminal (line-to-line) values of Table 2 divided by 2 (1.11 ohm -> 0.555 ohm,
//!   1.28 mH -> 0.64 mH). The paper's remark `R = 1.5 R_phase` below eq. (1) is
//!   not applied: with the amplitude-invariant Clarke transform the dq model uses
//!   the per-phase resistance and inductance unchanged.
//! - `psi_pm_wb` is the permanent-magnet flux linkage amplitude (peak, per phase)
//!   in the amplitude-invariant frame. Default: from the speed constant,
//!   `k_e = 60 / (2 pi 84.8)` V s/rad (line-to-line peak per mechanical rad/s),
//!   `psi_pm = k_e / (sqrt(3) p) = 0.0092879` Wb. The other convention,
//!   `k_T / (1.5 p) = 0.113 / 10.5 = 0.01076` Wb, is [`PSI_PM_FROM_KT_WB`];
//!   the two differ by 16 % (the datasheet constants are not mutually
//!   consistent with an ideal sinusoidal machine). We take the back-EMF one
//!   because the plant's voltage equation is what the back-EMF constant measures.

/// Flux linkage from the back-EMF (speed) constant, Wb: `k_e / (sqrt(3) p)`.
pub const PSI_PM_FROM_KE_WB: f64 = 0.009_287_9;
/// Flux linkage from the torque constant, Wb: `k_T / (1.5 p)` = 0.113 / 10.5.
pub const PSI_PM_FROM_KT_WB: f64 = 0.113 / 10.5;

pub use crate::validate::{check_finite, check_nonneg, check_pos, ParamError};

/// Surface PMSM + DC link (paper 000, Table 2; star-equivalent per phase).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(default, deny_unknown_fields))]
pub struct MotorParams {
    /// Stator resistance per phase (star equivalent), ohm.
    pub r_s_ohm: f64,
    /// d-axis inductance, H.
    pub l_d_h: f64,
    /// q-axis inductance, H. The plant supports `l_q_h == l_d_h` only
    /// (surface PMSM, as in the paper).
    pub l_q_h: f64,
    /// Pole pairs (the paper does not give it; the EC 60 flat has 14 poles).
    pub pole_pairs: u32,
    /// PM flux linkage amplitude, Wb (convention: see the module doc).
    pub psi_pm_wb: f64,
    /// DC-link voltage, V.
    pub u_dc_v: f64,
    /// Rotor inertia, kg m^2 (810 g cm^2 = 8.1e-5 kg m^2).
    pub j_kg_m2: f64,
    /// Viscous friction, N m s/rad (mechanical speed).
    pub friction_nm_s_per_rad: f64,
}

impl Default for MotorParams {
    fn default() -> Self {
        Self {
            r_s_ohm: 0.555,
            l_d_h: 0.64e-3,
            l_q_h: 0.64e-3,
            pole_pairs: 7,
            psi_pm_wb: PSI_PM_FROM_KE_WB,
            u_dc_v: 48.0,
            j_kg_m2: 8.1e-5,
            friction_nm_s_per_rad: 0.0,
        }
    }
}

impl MotorParams {
    /// Checks every field: finite, positive where physical, pole pairs 1..=64.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_pos("r_s_ohm", self.r_s_ohm)?;
        check_pos("l_d_h", self.l_d_h)?;
        check_pos("l_q_h", self.l_q_h)?;
        if self.pole_pairs == 0 || self.pole_pairs > 64 {
            return Err(ParamError {
                field: "pole_pairs",
                reason: "must be in 1..=64",
            });
        }
        check_pos("psi_pm_wb", self.psi_pm_wb)?;
        check_pos("u_dc_v", self.u_dc_v)?;
        check_pos("j_kg_m2", self.j_kg_m2)?;
        check_nonneg("friction_nm_s_per_rad", self.friction_nm_s_per_rad)?;
        Ok(())
    }

    /// Electromagnetic torque, N m, eq. (8): `1.5 p (psi i_q + (L_d - L_q) i_d i_q)`.
    pub fn torque_nm(&self, i_d_a: f64, i_q_a: f64) -> f64 {
        1.5 * self.pole_pairs as f64
            * (self.psi_pm_wb * i_q_a + (self.l_d_h - self.l_q_h) * i_d_a * i_q_a)
    }

    /// Torque constant in this model, N m/A (q-axis amplitude): `1.5 p psi`.
    pub fn k_t_nm_per_a(&self) -> f64 {
        1.5 * self.pole_pairs as f64 * self.psi_pm_wb
    }
}

/// Inverter, sampling and timing of the drive (paper 000, Section 4).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(default, deny_unknown_fields))]
pub struct SamplingParams {
    /// ADC sample rate, Hz (paper: 256 kHz).
    pub adc_sample_rate_hz: f64,
    /// Number of consecutive ADC samples averaged into one measurement
    /// (paper: 4, i.e. one measurement per 64 kHz period).
    pub adc_average_n: u32,
    /// Control period of the MPDTC, s (paper: 1/64 kHz = 15.625 us). The FOC
    /// runs at its own period (see `foc::FocParams::period_s`, 1/16 kHz).
    pub control_period_s: f64,
    /// Computation delay in control periods (paper: 1, the decision computed
    /// from the samples of period k is applied during period k+1).
    pub computation_delay_periods: u32,
    /// Inverter dead time, s (0 = ideal inverter). During the dead time the leg
    /// voltage follows the current direction (diode conduction).
    pub dead_time_s: f64,
}

impl Default for SamplingParams {
    fn default() -> Self {
        Self {
            adc_sample_rate_hz: 256_000.0,
            adc_average_n: 4,
            control_period_s: 1.0 / 64_000.0,
            computation_delay_periods: 1,
            dead_time_s: 0.0,
        }
    }
}

impl SamplingParams {
    /// Checks ranges: rates and periods finite and > 0, averaging 1..=64,
    /// delay 0..=2, dead time below a quarter control period, and the control
    /// period an integer number (>= averaging) of ADC sample periods.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_pos("adc_sample_rate_hz", self.adc_sample_rate_hz)?;
        if self.adc_average_n == 0 || self.adc_average_n > 64 {
            return Err(ParamError {
                field: "adc_average_n",
                reason: "must be in 1..=64",
            });
        }
        check_pos("control_period_s", self.control_period_s)?;
        if self.computation_delay_periods > 2 {
            return Err(ParamError {
                field: "computation_delay_periods",
                reason: "must be in 0..=2",
            });
        }
        check_nonneg("dead_time_s", self.dead_time_s)?;
        if self.dead_time_s >= 0.25 * self.control_period_s {
            return Err(ParamError {
                field: "dead_time_s",
                reason: "must be below a quarter of the control period",
            });
        }
        samples_per_period(self.control_period_s, self.adc_sample_rate_hz)
            .filter(|&n| n >= self.adc_average_n as usize)
            .map(|_| ())
            .ok_or(ParamError {
                field: "control_period_s",
                reason: "must be an integer multiple (>= adc_average_n) of the ADC sample period",
            })
    }
}

/// Number of ADC samples in a control period if it is an integer (1..=4096).
pub fn samples_per_period(period_s: f64, adc_rate_hz: f64) -> Option<usize> {
    let x = period_s * adc_rate_hz;
    if !x.is_finite() {
        return None;
    }
    let n = libm::round(x);
    if (1.0..=4096.0).contains(&n) && libm::fabs(x - n) < 1e-6 * n {
        Some(n as usize)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_match_table_2() {
        let m = MotorParams::default();
        m.validate().unwrap();
        SamplingParams::default().validate().unwrap();
        // Terminal values of Table 2 halved (star equivalent).
        assert_eq!(m.r_s_ohm * 2.0, 1.11);
        assert!((m.l_d_h * 2.0 - 1.28e-3).abs() < 1e-15);
        // psi from the speed constant 84.8 rpm/V, independently recomputed.
        let k_e = 60.0 / (2.0 * core::f64::consts::PI * 84.8);
        let psi = k_e / (3f64.sqrt() * 7.0);
        assert!((psi - m.psi_pm_wb).abs() < 1e-7, "{psi}");
        assert!((PSI_PM_FROM_KT_WB - 0.010_762).abs() < 1e-6);
        assert_eq!(
            samples_per_period(SamplingParams::default().control_period_s, 256e3),
            Some(4)
        );
        assert_eq!(samples_per_period(1.0 / 16e3, 256e3), Some(16));
    }

    #[test]
    fn validation_rejects_bad_values() {
        let bad = [
            MotorParams {
                r_s_ohm: f64::NAN,
                ..Default::default()
            },
            MotorParams {
                l_d_h: 0.0,
                ..Default::default()
            },
            MotorParams {
                l_q_h: -1e-3,
                ..Default::default()
            },
            MotorParams {
                pole_pairs: 0,
                ..Default::default()
            },
            MotorParams {
                psi_pm_wb: f64::INFINITY,
                ..Default::default()
            },
            MotorParams {
                u_dc_v: 0.0,
                ..Default::default()
            },
            MotorParams {
                j_kg_m2: -1.0,
                ..Default::default()
            },
            MotorParams {
                friction_nm_s_per_rad: -1e-6,
                ..Default::default()
            },
        ];
        for (i, m) in bad.iter().enumerate() {
            assert!(m.validate().is_err(), "case {i}");
        }
        let bad = [
            SamplingParams {
                adc_sample_rate_hz: f64::NAN,
                ..Default::default()
            },
            SamplingParams {
                adc_average_n: 0,
                ..Default::default()
            },
            SamplingParams {
                control_period_s: 1.0 / 60e3,
                ..Default::default()
            },
            SamplingParams {
                control_period_s: 1.0 / 256e3,
                ..Default::default()
            },
            SamplingParams {
                dead_time_s: 5e-6,
                ..Default::default()
            },
            SamplingParams {
                computation_delay_periods: 3,
                ..Default::default()
            },
        ];
        for (i, d) in bad.iter().enumerate() {
            assert!(d.validate().is_err(), "case {i}");
        }
        let e = MotorParams {
            pole_pairs: 0,
            ..Default::default()
        }
        .validate()
        .unwrap_err();
        assert_eq!(e.field, "pole_pairs");
    }
}
