//! `drivectl experiment step|sweep` and `drivectl capture`: experiments on
//! the firmware through its console (QEMU by default, `--port` for a
//! board), with the PL capture buffer's record as CSV and an SVG plot in
//! `--out`, a table on the terminal or one JSON line (`--json`).
use crate::console::Target;
use anyhow::{anyhow, bail, Context as _, Result};
use drivectl::link::{Final, Reply, Session};
use indicatif::{ProgressBar, ProgressStyle};
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Control mode of an experiment.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// FOC (PI + SVPWM) on the PS.
    Foc,
    /// The PL's MPDTC core.
    Mpdtc,
}

impl Mode {
    pub(crate) fn name(self) -> &'static str {
        match self {
            Mode::Foc => "foc",
            Mode::Mpdtc => "mpdtc",
        }
    }
}

#[derive(clap::Args)]
pub struct Common {
    #[command(flatten)]
    pub target: Target,
    /// Directory for the CSV and SVG files (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// One JSON line on stdout instead of the table.
    #[arg(long)]
    pub json: bool,
}

#[derive(clap::Args)]
pub struct StepArgs {
    #[command(flatten)]
    pub common: Common,
    /// Control mode.
    #[arg(long, value_enum, default_value = "mpdtc")]
    pub mode: Mode,
    /// Step target, N m (from rest).
    #[arg(long, default_value_t = 0.4)]
    pub to: f64,
    /// Capture samples kept before the step.
    #[arg(long, default_value_t = 64)]
    pub pre: u32,
}

#[derive(clap::Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub common: Common,
    /// Control mode.
    #[arg(long, value_enum, default_value = "mpdtc")]
    pub mode: Mode,
    /// First frequency, Hz.
    #[arg(long, default_value_t = 200.0)]
    pub f_start: f64,
    /// Last frequency, Hz (at most a quarter of the control rate).
    #[arg(long, default_value_t = 12_000.0)]
    pub f_stop: f64,
    /// Sine amplitude, N m.
    #[arg(long, default_value_t = 0.2)]
    pub amplitude: f64,
    /// Number of frequencies (log spaced).
    #[arg(long, default_value_t = 8)]
    pub points: u32,
}

#[derive(clap::Args)]
pub struct CaptureArgs {
    #[command(flatten)]
    pub common: Common,
    /// Control mode set (and gates enabled) before arming; none: as it is.
    #[arg(long, value_enum)]
    pub mode: Option<Mode>,
    /// Trigger: manual (triggered right away), step, fault, or
    /// <channel>>x / <channel><x (i_d, i_q [A], torque, torque_ref [Nm]).
    #[arg(long, default_value = "manual")]
    pub trigger: String,
    /// Samples kept before the trigger.
    #[arg(long, default_value_t = 64)]
    pub pre: u32,
    /// Seconds to wait for the trigger and the record.
    #[arg(long, default_value_t = 60.0)]
    pub timeout_s: f64,
}

const BOOT: Duration = Duration::from_secs(20);
const CMD: Duration = Duration::from_secs(30);

pub(crate) fn open(t: &Target) -> Result<Session> {
    t.open(BOOT)
}

/// Sends `line`; an `ERR` reply is an error with the firmware's message.
pub(crate) fn ok(s: &mut Session, line: &str, timeout: Duration) -> Result<Reply> {
    let r = s.command(line, timeout)?;
    match &r.fin {
        Final::Ok => Ok(r),
        Final::Err { code, message } => bail!("`{line}`: ERR {code} {message}"),
    }
}

pub(crate) fn field<'a>(r: &'a Reply, key: &str) -> Option<&'a str> {
    r.lines
        .iter()
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(": "))
        .and_then(|v| v.split_whitespace().next())
}

pub(crate) fn num(r: &Reply, key: &str) -> Result<f64> {
    field(r, key)
        .and_then(|v| v.parse().ok())
        .ok_or_else(|| anyhow!("no number for `{key}` in {:?}", r.lines))
}

