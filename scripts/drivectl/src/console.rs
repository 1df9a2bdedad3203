//! `drivectl console`, `drivectl send`, `drivectl log`.
use anyhow::{bail, Context as _, Result};
use drivectl::defmt_log::LogTable;
use drivectl::link::{default_elf, Final, Qemu, Session, PROMPT};
use std::io::{IsTerminal, Read, Write};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// Where the firmware is.
#[derive(clap::Args, Clone)]
pub struct Target {
    /// Serial device of a board (e.g. /dev/ttyUSB1); without it the firmware
    /// is booted in QEMU.
    #[arg(long)]
    pub port: Option<String>,
    /// Baud rate of --port, 8N1 (the firmware's console UART runs at 921600).
    #[arg(long, default_value_t = drive::telemetry::CONSOLE_BAUD)]
    pub baud: u32,
    /// Firmware ELF booted in QEMU (default: this checkout's release build).
    #[arg(long)]
    pub elf: Option<PathBuf>,
    /// Run QEMU with -icount shift=0 (repeatable guest time).
    #[arg(long)]
    pub icount: bool,
    /// What the QEMU firmware's PL is: `sim` (the fast simulated PL) or
    /// `rtl` (the Verilated pl_top through the co-simulation bridge
    /// `pl-cosim`; implies -icount).
    #[arg(long, default_value = "sim", value_parser = ["sim", "rtl"])]
    pub pl: String,
    /// QSPI flash image of QEMU (the saved configuration); created erased
    /// (16 MiB of 0xFF) when missing.
    #[arg(long, default_value = "target/run/qspi-flash.img")]
    pub flash: PathBuf,
}

impl Target {
    pub fn qemu(&self) -> Qemu {
        let mut q = Qemu::new(self.elf.clone().unwrap_or_else(default_elf));
        q.icount = self.icount;
        q.pl_rtl = self.pl == "rtl";
        q.flash = Some(self.flash.clone());
        q
    }
}

#[derive(clap::Args)]
pub struct ConsoleArgs {
    #[command(flatten)]
    pub target: Target,
    /// Decoded defmt log (UART0) of the QEMU firmware; the raw stream goes
    /// beside it with `.bin` appended.
    #[arg(long, default_value = "target/run/defmt.log")]
    pub defmt_log: PathBuf,
}

#[derive(clap::Args)]
pub struct SendArgs {
    #[command(flatten)]
    pub target: Target,
    /// Seconds to wait for boot and for the reply.
    #[arg(long, default_value_t = 20.0)]
    pub timeout_s: f64,
    /// The command line, e.g. "status".
    pub command: String,
}

#[derive(clap::Args)]
pub struct ConfigFileArgs {
    #[command(flatten)]
    pub target: Target,
    /// Seconds to wait for boot and for each reply.
    #[arg(long, default_value_t = 20.0)]
    pub timeout_s: f64,
    /// The TOML file.
    pub file: PathBuf,
}

pub fn session(target: &Target, t: Duration) -> Result<Session> {
    match &target.port {
        Some(p) => Session::open_serial(p, target.baud, t),
        None => Session::spawn_qemu(&target.qemu(), t),
    }
}

pub fn config_pull(a: ConfigFileArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let mut s = session(&a.target, t)?;
    let (schema, values) = drivectl::config_file::pull(&mut s, t)?;
    let text = drivectl::config_file::to_toml(&schema, &values)?;
    std::fs::write(&a.file, text).with_context(|| format!("cannot write {}", a.file.display()))?;
    println!(
        "{} parameters written to {}",
        values.len(),
        a.file.display()
    );
    Ok(())
}

pub fn config_push(a: ConfigFileArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let text = std::fs::read_to_string(&a.file)
        .with_context(|| format!("cannot read {}", a.file.display()))?;
    let mut s = session(&a.target, t)?;
    let n = drivectl::config_file::push(&mut s, &text, t)
        .with_context(|| format!("push {}", a.file.display()))?;
    println!("{n} parameters set and saved to the drive's flash");
    Ok(())
}

