//! One running drive, many clients: the console of a firmware (QEMU or a
//! serial port) shared on a local socket, as `drivectl up` runs it.
//!
//! A client speaks the console's own byte protocol: what it sends goes to
//! the firmware, what the firmware answers comes back, so a
//! [`Session::connect`] works as over a serial port. The server serialises
//! per command: a client holds the console from the first byte of a line to
//! the prompt that ends the reply; the next client's line waits. A line ends
//! as the firmware's line editor ends it (`\r`, `\n` not after `\r`,
//! Ctrl-C, Ctrl-U), and each such end is answered with a prompt.
//!
//! - Ctrl-C from the holder while its command runs (`calibrate`, `move`)
//!   goes through at once. Whether the firmware took it inside the command
//!   or as a line of its own after the reply (one more prompt), the server
//!   resynchronises with a marker before the next client's line.
//! - Telemetry frames go to the client whose stream runs, and to no one
//!   else. The firmware has one stream: another client's `tel start`
//!   suspends the running one, which is resumed when the newer ends
//!   (stopped, or its client gone: the server sends `tel stop`), under the
//!   number and sequence its client knows ([`crate::tel_route`]).
//! - Text nobody asked for (a holder gone mid-reply) goes to the server's
//!   log (standard error), not to another client.
use crate::link::{Session, PROMPT};
use crate::tel_route::{Router, TelLine};
use anyhow::Result;
use std::collections::{HashMap, VecDeque};
use std::io::{Read, Write};
use std::os::unix::net::{UnixListener, UnixStream};
use std::path::{Path, PathBuf};
use std::sync::mpsc::{self, Receiver, Sender};
use std::time::Duration;

/// Where a running drive keeps its files: `<dir>/drive.sock` (the console),
/// `drive.pid` (the server's process), `drive.log` (its log),
/// `defmt.log` (the firmware's decoded defmt log), `drive.info` (how it was
/// started, one line), `drive.flash` (its QEMU's flash image).
#[derive(Clone, Debug)]
pub struct RunDir {
    pub dir: PathBuf,
}

impl RunDir {
    /// `$DRIVECTL_RUN_DIR`, else this checkout's `target/run`.
    pub fn default_dir() -> Self {
        let dir = match std::env::var_os("DRIVECTL_RUN_DIR") {
            Some(d) if !d.is_empty() => PathBuf::from(d),
            _ => {
                let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target/run");
                // The directory may not exist yet: canonicalise its parent.
                match Path::new(env!("CARGO_MANIFEST_DIR"))
                    .join("../../target")
                    .canonicalize()
                {
                    Ok(t) => t.join("run"),
                    Err(_) => p,
                }
            }
        };
        Self { dir }
    }
    pub fn socket(&self) -> PathBuf {
        self.dir.join("drive.sock")
    }
    pub fn pid_file(&self) -> PathBuf {
        self.dir.join("drive.pid")
    }
    pub fn log(&self) -> PathBuf {
        self.dir.join("drive.log")
    }
    pub fn defmt_log(&self) -> PathBuf {
        self.dir.join("defmt.log")
    }
    pub fn info(&self) -> PathBuf {
        self.dir.join("drive.info")
    }
    /// The path of the running QEMU's flash image (one line), absent for a
    /// board.
    pub fn flash(&self) -> PathBuf {
        self.dir.join("drive.flash")
    }

    /// The server's process id, if its pid file names a live process.
    pub fn running_pid(&self) -> Option<i32> {
        let pid: i32 = std::fs::read_to_string(self.pid_file())
            .ok()?
            .trim()
            .parse()
            .ok()?;
        // SAFETY: signal 0 only checks that the process exists.
        (pid > 0 && unsafe { libc::kill(pid, 0) } == 0).then_some(pid)
    }

    /// The socket of a running drive that accepts connections, if any.
    pub fn live_socket(&self) -> Option<PathBuf> {
        let s = self.socket();
        UnixStream::connect(&s).ok().map(|_| s)
    }
}

/// Events of the server's one loop.
enum Event {
    Connected(u64, UnixStream),
    Bytes(u64, Vec<u8>),
    Gone(u64),
    Stop,
}

