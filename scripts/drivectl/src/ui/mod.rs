//! `drivectl ui`: a local web server with one page (live telemetry plots,
//! status and faults, console, configuration editor, experiments) for the
//! firmware in QEMU or on a board.
//!
//! The page and its scripts are compiled into the binary; uPlot (MIT) is
//! vendored under `ui/vendor/uplot` with its licence. The server listens on
//! a loopback address unless `--allow-remote` is given: the page drives
//! the motor.
//!
//! HTTP API (JSON):
//! - `POST /api/cmd` (body: one command line): the reply, `{"lines": [...],
//!   "ok": bool, "code": "...", "message": "..."}`;
//! - `POST /api/tel/start?rate=<hz>&channels=<a,b>` and `POST /api/tel/stop`:
//!   the stream (the reply as for `/api/cmd`);
//! - `GET /api/tel?since=<k>`: the samples from index `k` on, `{"channels",
//!   "rate_hz", "next", "lost", "bad", "t": [...], "v": [[...], ...]}`.
use crate::console::Target;
use anyhow::{bail, Context as _, Result};
use drivectl::frames::Frames;
use drivectl::link::{Final, Reply, Session};
use drivectl::tel::Stream;
use serde_json::json;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::Duration;

mod server;

#[derive(clap::Args)]
pub struct UiArgs {
    #[command(flatten)]
    pub target: Target,
    /// Address to serve on. Loopback only unless --allow-remote.
    #[arg(long, default_value = "127.0.0.1:8750")]
    pub listen: SocketAddr,
    /// Serve on a non-loopback address (anyone who reaches it can run
    /// the drive).
    #[arg(long)]
    pub allow_remote: bool,
    /// Seconds to wait for boot.
    #[arg(long, default_value_t = 20.0)]
    pub timeout_s: f64,
}

/// Samples kept for the page (the rolling window is the page's).
const TEL_KEEP: usize = 200_000;

/// The stream's samples as the page reads them.
#[derive(Default)]
struct TelBuf {
    stream: Option<Stream>,
    /// Index of `t[0]` since the start of the stream.
    first: usize,
    t: Vec<f64>,
    v: Vec<Vec<f32>>,
}

impl TelBuf {
    fn push(&mut self, t: f64, v: &[f32]) {
        self.t.push(t);
        self.v.push(v.to_vec());
        if self.t.len() > TEL_KEEP {
            let cut = self.t.len() - TEL_KEEP / 2;
            self.t.drain(..cut);
            self.v.drain(..cut);
            self.first += cut;
        }
    }
}

/// What the request handlers share.
pub(crate) struct Shared {
    session: Mutex<Session>,
    tel: Mutex<TelBuf>,
    bad: Mutex<u64>,
}

/// Checks the address: loopback, or remote with the flag.
pub fn check_listen(addr: &SocketAddr, allow_remote: bool) -> Result<()> {
    if !addr.ip().is_loopback() && !allow_remote {
        bail!(
            "refusing to listen on {addr}: not a loopback address, and the page runs the \
             drive (gates, torque, configuration). Pass --allow-remote to serve other machines."
        );
    }
    Ok(())
}

fn reply_json(r: &Reply) -> serde_json::Value {
    match &r.fin {
        Final::Ok => json!({"lines": r.lines, "ok": true}),
        Final::Err { code, message } => {
            json!({"lines": r.lines, "ok": false, "code": code, "message": message})
        }
    }
}

impl Shared {
    /// One console command; long ones (`sweep`) get a long timeout.
    fn command(&self, line: &str) -> Result<serde_json::Value> {
        let line = line.trim();
        if line.is_empty() || line.contains(['\r', '\n']) {
            bail!("a command is one non-empty line");
        }
        let mut s = self.session.lock().expect("session lock");
        let r = s.command(line, Duration::from_secs(600))?;
        Ok(reply_json(&r))
    }

    fn tel_start(&self, rate: u32, channels: &[String]) -> Result<serde_json::Value> {
        let mut s = self.session.lock().expect("session lock");
        let line = format!("tel start {rate} {}", channels.join(","));
        let r = s.command(&line, Duration::from_secs(20))?;
        if r.is_ok() {
            // The reply's stream number; the frames that follow are its.
            let mut st = Stream::start_from_reply(&r, rate, channels)?;
            st.received = 0;
            let mut tel = self.tel.lock().expect("tel lock");
            *tel = TelBuf {
                stream: Some(st),
                ..TelBuf::default()
            };
        }
        Ok(reply_json(&r))
    }

