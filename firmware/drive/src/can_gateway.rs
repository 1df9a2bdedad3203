//! The socketcand connection in front of the drive's CANopen device:
//! bytes from the TCP client go through `canopen::socketcand`, the frames
//! they carry go to the [`Device`], and the frames the device produces
//! (boot-up, SDO answers, PDOs, heartbeat, EMCY) go back to the client as
//! `< frame ... >` lines. Transport-free: the firmware's network code
//! hands in received bytes and the time, and passes each returned line to
//! the TCP socket whole.
//!
//! One client at a time, as socketcand serves one bus per connection;
//! the device lives on between connections (it is the drive's, not the
//! connection's). Frames it produces while no client is in raw mode are
//! dropped, as on a CAN bus with no other node listening.

use canopen::socketcand::{self, Event, Line, Server};
use canopen::{CanFrame, Frames};

/// TCP port of the socketcand server (socketcand's default).
pub const PORT: u16 = 29536;
/// The bus name a client opens.
pub const BUS: &str = "can0";
/// How long frames wait after the raw-mode `< ok >`, so that it reaches
/// the client alone (python-can compares that read with the exact text),
/// µs; the client's next command ends the wait earlier.
pub const RAW_HOLD_US: u64 = 100_000;

/// The CANopen device on the bus: the drive's node (`fieldbus::Link` with
/// the servo, in the firmware).
pub trait Device {
    /// A frame from the bus; the frames to send, in order.
    fn on_frame(&mut self, f: &CanFrame) -> Frames;
    /// Time passes (µs, monotonic); the frames to send (heartbeat, timed
    /// PDOs, frames the control loop left).
    fn tick(&mut self, now_us: u64) -> Frames;
}

/// Where lines go: the TCP socket. `send` writes the whole line or
/// nothing and says which.
pub trait LineSink {
    fn send(&mut self, line: &[u8]) -> bool;
}

/// One client connection.
#[derive(Clone, Debug)]
struct Session {
    server: Server,
    /// Frames wait until this time (after the raw-mode `< ok >`), µs.
    hold_until_us: Option<u64>,
}

/// Counters for the console and the tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Frames from the client put on the node.
    pub frames_in: u32,
    /// Frames sent to the client.
    pub frames_out: u32,
    /// Lines the socket had no room for, and frames with no client.
    pub dropped: u32,
    /// Commands answered with `< error ... >`.
    pub errors: u32,
}

/// The current client and the counters.
#[derive(Default)]
pub struct Gateway {
    session: Option<Session>,
    counts: Counts,
}

impl Gateway {
    /// No client yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// The counters.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Whether a client is connected.
    pub fn connected(&self) -> bool {
        self.session.is_some()
    }