/// A handle that ends [`serve`] (from a signal thread, say).
#[derive(Clone)]
pub struct Stopper(Sender<Event>);

impl Stopper {
    pub fn stop(&self) {
        let _ = self.0.send(Event::Stop);
    }
}

/// The client that sends the server's own lines (`tel stop`, markers).
const SERVER: u64 = 0;

/// What the console is doing for its holder.
#[derive(Clone, Debug, PartialEq)]
enum Phase {
    /// Bytes of a line are going through; no line end yet.
    Typing,
    /// The line ended; the reply runs until a prompt.
    Reply { ctrl_c: bool },
    /// After a Ctrl-C in a reply: text up to the marker's answer is
    /// dropped (a late Ctrl-C's own `^C` and prompt).
    Resync { answer: Vec<u8> },
}

struct Client {
    out: Option<UnixStream>,
    queue: VecDeque<u8>,
    /// The last byte taken from this client was `\r` (a following `\n`
    /// is the same line end, as the firmware's editor takes it).
    after_cr: bool,
}

struct Server {
    link: Session,
    clients: HashMap<u64, Client>,
    /// Clients with bytes waiting, in arrival order.
    waiting: VecDeque<u64>,
    holder: Option<(u64, Phase)>,
    /// The holder's line as typed (to see `tel start` / `tel stop`).
    line: Vec<u8>,
    /// Whose telemetry frames they are.
    tel: Router,
    /// The holder's line, if it starts or stops the stream, and the reply
    /// to it so far.
    tel_line: Option<TelLine>,
    tel_reply: Vec<u8>,
    /// The last bytes of the reply text (a prompt may arrive split; the
    /// final `OK` is before it).
    tail: Vec<u8>,
    nonce: u32,
}

/// Serves `link` (a booted firmware) on `listener` until [`Stopper::stop`]
/// or until the firmware's link closes; returns the link for a clean quit.
pub fn serve(link: Session, listener: UnixListener) -> (Stopper, ServeHandle) {
    let (tx, rx) = mpsc::channel();
    let stopper = Stopper(tx.clone());
    std::thread::spawn(move || accept(listener, tx));
    (stopper, ServeHandle { link, rx })
}

/// A server ready to run (see [`serve`]).
pub struct ServeHandle {
    link: Session,
    rx: Receiver<Event>,
}

impl ServeHandle {
    /// Runs the server's loop on this thread; the link comes back when it
    /// ends (stopped: `Ok`; the firmware's link closed: `Err`).
    pub fn run(self) -> (Session, Result<()>) {
        let mut s = Server {
            link: self.link,
            clients: HashMap::new(),
            waiting: VecDeque::new(),
            holder: None,
            line: Vec::new(),
            tel: Router::default(),
            tel_line: None,
            tel_reply: Vec::new(),
            tail: Vec::new(),
            nonce: std::process::id(),
        };
        s.clients.insert(
            SERVER,
            Client {
                out: None,
                queue: VecDeque::new(),
                after_cr: false,
            },
        );
        let r = s.run(&self.rx);
        (s.link, r)
    }
}

fn accept(listener: UnixListener, tx: Sender<Event>) {
    for (id, conn) in (SERVER + 1..).zip(listener.incoming()) {
        let Ok(conn) = conn else { continue };
        let Ok(mut reader) = conn.try_clone() else {
            continue;
        };
        if tx.send(Event::Connected(id, conn)).is_err() {
            return;
        }
        let tx = tx.clone();
        std::thread::spawn(move || {
            let mut buf = [0u8; 1024];
            loop {
                match reader.read(&mut buf) {
                    Ok(0) | Err(_) => break,
                    Ok(n) => {
                        if tx.send(Event::Bytes(id, buf[..n].to_vec())).is_err() {
                            return;
                        }
                    }
                }
            }
            let _ = tx.send(Event::Gone(id));
        });
    }
}

