//! `drivectl console`, `drivectl send`, `drivectl log`.
use anyhow::{bail, Context as _, Result};
use drivectl::defmt_log::{LiveLog, LogTable};
use drivectl::link::{default_elf, Final, Qemu, Session, PROMPT};
use std::io::{IsTerminal, Read, Write};
use std::path::{Path, PathBuf};
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
    #[arg(long, default_value = DEFAULT_FLASH)]
    pub flash: PathBuf,
    /// Boot a QEMU for this command even when a drive is running
    /// (`drivectl up`); without it, the running drive is used.
    #[arg(long)]
    pub fresh: bool,
    /// Forward this host TCP port (127.0.0.1) to the QEMU firmware's
    /// socketcand server (CANopen over TCP, port 29536 on GEM0), e.g. for
    /// python-can's `socketcand` interface.
    #[arg(long, value_name = "PORT")]
    pub can_port: Option<u16>,
}

const DEFAULT_FLASH: &str = "target/run/qspi-flash.img";

impl Target {
    /// The firmware this command talks to: the board on `--port`; else the
    /// running drive (`drivectl up`), unless `--fresh`; else a QEMU booted
    /// for this command alone (and ended with it), saying so.
    pub fn open(&self, t: Duration) -> Result<Session> {
        if let Some(p) = &self.port {
            return Session::open_serial(p, self.baud, t);
        }
        if let Some(sock) = self.running()? {
            return Session::connect(&sock, t);
        }
        if self.fresh {
            self.check_flash_not_shared()?;
            eprintln!("drivectl: --fresh: booting QEMU for this command");
        } else {
            eprintln!(
                "drivectl: no drive running (`drivectl up` starts one): booting QEMU for this command"
            );
        }
        Session::spawn_qemu(&self.qemu(), t)
    }

    /// Two QEMUs on one flash image would overwrite each other's saved
    /// configuration: `--fresh` beside a running drive needs its own.
    fn check_flash_not_shared(&self) -> Result<()> {
        let run = drivectl::server::RunDir::default_dir();
        if run.live_socket().is_none() {
            return Ok(());
        }
        let Ok(theirs) = std::fs::read_to_string(run.flash()) else {
            return Ok(());
        };
        let ours = self
            .flash
            .canonicalize()
            .unwrap_or_else(|_| self.flash.clone());
        if Path::new(theirs.trim()) == ours {
            bail!(
                "the running drive uses the flash image {}: give this --fresh QEMU another \
                 (--flash FILE)",
                ours.display()
            );
        }
        Ok(())
    }

    /// The running drive's socket, if this command uses it. Options that
    /// describe a QEMU to boot are an error then: they would be ignored.
    pub fn running(&self) -> Result<Option<PathBuf>> {
        if self.fresh || self.port.is_some() {
            return Ok(None);
        }
        let run = drivectl::server::RunDir::default_dir();
        let Some(sock) = run.live_socket() else {
            return Ok(None);
        };
        let boot_options = [
            (self.elf.is_some(), "--elf"),
            (self.icount, "--icount"),
            (self.pl != "sim", "--pl"),
            (self.flash != Path::new(DEFAULT_FLASH), "--flash"),
            (self.can_port.is_some(), "--can-port"),
        ];
        let given: Vec<&str> = boot_options
            .iter()
            .filter(|(set, _)| *set)
            .map(|(_, name)| *name)
            .collect();
        if !given.is_empty() {
            let info = std::fs::read_to_string(run.info()).unwrap_or_default();
            bail!(
                "a drive is running ({}, console {}); {} describe a QEMU to boot: \
                 add --fresh to boot one for this command, or `drivectl down` first",
                info.trim(),
                sock.display(),
                given.join(", ")
            );
        }
        Ok(Some(sock))
    }

