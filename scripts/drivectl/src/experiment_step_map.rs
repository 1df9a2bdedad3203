//! `drivectl experiment step-map`: the torque step-response map of the
//! MPDTC and the FOC on the nominal motor and the 26 corners of (R, L, psi),
//! through the firmware's console (`sim set` for the simulated motor's true
//! values, `config set` for the controllers' model, `step` for each case).
//! Cells, judgement and files: [`drivectl::step_map`].
use crate::console::Target;
use crate::experiment::{field, ok, open, plot_record, wait_and_dump, write_csv};
use anyhow::{bail, Context as _, Result};
use drivectl::link::{Final, Session};
use drivectl::step_map::{self, Cell, Corner, Outcome, CASES};
use std::path::PathBuf;
use std::time::{Duration, Instant};

#[derive(clap::Args)]
pub struct StepMapArgs {
    #[command(flatten)]
    pub target: Target,
    /// Directory for step-map.csv and step-map.md (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// Motors: `nominal`, or `all` (nominal and the 26 corners of R, L, psi
    /// in {0.65, 1, 1.35} x nominal).
    #[arg(long, default_value = "all", value_parser = ["nominal", "all"])]
    pub motors: String,
    /// Window of the measured step, ms (the dwell at its start is 20 ms).
    #[arg(long, default_value_t = 10.0)]
    pub window_ms: f64,
    /// Extra `config set` before each motor's runs, as key=value
    /// (repeatable), e.g. --set mpdtc_k=8000.
    #[arg(long = "set")]
    pub set: Vec<String>,
    /// Also run five of the motors (`step_map::CALIBRATED_CORNERS`) with
    /// the controllers' model from `calibrate all` on that motor instead of
    /// its true values.
    #[arg(long)]
    pub calibrated: bool,
}

const CMD: Duration = Duration::from_secs(60);
/// Dwell at a step's start value, ms.
const DWELL_MS: f64 = 20.0;

pub fn run(a: StepMapArgs) -> Result<()> {
    if !(a.window_ms > 0.0 && a.window_ms <= 20.0) {
        bail!("--window-ms must be in (0, 20] ms, got {}", a.window_ms);
    }
    let extra = a
        .set
        .iter()
        .map(|kv| {
            let (k, v) = kv
                .split_once('=')
                .with_context(|| format!("--set {kv:?}: expected key=value"))?;
            let v: f64 = v
                .parse()
                .with_context(|| format!("--set {kv:?}: {v:?} is not a number"))?;
            Ok((k.to_string(), v))
        })
        .collect::<Result<Vec<_>>>()?;
    std::fs::create_dir_all(&a.out)
        .with_context(|| format!("cannot create {}", a.out.display()))?;
    let corners = step_map::corners(a.motors == "all", a.calibrated);
    let t0 = Instant::now();
    let mut cells = Vec::new();
    for (i, c) in corners.iter().enumerate() {
        eprintln!(
            "step-map: motor {}/{} (R x L x psi = {}), {:.0} s so far",
            i + 1,
            corners.len(),
            c.label(),
            t0.elapsed().as_secs_f64()
        );
        let model = if c.calibrated {
            calibrated_model(&a.target, c).with_context(|| format!("motor {}", c.label()))?
        } else {
            c.motor()
        };
        let mut s = open(&a.target).with_context(|| format!("motor {}", c.label()))?;
        let r = motor_cells(&mut s, c, &model, &extra, a.window_ms);
        let _ = s.quit(Duration::from_secs(5));
        cells.extend(r.with_context(|| format!("motor {}", c.label()))?);
    }
    let how = format!(
        "`drivectl experiment step-map --motors {}{} --window-ms {}{}` ({} PL), locked rotor, \
         `torque_limit` 1 N m; each step after a {DWELL_MS} ms dwell at its start value; \
         {:.0} s.",
        a.motors,
        if a.calibrated { " --calibrated" } else { "" },
        a.window_ms,
        a.set
            .iter()
            .map(|kv| format!(" --set {kv}"))
            .collect::<String>(),
        if a.target.pl == "rtl" {
            "the Verilated pl_top"
        } else {
            "the simulated"
        },
        t0.elapsed().as_secs_f64()
    );
    let (csv, md) = (a.out.join("step-map.csv"), a.out.join("step-map.md"));
    std::fs::write(&csv, step_map::csv(&cells))
        .with_context(|| format!("cannot write {}", csv.display()))?;
    std::fs::write(&md, step_map::markdown(&cells, &how))
        .with_context(|| format!("cannot write {}", md.display()))?;
    let sm = step_map::summary(&cells);
    println!(
        "cells run: {}, meeting every MPDTC target: {}, missing one beyond one period's torque \
         step: {}, not run (beyond the current): {}",
        sm.run, sm.meeting, sm.missing_beyond, sm.skipped
    );
    println!(
        "worst MPDTC overshoot: {:.1} %, worst settling ratio MPDTC/FOC: {:.2}, worst final error: {:.1} %",
        sm.worst_overshoot_percent, sm.worst_settling_ratio, sm.worst_final_percent
    );
    println!("files: {} {}", csv.display(), md.display());
    if let Some(i) = sm.worst {
        let cell = &cells[i];
        // A calibrated motor is calibrated again: the same procedure on
        // the same simulated motor, within its error bars.
        let model = if cell.corner.calibrated {
            calibrated_model(&a.target, &cell.corner).context("the worst cell's trace")?
        } else {
            cell.corner.motor()
        };
        let mut s = open(&a.target).context("the worst cell's trace")?;
        let r = trace_worst(&mut s, cell, &model, &extra, a.window_ms, &a.out);
        let _ = s.quit(Duration::from_secs(5));
        r.context("the worst cell's trace")?;
    }
    Ok(())
}

