//! `drivectl paper mpdtc` and `drivectl bench pmsm`: the experiments of
//! paper 000 (Tables 3, 4; Figs. 10, 11), MPDTC vs FOC on one plant, and the
//! PMSM throughput benchmark. Definitions: `paper_mpdtc/metrics.rs`; setup:
//! `paper_mpdtc/experiments.rs`; write-up: `docs/mpdtc.md`.
use anyhow::{Context, Result};
use serde_json::json;
use std::path::Path;

mod experiments;
mod metrics;
mod pl_loop;
mod plots;
mod runs;

use experiments::Results;

#[derive(clap::Args)]
pub struct Args {
    /// Print one JSON object instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Directory for CSV files and plots.
    #[arg(long)]
    pub out: Option<std::path::PathBuf>,
    /// Instead: the PL's loop (front end + core models) at this control
    /// rate, `64khz` or `1mhz`, on Figs. 10 and 11 against the slew bound.
    #[arg(long)]
    pub rate: Option<String>,
}

#[derive(clap::Args)]
pub struct BenchArgs {
    /// Simulated time per measurement, s.
    #[arg(long, default_value_t = 2.0)]
    pub sim_s: f64,
}

pub fn run(a: Args) -> Result<()> {
    if let Some(rate) = &a.rate {
        let (name, rate) = pl_loop::parse_rate(rate)?;
        let r = pl_loop::run(name, rate)?;
        let text = if a.json {
            serde_json::to_string(&r)? + "\n"
        } else {
            pl_loop::markdown(&r)
        };
        return print_stdout(&text);
    }
    let r = experiments::all()?;
    if let Some(dir) = &a.out {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
        write_csv(dir, &r)?;
        plots::all(dir, &r)?;
    }
    let text = if a.json {
        serde_json::to_string_pretty(&to_json(&r))? + "\n"
    } else {
        markdown(&r)
    };
    print_stdout(&text)
}

/// Writes `text` to stdout; a closed pipe (`| head`) ends quietly instead of
/// panicking like `print!` does.
fn print_stdout(text: &str) -> Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        r => r.context("writing to stdout"),
    }
}

fn to_json(r: &Results) -> serde_json::Value {
    json!({
        "table3": r.table3,
        "table4": r.table4,
        "step": {"mpdtc": r.step_mpdtc, "foc": r.step_foc,
                 "paper": {"mpdtc_settling_time_ms": 0.19, "foc_settling_time_ms": 0.27}},
        "bode": {"mpdtc": r.bode_mpdtc, "foc": r.bode_foc, "paper": {"mpdtc_bandwidth_hz": 5000.0}},
        "fixed_vs_reference": r.agreement,
        "definitions": {
            "settling_band_fraction_of_step": metrics::SETTLING_BAND,
            "settling_eval_interval_ms": experiments::EVAL_S * 1e3,
            "signal": "plant value averaged over 15.625 us windows (4 ADC samples at 256 kHz)",
            "fsw": "gate transitions per leg per second",
        },
    })
}

fn opt(x: Option<f64>, prec: usize) -> String {
    x.map_or("not settled".into(), |v| format!("{v:.prec$}"))
}

