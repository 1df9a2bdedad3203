//! The experiments of paper 000 (Tables 3, 4; Figs. 10, 11) on one plant.
//!
//! Common setup: the paper's motor (`MotorParams::default()`), free rotor with
//! its inertia and no load, starting at rest; the paper's measurement chain
//! (256 kHz, mean of 4, one-period computation delay); ideal inverter.
//! MPDTC at 64 kHz, FOC at 16 kHz (`models::pmsm::foc::Foc`, default tuning).

use super::metrics;
use super::runs::{self, Mech, Trace, Window};
use anyhow::{anyhow, Result};
use models::pmsm::closed_loop::Controller;
use models::pmsm::foc::{Foc, FocParams};
use models::pmsm::mpdtc_ctrl::{MpdtcFixed, MpdtcShadow};
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use models::pmsm::params::{MotorParams, SamplingParams};
use serde::Serialize;
use std::f64::consts::PI;

/// Step time of Tables 3/4, s (paper: 0.1 ms).
pub const STEP_T0_S: f64 = 0.1e-3;
/// Step height of Tables 3/4, N m.
pub const STEP_NM: f64 = 0.4;
/// Evaluation interval after a step for settling/overshoot, s.
pub const EVAL_S: f64 = 2e-3;
/// Fig. 10: toggle period and amplitude.
pub const TOGGLE_HALF_S: f64 = 10e-3;
/// Fig. 10 run length (steps at 10, 20, 30 ms), s.
pub const TOGGLE_RUN_S: f64 = 40e-3;

fn mpdtc_cfg(p: MpdtcParams) -> Result<MpdtcConfig> {
    let p = tuning_override(p)?;
    MpdtcConfig::new(MotorParams::default(), p).map_err(|e| anyhow!("{e}"))
}

/// Development aid: `MPDTC_TUNE="k_int_per_s=5000,cost_norm=euclidean"`
/// overrides defaults of every MPDTC in the experiments (not for reports).
/// An unknown key or a value that does not parse is an error.
pub(super) fn tuning_override(mut p: MpdtcParams) -> Result<MpdtcParams> {
    use models::pmsm::mpdtc_ref::CostNorm;
    let Ok(v) = std::env::var("MPDTC_TUNE") else {
        return Ok(p);
    };
    static WARN: std::sync::Once = std::sync::Once::new();
    WARN.call_once(|| eprintln!("warning: MPDTC_TUNE={v} overrides the documented tuning"));
    for kv in v.split(',').filter(|kv| !kv.trim().is_empty()) {
        let (k, x) = kv
            .split_once('=')
            .map(|(k, x)| (k.trim(), x.trim()))
            .ok_or_else(|| anyhow!("MPDTC_TUNE: expected key=value, got {kv:?}"))?;
        let num = || -> Result<f64> {
            x.parse()
                .map_err(|_| anyhow!("MPDTC_TUNE: {k} = {x:?} is not a number"))
        };
        match k {
            "k_int_per_s" => p.k_int_per_s = num()?,
            "t_tol_nm" => p.t_tol_nm = num()?,
            "p_weight" => p.p_weight = num()?,
            "int_limit_nm" => p.int_limit_nm = num()?,
            "obs_kp_v_per_a" => p.obs_kp_v_per_a = num()?,
            "obs_ki_per_s" => p.obs_ki_per_s = num()?,
            "meas_age_periods" => p.meas_age_periods = num()?,
            "int_conditional" => {
                p.int_conditional = match x {
                    "0" | "false" => false,
                    "1" | "true" => true,
                    _ => anyhow::bail!("MPDTC_TUNE: int_conditional = {x:?}: expected 0/1"),
                }
            }
            "cost_norm" => {
                p.cost_norm = match x {
                    "squared" => CostNorm::Squared,
                    "euclidean" => CostNorm::Euclidean,
                    _ => anyhow::bail!("MPDTC_TUNE: cost_norm = {x:?}: expected squared/euclidean"),
                }
            }
            _ => anyhow::bail!(
                "MPDTC_TUNE: unknown key {k:?} (k_int_per_s, t_tol_nm, p_weight, int_limit_nm, obs_kp_v_per_a, \
                 obs_ki_per_s, meas_age_periods, int_conditional, cost_norm)"
            ),
        }
    }
    Ok(p)
}