/// Samples of the PL capture before the step's trigger.
const TRACE_PRE: u32 = 16;

/// The worst cell again, MPDTC and FOC, with the PL capture armed on the
/// measured step: `worst-cell-<mode>.csv` and `.svg` in `out`.
fn trace_worst(
    s: &mut Session,
    cell: &Cell,
    model: &models::pmsm::params::MotorParams,
    extra: &[(String, f64)],
    window_ms: f64,
    out: &std::path::Path,
) -> Result<()> {
    set_motor(s, &cell.corner, model, extra)?;
    let (from, to) = cell.case;
    for mode in ["mpdtc", "foc"] {
        ok(s, &format!("mode {mode}"), CMD)?;
        ok(s, "enable", CMD)?;
        dwell(s, from)?;
        ok(s, &format!("capture arm step {TRACE_PRE}"), CMD)?;
        let r = until_aligned(s, &format!("step {to} {window_ms}"))?;
        let rows = wait_and_dump(s, 60.0, true)?;
        ok(s, "disable", CMD)?;
        let (csv, svg) = (
            out.join(format!("worst-cell-{mode}.csv")),
            out.join(format!("worst-cell-{mode}.svg")),
        );
        write_csv(&csv, &rows)?;
        let settling = field(&r, "settling_time").unwrap_or("none");
        let overshoot = field(&r, "overshoot").unwrap_or("?");
        let title = format!(
            "{} {from} -> {to} N m, R x L x psi = {} (QEMU): settling {settling}, overshoot {overshoot}",
            mode.to_uppercase(),
            cell.corner.label()
        );
        plot_record(&svg, &title, &rows, Some(3.0))?;
        println!("worst cell ({mode}): {} {}", csv.display(), svg.display());
    }
    Ok(())
}

/// The motor's true values in the simulation, `model` in the
/// controllers' (the true values, or what `calibrate all` measured), then
/// the extra settings.
fn set_motor(
    s: &mut Session,
    c: &Corner,
    model: &models::pmsm::params::MotorParams,
    extra: &[(String, f64)],
) -> Result<()> {
    let m = c.motor();
    for (k, v) in [("r_s", m.r_s_ohm), ("l", m.l_d_h), ("psi_pm", m.psi_pm_wb)] {
        ok(s, &format!("sim set {k} {v}"), CMD)?;
    }
    for (k, v) in [
        ("motor_pole_pairs", f64::from(model.pole_pairs)),
        ("motor_r_s", model.r_s_ohm),
        ("motor_l", model.l_d_h),
        ("motor_psi_pm", model.psi_pm_wb),
        ("torque_limit", 1.0),
    ] {
        ok(s, &format!("config set {k} {v}"), CMD)?;
    }
    for (k, v) in extra {
        ok(s, &format!("config set {k} {v}"), CMD)?;
    }
    Ok(())
}