/// The tables as Markdown (the same text goes to `docs/mpdtc.md`).
pub fn markdown(r: &Results) -> String {
    let mut s = String::new();
    s += "### Table 3: influence of T_tol (0.4 Nm step at 0.1 ms, p = 0.1)\n\n";
    s += "| T_tol [Nm] | abs I_d,max [A] paper | ours | settling of I_q [ms] paper | ours | f_sw [kHz] ours |\n|---|---|---|---|---|---|\n";
    for x in &r.table3 {
        s += &format!(
            "| {} | {:.2} | {:.2} | {:.2} | {} | {:.1} |\n",
            x.t_tol_nm,
            x.paper_id_max_a,
            x.id_max_a,
            x.paper_iq_settling_time_ms,
            opt(x.iq_settling_time_ms, 3),
            x.fsw_khz
        );
    }
    s += "\n### Table 4: influence of p (T_tol = 0.08 Nm, 10 ms run with the step)\n\n";
    s += "| p | abs I_d,max [A] paper | ours | f_sw [kHz] paper | ours (transitions/leg/s) | settling of I_q [ms] ours |\n|---|---|---|---|---|---|\n";
    for x in &r.table4 {
        s += &format!(
            "| {} | {:.2} | {:.2} | {:.1} | {:.1} | {} |\n",
            x.p,
            x.paper_id_max_a,
            x.id_max_a,
            x.paper_fsw_khz,
            x.fsw_khz,
            opt(x.iq_settling_time_ms, 3)
        );
    }
    s += "\n### Fig. 10: +-0.4 Nm toggle every 10 ms (mean of 3 steps)\n\n";
    s += "| | settling [ms] paper | ours (mean / max) | overshoot [%] | f_sw [kHz] (transitions/leg/s) | carrier-equivalent [kHz] | ripple RMS [Nm] |\n|---|---|---|---|---|---|---|\n";
    for (n, m, p) in [
        ("MPDTC 64 kHz", &r.step_mpdtc, 0.19),
        ("FOC 16 kHz", &r.step_foc, 0.27),
    ] {
        s += &format!(
            "| {n} | {p} | {} / {} | {:.1} | {:.1} | {:.1} | {:.4} |\n",
            opt(m.settling_time_ms, 3),
            opt(m.settling_time_max_ms, 3),
            m.overshoot_percent,
            m.fsw_khz,
            m.fsw_carrier_equiv_khz,
            m.torque_ripple_rms_nm
        );
    }
    s += "\n### Fig. 11: torque loop, 0.3 Nm sine\n\n";
    s += "| f [Hz] | MPDTC gain [dB] | phase [deg] | FOC gain [dB] | phase [deg] |\n|---|---|---|---|---|\n";
    for a in &r.bode_mpdtc.points {
        let b = r.bode_foc.points.iter().find(|b| b.freq_hz == a.freq_hz);
        let fb = b.map_or("n/a (>= f_s/2) | n/a".into(), |b| {
            format!("{:.2} | {:.1}", b.gain_db, b.phase_deg)
        });
        s += &format!(
            "| {} | {:.2} | {:.1} | {fb} |\n",
            a.freq_hz, a.gain_db, a.phase_deg
        );
    }
    s += &format!(
        "\n-3 dB bandwidth: MPDTC {} Hz (paper about 5000), FOC {} Hz\n",
        opt(r.bode_mpdtc.bandwidth_hz, 0),
        opt(r.bode_foc.bandwidth_hz, 0)
    );
    let g = &r.agreement;
    s += &format!(
        "\n### Fixed-point core vs f64 reference (Fig. 10 run)\n\nsame decision in {:.2} % of {} periods; 1 ms torque means differ by at most {:.4} Nm; settling {} ms (fixed) vs {} ms (reference); ripple RMS {:.4} vs {:.4} Nm\n",
        g.same_decision_percent,
        g.periods,
        g.torque_block_mean_max_diff_nm,
        opt(g.settling_time_fixed_ms, 3),
        opt(g.settling_time_ref_ms, 3),
        g.torque_ripple_rms_fixed_nm,
        g.torque_ripple_rms_ref_nm
    );
    s
}

