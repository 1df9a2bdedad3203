//! `drivectl experiment move`: `move` on the firmware (QEMU by default,
//! `--port` for a board) and the same move in the host simulation of the
//! same loops on the same plant code (`drivectl::motion`); the figures side
//! by side, and the host run's position, velocity, following error and
//! torque as CSV and SVG in `--out`. The capture buffer has no position
//! and velocity channels yet, so the traces are the host simulation's.
use crate::experiment::{num, ok, open, Common, Mode};
use anyhow::{bail, Context as _, Result};
use drivectl::motion::{run_move, Sample};
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

/// Both runs' figures.
#[derive(Debug, serde::Serialize)]
struct Report {
    mode: &'static str,
    distance_rev: f64,
    drive: Figures,
    host: Figures,
    csv: std::path::PathBuf,
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

fn write_csv(path: &Path, rows: &[Sample]) -> Result<()> {
    let mut out = String::from("t_ms,position_rev,velocity_rev_s,position_ref_rev,following_error_counts,torque_ref_Nm,torque_Nm\n");
    for r in rows {
        let m = &r.motion;
        out += &format!(
            "{:.5},{:.7},{:.5},{:.7},{:.2},{:.5},{:.5}\n",
            r.t_s * 1e3,
            m.position_rev,
            m.velocity_rev_s,
            m.position_ref_rev,
            m.following_error_counts,
            r.torque_ref_nm,
            r.torque_nm
        );
    }
    std::fs::write(path, out).with_context(|| format!("cannot write {}", path.display()))
}

fn e<E: std::fmt::Display>(x: E) -> anyhow::Error {
    anyhow::anyhow!("{x}")
}

fn plot(path: &Path, title: &str, rows: &[Sample]) -> Result<()> {
    type Get = fn(&Sample) -> f64;
    let panels: [(&str, Get); 4] = [
        ("position [rev]", |r| r.motion.position_rev),
        ("velocity [rev/s]", |r| r.motion.velocity_rev_s),
        ("following error [counts]", |r| {
            r.motion.following_error_counts
        }),
        ("torque reference [Nm]", |r| r.torque_ref_nm),
    ];
    let root = SVGBackend::new(path, (900, 900)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(title, ("sans-serif", 18)).map_err(e)?;
    let areas = root.split_evenly((4, 1));
    let t1 = rows.last().map_or(1.0, |r| r.t_s * 1e3);
    for (area, (label, get)) in areas.iter().zip(panels) {
        let (lo, hi) = rows
            .iter()
            .map(get)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                (a.min(x), b.max(x))
            });
        let pad = ((hi - lo) * 0.05).max(1e-6);
        let mut ch = ChartBuilder::on(area)
            .margin(8)
            .x_label_area_size(30)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..t1, (lo - pad)..(hi + pad))
            .map_err(e)?;
        ch.configure_mesh()
            .x_desc("t [ms] (0 = move command)")
            .y_desc(label)
            .draw()
            .map_err(e)?;
        ch.draw_series(LineSeries::new(
            rows.iter().map(|r| (r.t_s * 1e3, get(r))),
            &BLUE,
        ))
        .map_err(e)?;
    }
    root.present().map_err(e)?;
    Ok(())
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
    let mut s = open(&a.common.target)?;
    let cmd = Duration::from_secs(30);
    if a.common.target.port.is_none() {
        ok(&mut s, "sim set locked 0", cmd)?;
    }
    ok(&mut s, &format!("mode {}", a.mode.name()), cmd)?;
    ok(&mut s, "enable", cmd)?;
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
    let m = match a.mode {
        Mode::Foc => drive::pl::top::Mode::Foc,
        Mode::Mpdtc => drive::pl::top::Mode::Mpdtc,
    };
    let (h, rows) = run_move(m, &[("locked", 0.0)], a.distance, a.window_ms * 1e-3)?;
    let host = Figures {
        move_time_ms: h.move_time_s * 1e3,
        settling_ms: h.settling_s.map(|t| t * 1e3),
        overshoot_counts: h.overshoot_counts,
        max_following_error_counts: h.max_following_error_counts,
        final_error_counts: h.final_error_counts,
    };
    let name = format!("move_{}", a.mode.name());
    let (csv, svg) = (
        a.common.out.join(format!("{name}.csv")),
        a.common.out.join(format!("{name}.svg")),
    );
    write_csv(&csv, &rows)?;
    let title = format!(
        "{} move {} rev (host simulation of the drive's loops, bare rotor)",
        a.mode.name().to_uppercase(),
        a.distance
    );
    plot(&svg, &title, &rows)?;
    let rep = Report {
        mode: a.mode.name(),
        distance_rev: a.distance,
        drive,
        host,
        csv,
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
        println!("wrote {} and {}", rep.csv.display(), rep.svg.display());
    }
    Ok(())
}