fn step_ref(t: f64) -> f64 {
    if t >= STEP_T0_S {
        STEP_NM
    } else {
        0.0
    }
}

/// Fig. 10 reference: -0.4 N m, toggling every 10 ms.
pub fn toggle_ref(t: f64) -> f64 {
    if ((t / TOGGLE_HALF_S).floor() as i64) % 2 == 0 {
        -STEP_NM
    } else {
        STEP_NM
    }
}

/// One row of Table 3.
#[derive(Serialize, Clone)]
pub struct Table3Row {
    pub t_tol_nm: f64,
    pub id_max_a: f64,
    pub iq_settling_time_ms: Option<f64>,
    pub paper_id_max_a: f64,
    pub paper_iq_settling_time_ms: f64,
    pub fsw_khz: f64,
}

/// One row of Table 4.
#[derive(Serialize, Clone)]
pub struct Table4Row {
    pub p: f64,
    pub id_max_a: f64,
    pub fsw_khz: f64,
    pub paper_id_max_a: f64,
    pub paper_fsw_khz: f64,
    pub iq_settling_time_ms: Option<f64>,
}

/// Step-test metrics of one controller (Fig. 10).
#[derive(Serialize, Clone)]
pub struct StepMetrics {
    /// Mean over the three toggles (None if any did not settle).
    pub settling_time_ms: Option<f64>,
    /// Largest of the three toggles.
    pub settling_time_max_ms: Option<f64>,
    pub overshoot_percent: f64,
    pub fsw_khz: f64,
    /// Half of `fsw_khz` (one on + one off = one carrier cycle).
    pub fsw_carrier_equiv_khz: f64,
    pub torque_ripple_rms_nm: f64,
    /// Mean torque error in the steady-state windows, N m.
    pub torque_mean_error_nm: f64,
}

/// One Bode point.
#[derive(Serialize, Clone)]
pub struct BodePoint {
    pub freq_hz: f64,
    pub gain_db: f64,
    pub phase_deg: f64,
}

/// Bode result of one controller.
#[derive(Serialize, Clone)]
pub struct Bode {
    pub bandwidth_hz: Option<f64>,
    pub points: Vec<BodePoint>,
}

/// Fixed-point vs reference agreement over the Fig. 10 run.
#[derive(Serialize, Clone)]
pub struct Agreement {
    pub periods: u64,
    pub same_decision_percent: f64,
    /// Largest difference of 1 ms block means of the torque, fixed core in
    /// the loop vs reference in the loop, N m.
    pub torque_block_mean_max_diff_nm: f64,
    pub settling_time_fixed_ms: Option<f64>,
    pub settling_time_ref_ms: Option<f64>,
    pub torque_ripple_rms_fixed_nm: f64,
    pub torque_ripple_rms_ref_nm: f64,
}

/// Everything `paper mpdtc` reports.
pub struct Results {
    pub table3: Vec<Table3Row>,
    pub table3_traces: Vec<(f64, Trace)>,
    pub table4: Vec<Table4Row>,
    pub table4_traces: Vec<(f64, Trace)>,
    pub step_mpdtc: StepMetrics,
    pub step_foc: StepMetrics,
    pub toggle_mpdtc: Trace,
    pub toggle_foc: Trace,
    pub bode_mpdtc: Bode,
    pub bode_foc: Bode,
    pub agreement: Agreement,
}

fn id_max(w: &[Window]) -> f64 {
    w.iter().map(|x| x.i_d_a.abs()).fold(0.0, f64::max)
}

fn iq_settling(tr: &Trace) -> Option<f64> {
    let iq1 = STEP_NM / MotorParams::default().k_t_nm_per_a();
    metrics::settling(
        &tr.windows,
        |w| w.i_q_a,
        STEP_T0_S,
        STEP_T0_S + EVAL_S,
        0.0,
        iq1,
    )
}

/// Table 3 rows and the step traces (for the Fig. 8 plot).
pub type Table3 = (Vec<Table3Row>, Vec<(f64, Trace)>);

