//! The link to a running firmware: QEMU (spawned here) or a serial port, and
//! the console protocol on top of it (see `drive::console`).
use anyhow::{anyhow, bail, Context as _, Result};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

pub use drive::console::PROMPT;

pub use crate::children::end_children_with_parent;
use crate::children::end_with_parent;

/// The last line of the firmware's boot banner: the receiver is on by then.
pub const BANNER_END: &str = "type `help`";

/// The release firmware ELF of this checkout.
pub fn default_elf() -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../target/armv7a-none-eabi/release/firmware");
    p.canonicalize().unwrap_or(p)
}

/// How to boot the firmware in QEMU.
#[derive(Clone, Debug)]
pub struct Qemu {
    /// Firmware ELF.
    pub elf: PathBuf,
    /// Where UART0 (the raw defmt stream) goes; `None` discards it.
    pub defmt_raw: Option<PathBuf>,
    /// `-icount shift=0`: guest time advances 1 ns per instruction, so
    /// timer readings are repeatable cost figures.
    pub icount: bool,
    /// The PL is the co-simulated RTL: a `pl-cosim` bridge is started with
    /// QEMU (see [`crate::cosim`]).
    pub pl_rtl: bool,
    /// The bridge's directory once started (set by the spawner).
    pub cosim_dir: Option<PathBuf>,
    /// Image of the QSPI flash (the configuration store), see
    /// [`ensure_flash_image`]; `None`: an erased flash that lives as long
    /// as QEMU.
    pub flash: Option<PathBuf>,
    /// Host TCP port (on 127.0.0.1) forwarded to the firmware's socketcand
    /// server (`drive::can_gateway::PORT`) through GEM0 on QEMU's user
    /// network; `None`: QEMU's default network, nothing forwarded.
    pub can_port: Option<u16>,
}

/// A TCP port on 127.0.0.1 that nothing listens on right now (the kernel
/// picks it), for [`Qemu::can_port`]: parallel QEMUs get different ones.
/// Another process may still take it before QEMU binds it; QEMU then
/// fails to start and says so.
pub fn free_tcp_port() -> Result<u16> {
    let l = std::net::TcpListener::bind("127.0.0.1:0").context("no free TCP port")?;
    Ok(l.local_addr()?.port())
}

/// QEMU's `-nic` for GEM0 with the host's `port` forwarded to the
/// firmware's socketcand port. The xilinx-zynq-a9 machine gives the
/// first NIC to the GEM at 0xE000B000 (the firmware's GEM0).
pub fn can_nic(port: u16) -> String {
    format!(
        "user,model=cadence_gem,hostfwd=tcp:127.0.0.1:{port}-:{}",
        drive::can_gateway::PORT
    )
}

/// Bytes of the QSPI flash image: QEMU's n25q128, 16 MiB.
pub const FLASH_IMAGE_BYTES: u64 = 16 << 20;

/// Creates `path` as an erased flash image (all 0xFF) if it does not
/// exist; an existing file must have the flash's size.
pub fn ensure_flash_image(path: &Path) -> Result<()> {
    match std::fs::metadata(path) {
        Ok(m) if m.len() == FLASH_IMAGE_BYTES => Ok(()),
        Ok(m) => bail!(
            "flash image {} is {} bytes, expected {FLASH_IMAGE_BYTES} (delete it to start afresh)",
            path.display(),
            m.len()
        ),
        Err(_) => {
            if let Some(dir) = path.parent() {
                std::fs::create_dir_all(dir)?;
            }
            std::fs::write(path, vec![0xFF; FLASH_IMAGE_BYTES as usize])
                .with_context(|| format!("cannot create flash image {}", path.display()))
        }
    }
}

impl Qemu {
    pub fn new(elf: impl Into<PathBuf>) -> Self {
        Self {
            elf: elf.into(),
            defmt_raw: None,
            icount: false,
            pl_rtl: false,
            cosim_dir: None,
            flash: None,
            can_port: None,
        }
    }