/// Whether `b` ends a line in the firmware's editor (given whether the
/// byte before it was `\r`); `None` for a byte the editor drops (`\n`
/// right after `\r`).
fn ends_line(b: u8, after_cr: bool) -> Option<bool> {
    match b {
        b'\n' if after_cr => None,
        b'\r' | b'\n' | 0x03 | 0x15 => Some(true),
        _ => Some(false),
    }
}

impl Server {
    fn run(&mut self, rx: &Receiver<Event>) -> Result<()> {
        loop {
            // The firmware's link is polled in short slices; client events
            // are taken between them.
            loop {
                match rx.try_recv() {
                    Ok(Event::Stop) => return Ok(()),
                    Ok(e) => self.event(e),
                    Err(mpsc::TryRecvError::Empty) => break,
                    Err(mpsc::TryRecvError::Disconnected) => return Ok(()),
                }
            }
            self.advance()?;
            let text = self.link.recv_text(Duration::from_millis(2))?;
            // The session keeps a transcript for diagnostics; a server
            // runs for hours.
            self.link.transcript.clear();
            if !text.is_empty() {
                self.text(&text)?;
            }
            for f in self.link.frames.drain() {
                self.route(f);
            }
        }
    }

    /// A frame to the client whose stream it is, under that client's
    /// stream number and sequence.
    fn route(&mut self, f: drive::telemetry::Sample) {
        let waiting = matches!(self.tel_line, Some(TelLine::Start { .. }));
        if let Some((client, g)) = self.tel.frame(f, waiting) {
            let mut buf = [0u8; drive::telemetry::FRAME_MAX];
            let n = g.encode(&mut buf);
            self.write_to(client, &buf[..n]);
        }
    }

    fn event(&mut self, e: Event) {
        match e {
            Event::Connected(id, out) => {
                // A client that stops reading must not stall the drive's
                // other clients: after this long its writes fail and it
                // is dropped.
                let _ = out.set_write_timeout(Some(Duration::from_secs(2)));
                self.clients.insert(
                    id,
                    Client {
                        out: Some(out),
                        queue: VecDeque::new(),
                        after_cr: false,
                    },
                );
            }
            Event::Bytes(id, bytes) => self.queue(id, &bytes),
            Event::Gone(id) => self.gone(id),
            Event::Stop => {}
        }
    }

    fn queue(&mut self, id: u64, bytes: &[u8]) {
        let Some(c) = self.clients.get_mut(&id) else {
            return;
        };
        c.queue.extend(bytes);
        if !self.waiting.contains(&id) && self.holder.as_ref().map(|h| h.0) != Some(id) {
            self.waiting.push_back(id);
        }
    }

    fn gone(&mut self, id: u64) {
        self.clients.remove(&id);
        self.waiting.retain(|&w| w != id);
        if let Some(line) = self.tel.gone(id) {
            eprintln!("drivectl serve: client {id} left with a telemetry stream running: `{line}`");
            self.queue(SERVER, format!("{line}\r").as_bytes());
        }
        if let Some((h, Phase::Typing)) = &self.holder {
            if *h == id {
                // A half-typed line: Ctrl-U discards it; its prompt ends
                // the turn (the reply goes to no one).
                let _ = self.link.send(&[0x15]);
                self.holder = Some((id, Phase::Reply { ctrl_c: false }));
            }
        }
    }