#[derive(clap::Args)]
pub struct LogArgs {
    /// Firmware ELF that produced the log (its defmt table decodes it).
    #[arg(long)]
    pub elf: Option<PathBuf>,
    /// Keep reading the input as it grows (Ctrl-C to stop).
    #[arg(long)]
    pub follow: bool,
    /// Raw defmt stream (UART0 capture); `-` for standard input.
    pub input: PathBuf,
}

pub fn timeout(s: f64) -> Result<Duration> {
    if !(s.is_finite() && s > 0.0 && s <= 3600.0) {
        bail!("--timeout-s must be in (0, 3600] s, got {s}");
    }
    Ok(Duration::from_secs_f64(s))
}

pub fn console(a: ConsoleArgs) -> Result<()> {
    if let Some(port) = &a.target.port {
        return serial_terminal(port, a.target.baud);
    }
    let mut q = a.target.qemu();
    let raw = PathBuf::from(format!("{}.bin", a.defmt_log.display()));
    if let Some(dir) = a.defmt_log.parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(&raw, b"").with_context(|| format!("cannot create {}", raw.display()))?;
    q.defmt_raw = Some(raw.clone());
    let table = LogTable::load(&q.elf)?;
    let mut log_out = std::fs::File::create(&a.defmt_log)
        .with_context(|| format!("cannot create {}", a.defmt_log.display()))?;
    let stop = Arc::new(AtomicBool::new(false));
    let decoder = {
        let (stop, raw) = (stop.clone(), raw.clone());
        std::thread::spawn(move || -> Result<usize> {
            let f = std::fs::File::open(&raw)?;
            table.decode(f, &mut log_out, Some(stop))
        })
    };
    eprintln!(
        "drivectl: firmware {} in QEMU; defmt log (decoded) in {}",
        q.elf.display(),
        a.defmt_log.display()
    );
    let result = if std::io::stdin().is_terminal() {
        eprintln!("drivectl: console on this terminal; Ctrl-A X quits QEMU\r");
        // The bridge lives as long as QEMU does.
        let bridge = if q.pl_rtl {
            let b = drivectl::cosim::Bridge::start()?;
            q.cosim_dir = Some(b.dir().to_path_buf());
            eprintln!(
                "drivectl: PL = the Verilated pl_top (pl-cosim in {})\r",
                b.dir().display()
            );
            Some(b)
        } else {
            None
        };
        let status = q
            .interactive()?
            .status()
            .context("cannot start qemu-system-arm")?;
        if let Some(b) = bridge {
            if let Ok(stats) = b.finish() {
                eprintln!("drivectl: pl-cosim: {}", stats.trim());
            }
        }
        if status.success() {
            Ok(())
        } else {
            Err(anyhow::anyhow!("QEMU exited with {status}"))
        }
    } else {
        piped_console(&q)
    };
    stop.store(true, Ordering::Relaxed);
    let frames = decoder
        .join()
        .map_err(|_| anyhow::anyhow!("decoder thread panicked"))??;
    eprintln!("drivectl: {frames} log frames in {}", a.defmt_log.display());
    result
}