    /// QEMU's arguments with the console (UART1) on `console` (a QEMU
    /// chardev spec such as `stdio` or `mon:stdio`).
    pub fn args(&self, console: &str) -> Vec<String> {
        let uart0 = match &self.defmt_raw {
            Some(p) => format!("file:{}", p.display()),
            None => "null".into(),
        };
        let mut a: Vec<String> = [
            "-M",
            "xilinx-zynq-a9",
            "-display",
            "none",
            "-monitor",
            "none",
            "-serial",
            &uart0,
            "-serial",
            console,
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        if let Some(dir) = &self.cosim_dir {
            a.extend(crate::cosim::qemu_args(dir));
        } else if self.icount {
            a.extend(["-icount".into(), "shift=0".into()]);
        }
        if let Some(f) = &self.flash {
            // Drives 0..=7 are the two SPI controllers' flashes; 8 is the
            // QSPI controller's first (bus 0, chip select 0).
            a.extend([
                "-drive".into(),
                format!("if=mtd,index=8,format=raw,file={}", f.display()),
            ]);
        }
        if let Some(port) = self.can_port {
            a.extend(["-nic".into(), can_nic(port)]);
        }
        a.extend(["-kernel".into(), self.elf.display().to_string()]);
        a
    }

    fn check(&self) -> Result<()> {
        if let Some(f) = &self.flash {
            ensure_flash_image(f)?;
        }
        if !self.elf.is_file() {
            bail!(
                "firmware ELF {} not found: build it with `cargo fw-build` (or scripts/run)",
                self.elf.display()
            );
        }
        Ok(())
    }

    /// A QEMU command for an interactive console on this terminal.
    pub fn interactive(&self) -> Result<Command> {
        self.check()?;
        let mut c = Command::new("qemu-system-arm");
        c.args(self.args("mon:stdio"));
        end_with_parent(&mut c);
        Ok(c)
    }
}

/// The final line of a console reply.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Final {
    Ok,
    Err { code: String, message: String },
}

/// A console reply: the lines before the final line, and the final line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reply {
    pub lines: Vec<String>,
    pub fin: Final,
}

impl Reply {
    pub fn is_ok(&self) -> bool {
        self.fin == Final::Ok
    }
}

/// Splits the text the firmware sent after a command line (echo included,
/// up to the next prompt) into a [`Reply`].
pub fn parse_reply(text: &str) -> Result<Reply> {
    let mut lines: Vec<String> = text.split("\r\n").map(str::to_string).collect();
    // The echo of the command is the first line; the prompt follows the last CRLF.
    if lines.len() < 3 {
        bail!("incomplete reply: {text:?}");
    }
    lines.remove(0);
    lines.pop();
    let last = lines.pop().unwrap_or_default();
    let fin = if last == "OK" {
        Final::Ok
    } else if let Some(rest) = last.strip_prefix("ERR ") {
        let (code, message) = rest.split_once(' ').unwrap_or((rest, ""));
        Final::Err {
            code: code.into(),
            message: message.into(),
        }
    } else {
        bail!("reply without a final OK/ERR line: {text:?}");
    };
    Ok(Reply { lines, fin })
}

/// A byte link to the firmware's console.
pub struct Session {
    child: Option<Child>,
    tx: Box<dyn Write + Send>,
    rx: Receiver<Vec<u8>>,
    /// Telemetry frames split off the byte stream (`drive::telemetry`).
    pub frames: crate::frames::Frames,
    /// Received and not yet consumed.
    pending: Vec<u8>,
    /// Everything received so far (for diagnostics).
    pub transcript: Vec<u8>,
    /// The co-simulation bridge of this QEMU, if any.
    bridge: Option<crate::cosim::Bridge>,
    /// The socket of a running drive's console: shut down on drop, or
    /// the reader thread's handle would keep the connection open.
    socket: Option<std::os::unix::net::UnixStream>,
}