fn write_csv(dir: &Path, r: &Results) -> Result<()> {
    let w = |name: &str, text: String| {
        std::fs::write(dir.join(name), text).with_context(|| format!("writing {name}"))
    };
    let mut t = String::from(
        "t_tol_nm,id_max_a,iq_settling_time_ms,paper_id_max_a,paper_iq_settling_time_ms,fsw_khz\n",
    );
    for x in &r.table3 {
        t += &format!(
            "{},{},{},{},{},{}\n",
            x.t_tol_nm,
            x.id_max_a,
            x.iq_settling_time_ms
                .map_or(String::new(), |v| v.to_string()),
            x.paper_id_max_a,
            x.paper_iq_settling_time_ms,
            x.fsw_khz
        );
    }
    w("table3.csv", t)?;
    let mut t = String::from("p,id_max_a,fsw_khz,paper_id_max_a,paper_fsw_khz\n");
    for x in &r.table4 {
        t += &format!(
            "{},{},{},{},{}\n",
            x.p, x.id_max_a, x.fsw_khz, x.paper_id_max_a, x.paper_fsw_khz
        );
    }
    w("table4.csv", t)?;
    let trace = |tr: &runs::Trace| {
        let mut t = String::from("t_s,i_d_a,i_q_a,torque_nm,torque_ref_nm\n");
        for x in &tr.windows {
            t += &format!(
                "{:.9},{:.6},{:.6},{:.6},{}\n",
                x.t_s, x.i_d_a, x.i_q_a, x.torque_nm, x.torque_ref_nm
            );
        }
        t
    };
    w("fig10_mpdtc.csv", trace(&r.toggle_mpdtc))?;
    w("fig10_foc.csv", trace(&r.toggle_foc))?;
    for (tt, tr) in &r.table3_traces {
        w(&format!("table3_ttol_{tt}.csv"), trace(tr))?;
    }
    for (p, tr) in &r.table4_traces {
        w(&format!("table4_p_{p}.csv"), trace(tr))?;
    }
    let mut t = String::from("freq_hz,mpdtc_gain_db,mpdtc_phase_deg,foc_gain_db,foc_phase_deg\n");
    for a in &r.bode_mpdtc.points {
        let b = r.bode_foc.points.iter().find(|b| b.freq_hz == a.freq_hz);
        let fb = b.map_or(",".into(), |b| format!("{},{}", b.gain_db, b.phase_deg));
        t += &format!("{},{},{},{fb}\n", a.freq_hz, a.gain_db, a.phase_deg);
    }
    w("fig11_bode.csv", t)?;
    Ok(())
}

