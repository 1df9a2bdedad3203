//! The drive's CANopen node behind a socketcand connection: bytes from the
//! TCP client go through `canopen::socketcand` to the node, the frames the
//! node produces (boot-up, SDO responses, heartbeat, EMCY) go back to the
//! client as `< frame ... >` lines. Transport-free: the firmware's network
//! code hands in received bytes and the time, and passes each returned
//! line to the TCP socket whole.
//!
//! One client at a time, as socketcand serves one bus per connection;
//! the node lives on between connections (it is the drive's, not the
//! connection's). Frames the node produces while no client is in raw mode
//! are dropped, as on a CAN bus with no other node listening.

use canopen::node::{Application, Config, Node};
use canopen::od::{Abort, Access, DataType, Entry, ObjectDictionary, Table};
use canopen::pdo::Pdos;
use canopen::socketcand::{self, Event, Line, Server};
use canopen::CanFrame;

/// TCP port of the socketcand server (socketcand's default).
pub const PORT: u16 = 29536;
/// The bus name a client opens.
pub const BUS: &str = "can0";
/// Node-ID of the drive.
pub const NODE_ID: u8 = 1;
/// Heartbeat period at power-on (0x1017), ms.
pub const HEARTBEAT_MS: u16 = 1000;
/// How long frames wait after the raw-mode `< ok >`, so that it reaches
/// the client alone (python-can compares that read with the exact text),
/// µs; the client's next command ends the wait earlier.
pub const RAW_HOLD_US: u64 = 100_000;

/// 0x1000 device type: CiA 402 device profile (0x0192) with the servo
/// drive's additional information 0x0002 (CiA 402-2, 0x1000).
pub const DEVICE_TYPE: u32 = 0x0002_0192;
/// 0x1018:01 vendor ID: 0, no CiA-assigned ID.
pub const VENDOR_ID: u32 = 0;
/// 0x1018:02 product code.
pub const PRODUCT_CODE: u32 = 0x0000_0001;
/// 0x1018:03 revision number: major 0, minor 1 (CiA 301 7.5.2.21).
pub const REVISION: u32 = 0x0000_0001;

/// The drive's own objects (the node owns the communication and CiA 402
/// ones).
const ENTRIES: &[Entry] = &[
    Entry::new(0x1000, 0, DataType::Unsigned32, Access::Const),
    Entry::new(0x1018, 0, DataType::Unsigned8, Access::Const),
    Entry::new(0x1018, 1, DataType::Unsigned32, Access::Const),
    Entry::new(0x1018, 2, DataType::Unsigned32, Access::Const),
    Entry::new(0x1018, 3, DataType::Unsigned32, Access::Const),
    Entry::new(0x1018, 4, DataType::Unsigned32, Access::Const),
];

/// The drive's object dictionary as the node sees it.
#[derive(Clone, Copy, Debug)]
pub struct DriveObjects {
    /// 0x1018:04.
    pub serial: u32,
}

impl ObjectDictionary for DriveObjects {
    fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
        Table::new(ENTRIES).entry(index, sub)
    }

    fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        let value: &[u8] = match (index, sub) {
            (0x1000, 0) => &DEVICE_TYPE.to_le_bytes(),
            (0x1018, 0) => &[4],
            (0x1018, 1) => &VENDOR_ID.to_le_bytes(),
            (0x1018, 2) => &PRODUCT_CODE.to_le_bytes(),
            (0x1018, 3) => &REVISION.to_le_bytes(),
            (0x1018, 4) => &self.serial.to_le_bytes(),
            _ => return Err(Abort::ObjectDoesNotExist),
        };
        out.get_mut(..value.len())
            .ok_or(Abort::General)?
            .copy_from_slice(value);
        Ok(value.len())
    }

    fn write(&mut self, _index: u16, _sub: u8, _data: &[u8]) -> Result<(), Abort> {
        // Every entry is constant; the checks refuse writes before this.
        Err(Abort::WriteReadOnly)
    }
}

impl Application for DriveObjects {}

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

/// The node and the current client.
pub struct Gateway {
    node: Node,
    objects: DriveObjects,
    session: Option<Session>,
    counts: Counts,
}

impl Gateway {
    /// The drive's node, booted (NMT pre-operational, its boot-up frame
    /// dropped: no client is connected yet).
    pub fn new(serial: u32) -> Self {
        let config = Config {
            node_id: NODE_ID,
            heartbeat_ms: HEARTBEAT_MS,
            // No CiA 402 mode drives the servo over CANopen yet: 0x6502
            // says so, and 0x6060 reads 0 (no mode).
            supported_modes: 0,
            initial_mode: 0,
            quick_stop_option: 2,
        };
        let node = match Node::new(config, Pdos::new(NODE_ID)) {
            Some(n) => n,
            // NODE_ID is a constant inside 1..=127 (checked by a test).
            None => unreachable!(),
        };
        let mut g = Self {
            node,
            objects: DriveObjects { serial },
            session: None,
            counts: Counts::default(),
        };
        let boot = g.node.boot();
        g.counts.dropped += boot.len() as u32;
        g.node.drive_initialised(&mut g.objects);
        g
    }