/// Standard input is a pipe: hold it until the firmware is ready, relay
/// both ways, quit one second after the input ends and the firmware is back
/// at its prompt (a slow command, e.g. a `step` on the co-simulated RTL,
/// may print nothing for longer; at most 30 s of silence).
fn piped_console(q: &Qemu) -> Result<()> {
    let mut s = Session::spawn_qemu(q, Duration::from_secs(20))?;
    let mut out = std::io::stdout();
    out.write_all(&s.transcript)?;
    let (tx, rx) = mpsc::channel::<Vec<u8>>();
    std::thread::spawn(move || {
        let mut stdin = std::io::stdin();
        let mut buf = [0u8; 1024];
        while let Ok(n) = stdin.read(&mut buf) {
            if n == 0 || tx.send(buf[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    let mut eof_at: Option<Instant> = None;
    let mut tail: Vec<u8> = Vec::new();
    loop {
        match rx.try_recv() {
            Ok(chunk) => s.send(&chunk)?,
            Err(mpsc::TryRecvError::Empty) => {}
            Err(mpsc::TryRecvError::Disconnected) => {
                eof_at.get_or_insert_with(Instant::now);
            }
        }
        let got = s.drain_quiet(Duration::from_millis(20), Duration::from_millis(100))?;
        out.write_all(&got)?;
        out.flush()?;
        tail.extend_from_slice(&got);
        let keep = tail.len().saturating_sub(PROMPT.len());
        tail.drain(..keep);
        if !got.is_empty() {
            if let Some(t) = &mut eof_at {
                *t = Instant::now();
            }
        }
        let at_prompt = tail == PROMPT.as_bytes();
        if eof_at.is_some_and(|t| {
            let e = t.elapsed();
            (at_prompt && e > Duration::from_secs(1)) || e > Duration::from_secs(30)
        }) {
            if let Some(Ok(stats)) = s.finish_bridge() {
                eprintln!("drivectl: pl-cosim: {}", stats.trim());
            }
            return Ok(());
        }
    }
}

/// A raw terminal on a serial port (like picocom); Ctrl-] quits.
fn serial_terminal(port: &str, baud: u32) -> Result<()> {
    let p = serialport::new(port, baud)
        .timeout(Duration::from_millis(50))
        .open()
        .with_context(|| format!("cannot open serial port {port}"))?;
    let mut reader = p.try_clone()?;
    let mut writer = p;
    let saved = stty(&["-g"]).ok();
    stty(&["raw", "-echo"]).context("cannot put the terminal in raw mode")?;
    eprint!("drivectl: {port} at {baud} 8N1; Ctrl-] quits\r\n");
    let done = Arc::new(AtomicBool::new(false));
    let d2 = done.clone();
    let echo = std::thread::spawn(move || {
        let mut buf = [0u8; 256];
        let mut out = std::io::stdout();
        while !d2.load(Ordering::Relaxed) {
            match reader.read(&mut buf) {
                Ok(n) if n > 0 => {
                    let _ = out.write_all(&buf[..n]);
                    let _ = out.flush();
                }
                _ => {}
            }
        }
    });
    let mut stdin = std::io::stdin();
    let mut buf = [0u8; 64];
    let result = loop {
        let n = match stdin.read(&mut buf) {
            Ok(0) => break Ok(()),
            Ok(n) => n,
            Err(e) => break Err(e.into()),
        };
        if let Some(i) = buf[..n].iter().position(|&b| b == 0x1d) {
            let _ = writer.write_all(&buf[..i]);
            break Ok(());
        }
        if let Err(e) = writer.write_all(&buf[..n]) {
            break Err(e.into());
        }
    };
    done.store(true, Ordering::Relaxed);
    let _ = echo.join();
    if let Some(s) = saved {
        let _ = stty(&[s.trim()]);
    }
    eprintln!();
    result
}

fn stty(args: &[&str]) -> Result<String> {
    let tty = std::fs::File::open("/dev/tty")?;
    let o = std::process::Command::new("stty")
        .args(args)
        .stdin(tty)
        .output()?;
    if !o.status.success() {
        bail!("stty {args:?} failed");
    }
    Ok(String::from_utf8_lossy(&o.stdout).into_owned())
}

pub fn send(a: SendArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let mut s = match &a.target.port {
        Some(p) => Session::open_serial(p, a.target.baud, t)?,
        None => Session::spawn_qemu(&a.target.qemu(), t)?,
    };
    let reply = s.command(&a.command, t)?;
    for l in &reply.lines {
        println!("{l}");
    }
    match reply.fin {
        Final::Ok => {
            println!("OK");
            Ok(())
        }
        Final::Err { code, message } => {
            println!("ERR {code} {message}");
            drop(s);
            std::process::exit(1);
        }
    }
}

pub fn log(a: LogArgs) -> Result<()> {
    let table = LogTable::load(&a.elf.unwrap_or_else(default_elf))?;
    let stop = a.follow.then(|| Arc::new(AtomicBool::new(false)));
    let mut out = std::io::stdout();
    if a.input.as_os_str() == "-" {
        table.decode(std::io::stdin(), &mut out, stop)?;
    } else {
        let f = std::fs::File::open(&a.input)
            .with_context(|| format!("cannot open {}", a.input.display()))?;
        table.decode(f, &mut out, stop)?;
    }
    Ok(())
}