    fn tel_since(&self, since: usize) -> serde_json::Value {
        let tel = self.tel.lock().expect("tel lock");
        let from = since.max(tel.first) - tel.first;
        let from = from.min(tel.t.len());
        let (channels, rate, lost) = match &tel.stream {
            Some(s) => (s.channels.clone(), s.rate_hz, s.lost),
            None => (Vec::new(), 0, 0),
        };
        json!({
            "channels": channels,
            "rate_hz": rate,
            "next": tel.first + tel.t.len(),
            "lost": lost,
            "bad": *self.bad.lock().expect("bad lock"),
            "t": &tel.t[from..],
            "v": &tel.v[from..],
        })
    }
}

/// Moves the link's frames into the page's buffer.
fn pump_frames(shared: Arc<Shared>, frames: Frames) {
    loop {
        let Some(f) = frames.next(Duration::from_millis(100)) else {
            *shared.bad.lock().expect("bad lock") = frames.bad();
            continue;
        };
        let mut tel = shared.tel.lock().expect("tel lock");
        for f in std::iter::once(f).chain(frames.drain()) {
            let Some(st) = tel.stream.as_mut() else {
                continue;
            };
            if let Some((t, v)) = st.accept(&f) {
                let v = v.to_vec();
                tel.push(t, &v);
            }
        }
    }
}

pub fn run(a: UiArgs) -> Result<()> {
    check_listen(&a.listen, a.allow_remote)?;
    let t = crate::console::timeout(a.timeout_s)?;
    let mut s = a.target.open(t)?;
    // The frames go to their own thread; the session keeps the text.
    let frames = std::mem::replace(&mut s.frames, Frames::new().0);
    let shared = Arc::new(Shared {
        session: Mutex::new(s),
        tel: Mutex::new(TelBuf::default()),
        bad: Mutex::new(0),
    });
    let http = tiny_http::Server::http(a.listen)
        .map_err(|e| anyhow::anyhow!("cannot listen on {}: {e}", a.listen))?;
    let addr = http
        .server_addr()
        .to_ip()
        .context("server address is not an IP socket")?;
    let scope = if addr.ip().is_loopback() {
        "loopback only: other machines cannot reach it"
    } else {
        "REMOTE ACCESS: anyone who reaches this address can run the drive"
    };
    let target = match (&a.target.port, a.target.running()?) {
        (Some(p), _) => format!("the board on {p}"),
        (None, Some(sock)) => format!("the running drive ({})", sock.display()),
        (None, None) => "the firmware in QEMU (ended with this page's server)".to_string(),
    };
    println!("drivectl ui: serving {target} on http://{addr}/ ({scope}); Ctrl-C ends");
    {
        let shared = shared.clone();
        std::thread::spawn(move || pump_frames(shared, frames));
    }
    server::serve(http, shared)
}

#[cfg(test)]
mod tests {
    use super::check_listen;
    use drive::servo::{bandwidth_hz, tone_response, SweepPoint};
    use models::pmsm::closed_loop::{self, Controller};
    use models::pmsm::foc::{Foc, FocParams};
    use models::pmsm::mpdtc_ctrl::MpdtcRef;
    use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
    use models::pmsm::params::{MotorParams, SamplingParams};
    use models::pmsm::plant::{MechanicalMode, Plant};

    const PAGE: &str = include_str!("page.html");
    const APP_JS: &str = include_str!("app.js");

    /// The `value` of the page's input `id`.
    fn page_value(id: &str) -> f64 {
        let tag = PAGE
            .split('<')
            .find(|t| t.contains(&format!("id=\"{id}\"")))
            .unwrap_or_else(|| panic!("no input {id} in page.html"));
        let v = tag.split("value=\"").nth(1).expect("a value");
        v[..v.find('"').unwrap()].parse().expect("a number")
    }

    /// The default range of `mode` in app.js's `SWEEP_RANGE_HZ`.
    fn default_range(mode: &str) -> (f64, f64) {
        let line = APP_JS
            .lines()
            .find(|l| l.starts_with("const SWEEP_RANGE_HZ = {"))
            .expect("SWEEP_RANGE_HZ in app.js");
        let tail = line.split(&format!("{mode}: [")).nth(1).expect("the mode");
        let nums: Vec<f64> = tail[..tail.find(']').unwrap()]
            .split(',')
            .map(|x| x.trim().parse().unwrap())
            .collect();
        (nums[0], nums[1])
    }