impl Session {
    pub(crate) fn new(
        child: Option<Child>,
        tx: Box<dyn Write + Send>,
        mut reader: Box<dyn Read + Send>,
    ) -> Self {
        let (send, rx) = mpsc::channel();
        // Telemetry frames are taken out here: the console's text (and
        // `transcript`) is what it would be without a stream.
        let (frames, mut demux) = crate::frames::Frames::new();
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            loop {
                match reader.read(&mut buf) {
                    Ok(0) => break,
                    Ok(n) => {
                        let text = demux.split(&buf[..n]);
                        if !text.is_empty() && send.send(text).is_err() {
                            break;
                        }
                    }
                    Err(e) if e.kind() == std::io::ErrorKind::TimedOut => continue,
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                    Err(_) => break,
                }
            }
        });
        Self {
            child,
            tx,
            rx,
            frames,
            pending: Vec::new(),
            transcript: Vec::new(),
            bridge: None,
            socket: None,
        }
    }

    /// Boots the firmware in QEMU with the console on pipes and waits for
    /// the end of the boot banner.
    pub fn spawn_qemu(q: &Qemu, boot_timeout: Duration) -> Result<Self> {
        q.check()?;
        let mut q = q.clone();
        let bridge = if q.pl_rtl && q.cosim_dir.is_none() {
            let b = crate::cosim::Bridge::start()?;
            q.cosim_dir = Some(b.dir().to_path_buf());
            Some(b)
        } else {
            None
        };
        let mut cmd = Command::new("qemu-system-arm");
        cmd.args(q.args("stdio"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null());
        end_with_parent(&mut cmd);
        let mut child = cmd
            .spawn()
            .context("cannot start qemu-system-arm (run scripts/setup)")?;
        let tx = Box::new(child.stdin.take().expect("piped stdin"));
        let rx = Box::new(child.stdout.take().expect("piped stdout"));
        let mut s = Self::new(Some(child), tx, rx);
        s.bridge = bridge;
        s.read_until(BANNER_END.as_bytes(), boot_timeout)
            .context("firmware did not boot")?;
        s.read_until(PROMPT.as_bytes(), boot_timeout)?;
        Ok(s)
    }

    /// Opens a serial port (8N1) and synchronises on a fresh prompt.
    pub fn open_serial(port: &str, baud: u32, timeout: Duration) -> Result<Self> {
        let p = serialport::new(port, baud)
            .timeout(Duration::from_millis(100))
            .open()
            .with_context(|| format!("cannot open serial port {port}"))?;
        let reader = p.try_clone().context("cannot clone the serial port")?;
        let mut s = Self::new(None, Box::new(p), Box::new(reader));
        s.sync(timeout)?;
        Ok(s)
    }

    /// Connects to a running drive's console socket (`drivectl up`, see
    /// [`crate::server`]) and synchronises on a fresh prompt.
    pub fn connect(socket: &Path, timeout: Duration) -> Result<Self> {
        let s = std::os::unix::net::UnixStream::connect(socket)
            .with_context(|| format!("cannot connect to {}", socket.display()))?;
        let reader = s.try_clone().context("cannot clone the socket")?;
        let shut = s.try_clone().context("cannot clone the socket")?;
        let mut s = Self::new(None, Box::new(s), Box::new(reader));
        s.socket = Some(shut);
        s.sync(timeout)?;
        Ok(s)
    }

    /// The QEMU process of this session, if it started one.
    pub fn child_id(&self) -> Option<u32> {
        self.child.as_ref().map(Child::id)
    }

    /// Text received and not yet consumed, waiting at most `timeout` for
    /// some; empty on timeout, an error once the link closed.
    pub fn recv_text(&mut self, timeout: Duration) -> Result<Vec<u8>> {
        if self.pending.is_empty() {
            self.pull(Instant::now() + timeout)?;
        }
        Ok(std::mem::take(&mut self.pending))
    }

    /// Synchronises on a fresh prompt, dropping whatever came before.
    ///
    /// Sends a marker the firmware echoes (`sync<nonce>`) and Ctrl-U, which
    /// discards the typed line and prints `^C` and a prompt: a no-op for the
    /// firmware. Waiting for that exact echo, not for any prompt, matters:
    /// a board or a loaded QEMU may still be booting when the marker goes
    /// out, and then its boot prompt (and the answer to a byte sent during
    /// boot) would pass for the answer and leave a stale prompt that the
    /// next command would take for its reply.
    /// Tries three times: bytes sent before the receiver is on are lost.
    pub fn sync(&mut self, timeout: Duration) -> Result<()> {
        let attempt = timeout / 3;
        let mut last = None;
        for k in 0..3u32 {
            self.drain_quiet(Duration::from_millis(200), attempt)?;
            let nonce = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| d.subsec_nanos())
                ^ std::process::id()
                ^ k;
            let marker = format!("sync{nonce:08x}");
            self.send(format!("{marker}\x15").as_bytes())?;
            let answer = format!("{marker}^C\r\n{PROMPT}");
            match self.read_until(answer.as_bytes(), attempt) {
                Ok(_) => return Ok(()),
                Err(e) => last = Some(e),
            }
        }
        Err(last
            .expect("three attempts")
            .context("no prompt from the firmware"))
    }

    pub fn send(&mut self, bytes: &[u8]) -> Result<()> {
        self.tx.write_all(bytes).context("console link closed")?;
        self.tx.flush().context("console link closed")?;
        Ok(())
    }

    fn pull(&mut self, deadline: Instant) -> Result<bool> {
        let left = deadline.saturating_duration_since(Instant::now());
        match self.rx.recv_timeout(left) {
            Ok(chunk) => {
                self.transcript.extend_from_slice(&chunk);
                self.pending.extend_from_slice(&chunk);
                Ok(true)
            }
            Err(RecvTimeoutError::Timeout) => Ok(false),
            Err(RecvTimeoutError::Disconnected) => Err(anyhow!(
                "console link closed; received so far: {:?}",
                String::from_utf8_lossy(&self.transcript)
            )),
        }
    }

    /// Consumes and returns everything up to and including `needle`.
    pub fn read_until(&mut self, needle: &[u8], timeout: Duration) -> Result<Vec<u8>> {
        let deadline = Instant::now() + timeout;
        loop {
            if let Some(i) = self.pending.windows(needle.len()).position(|w| w == needle) {
                let rest = self.pending.split_off(i + needle.len());
                return Ok(std::mem::replace(&mut self.pending, rest));
            }
            if !self.pull(deadline)? {
                bail!(
                    "timeout after {:?} waiting for {:?}; pending: {:?}",
                    timeout,
                    String::from_utf8_lossy(needle),
                    String::from_utf8_lossy(&self.pending)
                );
            }
        }
    }

    /// Consumes everything until the link has been silent for `quiet`
    /// (at most `timeout`); returns it.
    pub fn drain_quiet(&mut self, quiet: Duration, timeout: Duration) -> Result<Vec<u8>> {
        let end = Instant::now() + timeout;
        while Instant::now() < end {
            if !self.pull(Instant::now() + quiet)? {
                break;
            }
        }
        Ok(std::mem::take(&mut self.pending))
    }

    /// Sends one command line and returns the firmware's reply.
    pub fn command(&mut self, line: &str, timeout: Duration) -> Result<Reply> {
        if line.contains(['\r', '\n']) {
            bail!("a command is one line: {line:?}");
        }
        self.send(format!("{line}\r").as_bytes())?;
        let text = self.read_until(PROMPT.as_bytes(), timeout)?;
        parse_reply(&String::from_utf8_lossy(&text))
    }
}