    /// Moves the holder's bytes to the firmware; gives the console to the
    /// next waiting client when it is free.
    fn advance(&mut self) -> Result<()> {
        loop {
            let Some((id, phase)) = self.holder.clone() else {
                let Some(next) = self.waiting.pop_front() else {
                    return Ok(());
                };
                self.holder = Some((next, Phase::Typing));
                self.line.clear();
                self.tail.clear();
                continue;
            };
            let Some(c) = self.clients.get_mut(&id) else {
                // Gone while holding: its turn ends with the reply.
                if phase == Phase::Typing {
                    self.holder = None;
                }
                return Ok(());
            };
            match phase {
                Phase::Typing => {
                    let mut sent = Vec::new();
                    let mut ended = false;
                    while let Some(b) = c.queue.pop_front() {
                        let after_cr = std::mem::replace(&mut c.after_cr, b == b'\r');
                        match ends_line(b, after_cr) {
                            None => {}
                            Some(end) => {
                                sent.push(b);
                                if end {
                                    ended = true;
                                    break;
                                }
                            }
                        }
                    }
                    if !sent.is_empty() {
                        self.link.send(&sent)?;
                        self.line
                            .extend(sent.iter().filter(|b| !b.is_ascii_control()));
                    }
                    if !ended {
                        return Ok(());
                    }
                    let line = String::from_utf8_lossy(&self.line).trim().to_string();
                    self.tel_line = TelLine::parse(&line);
                    self.tel_reply.clear();
                    self.holder = Some((id, Phase::Reply { ctrl_c: false }));
                    return Ok(());
                }
                Phase::Reply { ctrl_c } => {
                    // Only a Ctrl-C goes through while a command runs.
                    if c.queue.front() == Some(&0x03) {
                        c.queue.pop_front();
                        c.after_cr = false;
                        self.link.send(&[0x03])?;
                        if !ctrl_c {
                            self.holder = Some((id, Phase::Reply { ctrl_c: true }));
                        }
                    }
                    return Ok(());
                }
                Phase::Resync { .. } => return Ok(()),
            }
        }
    }

    /// Text from the firmware: to the holder; a prompt ends its turn.
    fn text(&mut self, text: &[u8]) -> Result<()> {
        let Some((id, phase)) = self.holder.clone() else {
            eprintln!(
                "drivectl serve: text with no command running: {:?}",
                String::from_utf8_lossy(text)
            );
            return Ok(());
        };
        match phase {
            Phase::Typing => self.write_to(id, text),
            Phase::Reply { ctrl_c } => {
                let start = self.tail.len();
                self.tail.extend_from_slice(text);
                let end = find(&self.tail, PROMPT.as_bytes());
                match end {
                    None => {
                        self.write_to(id, text);
                        self.keep_tel_reply(text);
                        let keep = self.tail.len().saturating_sub(TAIL);
                        self.tail.drain(..keep);
                    }
                    Some(e) => {
                        let upto = e.saturating_sub(start).min(text.len());
                        self.write_to(id, &text[..upto]);
                        let rest = text[upto..].to_vec();
                        self.keep_tel_reply(&text[..upto]);
                        self.tel_replied(id);
                        self.tail.clear();
                        if ctrl_c {
                            self.nonce = self.nonce.wrapping_add(1);
                            let marker = format!("resync{:08x}", self.nonce);
                            self.link.send(format!("{marker}\x15").as_bytes())?;
                            self.holder = Some((
                                id,
                                Phase::Resync {
                                    answer: format!("{marker}^C\r\n{PROMPT}").into_bytes(),
                                },
                            ));
                            if !rest.is_empty() {
                                self.text(&rest)?;
                            }
                        } else {
                            self.release(id);
                            if !rest.is_empty() {
                                self.text(&rest)?;
                            }
                        }
                    }
                }
            }
            Phase::Resync { answer } => {
                self.tail.extend_from_slice(text);
                if let Some(e) = find(&self.tail, &answer) {
                    let rest = self.tail.split_off(e);
                    self.tail.clear();
                    self.release(id);
                    if !rest.is_empty() {
                        self.text(&rest)?;
                    }
                }
            }
        }
        Ok(())
    }

    fn keep_tel_reply(&mut self, text: &[u8]) {
        if self.tel_line.is_some() && self.tel_reply.len() < 4096 {
            self.tel_reply.extend_from_slice(text);
        }
    }

    /// The reply to a telemetry line has ended: the router learns the
    /// stream, perhaps a resume is due, and the frames held for it go out.
    fn tel_replied(&mut self, id: u64) {
        let Some(line) = self.tel_line.take() else {
            return;
        };
        let reply = String::from_utf8_lossy(&self.tel_reply).into_owned();
        let ok = reply.ends_with(&format!("\r\nOK\r\n{PROMPT}"));
        if let Some(next) = self.tel.reply(id, SERVER, &line, &reply, ok) {
            eprintln!("drivectl serve: resuming a suspended telemetry stream: `{next}`");
            self.queue(SERVER, format!("{next}\r").as_bytes());
        }
        for f in self.tel.take_held() {
            self.route(f);
        }
    }