/// The six cases of one motor in both modes.
fn motor_cells(
    s: &mut Session,
    c: &Corner,
    model: &models::pmsm::params::MotorParams,
    extra: &[(String, f64)],
    window_ms: f64,
) -> Result<Vec<Cell>> {
    let m = c.motor();
    set_motor(s, c, model, extra)?;
    let current_limit: f64 = {
        // `current_limit = 14 A`
        let r = ok(s, "config get current_limit", CMD)?;
        let v = r
            .lines
            .iter()
            .find_map(|l| l.strip_prefix("current_limit = "))
            .and_then(|v| v.split_whitespace().next())
            .with_context(|| format!("no value in {:?}", r.lines))?;
        v.parse()
            .with_context(|| format!("current_limit {v:?} is not a number"))?
    };
    let mut out = Vec::new();
    let mut run = Vec::new();
    for case in CASES {
        let skip = step_map::infeasible(&m, case, current_limit);
        run.push(skip.is_none());
        let o = Outcome::Skipped(skip.unwrap_or_default());
        out.push(Cell {
            corner: *c,
            case,
            mpdtc: o.clone(),
            foc: o,
        });
    }
    for mode in ["mpdtc", "foc"] {
        let mut enabled = false;
        for (cell, _) in out.iter_mut().zip(&run).filter(|(_, r)| **r) {
            if !enabled {
                ok(s, &format!("mode {mode}"), CMD)?;
                ok(s, "enable", CMD)?;
                enabled = true;
            }
            let o = match one_step(s, cell.case, window_ms) {
                Ok(o) => o,
                Err(e) => {
                    // Leave the drive ready for the next case: the fault
                    // cleared, the mode chosen again (gates off), enabled.
                    let st = s.command("status", CMD)?;
                    let fault = field(&st, "fault").unwrap_or("?").to_string();
                    let _ = s.command("fault clear", CMD)?;
                    enabled = false;
                    Outcome::Failed(format!("{e:#} (fault: {fault})"))
                }
            };
            match mode {
                "mpdtc" => cell.mpdtc = o,
                _ => cell.foc = o,
            }
        }
        if enabled {
            ok(s, "disable", CMD)?;
        }
    }
    Ok(out)
}

/// Sends `line`, retrying while the MPDTC's rotor alignment runs (`ERR
/// aligning`, at most 5 s of wall time).
fn until_aligned(s: &mut Session, line: &str) -> Result<drivectl::link::Reply> {
    let t0 = Instant::now();
    loop {
        let r = s.command(line, CMD)?;
        match &r.fin {
            Final::Ok => return Ok(r),
            Final::Err { code, .. } if code == "aligning" && t0.elapsed().as_secs() < 5 => {
                std::thread::sleep(Duration::from_millis(50));
            }
            Final::Err { code, message } => bail!("`{line}`: ERR {code} {message}"),
        }
    }
}

/// A 20 ms dwell at `from` (reached by a step from 0.1 N m beside it when
/// the reference is already there), then the step to `to` in a window of
/// `window_ms`.
fn one_step(s: &mut Session, (from, to): (f64, f64), window_ms: f64) -> Result<Outcome> {
    dwell(s, from)?;
    let r = until_aligned(s, &format!("step {to} {window_ms}"))?;
    step_map::parse_step(|k| field(&r, k).map(str::to_string))
}

/// The 20 ms dwell at `from` before a measured step (reached by a step
/// from 0.1 N m beside it when the reference is already there).
fn dwell(s: &mut Session, from: f64) -> Result<()> {
    let r = until_aligned(s, "torque")?;
    let now: f64 = field(&r, "torque_ref")
        .and_then(|v| v.parse().ok())
        .context("no torque_ref in the `torque` reply")?;
    if (now - from).abs() < 0.05 {
        let beside = if from + 0.1 <= 1.0 {
            from + 0.1
        } else {
            from - 0.1
        };
        until_aligned(s, &format!("step {beside} 2"))?;
    }
    until_aligned(s, &format!("step {from} {DWELL_MS}"))?;
    Ok(())
}

/// What `calibrate all` measures on the corner's motor, in a drive of its
/// own (the calibration turns the rotor; the map's runs start from the
/// locked rotor's own angle).
fn calibrated_model(t: &Target, c: &Corner) -> Result<models::pmsm::params::MotorParams> {
    let mut s = open(t)?;
    let m = calibrate_in(&mut s, c);
    let _ = s.quit(Duration::from_secs(5));
    m
}

/// `calibrate all` on a free rotor with the corner's true values in the
/// simulation; the model the drive configured from it.
fn calibrate_in(s: &mut Session, c: &Corner) -> Result<models::pmsm::params::MotorParams> {
    let m = c.motor();
    for (k, v) in [("r_s", m.r_s_ohm), ("l", m.l_d_h), ("psi_pm", m.psi_pm_wb)] {
        ok(s, &format!("sim set {k} {v}"), CMD)?;
    }
    ok(s, "sim set locked 0", CMD)?;
    ok(s, "calibrate all", Duration::from_secs(300))?;
    let get = |s: &mut Session, name: &str| -> Result<f64> {
        let r = ok(s, &format!("config get {name}"), CMD)?;
        let prefix = format!("{name} = ");
        r.lines
            .iter()
            .find_map(|l| l.strip_prefix(prefix.as_str()))
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .with_context(|| format!("no value in {:?}", r.lines))
    };
    Ok(models::pmsm::params::MotorParams {
        r_s_ohm: get(s, "motor_r_s")?,
        l_d_h: get(s, "motor_l")?,
        l_q_h: get(s, "motor_l")?,
        psi_pm_wb: get(s, "motor_psi_pm")?,
        pole_pairs: get(s, "motor_pole_pairs")? as u32,
        ..m
    })
}