impl Session {
    /// Ends QEMU and returns the co-simulation bridge's statistics line
    /// (JSON: control periods per wall second and more), if it had one.
    pub fn finish_bridge(mut self) -> Option<Result<String>> {
        if let Some(c) = &mut self.child {
            let _ = c.kill();
            let _ = c.wait();
        }
        self.bridge.take().map(crate::cosim::Bridge::finish)
    }
}

impl Session {
    /// Ends the QEMU this session started as its window closing would:
    /// SIGTERM, then waiting (at most `t`, then SIGKILL) for it to exit.
    /// QEMU's clean exit drains its block layer, so every flash write the
    /// firmware finished is in the image file afterwards; a plain kill
    /// (`drop`) may lose the last ones, as a power cut may. Does nothing
    /// for a session without a child process (a serial port).
    pub fn quit(mut self, t: Duration) -> Result<()> {
        let Some(mut c) = self.child.take() else {
            return Ok(());
        };
        let pid = libc::pid_t::try_from(c.id()).context("QEMU's process id")?;
        // SAFETY: kill(2) on the child this session spawned and still owns
        // (not yet waited for, so the id cannot have been reused).
        unsafe { libc::kill(pid, libc::SIGTERM) };
        let end = Instant::now() + t;
        loop {
            if c.try_wait()?.is_some() {
                return Ok(());
            }
            if Instant::now() >= end {
                let _ = c.kill();
                let _ = c.wait();
                bail!("QEMU did not exit within {t:?} of SIGTERM: killed");
            }
            std::thread::sleep(Duration::from_millis(5));
        }
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        if let Some(s) = &self.socket {
            let _ = s.shutdown(std::net::Shutdown::Both);
        }
        if let Some(c) = &mut self.child {
            let _ = c.kill();
            let _ = c.wait();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::net::UnixStream;

    /// A console that boots when its first bytes arrive (they came while it
    /// was booting): banner and boot prompt first, then those bytes as
    /// typed. Echo, `version`, empty lines and Ctrl-U as the firmware does.
    fn fake_console(mut link: UnixStream) {
        let mut out = link.try_clone().unwrap();
        let mut line = Vec::new();
        let mut booted = false;
        let mut buf = [0u8; 256];
        while let Ok(n) = link.read(&mut buf) {
            if n == 0 {
                return;
            }
            let mut o: Vec<u8> = Vec::new();
            if !booted {
                o.extend_from_slice(b"\r\nfirmware banner, type `help`\r\ndrive> ");
                booted = true;
            }
            for &b in &buf[..n] {
                match b {
                    b'\r' => {
                        o.extend_from_slice(b"\r\n");
                        match &line[..] {
                            b"" => {}
                            b"version" => o.extend_from_slice(b"firmware 0.1.0\r\nOK\r\n"),
                            _ => o.extend_from_slice(b"ERR unknown-command x\r\n"),
                        }
                        o.extend_from_slice(PROMPT.as_bytes());
                        line.clear();
                    }
                    0x15 => {
                        o.extend_from_slice(b"^C\r\n");
                        o.extend_from_slice(PROMPT.as_bytes());
                        line.clear();
                    }
                    _ => {
                        o.push(b);
                        line.push(b);
                    }
                }
            }
            if out.write_all(&o).is_err() {
                return;
            }
        }
    }

    /// The sync bytes reach the console while it boots: the boot prompt is
    /// not the answer, and the next command gets its own reply.
    #[test]
    fn sync_while_booting_leaves_no_stale_prompt() {
        let (host, console) = UnixStream::pair().unwrap();
        std::thread::spawn(move || fake_console(console));
        let tx = Box::new(host.try_clone().unwrap());
        let mut s = Session::new(None, tx, Box::new(host));
        s.sync(Duration::from_secs(6)).unwrap();
        let r = s.command("version", Duration::from_secs(2)).unwrap();
        assert!(r.is_ok(), "{r:?}");
        assert_eq!(r.lines, ["firmware 0.1.0"], "{r:?}");
        let r = s.command("nope", Duration::from_secs(2)).unwrap();
        assert!(!r.is_ok(), "{r:?}");
    }

    #[test]
    fn reply_ok_with_lines() {
        let r = parse_reply("status\r\nuptime: 1 s\r\nticks: 3\r\nOK\r\ndrive> ").unwrap();
        assert_eq!(r.lines, ["uptime: 1 s", "ticks: 3"]);
        assert!(r.is_ok());
    }

    #[test]
    fn reply_err() {
        let r = parse_reply("xyz\r\nERR unknown-command `xyz` (try `help`)\r\ndrive> ").unwrap();
        assert_eq!(
            r.fin,
            Final::Err {
                code: "unknown-command".into(),
                message: "`xyz` (try `help`)".into()
            }
        );
        assert!(r.lines.is_empty());
    }

    #[test]
    fn reply_without_final_line_is_an_error() {
        assert!(parse_reply("status\r\nuptime: 1 s\r\ndrive> ").is_err());
        assert!(parse_reply("drive> ").is_err());
    }

    #[test]
    fn qemu_args_put_the_console_on_uart1() {
        let mut q = Qemu::new("fw.elf");
        q.defmt_raw = Some("log.bin".into());
        let a = q.args("stdio").join(" ");
        assert!(a.contains("-serial file:log.bin -serial stdio"), "{a}");
        assert!(a.ends_with("-kernel fw.elf"));
        assert!(!a.contains("icount"));
        assert!(!a.contains("-nic"));
    }

    #[test]
    fn can_port_forwards_to_the_socketcand_port() {
        let mut q = Qemu::new("fw.elf");
        q.can_port = Some(40123);
        let a = q.args("stdio").join(" ");
        assert!(
            a.contains("-nic user,model=cadence_gem,hostfwd=tcp:127.0.0.1:40123-:29536 "),
            "{a}"
        );
        let (p1, p2) = (free_tcp_port().unwrap(), free_tcp_port().unwrap());
        assert!(p1 != 0 && p2 != 0);
    }
}
