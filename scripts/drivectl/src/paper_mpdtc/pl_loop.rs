//! `drivectl paper mpdtc --rate 64khz|1mhz`: the PL's autonomous loop
//! (`models::pmsm::mpdtc_pl::MpdtcPl`: sensors -> front end model -> core
//! model) on Fig. 10 and Fig. 11 at one control rate, against the
//! inverter's slew bound (docs/mpdtc.md). Same runs and metrics as the
//! paper experiments; the signal is the plant torque averaged over one
//! control period (4 ADC samples: 15.625 us at 64 kHz, 1 us at 1 MHz).
use super::experiments::{self, Bode, StepMetrics, STEP_NM, TOGGLE_RUN_S};
use super::runs::{self, Mech};
use anyhow::{anyhow, bail, Result};
use models::pmsm::mpdtc_pl::{self, MpdtcPl, PlRate};
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use models::pmsm::params::MotorParams;
use serde::Serialize;

/// The rate named on the command line.
pub fn parse_rate(s: &str) -> Result<(&'static str, PlRate)> {
    match s.to_ascii_lowercase().as_str() {
        "64khz" => Ok(("64 kHz", mpdtc_pl::RATE_64KHZ)),
        "1mhz" => Ok(("1 MHz", mpdtc_pl::RATE_1MHZ)),
        _ => bail!("--rate: expected 64khz or 1mhz, got {s:?}"),
    }
}

/// What `--rate` reports.
#[derive(Serialize)]
pub struct PlLoop {
    pub rate: &'static str,
    pub control_period_us: f64,
    pub t_tol_nm: f64,
    pub k_int_per_s: f64,
    pub step: StepMetrics,
    /// Settling bound of the 0.8 N m toggle, ms (slew + one period).
    pub settling_bound_ms: f64,
    /// Mean settling time over the bound.
    pub settling_over_bound: Option<f64>,
    pub bode: Bode,
    /// -3 dB bound of a slew-limited 0.3 N m sine, Hz.
    pub bandwidth_bound_hz: f64,
    /// Measured bandwidth over the bound.
    pub bandwidth_over_bound: Option<f64>,
}

/// The loop at `rate` on both experiments.
pub fn run(name: &'static str, rate: PlRate) -> Result<PlLoop> {
    let motor = MotorParams::default();
    let p = experiments::tuning_override(rate.params(MpdtcParams::default()))?;
    let cfg = MpdtcConfig::new(motor, p).map_err(|e| anyhow!("{e}"))?;
    let drive = rate.drive();
    let mut c = MpdtcPl::new(cfg).map_err(|e| anyhow!("{e}"))?;
    let tr = runs::run(
        &mut c,
        &motor,
        &drive,
        Mech::Free,
        TOGGLE_RUN_S,
        experiments::toggle_ref,
    )?;
    let step = experiments::toggle_metrics(&tr);
    let bode = experiments::bode(&drive, || MpdtcPl::new(cfg).map_err(|e| anyhow!("{e}")))?;
    let sb = mpdtc_pl::settling_bound_s(&motor, 2.0 * STEP_NM, rate.control_period_s) * 1e3;
    let bb = mpdtc_pl::slew_bandwidth_bound_hz(&motor, experiments::BODE_AMP_NM);
    Ok(PlLoop {
        rate: name,
        control_period_us: rate.control_period_s * 1e6,
        t_tol_nm: p.t_tol_nm,
        k_int_per_s: p.k_int_per_s,
        settling_over_bound: step.settling_time_ms.map(|s| s / sb),
        step,
        settling_bound_ms: sb,
        bandwidth_over_bound: bode.bandwidth_hz.map(|b| b / bb),
        bode,
        bandwidth_bound_hz: bb,
    })
}

fn opt(x: Option<f64>, prec: usize) -> String {
    x.map_or("none".into(), |v| format!("{v:.prec$}"))
}

/// The result as Markdown.
pub fn markdown(r: &PlLoop) -> String {
    let m = &r.step;
    let mut s = format!(
        "### PL loop (front end + core models) at {} (T_s = {} us, T_tol = {} Nm, K = {}/s)\n\n",
        r.rate, r.control_period_us, r.t_tol_nm, r.k_int_per_s
    );
    s += "| | result | slew bound | result / bound |\n|---|---|---|---|\n";
    s += &format!(
        "| Fig. 10 settling, 0.8 Nm toggle (mean / max) [ms] | {} / {} | {:.3} | {} |\n",
        opt(m.settling_time_ms, 3),
        opt(m.settling_time_max_ms, 3),
        r.settling_bound_ms,
        opt(r.settling_over_bound, 3)
    );
    s += &format!(
        "| Fig. 11 -3 dB bandwidth, 0.3 Nm sine [Hz] | {} | {:.0} | {} |\n",
        opt(r.bode.bandwidth_hz, 0),
        r.bandwidth_bound_hz,
        opt(r.bandwidth_over_bound, 3)
    );
    s += &format!(
        "\nFig. 10: overshoot {:.1} %, f_sw {:.1} kHz (transitions/leg/s), ripple RMS {:.4} Nm, mean error {:.4} Nm\n",
        m.overshoot_percent, m.fsw_khz, m.torque_ripple_rms_nm, m.torque_mean_error_nm
    );
    s += "\n| f [Hz] | gain [dB] | phase [deg] |\n|---|---|---|\n";
    for p in &r.bode.points {
        s += &format!(
            "| {} | {:.2} | {:.1} |\n",
            p.freq_hz, p.gain_db, p.phase_deg
        );
    }
    s
}