    /// The holder's turn is over: the next waiting client goes first; the
    /// holder queues again if it sent more.
    fn release(&mut self, id: u64) {
        self.holder = None;
        if self.clients.get(&id).is_some_and(|c| !c.queue.is_empty()) {
            self.waiting.push_back(id);
        }
    }

    fn write_to(&mut self, id: u64, bytes: &[u8]) {
        let Some(c) = self.clients.get_mut(&id) else {
            return;
        };
        if let Some(out) = &mut c.out {
            // A client that stopped reading is gone for the server: its
            // reader thread reports it.
            if out.write_all(bytes).is_err() {
                eprintln!("drivectl serve: client {id} does not read its replies: dropped");
                let _ = out.shutdown(std::net::Shutdown::Both);
                c.out = None;
            }
        }
    }
}

/// Bytes of reply text kept to find the prompt and the `OK` before it.
const TAIL: usize = 64;

/// The end (exclusive) of the first `needle` in `hay`.
fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len())
        .position(|w| w == needle)
        .map(|i| i + needle.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link::{Final, Session};
    use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
    use std::sync::{Arc, Mutex};

    /// Lines the fake firmware executed, in order.
    type Log = Arc<Mutex<Vec<String>>>;

    /// A console as the firmware's: echo, a reply and a prompt per line
    /// end (`\r`, Ctrl-C, Ctrl-U). `echo X` answers X; `slow` answers
    /// after 300 ms and ignores Ctrl-C, so a Ctrl-C sent during it is a
    /// line of its own afterwards (`^C` and one more prompt); `tel start`
    /// (any channels) starts stream n + 1 (a frame every 5 ms of wall
    /// time, 1 ms of drive time apart) until `tel stop`.
    fn fake_firmware(link: UnixStream, log: Log) {
        let out = Arc::new(Mutex::new(link.try_clone().unwrap()));
        let streaming = Arc::new(AtomicBool::new(false));
        // The stream's number; a `tel start` restarts the sequence.
        let number = Arc::new(AtomicU8::new(0));
        let restart = Arc::new(AtomicBool::new(false));
        {
            let (out, streaming) = (out.clone(), streaming.clone());
            let (number, restart) = (number.clone(), restart.clone());
            std::thread::spawn(move || {
                let mut seq = 0u16;
                loop {
                    std::thread::sleep(Duration::from_millis(5));
                    if restart.swap(false, Ordering::Relaxed) {
                        seq = 0;
                    }
                    if streaming.load(Ordering::Relaxed) {
                        let mut v = [0f32; drive::telemetry::MAX_CHANNELS];
                        v[0] = 0.25;
                        let s = drive::telemetry::Sample {
                            stream: number.load(Ordering::Relaxed),
                            seq,
                            time_us: u32::from(seq) * 1000,
                            n: 1,
                            values: v,
                        };
                        seq = seq.wrapping_add(1);
                        let mut buf = [0u8; drive::telemetry::FRAME_MAX];
                        let n = s.encode(&mut buf);
                        if out.lock().unwrap().write_all(&buf[..n]).is_err() {
                            return;
                        }
                    }
                }
            });
        }
        let mut link = link;
        let mut line = Vec::new();
        let mut buf = [0u8; 256];
        let w = |b: &[u8]| {
            let _ = out.lock().unwrap().write_all(b);
        };
        w(b"banner, type `help`\r\n");
        w(PROMPT.as_bytes());
        while let Ok(n) = link.read(&mut buf) {
            if n == 0 {
                return;
            }
            for &b in &buf[..n] {
                match b {
                    b'\r' => {
                        let l = String::from_utf8_lossy(&line).to_string();
                        line.clear();
                        log.lock().unwrap().push(l.clone());
                        let mut o = b"\r\n".to_vec();
                        if let Some(x) = l.strip_prefix("echo ") {
                            o.extend_from_slice(format!("{x}\r\nOK\r\n").as_bytes());
                        } else if l == "slow" {
                            std::thread::sleep(Duration::from_millis(300));
                            o.extend_from_slice(b"done\r\nOK\r\n");
                        } else if l.starts_with("tel start ") {
                            streaming.store(false, Ordering::Relaxed);
                            let n = number.fetch_add(1, Ordering::Relaxed) + 1;
                            restart.store(true, Ordering::Relaxed);
                            o.extend_from_slice(format!("stream: {n}\r\nOK\r\n").as_bytes());
                        } else if l == "tel stop" {
                            streaming.store(false, Ordering::Relaxed);
                            o.extend_from_slice(b"OK\r\n");
                        } else if !l.is_empty() {
                            o.extend_from_slice(b"ERR unknown-command x\r\n");
                        }
                        o.extend_from_slice(PROMPT.as_bytes());
                        w(&o);
                        if l.starts_with("tel start ") {
                            streaming.store(true, Ordering::Relaxed);
                        }
                    }
                    0x03 | 0x15 => {
                        line.clear();
                        log.lock().unwrap().push("^C".into());
                        let mut o = b"^C\r\n".to_vec();
                        o.extend_from_slice(PROMPT.as_bytes());
                        w(&o);
                    }
                    _ => {
                        line.push(b);
                        w(&[b]);
                    }
                }
            }
        }
    }

    /// A server on a fake firmware, on a socket in a fresh directory.
    fn start() -> (PathBuf, Stopper, Log, std::thread::JoinHandle<()>) {
        let dir = std::env::temp_dir().join(format!(
            "drivectl-serve-{}-{:?}",
            std::process::id(),
            std::thread::current().id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let sock = dir.join("drive.sock");
        let (host, fw) = UnixStream::pair().unwrap();
        let log: Log = Arc::default();
        {
            let log = log.clone();
            std::thread::spawn(move || fake_firmware(fw, log));
        }
        let tx = Box::new(host.try_clone().unwrap());
        let mut link = Session::new(None, tx, Box::new(host));
        link.read_until(PROMPT.as_bytes(), Duration::from_secs(5))
            .unwrap();
        let (stopper, h) = serve(link, UnixListener::bind(&sock).unwrap());
        let j = std::thread::spawn(move || {
            let (_, r) = h.run();
            r.unwrap();
        });
        (sock, stopper, log, j)
    }

    const T: Duration = Duration::from_secs(10);

    /// Waits (at most [`T`]) until the fake firmware's log of lines holds
    /// what `done` looks for.
    fn wait_for(log: &Log, what: &str, done: impl Fn(&[String]) -> bool) {
        let t0 = std::time::Instant::now();
        while !done(&log.lock().unwrap()) {
            assert!(t0.elapsed() < T, "no {what}: {:?}", log.lock().unwrap());
            std::thread::sleep(Duration::from_millis(10));
        }
    }

    #[test]
    fn two_clients_at_once_each_get_their_own_replies() {
        let (sock, stop, log, j) = start();
        let workers: Vec<_> = (0..3)
            .map(|k| {
                let sock = sock.clone();
                std::thread::spawn(move || {
                    let mut s = Session::connect(&sock, T).unwrap();
                    for i in 0..40 {
                        let r = s.command(&format!("echo c{k}-{i}"), T).unwrap();
                        assert_eq!(r.fin, Final::Ok, "{r:?}");
                        assert_eq!(r.lines, [format!("c{k}-{i}")], "{r:?}");
                    }
                })
            })
            .collect();
        for w in workers {
            w.join().unwrap();
        }
        // Every line reached the firmware whole: none interleaved.
        let lines = log.lock().unwrap().clone();
        let echoes = lines.iter().filter(|l| l.starts_with("echo c")).count();
        assert_eq!(echoes, 120, "{lines:?}");
        stop.stop();
        j.join().unwrap();
    }

    #[test]
    fn a_late_ctrl_c_does_not_reach_the_next_clients_reply() {
        let (sock, stop, _log, j) = start();
        let mut a = Session::connect(&sock, T).unwrap();
        let mut b = Session::connect(&sock, T).unwrap();
        // `slow` ignores the Ctrl-C: it becomes a line of its own after
        // the reply, with one more prompt.
        a.send(b"slow\r").unwrap();
        std::thread::sleep(Duration::from_millis(50));
        a.send(&[0x03]).unwrap();
        let bt = std::thread::spawn(move || {
            let r = b.command("echo for-b", T).unwrap();
            assert_eq!(r.lines, ["for-b"], "{r:?}");
            b
        });
        a.read_until(b"done\r\nOK\r\n", T).unwrap();
        a.read_until(PROMPT.as_bytes(), T).unwrap();
        let mut b = bt.join().unwrap();
        let r = a.command("echo for-a", T).unwrap();
        assert_eq!(r.lines, ["for-a"], "{r:?}");
        let r = b.command("echo again", T).unwrap();
        assert_eq!(r.lines, ["again"], "{r:?}");
        stop.stop();
        j.join().unwrap();
    }

    #[test]
    fn frames_go_to_the_stream_owner_and_its_leaving_stops_the_stream() {
        let (sock, stop, log, j) = start();
        let mut owner = Session::connect(&sock, T).unwrap();
        let mut other = Session::connect(&sock, T).unwrap();
        let r = owner.command("tel start 1000 torque", T).unwrap();
        assert!(r.is_ok(), "{r:?}");
        for i in 0..20 {
            let r = other.command(&format!("echo {i}"), T).unwrap();
            assert_eq!(r.lines, [format!("{i}")]);
        }
        let f = owner.frames.next(T).expect("the owner gets frames");
        assert_eq!(f.values[0], 0.25);
        assert!(
            other.frames.drain().is_empty(),
            "frames reached a client that did not start the stream"
        );
        assert_eq!(other.frames.bad(), 0);
        drop(owner);
        wait_for(&log, "a `tel stop` after the owner left", |l| {
            l.iter().any(|l| l == "tel stop")
        });
        let r = other.command("echo after", T).unwrap();
        assert_eq!(r.lines, ["after"]);
        stop.stop();
        j.join().unwrap();
    }

    #[test]
    fn a_client_gone_mid_line_leaves_no_half_line() {
        let (sock, stop, log, j) = start();
        {
            let mut a = Session::connect(&sock, T).unwrap();
            a.send(b"echo half").unwrap();
            std::thread::sleep(Duration::from_millis(50));
        }
        let mut b = Session::connect(&sock, T).unwrap();
        let r = b.command("echo whole", T).unwrap();
        assert_eq!(r.lines, ["whole"], "{r:?}");
        assert!(!log.lock().unwrap().iter().any(|l| l.contains("half")));
        stop.stop();
        j.join().unwrap();
    }

    /// The page streams; a terminal's recording takes the stream over and
    /// stops it: the page's stream comes back, under its own number and
    /// with its sequence continued.
    #[test]
    fn a_stream_taken_over_comes_back_to_its_client() {
        let (sock, stop, log, j) = start();
        let mut page = Session::connect(&sock, T).unwrap();
        let mut term = Session::connect(&sock, T).unwrap();
        let r = page.command("tel start 1000 torque", T).unwrap();
        assert_eq!(r.lines, ["stream: 1"]);
        let first = page.frames.next(T).expect("the page's frames");
        assert_eq!(first.stream, 1);
        let r = term.command("tel start 1000 torque", T).unwrap();
        assert_eq!(r.lines, ["stream: 2"]);
        let f = term.frames.next(T).expect("the terminal's frames");
        assert_eq!(f.stream, 2);
        let r = term.command("tel stop", T).unwrap();
        assert!(r.is_ok());
        // The server resumed the page's stream: the firmware's third.
        wait_for(&log, "the resume", |l| {
            l.iter().filter(|l| l.starts_with("tel start")).count() == 3
        });
        page.frames.drain();
        let g = page.frames.next(T).expect("the page's frames again");
        assert_eq!(g.stream, 1, "under the number the page knows");
        assert!(
            g.seq > first.seq,
            "its sequence goes on: {} after {}",
            g.seq,
            first.seq
        );
        assert!(term.frames.drain().iter().all(|f| f.stream == 2));
        stop.stop();
        j.join().unwrap();
    }
}