/// Table 3: T_tol sweep (p = 0.1), 0.4 N m step at 0.1 ms, 2.1 ms run.
pub fn table3(drive: &SamplingParams) -> Result<Table3> {
    let paper = [
        (0.02, 7.89, 0.12),
        (0.04, 4.28, 0.12),
        (0.08, 1.05, 0.18),
        (0.12, 1.07, 0.38),
    ];
    let (mut rows, mut traces) = (vec![], vec![]);
    let dur = STEP_T0_S + EVAL_S;
    for (t_tol, pid, pts) in paper {
        let cfg = mpdtc_cfg(MpdtcParams {
            t_tol_nm: t_tol,
            ..Default::default()
        })?;
        let mut c = models::pmsm::mpdtc_ctrl::MpdtcRef::new(cfg);
        let tr = runs::run(
            &mut c,
            &MotorParams::default(),
            drive,
            Mech::Free,
            dur,
            step_ref,
        )?;
        rows.push(Table3Row {
            t_tol_nm: t_tol,
            id_max_a: id_max(&tr.windows),
            iq_settling_time_ms: iq_settling(&tr).map(|s| s * 1e3),
            paper_id_max_a: pid,
            paper_iq_settling_time_ms: pts,
            fsw_khz: metrics::fsw_hz(tr.summary.transitions, dur) * 1e-3,
        });
        traces.push((t_tol, tr));
    }
    Ok((rows, traces))
}

/// Table 4 rows and the step traces.
pub type Table4 = (Vec<Table4Row>, Vec<(f64, Trace)>);

/// Table 4: p sweep (T_tol = 0.08 N m); f_sw over a 10 ms run with the step.
pub fn table4_traces(drive: &SamplingParams) -> Result<Table4> {
    let paper = [
        (0.02, 1.07, 16.7),
        (0.1, 1.06, 14.0),
        (0.15, 2.02, 12.7),
        (0.2, 4.13, 9.2),
    ];
    let dur = 10e-3;
    let (mut rows, mut traces) = (vec![], vec![]);
    for (p, pid, pf) in paper {
        let cfg = mpdtc_cfg(MpdtcParams {
            p_weight: p,
            ..Default::default()
        })?;
        let mut c = models::pmsm::mpdtc_ctrl::MpdtcRef::new(cfg);
        let tr = runs::run(
            &mut c,
            &MotorParams::default(),
            drive,
            Mech::Free,
            dur,
            step_ref,
        )?;
        rows.push(Table4Row {
            p,
            id_max_a: id_max(&tr.windows),
            fsw_khz: metrics::fsw_hz(tr.summary.transitions, dur) * 1e-3,
            paper_id_max_a: pid,
            paper_fsw_khz: pf,
            iq_settling_time_ms: iq_settling(&tr).map(|s| s * 1e3),
        });
        traces.push((p, tr));
    }
    Ok((rows, traces))
}

/// Fig. 10 metrics of a toggle trace.
pub fn toggle_metrics(tr: &Trace) -> StepMetrics {
    let w = &tr.windows;
    let mut st = vec![];
    let mut ov: f64 = 0.0;
    let mut steady = vec![];
    let mut k = 1;
    while (k as f64) * TOGGLE_HALF_S < TOGGLE_RUN_S - 1e-9 {
        let t0 = k as f64 * TOGGLE_HALF_S;
        let y0 = toggle_ref(t0 - 1e-6);
        let y1 = toggle_ref(t0 + 1e-6);
        st.push(metrics::settling(
            w,
            |x| x.torque_nm,
            t0,
            t0 + EVAL_S,
            y0,
            y1,
        ));
        ov = ov.max(metrics::overshoot(
            w,
            |x| x.torque_nm,
            t0,
            t0 + EVAL_S,
            y0,
            y1,
        ));
        // Steady state: from 2 ms after the step to the next step.
        steady.extend(
            w.iter()
                .filter(|x| x.t_s >= t0 + EVAL_S && x.t_s < t0 + TOGGLE_HALF_S)
                .map(|x| (x.torque_nm, y1)),
        );
        k += 1;
    }
    let all: Option<Vec<f64>> = st.iter().copied().collect();
    let fsw = metrics::fsw_hz(tr.summary.transitions, tr.summary.duration_s);
    let (mean_err, ripple) =
        models::pmsm::metrics::error_mean_and_ripple_rms(steady).unwrap_or((0.0, 0.0));
    StepMetrics {
        settling_time_ms: all
            .as_ref()
            .map(|v| v.iter().sum::<f64>() / v.len() as f64 * 1e3),
        settling_time_max_ms: all
            .as_ref()
            .map(|v| v.iter().fold(0.0, |a: f64, &b| a.max(b)) * 1e3),
        overshoot_percent: ov,
        fsw_khz: fsw * 1e-3,
        fsw_carrier_equiv_khz: metrics::fsw_carrier_equiv_hz(
            tr.summary.transitions,
            tr.summary.duration_s,
        ) * 1e-3,
        torque_ripple_rms_nm: ripple,
        torque_mean_error_nm: mean_err,
    }
}

