//! `drivectl calibrate [PHASE] [--save] [--out DIR]`: runs `calibrate` on
//! the drive with a progress bar (one step per phase line), writes the
//! configuration it left (the format of `config pull`) and the reply to
//! `DIR`, and with `--save` keeps the configuration in the drive's flash.
use crate::console::{session, timeout, Target};
use anyhow::{bail, Context, Result};
use drivectl::link::{parse_reply, Final};
use std::path::PathBuf;

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
    /// about a second of PL time, longer under QEMU).
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
    if a.save {
        let r = s.command("config save", t)?;
        match r.fin {
            Final::Ok => println!("{}", r.lines.join("\n")),
            Final::Err { code, message } => bail!("config save: ERR {code} {message}"),
        }
    }
    if let Final::Err { code, message } = reply.fin {
        bail!("ERR {code} {message}");
    }
    Ok(())
}
