//! `drivectl calibrate [PHASE] [--save] [--out DIR]`: runs `calibrate` on
//! the drive with a progress bar (one step per phase line), writes the
//! configuration it left (the format of `config pull`), the reply and a
//! plot of each line fit the reply gives the points of (`fit ...` lines:
//! resistance, flux, friction) to `DIR`, and with `--save` keeps the
//! configuration in the drive's flash.
use crate::console::{session, timeout, Refused, Target};
use anyhow::{Context, Result};
use drivectl::link::{parse_reply, Final};
use std::path::PathBuf;

/// The points of each `fit <name>: <x> <unit>, <y> <unit>` line group, in
/// reply order.
pub fn fits(lines: &[String]) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut out: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for l in lines {
        let Some((name, rest)) = l.strip_prefix("fit ").and_then(|r| r.split_once(": ")) else {
            continue;
        };
        let num = |s: &str| s.split_whitespace().next()?.parse::<f64>().ok();
        let Some((x, y)) = rest
            .split_once(", ")
            .and_then(|(x, y)| Some((num(x)?, num(y)?)))
        else {
            continue;
        };
        match out.iter_mut().find(|(n, _)| n == name) {
            Some((_, v)) => v.push((x, y)),
            None => out.push((name.to_string(), vec![(x, y)])),
        }
    }
    out
}

/// Axis labels of each fit.
fn labels(name: &str) -> (&'static str, &'static str, &'static str) {
    match name {
        "resistance" => (
            "Resistance: voltage over current along phase a (slope R)",
            "current [A]",
            "voltage [V]",
        ),
        "flux" => (
            "Flux linkage: q-axis voltage balance over speed (slope psi)",
            "electrical speed [rad/s]",
            "v_q - R i_q - w L i_d - dead time [V]",
        ),
        _ => (
            "Friction: torque at steady speeds (slope b, intercept T_c)",
            "mechanical speed [rad/s]",
            "torque [N m]",
        ),
    }
}

/// The measured points and their least-squares line, as SVG.
fn plot_fit(name: &str, pts: &[(f64, f64)]) -> Result<String> {
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let slope = sxy / sxx;
    let x0 = pts
        .iter()
        .map(|p| p.0)
        .fold(f64::INFINITY, f64::min)
        .min(0.0);
    let x1 = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let line = vec![(x0, my + slope * (x0 - mx)), (x1, my + slope * (x1 - mx))];
    let (title, xl, yl) = labels(name);
    crate::plot::line_plot(
        title,
        xl,
        yl,
        &[
            crate::plot::Series {
                name: "measured".into(),
                points: pts.to_vec(),
                color: "#1f77b4",
                dashed: false,
                markers: true,
            },
            crate::plot::Series {
                name: format!("fit: slope {slope:.4e}"),
                points: line,
                color: "#d62728",
                dashed: true,
                markers: false,
            },
        ],
        false,
    )
}

#[derive(clap::Args)]
pub struct CalibrateArgs {
    #[command(flatten)]
    pub target: Target,
    /// `all` or one phase: encoder, resistance, inductance, flux, mechanics.
    #[arg(default_value = "all")]
    pub phase: String,
    /// `config save` on the drive after the calibration.
    #[arg(long)]
    pub save: bool,
    /// Directory of `calibration.toml` (the configuration after the
    /// calibration, as `config pull` writes it) and `calibration.txt` (the
    /// drive's reply).
    #[arg(long, default_value = "target/calibration")]
    pub out: PathBuf,
    /// Seconds to wait for boot and for the reply (a calibration takes
    /// about 1.3 s of PL time for `all`, longer under QEMU).
    #[arg(long, default_value_t = 600.0)]
    pub timeout_s: f64,
}

/// Phases `calibrate all` prints a line for.
const PHASES: u64 = 5;

pub fn calibrate(a: CalibrateArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let mut s = session(&a.target, t)?;
    std::fs::create_dir_all(&a.out)
        .with_context(|| format!("cannot create {}", a.out.display()))?;
    let bar = indicatif::ProgressBar::new(if a.phase == "all" { PHASES } else { 1 });
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")
            .expect("progress template"),
    );
    s.send(format!("calibrate {}\r", a.phase).as_bytes())?;
    let mut text = String::new();
    loop {
        let line = String::from_utf8_lossy(&s.read_until(b"\r\n", t)?).into_owned();
        text += &line;
        let l = line.trim();
        if let Some(rest) = l.strip_prefix("calibrate: ") {
            if !rest.contains("refused") && !rest.contains("poor fit") {
                bar.inc(1);
                bar.set_message(rest.split(':').next().unwrap_or("").to_string());
            }
        }
        if l == "OK" || l.starts_with("ERR ") {
            break;
        }
    }
    text += &String::from_utf8_lossy(&s.read_until(drive::console::PROMPT.as_bytes(), t)?);
    bar.finish_and_clear();
    let reply = parse_reply(&text)?;
    for l in &reply.lines {
        println!("{l}");
    }
    let txt = a.out.join("calibration.txt");
    let mut all = reply.lines.join("\n");
    all += &format!("\n{:?}\n", reply.fin);
    std::fs::write(&txt, all).with_context(|| format!("cannot write {}", txt.display()))?;
    let (schema, values) = drivectl::config_file::pull(&mut s, t)?;
    let toml = a.out.join("calibration.toml");
    std::fs::write(&toml, drivectl::config_file::to_toml(&schema, &values)?)
        .with_context(|| format!("cannot write {}", toml.display()))?;
    println!("written: {}, {}", toml.display(), txt.display());
    for (name, pts) in fits(&reply.lines) {
        let svg = a.out.join(format!("fit-{name}.svg"));
        std::fs::write(&svg, plot_fit(&name, &pts)?)
            .with_context(|| format!("cannot write {}", svg.display()))?;
        println!("written: {}", svg.display());
    }
    if a.save {
        let r = s.command("config save", t)?;
        match r.fin {
            Final::Ok => println!("{}", r.lines.join("\n")),
            Final::Err { code, message } => {
                println!("ERR {code} {message}");
                return Err(Refused(format!("config save: ERR {code} {message}")).into());
            }
        }
    }
    if let Final::Err { code, message } = reply.fin {
        println!("ERR {code} {message}");
        return Err(Refused(format!("calibrate {}: ERR {code} {message}", a.phase)).into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_lines_group_and_plot() {
        let lines: Vec<String> = [
            "motor_r_s = 5.5e-1 ohm (was 5.55e-1, +-1e-3)",
            "fit resistance: 4.0000 A, 2.7200 V",
            "fit resistance: 8.0000 A, 4.9400 V",
            "fit friction: 30.000 rad/s, 0.011000 Nm",
            "fit resistance: 6.0000 A, 3.8300 V",
            "fit flux: nonsense",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        let f = fits(&lines);
        assert_eq!(f.len(), 2);
        assert_eq!(f[0].0, "resistance");
        assert_eq!(f[0].1, vec![(4.0, 2.72), (8.0, 4.94), (6.0, 3.83)]);
        assert_eq!(f[1], ("friction".to_string(), vec![(30.0, 0.011)]));
        let svg = plot_fit("resistance", &f[0].1).unwrap();
        // The slope of the three points: 0.555 ohm.
        assert!(svg.contains("slope 5.5500e-1"), "{svg}");
    }
}