fn spinner(msg: &str, quiet: bool) -> ProgressBar {
    if quiet {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::new_spinner();
    pb.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    pb.set_message(msg.to_string());
    pb.enable_steady_tick(Duration::from_millis(100));
    pb
}

/// One sample of a `capture dump`.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct Row {
    pub t_ms: f64,
    pub i_d_a: f64,
    pub i_q_a: f64,
    pub torque_nm: f64,
    pub torque_ref_nm: f64,
    pub sw: u8,
    pub adc_ia_raw: i32,
    /// Multi-turn position modulo 2^32 as the drive wrote it, counts.
    pub position_counts: i32,
    pub velocity_rev_s: f64,
    pub following_error_counts: f64,
}

/// Parses the `capture dump` reply (header, then CSV rows).
pub fn parse_dump(r: &Reply) -> Result<Vec<Row>> {
    let mut it = r.lines.iter();
    let header = it.next().ok_or_else(|| anyhow!("empty capture dump"))?;
    if !header.starts_with("t_ms,") {
        bail!("unexpected capture dump header {header:?}");
    }
    it.map(|l| {
        let v: Vec<&str> = l.split(',').collect();
        if v.len() != 10 {
            bail!("bad capture row {l:?}");
        }
        let f = |i: usize| -> Result<f64> {
            v[i].parse().with_context(|| format!("bad number in {l:?}"))
        };
        Ok(Row {
            t_ms: f(0)?,
            i_d_a: f(1)?,
            i_q_a: f(2)?,
            torque_nm: f(3)?,
            torque_ref_nm: f(4)?,
            sw: v[5].parse()?,
            adc_ia_raw: v[6].parse()?,
            position_counts: v[7].parse()?,
            velocity_rev_s: f(8)?,
            following_error_counts: f(9)?,
        })
    })
    .collect()
}

/// Waits for a complete record, then dumps it.
pub(crate) fn wait_and_dump(s: &mut Session, timeout_s: f64, quiet: bool) -> Result<Vec<Row>> {
    let pb = spinner("capture: waiting for the record", quiet);
    let t0 = std::time::Instant::now();
    loop {
        let st = ok(s, "capture status", CMD)?;
        let state = field(&st, "capture").unwrap_or("?").to_string();
        pb.set_message(format!(
            "capture: {state}, {} samples",
            field(&st, "samples").unwrap_or("?")
        ));
        if state == "done" {
            break;
        }
        if t0.elapsed().as_secs_f64() > timeout_s {
            pb.finish_and_clear();
            bail!("capture not complete after {timeout_s} s (state {state})");
        }
        std::thread::sleep(Duration::from_millis(200));
    }
    pb.set_message("capture: reading the record");
    let rows = parse_dump(&ok(s, "capture dump", Duration::from_secs(120))?)?;
    pb.finish_and_clear();
    if rows.len() < 2 {
        bail!("the record has {} samples", rows.len());
    }
    Ok(rows)
}

pub(crate) fn write_csv(path: &Path, rows: &[Row]) -> Result<()> {
    let mut out = String::from("t_ms,i_d_A,i_q_A,torque_Nm,torque_ref_Nm,sw_state,adc_ia_raw\n");
    for r in rows {
        out += &format!(
            "{},{},{},{},{},{},{}\n",
            r.t_ms, r.i_d_a, r.i_q_a, r.torque_nm, r.torque_ref_nm, r.sw, r.adc_ia_raw
        );
    }
    std::fs::write(path, out).with_context(|| format!("cannot write {}", path.display()))
}

fn err<E: std::fmt::Display>(e: E) -> anyhow::Error {
    anyhow!("plot: {e}")
}

fn range(v: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    let lo = v.clone().fold(f64::INFINITY, f64::min);
    let hi = v.fold(f64::NEG_INFINITY, f64::max);
    let pad = ((hi - lo) * 0.08).max(1e-3);
    (lo - pad, hi + pad)
}

