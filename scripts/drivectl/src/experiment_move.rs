//! `drivectl experiment move`: `move` on the firmware (QEMU by default,
//! `--port` for a board) recorded by the drive's PL capture buffer
//! (position, velocity, following error and torque channels), and the same
//! move in the host simulation of the same loops on the same plant code
//! (`drivectl::motion`); the figures side by side, both traces as CSV and
//! one SVG in `--out`.
//!
//! The record: `capture arm manual 0 <every>` with `every` control periods
//! per sample so that 1024 samples span the move and its window; the
//! `move` command restarts and triggers it. Both traces are put on one
//! time axis, t = 0 at the trajectory's first control period (the first
//! nonzero torque reference: the move's acceleration feedforward); the
//! delay from the command to that period in the record is reported
//! (`start_delay_ms`: on the host 0, under QEMU the simulated PL runs on
//! while the console finishes the command). The position channel is 32
//! bits of the multi-turn count; it is unwrapped here by sample
//! differences.
use crate::experiment::{num, ok, open, wait_and_dump, Common, Mode, Row};
use anyhow::{bail, Context as _, Result};
use drivectl::motion::{firmware_config, run_move, Sample};
use plotters::prelude::*;
use std::path::Path;
use std::time::Duration;

#[derive(clap::Args)]
pub struct MoveArgs {
    #[command(flatten)]
    pub common: Common,
    /// Torque loop under the position loop.
    #[arg(long, value_enum, default_value = "mpdtc")]
    pub mode: Mode,
    /// Distance, rev.
    #[arg(long, default_value_t = 1.0)]
    pub distance: f64,
    /// Window after the trajectory, ms.
    #[arg(long, default_value_t = 20.0)]
    pub window_ms: f64,
}

/// Samples of a capture record.
const DEPTH: f64 = drive::pl::capture::DEPTH as f64;

/// Both runs' figures, and how the drive's record compares with the host's
/// trace.
#[derive(Debug, serde::Serialize)]
struct Report {
    mode: &'static str,
    distance_rev: f64,
    drive: Figures,
    host: Figures,
    /// From the drive's capture record.
    capture: CaptureFigures,
    csv_drive: std::path::PathBuf,
    csv_host: std::path::PathBuf,
    svg: std::path::PathBuf,
}

#[derive(Debug, serde::Serialize)]
struct Figures {
    move_time_ms: f64,
    settling_ms: Option<f64>,
    overshoot_counts: f64,
    max_following_error_counts: f64,
    final_error_counts: f64,
}

#[derive(Debug, serde::Serialize)]
struct CaptureFigures {
    samples: usize,
    sample_period_us: f64,
    every_periods: u32,
    /// Last sample's position minus the first's, counts.
    travel_counts: f64,
    /// Largest |following error| in the record, counts.
    max_following_error_counts: f64,
    /// Largest |velocity| in the record, rev/s.
    max_velocity_rev_s: f64,
    /// Record time from the trigger to the trajectory's first period, ms.
    start_delay_ms: f64,
    /// Largest |drive - host| over the samples both cover.
    max_position_diff_counts: f64,
    max_velocity_diff_rev_s: f64,
    max_following_error_diff_counts: f64,
}

/// One trace sample in physical units, from either run.
#[derive(Debug, Clone, Copy)]
struct Point {
    t_ms: f64,
    position_rev: f64,
    velocity_rev_s: f64,
    following_error_counts: f64,
    torque_nm: f64,
    torque_ref_nm: f64,
}

fn host_points(rows: &[Sample]) -> Vec<Point> {
    rows.iter()
        .map(|r| Point {
            t_ms: r.t_s * 1e3,
            position_rev: r.motion.position_rev,
            velocity_rev_s: r.motion.velocity_rev_s,
            following_error_counts: r.motion.following_error_counts,
            torque_nm: r.torque_nm,
            torque_ref_nm: r.torque_ref_nm,
        })
        .collect()
}