    /// A client connected: a new session, and the greeting it gets first.
    pub fn connect(&mut self) -> &'static [u8] {
        self.session = Some(Session {
            server: match Server::new(BUS) {
                Some(s) => s,
                // BUS is a constant of 4 bytes (checked by a test).
                None => unreachable!(),
            },
            hold_until_us: None,
        });
        socketcand::GREETING.as_bytes()
    }

    /// The client went away.
    pub fn disconnect(&mut self) {
        self.session = None;
    }

    /// Bytes from the client at `now_us`; replies and the device's answers
    /// go to `out`.
    pub fn on_input(
        &mut self,
        bytes: &[u8],
        now_us: u64,
        dev: &mut impl Device,
        out: &mut impl LineSink,
    ) {
        for &b in bytes {
            let Some(session) = self.session.as_mut() else {
                return;
            };
            let Some(event) = session.server.push(b) else {
                continue;
            };
            // The client's next command ends a raw-mode hold.
            session.hold_until_us = None;
            match event {
                Event::Reply(r) => {
                    if matches!(r, socketcand::Reply::Error(_)) {
                        self.counts.errors += 1;
                    }
                    if !out.send(r.text().as_bytes()) {
                        self.counts.dropped += 1;
                    }
                    if r == socketcand::Reply::Ok && session.server.forwards_frames() {
                        session.hold_until_us = Some(now_us + RAW_HOLD_US);
                    }
                }
                Event::Send(frame) => {
                    self.counts.frames_in += 1;
                    let answers = dev.on_frame(&frame);
                    for f in answers.iter() {
                        self.emit(f, now_us, out);
                    }
                }
            }
        }
    }

    /// Time passes: the device's timed frames.
    pub fn tick(&mut self, now_us: u64, dev: &mut impl Device, out: &mut impl LineSink) {
        let frames = dev.tick(now_us);
        for f in frames.iter() {
            self.emit(f, now_us, out);
        }
    }

    /// Whether frames go to the client now.
    fn forwarding(&mut self, now_us: u64) -> bool {
        let Some(s) = self.session.as_mut() else {
            return false;
        };
        if let Some(t) = s.hold_until_us {
            if now_us < t {
                return false;
            }
            s.hold_until_us = None;
        }
        s.server.forwards_frames()
    }

    fn emit(&mut self, f: &CanFrame, now_us: u64, out: &mut impl LineSink) {
        if !self.forwarding(now_us) {
            self.counts.dropped += 1;
            return;
        }
        let line: Line = socketcand::format_frame(f, now_us);
        if out.send(line.as_bytes()) {
            self.counts.frames_out += 1;
        } else {
            self.counts.dropped += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::fieldbus::{ConfigValues, Link};
    use crate::pl::fake::FakePl;
    use crate::servo::sensors::PlTime;
    use crate::servo::{Servo, ServoConfig};
    use regmap::bus::{BusError, RegisterBus};
    use std::string::String;
    use std::vec::Vec;

    /// A socket that keeps every line, or refuses all of them.
    #[derive(Default)]
    struct Sink {
        lines: Vec<String>,
        full: bool,
    }

    impl LineSink for Sink {
        fn send(&mut self, line: &[u8]) -> bool {
            if self.full {
                return false;
            }
            self.lines.push(String::from_utf8(line.to_vec()).unwrap());
            true
        }
    }

    /// The fake PL, its time standing still.
    struct Pl(FakePl);

    impl RegisterBus for Pl {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            self.0.read(addr)
        }
        fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
            self.0.write(addr, value)
        }
    }

    impl PlTime for Pl {
        fn wait_cycles(&mut self, _cycles: u64) {}
    }

    /// The drive's device as the firmware has it: node 1 on the servo,
    /// its boot-up frame sent at the first tick.
    struct Drive {
        link: Link<ConfigValues>,
        servo: Servo,
        pl: Pl,
        boot: Frames,
    }

    impl Drive {
        fn new(serial: u32) -> Self {
            let cfg = ServoConfig::default();
            let mut pl = Pl(FakePl::new());
            let mut servo = Servo::new(&cfg).unwrap();
            servo.init(&mut pl).unwrap();
            let mut link = Link::new(1, ConfigValues::new(cfg)).unwrap();
            link.obj.serial_number = serial;
            let boot = link.boot();
            Self {
                link,
                servo,
                pl,
                boot,
            }
        }
    }

    impl Device for Drive {
        fn on_frame(&mut self, f: &CanFrame) -> Frames {
            self.link
                .on_frame(f, &mut self.servo, &mut self.pl)
                .unwrap()
        }
        fn tick(&mut self, now_us: u64) -> Frames {
            let mut out = core::mem::take(&mut self.boot);
            let more = self
                .link
                .tick(now_us, &mut self.servo, &mut self.pl)
                .unwrap();
            for f in more.iter() {
                out.push(*f);
            }
            out
        }
    }

    fn raw_client() -> (Gateway, Drive, Sink) {
        let mut g = Gateway::new();
        let mut d = Drive::new(0x1234_5678);
        let mut s = Sink::default();
        assert_eq!(g.connect(), b"< hi >");
        g.on_input(b"< open can0 >", 0, &mut d, &mut s);
        g.on_input(b"< rawmode >", 0, &mut d, &mut s);
        assert_eq!(s.lines, ["< ok >", "< ok >"]);
        s.lines.clear();
        (g, d, s)
    }

    #[test]
    fn constants_are_valid() {
        assert!(Server::new(BUS).is_some());
        assert_eq!(PORT, 29536);
    }

    #[test]
    fn sdo_upload_of_the_device_type() {
        let (mut g, mut d, mut s) = raw_client();
        // CiA 301 expedited upload request to node 1 (COB-ID 0x600 + 1):
        // ccs 2 (0x40), index 0x1000 little-endian, sub-index 0.
        g.on_input(
            b"< send 601 8 40 00 10 00 00 00 00 00 >",
            1_500_000,
            &mut d,
            &mut s,
        );
        // Response on 0x580 + 1: 0x43 = scs 2, expedited, size indicated,
        // 4 bytes; index, sub-index; 0x00020192 little-endian.
        assert_eq!(s.lines, ["< frame 581 1.500000 4300100092010200 >"]);
        assert_eq!(g.counts().frames_in, 1);
        assert_eq!(g.counts().frames_out, 1);
    }

    #[test]
    fn sdo_upload_of_the_identity() {
        let (mut g, mut d, mut s) = raw_client();
        g.on_input(b"< send 601 8 40 18 10 00 00 00 00 00 >", 0, &mut d, &mut s);
        g.on_input(b"< send 601 8 40 18 10 04 00 00 00 00 >", 0, &mut d, &mut s);
        // 0x1018:00 = 4 (UNSIGNED8: 0x4F, 1 byte), 0x1018:04 = serial.
        assert_eq!(
            s.lines,
            [
                "< frame 581 0.000000 4F18100004000000 >",
                "< frame 581 0.000000 4318100478563412 >"
            ]
        );
        // An object the drive does not have: abort 0x06020000.
        g.on_input(b"< send 601 8 40 FF 2F 00 00 00 00 00 >", 0, &mut d, &mut s);
        assert_eq!(s.lines[2], "< frame 581 0.000000 80FF2F0000000206 >");
    }

    #[test]
    fn nmt_and_heartbeat() {
        let (mut g, mut d, mut s) = raw_client();
        // The boot-up frame (0x701, one byte 0) goes out at the first tick.
        g.tick(RAW_HOLD_US, &mut d, &mut s);
        assert_eq!(s.lines[0], "< frame 701 0.100000 00 >");
        s.lines.clear();
        // NMT start node 1: [0x01, 0x01] on COB-ID 0; no answer.
        g.on_input(b"< send 000 2 1 1 >", 0, &mut d, &mut s);
        assert!(s.lines.is_empty());
        // The heartbeat every 100 ms says operational (0x05).
        for t in (200_000..=2_000_000).step_by(100_000) {
            g.tick(t, &mut d, &mut s);
        }
        assert!(s.lines.len() >= 18, "{:?}", s.lines);
        assert!(s
            .lines
            .iter()
            .all(|l| l.starts_with("< frame 701 ") && l.ends_with(" 05 >")));
    }

    #[test]
    fn frames_wait_after_the_raw_mode_ok() {
        let mut g = Gateway::new();
        let mut d = Drive::new(0);
        let mut s = Sink::default();
        g.connect();
        g.on_input(b"< open can0 >< rawmode >", 0, &mut d, &mut s);
        // The boot-up frame and the first heartbeat, due right after the
        // `< ok >`, are held back (dropped); the next heartbeat, one
        // period (100 ms) later, goes out: 0x7F = pre-operational.
        g.tick(RAW_HOLD_US - 1, &mut d, &mut s);
        assert_eq!(s.lines.len(), 2, "{:?}", s.lines);
        assert_eq!(g.counts().dropped, 2);
        g.tick(RAW_HOLD_US - 1 + 100_000, &mut d, &mut s);
        assert_eq!(s.lines[2..], ["< frame 701 0.199999 7F >"]);
    }

    #[test]
    fn bad_input_gets_an_error_and_changes_nothing() {
        let (mut g, mut d, mut s) = raw_client();
        g.on_input(
            b"< send 601 9 1 2 3 4 5 6 7 8 9 >< bogus >",
            0,
            &mut d,
            &mut s,
        );
        assert_eq!(
            s.lines,
            ["< error syntax error >", "< error unknown command >"]
        );
        assert_eq!(g.counts().errors, 2);
        assert_eq!(g.counts().frames_in, 0);
        assert_eq!(
            d.link.node.nmt_state(),
            canopen::nmt::NmtState::PreOperational
        );
    }

    #[test]
    fn no_client_or_a_full_socket_drops_whole_lines() {
        let mut g = Gateway::new();
        let mut d = Drive::new(0);
        let mut s = Sink::default();
        // The boot-up frame has no client.
        g.tick(0, &mut d, &mut s);
        assert!(g.counts().dropped >= 1);
        g.on_input(b"< open can0 >", 0, &mut d, &mut s);
        assert!(s.lines.is_empty());
        let (mut g, mut d, mut s) = raw_client();
        s.full = true;
        g.on_input(b"< send 601 8 40 00 10 00 00 00 00 00 >", 0, &mut d, &mut s);
        assert_eq!(g.counts().dropped, 1);
        g.disconnect();
        assert!(!g.connected());
    }
}