    /// Gain and phase of the locked-rotor loop's torque (mean over each
    /// control period) against a sine reference of `amp_nm` at `f_hz`,
    /// after 1 ms (at least one period of the sine) of transient, over
    /// 4 ms (at least two periods): what the firmware's `sweep` measures
    /// on its capture.
    fn host_point<C: Controller>(mut ctrl: C, f_hz: f64, amp_nm: f64) -> SweepPoint {
        let drive = SamplingParams::default();
        let mut plant = Plant::new(
            &MotorParams::default(),
            drive.dead_time_s,
            MechanicalMode::ConstantSpeed,
            0.0,
        )
        .unwrap();
        let ts = ctrl.period_s();
        let skip = (1e-3f64.max(1.0 / f_hz) / ts).ceil() as usize;
        let periods = skip + (4e-3f64.max(2.0 / f_hz) / ts).ceil() as usize;
        let (mut reference, mut torque) = (Vec::new(), Vec::new());
        let (mut sum, mut n) = (0.0, 0u32);
        let sine = |t: f64| amp_nm * (std::f64::consts::TAU * f_hz * t).sin();
        closed_loop::run(&mut plant, &mut ctrl, &drive, periods as u64, sine, |p| {
            sum += p.torque_nm;
            n += 1;
            if p.end_of_period {
                reference.push(p.torque_ref_nm);
                torque.push(sum / f64::from(n));
                (sum, n) = (0.0, 0);
            }
        })
        .unwrap();
        tone_response(&reference[skip..], &torque[skip..], f_hz, ts).unwrap()
    }

    /// The page's default sweep (range of the mode, amplitude, points)
    /// against the loop computed on the host: the -3 dB bandwidth lies
    /// strictly inside the range (a first point already below -3 dB would
    /// report the range's start), and the range ends at or below a quarter
    /// of the control rate (the firmware refuses more). The browser test
    /// runs the FOC one on the firmware.
    #[test]
    fn the_default_sweep_range_holds_the_torque_loops_bandwidth() {
        let amp = page_value("sweep-amp");
        let n = page_value("sweep-points") as usize;
        assert_eq!(
            (page_value("sweep-f0"), page_value("sweep-f1")),
            default_range("foc"),
            "the page's initial range is FOC's"
        );
        let motor = MotorParams::default();
        let mpdtc = MpdtcConfig::new(motor, MpdtcParams::default()).unwrap();
        let foc = || Foc::new(&motor, &FocParams::default()).unwrap();
        type Point<'a> = &'a dyn Fn(f64) -> SweepPoint;
        let cases: [(&str, f64, Point); 2] = [
            ("foc", foc().period_s(), &|f| host_point(foc(), f, amp)),
            ("mpdtc", mpdtc.params.control_period_s, &|f| {
                host_point(MpdtcRef::new(mpdtc), f, amp)
            }),
        ];
        for (mode, period_s, point) in cases {
            let (f0, f1) = default_range(mode);
            assert!(f1 <= 0.25 / period_s, "{mode}: {f1} Hz above rate / 4");
            let pts: Vec<SweepPoint> = (0..n)
                .map(|k| point(f0 * (f1 / f0).powf(k as f64 / (n - 1) as f64)))
                .collect();
            let bw = bandwidth_hz(&pts);
            println!("{mode} {f0}..{f1} Hz at {amp} N m: {bw:?} Hz, {pts:?}");
            assert!(pts[0].gain_db > -3.0, "{mode}: {pts:?}");
            let bw = bw.unwrap_or_else(|| panic!("{mode}: no -3 dB point in {pts:?}"));
            assert!(f0 < bw && bw < f1, "{mode}: {bw} Hz");
        }
    }

    #[test]
    fn only_loopback_addresses_unless_asked() {
        for ok in ["127.0.0.1:8750", "127.0.0.2:1", "[::1]:8750"] {
            assert!(check_listen(&ok.parse().unwrap(), false).is_ok(), "{ok}");
        }
        for remote in ["0.0.0.0:8750", "192.168.1.20:8750", "[::]:8750"] {
            let a = remote.parse().unwrap();
            let e = check_listen(&a, false).unwrap_err().to_string();
            assert!(e.contains("not a loopback address"), "{e}");
            assert!(e.contains("--allow-remote"), "{e}");
            assert!(check_listen(&a, true).is_ok(), "{remote}");
        }
    }
}