/// The time of the first nonzero torque reference (the trajectory's first
/// period), ms; 0 if there is none.
fn start_ms(pts: &[Point]) -> f64 {
    pts.iter()
        .find(|p| p.torque_ref_nm != 0.0)
        .map_or(0.0, |p| p.t_ms)
}

/// `pts` with `t0_ms` subtracted from the times.
fn shift(pts: &mut [Point], t0_ms: f64) {
    for p in pts {
        p.t_ms -= t0_ms;
    }
}

/// The record in physical units, the position unwrapped from its 32 bits
/// and relative to the first sample, `offset_ms` added to the times.
fn drive_points(rows: &[Row], cpr: u32, offset_ms: f64) -> Vec<Point> {
    let mut total: i64 = 0;
    let mut prev = rows.first().map_or(0, |r| r.position_counts);
    rows.iter()
        .map(|r| {
            total += i64::from(r.position_counts.wrapping_sub(prev));
            prev = r.position_counts;
            Point {
                t_ms: r.t_ms + offset_ms,
                position_rev: total as f64 / f64::from(cpr),
                velocity_rev_s: r.velocity_rev_s,
                following_error_counts: r.following_error_counts,
                torque_nm: r.torque_nm,
                torque_ref_nm: r.torque_ref_nm,
            }
        })
        .collect()
}

fn write_csv(path: &Path, rows: &[Point]) -> Result<()> {
    let mut out = String::from(
        "t_ms,position_rev,velocity_rev_s,following_error_counts,torque_Nm,torque_ref_Nm\n",
    );
    for p in rows {
        out += &format!(
            "{:.5},{:.7},{:.5},{:.4},{:.5},{:.5}\n",
            p.t_ms,
            p.position_rev,
            p.velocity_rev_s,
            p.following_error_counts,
            p.torque_nm,
            p.torque_ref_nm
        );
    }
    std::fs::write(path, out).with_context(|| format!("cannot write {}", path.display()))
}

fn e<E: std::fmt::Display>(x: E) -> anyhow::Error {
    anyhow::anyhow!("{x}")
}

/// Four panels, the drive's record and the host's trace on each.
fn plot(path: &Path, title: &str, drive: &[Point], host: &[Point]) -> Result<()> {
    type Get = fn(&Point) -> f64;
    let panels: [(&str, Get); 4] = [
        ("position [rev]", |p| p.position_rev),
        ("velocity [rev/s]", |p| p.velocity_rev_s),
        ("following error [counts]", |p| p.following_error_counts),
        ("torque [Nm]", |p| p.torque_nm),
    ];
    let root = SVGBackend::new(path, (900, 1000)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(title, ("sans-serif", 16)).map_err(e)?;
    let areas = root.split_evenly((4, 1));
    let (t0, t1) = drive
        .iter()
        .chain(host)
        .map(|p| p.t_ms)
        .fold((0.0, 1.0), |(a, b): (f64, f64), t| (a.min(t), b.max(t)));
    for (area, (label, get)) in areas.iter().zip(panels) {
        let (lo, hi) = drive
            .iter()
            .chain(host)
            .map(get)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                (a.min(x), b.max(x))
            });
        let pad = ((hi - lo) * 0.05).max(1e-6);
        let mut ch = ChartBuilder::on(area)
            .margin(8)
            .x_label_area_size(30)
            .y_label_area_size(60)
            .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
            .map_err(e)?;
        ch.configure_mesh()
            .x_desc("t [ms] (0 = the trajectory's first control period)")
            .y_desc(label)
            .draw()
            .map_err(e)?;
        for (pts, color, name) in [
            (host, RED, "host simulation"),
            (drive, BLUE, "drive (PL capture)"),
        ] {
            ch.draw_series(LineSeries::new(
                pts.iter().map(|p| (p.t_ms, get(p))),
                &color,
            ))
            .map_err(e)?
            .label(name)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(e)?;
    }
    root.present().map_err(e)?;
    Ok(())
}

