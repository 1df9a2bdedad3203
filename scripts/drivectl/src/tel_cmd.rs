//! `drivectl tel`: records the drive's telemetry stream to CSV.
use crate::console::Target;
use anyhow::{Context as _, Result};
use drivectl::tel::{self, RecordOptions};
use std::path::PathBuf;
use std::time::Duration;

#[derive(clap::Args)]
pub struct TelArgs {
    #[command(flatten)]
    pub target: Target,
    /// Channels, comma separated (`drivectl send "tel list"` lists them).
    #[arg(long, default_value = "torque,i_q,torque_ref")]
    pub channels: String,
    /// Samples per second of drive time.
    #[arg(long, default_value_t = 1000)]
    pub rate: u32,
    /// Seconds of drive time to record (the simulated PL's time under QEMU).
    #[arg(long, default_value_t = 1.0)]
    pub seconds: f64,
    /// CSV file written: time_s and one column per channel.
    #[arg(long, default_value = "target/run/tel.csv")]
    pub out: PathBuf,
    /// Also send `status` every this many ms while recording and check that
    /// the replies come whole (0: never).
    #[arg(long, default_value_t = 0)]
    pub status_every_ms: u64,
    /// Seconds to wait for boot, a reply or a frame.
    #[arg(long, default_value_t = 20.0)]
    pub timeout_s: f64,
}

pub fn run(a: TelArgs) -> Result<()> {
    let t = crate::console::timeout(a.timeout_s)?;
    let channels: Vec<String> = a.channels.split(',').map(str::to_string).collect();
    let mut s = a.target.open(t)?;
    let bar = indicatif::ProgressBar::new(1000);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {percent:>3}% of drive time {msg}")
            .expect("progress template"),
    );
    let opts = RecordOptions {
        status_every: (a.status_every_ms > 0).then(|| Duration::from_millis(a.status_every_ms)),
        timeout: t,
    };
    let rec = tel::record(&mut s, a.rate, &channels, a.seconds, opts, &mut |x| {
        bar.set_position((x * 1000.0) as u64)
    })?;
    bar.finish_and_clear();
    if let Some(dir) = a.out.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut f = std::io::BufWriter::new(
        std::fs::File::create(&a.out)
            .with_context(|| format!("cannot write {}", a.out.display()))?,
    );
    tel::write_csv(&rec, &mut f)?;
    let span = rec.rows.last().map_or(0.0, |r| r.time_s);
    println!(
        "{} samples per channel ({}) over {:.4} s of drive time in {:.2} s wall",
        rec.rows.len(),
        rec.channels.join(", "),
        span,
        rec.wall.as_secs_f64()
    );
    println!(
        "lost frames: {}, bad frames: {}, stream: {} B/s of drive time at {} Hz",
        rec.lost, rec.bad, rec.bytes_per_s, rec.rate_hz
    );
    if opts.status_every.is_some() {
        println!(
            "`status` replies while streaming: {} (all whole)",
            rec.status_replies
        );
    }
    println!("written to {}", a.out.display());
    Ok(())
}