    pub fn qemu(&self) -> Qemu {
        let mut q = Qemu::new(self.elf.clone().unwrap_or_else(default_elf));
        q.icount = self.icount;
        q.pl_rtl = self.pl == "rtl";
        q.flash = Some(self.flash.clone());
        q.can_port = self.can_port;
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
    target.open(t)
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
    let interactive = std::io::stdin().is_terminal();
    if let Some(sock) = a.target.running()? {
        let s = Session::connect(&sock, Duration::from_secs(20))?;
        let run = drivectl::server::RunDir::default_dir();
        eprintln!(
            "drivectl: the running drive's console ({}); defmt log in {}",
            sock.display(),
            run.defmt_log().display()
        );
        return if interactive {
            eprint!("drivectl: Ctrl-] quits (the drive keeps running)\r\n");
            let mut out = std::io::stdout();
            out.write_all(PROMPT.as_bytes())?;
            out.flush()?;
            session_terminal(s)
        } else {
            piped_console(s)
        };
    }
    let mut q = a.target.qemu();
    let defmt_log = own_defmt_log(&a.defmt_log);
    let live = LiveLog::start(&q.elf, &defmt_log)?;
    q.defmt_raw = Some(live.raw().to_path_buf());
    eprintln!(
        "drivectl: firmware {} in QEMU for this console alone (`drivectl up` keeps one running); \
         defmt log (decoded) in {}",
        q.elf.display(),
        defmt_log.display()
    );
    if q.pl_rtl {
        eprintln!("drivectl: PL = the Verilated pl_top (pl-cosim)");
    }
    let result = Session::spawn_qemu(&q, Duration::from_secs(20)).and_then(|s| {
        if interactive {
            eprintln!("drivectl: Ctrl-] (or Ctrl-A X) quits and ends QEMU");
        }
        let mut out = std::io::stdout();
        out.write_all(&s.transcript)?;
        out.flush()?;
        if interactive {
            session_terminal(s)
        } else {
            piped_console(s)
        }
    });
    let frames = live.finish()?;
    eprintln!("drivectl: {frames} log frames in {}", defmt_log.display());
    result
}

/// The defmt log of a console's own QEMU: `wanted`, unless that is the
/// running drive's (a `--fresh` console beside it would truncate it), then
/// `defmt-fresh.log` beside it, said on standard error.
fn own_defmt_log(wanted: &Path) -> PathBuf {
    let run = drivectl::server::RunDir::default_dir();
    let theirs = run.defmt_log();
    let same = run.live_socket().is_some()
        && wanted.canonicalize().ok().as_deref() == theirs.canonicalize().ok().as_deref();
    if !same {
        return wanted.to_path_buf();
    }
    let other = theirs.with_file_name("defmt-fresh.log");
    eprintln!(
        "drivectl: {} is the running drive's defmt log; this console's goes to {}",
        theirs.display(),
        other.display()
    );
    other
}

/// The bytes typed on the terminal: Ctrl-] quits; so does Ctrl-A then
/// `x` (QEMU's own key, which users of `scripts/run` know). A Ctrl-A is
/// held back until the next byte says what it was.
#[derive(Default)]
struct Keys {
    after_ctrl_a: bool,
}

impl Keys {
    /// The bytes of `chunk` to send, and whether a quit key came (the bytes
    /// before it are sent, none after).
    fn feed(&mut self, chunk: &[u8]) -> (Vec<u8>, bool) {
        let mut send = Vec::with_capacity(chunk.len());
        for &b in chunk {
            match (std::mem::take(&mut self.after_ctrl_a), b) {
                (_, 0x1d) | (true, b'x' | b'X') => return (send, true),
                (false, 0x01) => self.after_ctrl_a = true,
                (true, _) => send.extend_from_slice(&[0x01, b]),
                (false, _) => send.push(b),
            }
        }
        (send, false)
    }
}

/// Standard input in chunks of at most `max` bytes, read by a thread; the
/// channel closes at its end.
fn stdin_chunks(max: usize) -> mpsc::Receiver<Vec<u8>> {
    let (tx, rx) = mpsc::channel::<Vec<u8>>();
    std::thread::spawn(move || {
        let mut stdin = std::io::stdin();
        let mut buf = vec![0u8; max];
        while let Ok(n) = stdin.read(&mut buf) {
            if n == 0 || tx.send(buf[..n].to_vec()).is_err() {
                break;
            }
        }
    });
    rx
}

/// A raw terminal on a console session (QEMU's pipes or the running
/// drive's socket): typed bytes go out as typed, the firmware's text
/// comes back (telemetry frames are not shown); Ctrl-] quits. A QEMU the
/// session started ends cleanly (its flash writes kept).
fn session_terminal(mut s: Session) -> Result<()> {
    let saved = stty(&["-g"]).ok();
    stty(&["raw", "-echo"]).context("cannot put the terminal in raw mode")?;
    let rx = stdin_chunks(64);
    let mut out = std::io::stdout();
    let mut keys = Keys::default();
    let result = loop {
        match s.recv_text(Duration::from_millis(20)) {
            Ok(text) => {
                let _ = out.write_all(&text);
                let _ = out.flush();
            }
            Err(e) => break Err(e),
        }
        let chunk = match rx.try_recv() {
            Ok(c) => c,
            Err(mpsc::TryRecvError::Empty) => continue,
            Err(mpsc::TryRecvError::Disconnected) => break Ok(()),
        };
        let (send, quit) = keys.feed(&chunk);
        if quit {
            let _ = s.send(&send);
            break Ok(());
        }
        if let Err(e) = s.send(&send) {
            break Err(e);
        }
    };
    if let Some(st) = saved {
        let _ = stty(&[st.trim()]);
    }
    eprintln!();
    let quit = s.quit(Duration::from_secs(10));
    result.and(quit)
}

/// Standard input is a pipe: hold it until the firmware is ready, relay
/// both ways, quit one second after the input ends and the firmware is back
/// at its prompt (a slow command, e.g. a `step` on the co-simulated RTL,
/// may print nothing for longer; at most 30 s of silence).
fn piped_console(mut s: Session) -> Result<()> {
    let mut out = std::io::stdout();
    let rx = stdin_chunks(1024);
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

/// The drive answered `ERR`: the command ran and was refused, as opposed
/// to a link or host failure. `drivectl` exits 1 for it, 2 for the others.
#[derive(Debug)]
pub struct Refused(pub String);

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Refused {}

pub fn send(a: SendArgs) -> Result<()> {
    let t = timeout(a.timeout_s)?;
    let mut s = a.target.open(t)?;
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
            Err(Refused(format!("`{}`: ERR {code} {message}", a.command)).into())
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

#[cfg(test)]
mod tests {
    use super::*;

    fn typed(bytes: &[u8]) -> (Vec<u8>, bool) {
        Keys::default().feed(bytes)
    }

    #[test]
    fn ctrl_close_bracket_and_ctrl_a_x_quit_other_bytes_go_through() {
        assert_eq!(typed(b"status\r\x1dmore"), (b"status\r".to_vec(), true));
        assert_eq!(typed(b"st\x01x"), (b"st".to_vec(), true));
        assert_eq!(typed(b"st\x01X"), (b"st".to_vec(), true));
        // Ctrl-A before anything else is sent as typed.
        assert_eq!(typed(b"\x01a\x03"), (b"\x01a\x03".to_vec(), false));
    }
}