/// The largest |drive - host| of each channel over the drive's samples the
/// host run covers (host sample at the nearest time).
fn compare(drive: &[Point], host: &[Point], cpr: u32) -> (f64, f64, f64) {
    let (Some(h0), Some(h1)) = (host.first(), host.get(1)) else {
        return (f64::NAN, f64::NAN, f64::NAN);
    };
    let dt = h1.t_ms - h0.t_ms;
    let mut worst = (0.0_f64, 0.0_f64, 0.0_f64);
    for d in drive {
        let k = ((d.t_ms - h0.t_ms) / dt).round();
        if k < 0.0 || k as usize >= host.len() {
            continue;
        }
        let h = &host[k as usize];
        worst.0 = worst
            .0
            .max((d.position_rev - h.position_rev).abs() * f64::from(cpr));
        worst.1 = worst.1.max((d.velocity_rev_s - h.velocity_rev_s).abs());
        worst.2 = worst
            .2
            .max((d.following_error_counts - h.following_error_counts).abs());
    }
    worst
}

pub fn run(a: MoveArgs) -> Result<()> {
    if !(a.distance.is_finite() && a.distance.abs() <= 100.0) {
        bail!(
            "--distance must be a finite number of revolutions within 100, got {}",
            a.distance
        );
    }
    if !(a.window_ms > 0.0 && a.window_ms <= 500.0) {
        bail!("--window-ms must be in (0, 500], got {}", a.window_ms);
    }
    std::fs::create_dir_all(&a.common.out)
        .with_context(|| format!("cannot create {}", a.common.out.display()))?;
    let m = match a.mode {
        Mode::Foc => drive::pl::top::Mode::Foc,
        Mode::Mpdtc => drive::pl::top::Mode::Mpdtc,
    };
    // The host run first: its move time sizes the record.
    let (h, host_rows) = run_move(m, &[("locked", 0.0)], a.distance, a.window_ms * 1e-3)?;
    let cpr = firmware_config().enc_cpr;
    let mut s = open(&a.common.target)?;
    let cmd = Duration::from_secs(30);
    if a.common.target.port.is_none() {
        ok(&mut s, "sim set locked 0", cmd)?;
    }
    ok(&mut s, &format!("mode {}", a.mode.name()), cmd)?;
    ok(&mut s, "enable", cmd)?;
    // The control period, then a record of 1024 samples over the move and
    // its window (+10 %).
    let period_us = num(&ok(&mut s, "capture arm manual 0 1", cmd)?, "sample_period")?;
    let span_us = (h.move_time_s + a.window_ms * 1e-3) * 1.1e6;
    let every = (span_us / (DEPTH * period_us)).ceil().clamp(1.0, 256.0) as u32;
    let ts_us = num(
        &ok(&mut s, &format!("capture arm manual 0 {every}"), cmd)?,
        "sample_period",
    )?;
    let r = ok(
        &mut s,
        &format!("move {} {}", a.distance, a.window_ms),
        Duration::from_secs(600),
    )?;
    let settling = crate::experiment::field(&r, "settling_time").and_then(|v| v.parse().ok());
    let drive = Figures {
        move_time_ms: num(&r, "move_time")?,
        settling_ms: settling,
        overshoot_counts: num(&r, "overshoot")?,
        max_following_error_counts: num(&r, "max_following_error")?,
        final_error_counts: num(&r, "final_error")?,
    };
    let rec = wait_and_dump(&mut s, 600.0, a.common.json)?;
    // Sample j holds the state after (j + 1) x every - 1 control periods.
    let offset_ms = (ts_us - period_us) * 1e-3;
    let mut drive_pts = drive_points(&rec, cpr, offset_ms);
    let mut host_pts = host_points(&host_rows);
    let (d0, h0) = (start_ms(&drive_pts), start_ms(&host_pts));
    shift(&mut drive_pts, d0);
    shift(&mut host_pts, h0);
    let host = Figures {
        move_time_ms: h.move_time_s * 1e3,
        settling_ms: h.settling_s.map(|t| t * 1e3),
        overshoot_counts: h.overshoot_counts,
        max_following_error_counts: h.max_following_error_counts,
        final_error_counts: h.final_error_counts,
    };
    let (dp, dv, df) = compare(&drive_pts, &host_pts, cpr);
    let fold = |f: fn(&Point) -> f64| {
        drive_pts
            .iter()
            .map(f)
            .fold(0.0, |a: f64, x| a.max(x.abs()))
    };
    let capture = CaptureFigures {
        samples: rec.len(),
        sample_period_us: ts_us,
        every_periods: every,
        start_delay_ms: d0 - offset_ms,
        travel_counts: drive_pts.last().map_or(0.0, |p| p.position_rev) * f64::from(cpr),
        max_following_error_counts: fold(|p| p.following_error_counts),
        max_velocity_rev_s: fold(|p| p.velocity_rev_s),
        max_position_diff_counts: dp,
        max_velocity_diff_rev_s: dv,
        max_following_error_diff_counts: df,
    };
    let name = format!("move_{}", a.mode.name());
    let (csv_drive, csv_host, svg) = (
        a.common.out.join(format!("{name}_drive.csv")),
        a.common.out.join(format!("{name}_host.csv")),
        a.common.out.join(format!("{name}.svg")),
    );
    write_csv(&csv_drive, &drive_pts)?;
    write_csv(&csv_host, &host_pts)?;
    let title = format!(
        "{} move {} rev, bare rotor: drive's PL capture ({:.1} us/sample) and host simulation",
        a.mode.name().to_uppercase(),
        a.distance,
        ts_us
    );
    plot(&svg, &title, &drive_pts, &host_pts)?;
    let rep = Report {
        mode: a.mode.name(),
        distance_rev: a.distance,
        drive,
        host,
        capture,
        csv_drive,
        csv_host,
        svg,
    };
    if a.common.json {
        println!("{}", serde_json::to_string(&rep)?);
    } else {
        let f = |x: Option<f64>| x.map_or("none".into(), |t| format!("{t:.3} ms"));
        println!("| quantity | drive | host simulation |\n|---|---|---|");
        println!(
            "| move time | {:.3} ms | {:.3} ms |",
            rep.drive.move_time_ms, rep.host.move_time_ms
        );
        println!(
            "| settling (+-2 counts) | {} | {} |",
            f(rep.drive.settling_ms),
            f(rep.host.settling_ms)
        );
        println!(
            "| overshoot | {} counts | {:.0} counts |",
            rep.drive.overshoot_counts, rep.host.overshoot_counts
        );
        println!(
            "| max following error | {} counts | {:.1} counts |",
            rep.drive.max_following_error_counts, rep.host.max_following_error_counts
        );
        println!(
            "| final error | {} counts | {:.0} counts |",
            rep.drive.final_error_counts, rep.host.final_error_counts
        );
        let c = &rep.capture;
        println!(
            "capture: {} samples, {:.3} us each ({} control periods), trajectory start {:.3} ms \
             after the trigger; travel {:.0} counts; largest |drive - host|: position {:.2} \
             counts, velocity {:.3} rev/s, following error {:.2} counts",
            c.samples,
            c.sample_period_us,
            c.every_periods,
            c.start_delay_ms,
            c.travel_counts,
            c.max_position_diff_counts,
            c.max_velocity_diff_rev_s,
            c.max_following_error_diff_counts
        );
        println!(
            "wrote {}, {} and {}",
            rep.csv_drive.display(),
            rep.csv_host.display(),
            rep.svg.display()
        );
    }
    Ok(())
}