/// Throughput: closed-loop control periods per second (MPDTC reference,
/// MPDTC fixed-point model, FOC), and open-loop replay steps per second.
pub fn bench(a: BenchArgs) -> Result<()> {
    use models::pmsm::closed_loop::{self, Controller};
    use models::pmsm::foc::{Foc, FocParams};
    use models::pmsm::mpdtc_ctrl::{MpdtcFixed, MpdtcRef};
    use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
    use models::pmsm::params::{MotorParams, SamplingParams};
    use models::pmsm::plant::{MechanicalMode, Plant};
    use std::time::Instant;
    anyhow::ensure!(
        a.sim_s.is_finite() && a.sim_s > 0.0 && a.sim_s <= 100.0,
        "--sim-s must be in (0, 100]"
    );
    let motor = MotorParams::default();
    let drive = SamplingParams::default();
    let e = |e: models::pmsm::params::ParamError| anyhow::anyhow!("{e}");
    let cfg = MpdtcConfig::new(motor, MpdtcParams::default()).map_err(e)?;
    fn closed<C: Controller>(
        c: &mut C,
        motor: &MotorParams,
        drive: &SamplingParams,
        sim_s: f64,
    ) -> Result<f64> {
        let mut plant = Plant::new(
            motor,
            0.0,
            MechanicalMode::Inertia {
                load_torque_nm: 0.0,
            },
            0.0,
        )
        .map_err(|e| anyhow::anyhow!("{e}"))?;
        let n = (sim_s / c.period_s()).round() as u64;
        let t = Instant::now();
        closed_loop::run(&mut plant, c, drive, n, experiments::toggle_ref, |_| {})
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        Ok(n as f64 / t.elapsed().as_secs_f64())
    }
    let mpdtc_ref = closed(&mut MpdtcRef::new(cfg), &motor, &drive, a.sim_s)?;
    let mpdtc_fixed = closed(
        &mut MpdtcFixed::new(cfg).map_err(e)?,
        &motor,
        &drive,
        a.sim_s,
    )?;
    let foc = closed(
        &mut Foc::new(&motor, &FocParams::default()).map_err(e)?,
        &motor,
        &drive,
        a.sim_s,
    )?;
    // Open loop: `drivectl sim replay`'s own code (one switch state per
    // 15.625 us period, constant speed, one row per period), input prepared
    // beforehand.
    let rc = crate::sim::ReplayConfig {
        r_s_ohm: motor.r_s_ohm,
        l_d_h: motor.l_d_h,
        l_q_h: motor.l_q_h,
        psi_pm_wb: motor.psi_pm_wb,
        pole_pairs: motor.pole_pairs,
        u_dc_v: motor.u_dc_v,
        omega_e_rad_s: 300.0,
        period_s: drive.control_period_s,
        dead_time_s: 0.0,
    };
    let n = (a.sim_s / drive.control_period_s).round() as usize;
    let states: Vec<u8> = (0..n).map(|k| [4u8, 6, 2, 3, 1, 5, 0, 7][k % 8]).collect();
    let t = Instant::now();
    let rows = crate::sim::simulate(&rc, &states)?;
    let replay = n as f64 / t.elapsed().as_secs_f64();
    std::hint::black_box(rows);
    let simdrive_mpdtc = simdrive_loop(true, a.sim_s)?;
    let simdrive_foc = simdrive_loop(false, a.sim_s)?;
    print_stdout(&format!(
        "{}\n",
        serde_json::to_string_pretty(&json!({
            "simdrive": {"mpdtc": simdrive_mpdtc, "foc": simdrive_foc},
            "closed_loop_periods_per_s": {"mpdtc_ref": mpdtc_ref, "mpdtc_fixed": mpdtc_fixed, "foc": foc},
            "closed_loop_simulated_s_per_s": {
                "mpdtc_ref": mpdtc_ref * drive.control_period_s,
                "mpdtc_fixed": mpdtc_fixed * drive.control_period_s,
                "foc": foc * FocParams::default().period_s,
            },
            "replay_steps_per_s": replay,
            "simulated_s_per_measurement": a.sim_s,
        }))?
    ))
}