/// Fig. 10 with MPDTC (reference in the loop, fixed core in its shadow) and
/// FOC, plus the fixed core in the loop for the trajectory comparison.
pub fn toggle(drive: &SamplingParams) -> Result<(Trace, Trace, Agreement)> {
    let motor = MotorParams::default();
    let cfg = mpdtc_cfg(MpdtcParams::default())?;
    let mut sh = MpdtcShadow::new(cfg).map_err(|e| anyhow!("{e}"))?;
    let tm = runs::run(&mut sh, &motor, drive, Mech::Free, TOGGLE_RUN_S, toggle_ref)?;
    let mut fx = MpdtcFixed::new(cfg).map_err(|e| anyhow!("{e}"))?;
    let tf = runs::run(&mut fx, &motor, drive, Mech::Free, TOGGLE_RUN_S, toggle_ref)?;
    let mut foc = Foc::new(&motor, &FocParams::default()).map_err(|e| anyhow!("{e}"))?;
    let tfoc = runs::run(
        &mut foc,
        &motor,
        drive,
        Mech::Free,
        TOGGLE_RUN_S,
        toggle_ref,
    )?;
    let block = |w: &[Window]| -> Vec<f64> {
        w.chunks(64)
            .map(|c| c.iter().map(|x| x.torque_nm).sum::<f64>() / c.len() as f64)
            .collect()
    };
    let (bm, bf) = (block(&tm.windows), block(&tf.windows));
    let diff = bm
        .iter()
        .zip(&bf)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let (mm, mf) = (toggle_metrics(&tm), toggle_metrics(&tf));
    let ag = Agreement {
        periods: sh.periods,
        same_decision_percent: 100.0 * sh.agree as f64 / sh.periods.max(1) as f64,
        torque_block_mean_max_diff_nm: diff,
        settling_time_fixed_ms: mf.settling_time_ms,
        settling_time_ref_ms: mm.settling_time_ms,
        torque_ripple_rms_fixed_nm: mf.torque_ripple_rms_nm,
        torque_ripple_rms_ref_nm: mm.torque_ripple_rms_nm,
    };
    Ok((tm, tfoc, ag))
}

/// Bode frequencies, Hz (paper: 100 Hz .. 8 kHz).
pub const BODE_FREQS_HZ: [f64; 15] = [
    100.0, 200.0, 500.0, 1000.0, 1500.0, 2000.0, 2500.0, 3000.0, 3500.0, 4000.0, 4500.0, 5000.0,
    6000.0, 7000.0, 8000.0,
];
/// Sine amplitude, N m (paper: 0.3).
pub const BODE_AMP_NM: f64 = 0.3;