    /// The node (NMT state, reads for the console).
    pub fn node(&self) -> &Node {
        &self.node
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

    /// Bytes from the client at `now_us`; replies and the node's answers
    /// go to `out`.
    pub fn on_input(&mut self, bytes: &[u8], now_us: u64, out: &mut impl LineSink) {
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
                    let answers = self.node.on_frame(&frame, &mut self.objects);
                    for f in answers.iter() {
                        self.emit(f, now_us, out);
                    }
                }
            }
        }
    }

    /// Time passes: heartbeat and the node's other timed frames.
    pub fn tick(&mut self, now_us: u64, out: &mut impl LineSink) {
        let frames = self.node.tick(now_us, &mut self.objects);
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

    fn raw_client() -> (Gateway, Sink) {
        let mut g = Gateway::new(0x1234_5678);
        let mut s = Sink::default();
        assert_eq!(g.connect(), b"< hi >");
        g.on_input(b"< open can0 >", 0, &mut s);
        g.on_input(b"< rawmode >", 0, &mut s);
        assert_eq!(s.lines, ["< ok >", "< ok >"]);
        s.lines.clear();
        (g, s)
    }

    #[test]
    fn constants_are_valid() {
        assert!((1..=127).contains(&NODE_ID));
        assert!(Server::new(BUS).is_some());
        assert_eq!(PORT, 29536);
    }

    #[test]
    fn sdo_upload_of_the_device_type() {
        let (mut g, mut s) = raw_client();
        // CiA 301 expedited upload request to node 1 (COB-ID 0x600 + 1):
        // ccs 2 (0x40), index 0x1000 little-endian, sub-index 0.
        g.on_input(b"< send 601 8 40 00 10 00 00 00 00 00 >", 1_500_000, &mut s);
        // Response on 0x580 + 1: 0x43 = scs 2, expedited, size indicated,
        // 4 bytes; index, sub-index; 0x00020192 little-endian.
        assert_eq!(s.lines, ["< frame 581 1.500000 4300100092010200 >"]);
        assert_eq!(g.counts().frames_in, 1);
        assert_eq!(g.counts().frames_out, 1);
    }

    #[test]
    fn sdo_upload_of_the_identity() {
        let (mut g, mut s) = raw_client();
        g.on_input(b"< send 601 8 40 18 10 00 00 00 00 00 >", 0, &mut s);
        g.on_input(b"< send 601 8 40 18 10 04 00 00 00 00 >", 0, &mut s);
        // 0x1018:00 = 4 (UNSIGNED8: 0x4F, 1 byte), 0x1018:04 = serial.
        assert_eq!(
            s.lines,
            [
                "< frame 581 0.000000 4F18100004000000 >",
                "< frame 581 0.000000 4318100478563412 >"
            ]
        );
        // An object the drive does not have: abort 0x06020000.
        g.on_input(b"< send 601 8 40 00 20 00 00 00 00 00 >", 0, &mut s);
        assert_eq!(s.lines[2], "< frame 581 0.000000 8000200000000206 >");
    }

    #[test]
    fn nmt_and_heartbeat() {
        let (mut g, mut s) = raw_client();
        // NMT start node 1: [0x01, 0x01] on COB-ID 0; no answer.
        g.on_input(b"< send 000 2 1 1 >", 0, &mut s);
        assert!(s.lines.is_empty());
        // The heartbeat at 1000 ms says operational (0x05).
        for t in (0..=2_000_000).step_by(100_000) {
            g.tick(t, &mut s);
        }
        assert!(!s.lines.is_empty());
        assert!(s
            .lines
            .iter()
            .all(|l| l.starts_with("< frame 701 ") && l.ends_with(" 05 >")));
    }

    #[test]
    fn frames_wait_after_the_raw_mode_ok() {
        let mut g = Gateway::new(0);
        let mut s = Sink::default();
        g.connect();
        g.on_input(b"< open can0 >< rawmode >", 0, &mut s);
        // The first heartbeat, due right after the `< ok >`, is held back
        // (dropped); the next, one period later, goes out: 0x7F =
        // pre-operational.
        let dropped = g.counts().dropped;
        g.tick(RAW_HOLD_US - 1, &mut s);
        assert_eq!(s.lines.len(), 2, "{:?}", s.lines);
        assert_eq!(g.counts().dropped, dropped + 1);
        g.tick(RAW_HOLD_US - 1 + 1_000_000, &mut s);
        assert_eq!(s.lines[2..], ["< frame 701 1.099999 7F >"]);
    }

    #[test]
    fn bad_input_gets_an_error_and_changes_nothing() {
        let (mut g, mut s) = raw_client();
        g.on_input(b"< send 601 9 1 2 3 4 5 6 7 8 9 >< bogus >", 0, &mut s);
        assert_eq!(
            s.lines,
            ["< error syntax error >", "< error unknown command >"]
        );
        assert_eq!(g.counts().errors, 2);
        assert_eq!(g.counts().frames_in, 0);
        assert_eq!(g.node().nmt_state(), canopen::nmt::NmtState::PreOperational);
    }

    #[test]
    fn no_client_or_a_full_socket_drops_whole_lines() {
        let mut g = Gateway::new(0);
        let mut s = Sink::default();
        // The boot-up frame had no client.
        assert_eq!(g.counts().dropped, 1);
        g.on_input(b"< open can0 >", 0, &mut s);
        assert!(s.lines.is_empty());
        let (mut g, mut s) = raw_client();
        s.full = true;
        g.on_input(b"< send 601 8 40 00 10 00 00 00 00 00 >", 0, &mut s);
        assert_eq!(g.counts().dropped, 2);
        g.disconnect();
        assert!(!g.connected());
    }
}