/// The simulated PL and motor (`simpl::SimDrive`) in closed loop
/// with the firmware's drive code (`drive::servo::Servo`: one control step
/// per control-period boundary, the Fig. 10 toggling reference): control
/// periods per second of host time, and the simulation's work per period
/// (PL cycles stepped, quiet spans skipped, plant segments) to estimate its
/// cost on a slower machine.
fn simdrive_loop(mpdtc: bool, sim_s: f64) -> Result<serde_json::Value> {
    use drive::pl::top::Mode;
    use drive::servo::{Servo, ServoConfig};
    use regmap as rm;
    use regmap::bus::RegisterBus;
    use simpl::{SimConfig, SimDrive};
    use std::time::Instant;
    let e = |e: models::pmsm::params::ParamError| anyhow::anyhow!("{e}");
    let s = |e: drive::servo::ServoError| anyhow::anyhow!("drive: {e:?}");
    let b = |e: regmap::bus::BusError| anyhow::anyhow!("register access failed: {e:?}");
    let mut sim = SimDrive::new(&SimConfig::default()).map_err(e)?;
    let mut servo = Servo::new(&ServoConfig::for_plant(
        sim.config().motor,
        sim.config().adc_amps_per_count,
    ))
    .map_err(e)?;
    servo.init(&mut sim).map_err(b)?;
    servo
        .set_mode(&mut sim, if mpdtc { Mode::Mpdtc } else { Mode::Foc })
        .map_err(s)?;
    servo.enable(&mut sim).map_err(s)?;
    // Past the MPDTC's rotor alignment (and the FOC's ADC phase lock).
    let settle = (3e-3 * servo.control_rate_hz()) as u32;
    for _ in 0..settle {
        if sim.advance_to_boundary(100_000).control_periods == 0 {
            anyhow::bail!("no control-period boundary");
        }
        servo.control_step(&mut sim).map_err(b)?;
    }
    let n = (sim_s * servo.control_rate_hz()).round() as u64;
    let (w0, c0, t0) = (sim.work(), sim.pl_cycles(), sim.time_s());
    let clock = Instant::now();
    for _ in 0..n {
        if sim.advance_to_boundary(100_000).control_periods == 0 {
            anyhow::bail!("no control-period boundary");
        }
        servo
            .set_torque_ref(experiments::toggle_ref(sim.time_s() - t0))
            .map_err(s)?;
        servo.control_step(&mut sim).map_err(b)?;
    }
    let host_s = clock.elapsed().as_secs_f64();
    let w = sim.work();
    let fault = sim.read(rm::FAULT_STATUS_ADDR).map_err(b)?;
    anyhow::ensure!(fault == 0, "the loop tripped a fault ({fault:#x})");
    anyhow::ensure!(servo.overruns() == 0, "the loop overran");
    let per = |x: u64, y: u64| (x - y) as f64 / n as f64;
    Ok(json!({
        "control_periods_per_s": n as f64 / host_s,
        "simulated_s_per_s": (sim.time_s() - t0) / host_s,
        "host_us_per_control_period": host_s / n as f64 * 1e6,
        "per_control_period": {
            "pl_cycles": per(sim.pl_cycles(), c0),
            "stepped_pl_cycles": per(w.stepped_cycles, w0.stepped_cycles),
            "skipped_spans": per(w.skips, w0.skips),
            "plant_segments": per(w.plant_segments, w0.plant_segments),
        },
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `paper mpdtc --json` carries the documented keys (units in the
    /// names), the rows in sweep order, and numbers where
    /// numbers are due; the Markdown has the four tables.
    #[test]
    fn json_has_the_issue_keys_in_order() {
        let r = experiments::all().unwrap();
        let j = to_json(&r);
        let obj = |v: &serde_json::Value, keys: &[&str]| {
            for k in keys {
                assert!(v.get(k).is_some(), "missing {k} in {v}");
            }
        };
        obj(&j, &["table3", "table4", "step", "bode"]);
        let t3: Vec<f64> = j["table3"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| {
                obj(x, &["t_tol_nm", "id_max_a", "iq_settling_time_ms"]);
                assert!(x["id_max_a"].as_f64().unwrap() > 0.0);
                x["t_tol_nm"].as_f64().unwrap()
            })
            .collect();
        assert_eq!(t3, [0.02, 0.04, 0.08, 0.12]);
        let t4: Vec<f64> = j["table4"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| {
                obj(x, &["p", "id_max_a", "fsw_khz"]);
                assert!(x["fsw_khz"].as_f64().unwrap() > 0.0);
                x["p"].as_f64().unwrap()
            })
            .collect();
        assert_eq!(t4, [0.02, 0.1, 0.15, 0.2]);
        for c in ["mpdtc", "foc"] {
            let s = &j["step"][c];
            obj(
                s,
                &[
                    "settling_time_ms",
                    "overshoot_percent",
                    "fsw_khz",
                    "torque_ripple_rms_nm",
                ],
            );
            assert!(s["settling_time_ms"].as_f64().is_some(), "{c} settles");
            let b = &j["bode"][c];
            obj(b, &["bandwidth_hz", "points"]);
            let pts = b["points"].as_array().unwrap();
            assert!(pts.len() >= 14, "{c}: {} points", pts.len());
            obj(&pts[0], &["freq_hz", "gain_db", "phase_deg"]);
        }
        let md = markdown(&r);
        for t in ["Table 3", "Table 4", "Fig. 10", "Fig. 11"] {
            assert!(md.contains(t), "{t}");
        }
    }
}