/// Fig. 11: gain and phase of torque / reference at each frequency below
/// half the controller's sample rate.
/// Transient: the first 1 ms (at least 1 period) is discarded; the DFT runs
/// over an integer number of periods (>= 2 ms) of window-mean torque (the
/// mean of the 4 ADC samples of each window: torque "calculated through the
/// measured motor current", as the paper does), against the sine evaluated
/// at the window centre, the mean instant of those samples (1.5 ADC periods
/// before the window end). The gain therefore includes the measurement's
/// averaging (-0.08 dB at 5 kHz, -0.21 dB at 8 kHz), not its delay.
pub fn bode<C: Controller>(
    drive: &SamplingParams,
    mut make: impl FnMut() -> Result<C>,
) -> Result<Bode> {
    let motor = MotorParams::default();
    let mut pts = vec![];
    for f in BODE_FREQS_HZ {
        // At and above half its sample rate a controller sees an aliased
        // reference (the FOC at 8 kHz samples a 16 kHz-sampled sine at its
        // zeros): no meaningful gain, the point is left out.
        if f * make()?.period_s() >= 0.5 - 1e-12 {
            continue;
        }
        let per = 1.0 / f;
        let t_skip = (1e-3f64).max(per);
        let n_per = (2e-3 / per).ceil();
        let dur = t_skip + n_per * per + 1e-4;
        let mut c = make()?;
        let r = move |t: f64| BODE_AMP_NM * (2.0 * PI * f * t).sin();
        let tr = runs::run(&mut c, &motor, drive, Mech::Free, dur, r)?;
        let t_adc = 1.0 / drive.adc_sample_rate_hz;
        let (mut yr, mut yi, mut rr, mut ri) = (0.0, 0.0, 0.0, 0.0);
        for x in tr.windows.iter() {
            // Window centre (the mean instant of its 4 samples).
            let tc = x.t_s - 0.5 * (runs::WINDOW_SAMPLES - 1) as f64 * t_adc;
            if tc < t_skip || tc >= t_skip + n_per * per {
                continue;
            }
            let (s, c) = (2.0 * PI * f * tc).sin_cos();
            let rv = r(tc);
            yr += x.torque_nm * c;
            yi -= x.torque_nm * s;
            rr += rv * c;
            ri -= rv * s;
        }
        let (ym, rm) = ((yr * yr + yi * yi).sqrt(), (rr * rr + ri * ri).sqrt());
        let mut ph = (yi.atan2(yr) - ri.atan2(rr)).to_degrees();
        while ph > 180.0 {
            ph -= 360.0;
        }
        while ph <= -180.0 {
            ph += 360.0;
        }
        pts.push(BodePoint {
            freq_hz: f,
            gain_db: 20.0 * (ym / rm).log10(),
            phase_deg: ph,
        });
    }
    // Unwrap the phase along frequency (a lag that grows past -180 deg).
    for i in 1..pts.len() {
        while pts[i].phase_deg - pts[i - 1].phase_deg > 180.0 {
            pts[i].phase_deg -= 360.0;
        }
    }
    Ok(Bode {
        bandwidth_hz: bandwidth(&pts),
        points: pts,
    })
}

/// First -3 dB crossing, log-interpolated between points; None if none.
pub fn bandwidth(p: &[BodePoint]) -> Option<f64> {
    for w in p.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a.gain_db >= -3.0 && b.gain_db < -3.0 {
            let x = (-3.0 - a.gain_db) / (b.gain_db - a.gain_db);
            return Some((a.freq_hz.ln() + x * (b.freq_hz.ln() - a.freq_hz.ln())).exp());
        }
    }
    if p.first().is_some_and(|a| a.gain_db < -3.0) {
        return p.first().map(|a| a.freq_hz);
    }
    None
}

/// Runs everything.
pub fn all() -> Result<Results> {
    let drive = SamplingParams::default();
    let (table3, table3_traces) = table3(&drive)?;
    let (table4, table4_traces) = table4_traces(&drive)?;
    let (toggle_mpdtc, toggle_foc, agreement) = toggle(&drive)?;
    let step_mpdtc = toggle_metrics(&toggle_mpdtc);
    let step_foc = toggle_metrics(&toggle_foc);
    let cfg = mpdtc_cfg(MpdtcParams::default())?;
    let bode_mpdtc = bode(&drive, || Ok(models::pmsm::mpdtc_ctrl::MpdtcRef::new(cfg)))?;
    let bode_foc = bode(&drive, || {
        Foc::new(&MotorParams::default(), &FocParams::default()).map_err(|e| anyhow!("{e}"))
    })?;
    Ok(Results {
        table3,
        table3_traces,
        table4,
        table4_traces,
        step_mpdtc,
        step_foc,
        toggle_mpdtc,
        toggle_foc,
        bode_mpdtc,
        bode_foc,
        agreement,
    })
}