/// Torque and reference (top), i_d and i_q (bottom) against time, up to
/// `until_ms` after the trigger (`None`: the whole record).
pub(crate) fn plot_record(
    path: &Path,
    title: &str,
    rows: &[Row],
    until_ms: Option<f64>,
) -> Result<()> {
    let n = rows
        .iter()
        .take_while(|r| until_ms.is_none_or(|u| r.t_ms <= u))
        .count()
        .max(2)
        .min(rows.len());
    let rows = &rows[..n];
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (top, bottom) = root.split_vertically(380);
    let (t0, t1) = (rows[0].t_ms, rows[rows.len() - 1].t_ms);
    let (ylo, yhi) = range(rows.iter().flat_map(|r| [r.torque_nm, r.torque_ref_nm]));
    let mut ch = ChartBuilder::on(&top)
        .caption(title, ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(t0..t1, ylo..yhi)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("t [ms] (0 = trigger)")
        .y_desc("torque [Nm]")
        .draw()
        .map_err(err)?;
    for (label, color, f) in [
        (
            "torque reference",
            RED,
            (|r: &Row| r.torque_ref_nm) as fn(&Row) -> f64,
        ),
        ("torque (measured currents)", BLUE, |r: &Row| r.torque_nm),
    ] {
        ch.draw_series(LineSeries::new(
            rows.iter().map(|r| (r.t_ms, f(r))),
            color.stroke_width(2),
        ))
        .map_err(err)?
        .label(label)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    ch.configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    let (ilo, ihi) = range(rows.iter().flat_map(|r| [r.i_d_a, r.i_q_a]));
    let mut ch = ChartBuilder::on(&bottom)
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d(t0..t1, ilo..ihi)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("t [ms]")
        .y_desc("current [A]")
        .draw()
        .map_err(err)?;
    for (label, color, f) in [
        ("i_q", BLUE, (|r: &Row| r.i_q_a) as fn(&Row) -> f64),
        ("i_d", GREEN, |r: &Row| r.i_d_a),
    ] {
        ch.draw_series(LineSeries::new(
            rows.iter().map(|r| (r.t_ms, f(r))),
            color.stroke_width(1),
        ))
        .map_err(err)?
        .label(label)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    ch.configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

fn prepare(s: &mut Session, mode: Mode) -> Result<()> {
    ok(s, &format!("mode {}", mode.name()), CMD)?;
    ok(s, "enable", CMD)?;
    Ok(())
}

fn out_dir(c: &Common) -> Result<()> {
    std::fs::create_dir_all(&c.out).with_context(|| format!("cannot create {}", c.out.display()))
}

/// The `step` reply's metrics.
#[derive(Debug, serde::Serialize)]
struct StepReport {
    mode: &'static str,
    to_nm: f64,
    settling_ms: Option<f64>,
    overshoot_percent: f64,
    switching_khz: f64,
    final_nm: f64,
    samples: usize,
    sample_period_us: f64,
    csv: PathBuf,
    svg: PathBuf,
}

pub fn step(a: StepArgs) -> Result<()> {
    if !(a.to.is_finite() && a.to.abs() <= 1.0) {
        bail!("--to must be a finite torque within 1.0 Nm, got {}", a.to);
    }
    out_dir(&a.common)?;
    let mut s = open(&a.common.target)?;
    prepare(&mut s, a.mode)?;
    ok(&mut s, &format!("capture arm step {}", a.pre), CMD)?;
    let ts_us = num(&ok(&mut s, "capture status", CMD)?, "sample_period")?;
    let pb = spinner(
        &format!("step to {} Nm in {}", a.to, a.mode.name()),
        a.common.json,
    );
    let r = ok(&mut s, &format!("step {}", a.to), Duration::from_secs(120))?;
    pb.finish_and_clear();
    let rows = wait_and_dump(&mut s, 60.0, a.common.json)?;
    let name = format!("step_{}", a.mode.name());
    let (csv, svg) = (
        a.common.out.join(format!("{name}.csv")),
        a.common.out.join(format!("{name}.svg")),
    );
    write_csv(&csv, &rows)?;
    let settling_ms = field(&r, "settling_time").and_then(|v| v.parse().ok());
    let on = if a.common.target.port.is_some() {
        "board"
    } else {
        "QEMU, simulated PL"
    };
    let title = format!(
        "{} torque step 0 -> {} Nm ({on}): PL capture, {} us per sample",
        a.mode.name().to_uppercase(),
        a.to,
        ts_us
    );
    plot_record(&svg, &title, &rows, Some(3.0))?;
    let rep = StepReport {
        mode: a.mode.name(),
        to_nm: a.to,
        settling_ms,
        overshoot_percent: num(&r, "overshoot")?,
        switching_khz: num(&r, "switching")?,
        final_nm: num(&r, "final")?,
        samples: rows.len(),
        sample_period_us: ts_us,
        csv,
        svg,
    };
    if a.common.json {
        println!("{}", serde_json::to_string(&rep)?);
    } else {
        println!("| quantity | value |\n|---|---|");
        println!("| mode | {} |", rep.mode);
        println!("| step | 0 -> {} Nm |", rep.to_nm);
        match rep.settling_ms {
            Some(t) => println!("| settling (10 % band) | {t} ms |"),
            None => println!("| settling (10 % band) | not settled |"),
        }
        println!("| overshoot | {} % |", rep.overshoot_percent);
        println!("| switching per leg | {} kHz |", rep.switching_khz);
        println!("| final torque | {} Nm |", rep.final_nm);
        println!(
            "| capture | {} samples, {} us each |",
            rep.samples, rep.sample_period_us
        );
        println!("wrote {} and {}", rep.csv.display(), rep.svg.display());
    }
    Ok(())
}

/// One point of the firmware's `sweep` reply.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct Point {
    pub f_hz: f64,
    pub gain_db: f64,
    pub phase_deg: f64,
}

/// Parses a `sweep` reply: the points and the bandwidth (`None`: not
/// reached).
pub fn parse_sweep(r: &Reply) -> Result<(Vec<Point>, Option<f64>)> {
    let mut pts = Vec::new();
    let mut bw = None;
    for l in &r.lines {
        if let Some(b) = l.strip_prefix("bandwidth: ") {
            bw = b.split_whitespace().next().and_then(|x| x.parse().ok());
            continue;
        }
        let v: Vec<f64> = l
            .split_whitespace()
            .filter_map(|x| x.parse().ok())
            .collect();
        if let [f_hz, gain_db, phase_deg] = v[..] {
            pts.push(Point {
                f_hz,
                gain_db,
                phase_deg,
            });
        }
    }
    if pts.is_empty() {
        bail!("no points in the sweep reply {:?}", r.lines);
    }
    Ok((pts, bw))
}

fn plot_bode(path: &Path, title: &str, pts: &[Point]) -> Result<()> {
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (top, bottom) = root.split_vertically(360);
    let (f0, f1) = (pts[0].f_hz * 0.9, pts[pts.len() - 1].f_hz * 1.1);
    let (glo, ghi) = range(pts.iter().map(|p| p.gain_db).chain([-3.5, 1.0]));
    let mut ch = ChartBuilder::on(&top)
        .caption(title, ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d((f0..f1).log_scale(), glo..ghi)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("f [Hz]")
        .y_desc("gain [dB]")
        .draw()
        .map_err(err)?;
    ch.draw_series(LineSeries::new(
        pts.iter().map(|p| (p.f_hz, p.gain_db)),
        BLUE.stroke_width(2),
    ))
    .map_err(err)?;
    ch.draw_series(
        pts.iter()
            .map(|p| Circle::new((p.f_hz, p.gain_db), 4, BLUE.filled())),
    )
    .map_err(err)?;
    ch.draw_series(LineSeries::new(
        [(f0, -3.0), (f1, -3.0)],
        RED.stroke_width(1),
    ))
    .map_err(err)?;
    let (plo, phi) = range(pts.iter().map(|p| p.phase_deg).chain([0.0]));
    let mut ch = ChartBuilder::on(&bottom)
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(55)
        .build_cartesian_2d((f0..f1).log_scale(), plo..phi)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("f [Hz]")
        .y_desc("phase [deg]")
        .draw()
        .map_err(err)?;
    ch.draw_series(LineSeries::new(
        pts.iter().map(|p| (p.f_hz, p.phase_deg)),
        BLUE.stroke_width(2),
    ))
    .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

#[derive(Debug, serde::Serialize)]
struct SweepReport {
    mode: &'static str,
    amplitude_nm: f64,
    points: Vec<Point>,
    bandwidth_hz: Option<f64>,
    csv: PathBuf,
    svg: PathBuf,
}

pub fn sweep(a: SweepArgs) -> Result<()> {
    out_dir(&a.common)?;
    let mut s = open(&a.common.target)?;
    prepare(&mut s, a.mode)?;
    let line = format!(
        "sweep {} {} {} {}",
        a.f_start, a.f_stop, a.amplitude, a.points
    );
    let pb = spinner(
        &format!("{} points in {}", a.points, a.mode.name()),
        a.common.json,
    );
    let r = ok(&mut s, &line, Duration::from_secs(600))?;
    pb.finish_and_clear();
    let (points, bandwidth_hz) = parse_sweep(&r)?;
    let name = format!("sweep_{}", a.mode.name());
    let (csv, svg) = (
        a.common.out.join(format!("{name}.csv")),
        a.common.out.join(format!("{name}.svg")),
    );
    let mut text = String::from("f_hz,gain_db,phase_deg\n");
    for p in &points {
        text += &format!("{},{},{}\n", p.f_hz, p.gain_db, p.phase_deg);
    }
    std::fs::write(&csv, text).with_context(|| format!("cannot write {}", csv.display()))?;
    let title = format!(
        "{} torque loop, {} Nm sine: measured torque / reference (PL capture)",
        a.mode.name().to_uppercase(),
        a.amplitude
    );
    plot_bode(&svg, &title, &points)?;
    let rep = SweepReport {
        mode: a.mode.name(),
        amplitude_nm: a.amplitude,
        points,
        bandwidth_hz,
        csv,
        svg,
    };
    if a.common.json {
        println!("{}", serde_json::to_string(&rep)?);
    } else {
        println!("| f [Hz] | gain [dB] | phase [deg] |\n|---|---|---|");
        for p in &rep.points {
            println!("| {} | {} | {} |", p.f_hz, p.gain_db, p.phase_deg);
        }
        match rep.bandwidth_hz {
            Some(b) => println!("bandwidth (-3 dB): {b} Hz"),
            None => println!("bandwidth (-3 dB): above {} Hz", a.f_stop),
        }
        println!("wrote {} and {}", rep.csv.display(), rep.svg.display());
    }
    Ok(())
}

#[derive(Debug, serde::Serialize)]
struct CaptureReport {
    trigger: String,
    samples: usize,
    trigger_index: usize,
    csv: PathBuf,
    svg: PathBuf,
}

pub fn capture(a: CaptureArgs) -> Result<()> {
    if !(a.timeout_s.is_finite() && a.timeout_s > 0.0) {
        bail!("--timeout-s must be > 0");
    }
    out_dir(&a.common)?;
    let mut s = open(&a.common.target)?;
    if let Some(m) = a.mode {
        prepare(&mut s, m)?;
    }
    ok(&mut s, &format!("capture arm {} {}", a.trigger, a.pre), CMD)?;
    if a.trigger == "manual" {
        ok(&mut s, "capture trigger", CMD)?;
    }
    let rows = wait_and_dump(&mut s, a.timeout_s, a.common.json)?;
    let trigger_index = rows.iter().position(|r| r.t_ms == 0.0).unwrap_or(0);
    let (csv, svg) = (
        a.common.out.join("capture.csv"),
        a.common.out.join("capture.svg"),
    );
    write_csv(&csv, &rows)?;
    plot_record(
        &svg,
        &format!("PL capture, trigger {}", a.trigger),
        &rows,
        None,
    )?;
    let rep = CaptureReport {
        trigger: a.trigger.clone(),
        samples: rows.len(),
        trigger_index,
        csv,
        svg,
    };
    if a.common.json {
        println!("{}", serde_json::to_string(&rep)?);
    } else {
        println!(
            "| trigger | samples | trigger index |\n|---|---|---|\n| {} | {} | {} |",
            rep.trigger, rep.samples, rep.trigger_index
        );
        println!("wrote {} and {}", rep.csv.display(), rep.svg.display());
    }
    Ok(())
}
