//! The socketcand text protocol over TCP, server side (the protocol of the
//! linux-can socketcand daemon, its `doc/protocol.md`), as far as
//! python-can's `socketcand` interface uses it: the client connects, the
//! server greets with `< hi >`, the client sends `< open BUS >` (answer
//! `< ok >`) and `< rawmode >` (answer `< ok >`); from then on the server
//! sends every bus frame as `< frame ID SECS.USECS DATA >` and the client
//! sends frames as `< send ID LEN B0 B1 ... >`. `< bcmmode >` and
//! `< echo >` are understood too; the BCM mode's cyclic jobs are not.
//!
//! Formats, as socketcand writes them and python-can parses them:
//! - Server frame: ID as exactly 3 upper-case hex digits (python-can takes
//!   any other width as a 29-bit identifier); SECS decimal, USECS 6
//!   decimal digits; DATA the bytes as 2 upper-case hex digits each, with
//!   no space between them, possibly empty, so an empty frame reads
//!   `< frame 123 1.000000  >` (two spaces).
//! - Client send: ID hex (python-can: 3 upper-case digits for 11-bit, 8
//!   for 29-bit, which this node refuses), LEN 0..=8 (python-can writes it
//!   in hex, socketcand reads decimal: the same digits), then LEN bytes as
//!   1 or 2 hex digits of either case (python-can writes `{:x}`: `a`,
//!   `0`, `ff`), separated by spaces; with no data python-can sends
//!   `< send 123 0  >`.
//! - Replies carry no line ending. python-can compares its first read
//!   after connecting, and after each of open and rawmode, with the exact
//!   text (`< hi >`, `< ok >`), so each must go out as its own write and
//!   no frame may precede the rawmode `< ok >`: [`Server::forwards_frames`]
//!   turns true only then. A frame written right after that `< ok >` can
//!   still reach python-can in the same read and fail its comparison, so
//!   the transport should let the `< ok >` leave alone (e.g. hold frames
//!   until the client's next command or a short delay).
//!
//! Input is parsed byte by byte, so it may arrive in any chunks. Bytes
//! outside `<` ... `>` are ignored (as socketcand does); a command longer
//! than [`MAX_COMMAND`] bytes, a `<` inside a command, an unknown command
//! or a malformed `send` gives an `< error ... >` reply and changes
//! nothing.

use crate::frame::CanFrame;

/// What the server sends first, on its own.
pub const GREETING: &str = "< hi >";

/// Longest command accepted between `<` and `>`, in bytes.
pub const MAX_COMMAND: usize = 96;

/// Longest bus name (socketcand: 16 characters).
pub const MAX_BUS_NAME: usize = 16;

/// The connection's mode (socketcand: NO_BUS, BCM, RAW).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    NoBus,
    Bcm,
    Raw,
}

/// Why a command was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// Unknown command, or not allowed in the current mode.
    UnknownCommand,
    /// A malformed command (bad numbers, wrong count, stray `<`).
    Syntax,
    /// Longer than [`MAX_COMMAND`].
    TooLong,
    /// `open` of a bus this server does not serve.
    CouldNotOpenBus,
    /// A 29-bit identifier (8 hex digits).
    ExtendedId,
}

/// A reply to the client.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reply {
    Ok,
    Echo,
    Error(ErrorKind),
}

impl Reply {
    /// The reply's exact text.
    pub fn text(self) -> &'static str {
        match self {
            Reply::Ok => "< ok >",
            Reply::Echo => "< echo >",
            Reply::Error(ErrorKind::UnknownCommand) => "< error unknown command >",
            Reply::Error(ErrorKind::Syntax) => "< error syntax error >",
            Reply::Error(ErrorKind::TooLong) => "< error command too long >",
            Reply::Error(ErrorKind::CouldNotOpenBus) => "< error could not open bus >",
            Reply::Error(ErrorKind::ExtendedId) => "< error extended identifiers not supported >",
        }
    }
}

/// What one complete command asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event {
    /// Send this text to the client.
    Reply(Reply),
    /// Put this frame on the bus (nothing is sent back).
    Send(CanFrame),
}

/// One client connection's protocol state.
#[derive(Clone, Debug)]
pub struct Server {
    bus: [u8; MAX_BUS_NAME],
    bus_len: usize,
    mode: Mode,
    buf: [u8; MAX_COMMAND],
    len: usize,
    in_command: bool,
    overflow: bool,
}

impl Server {
    /// A connection serving the bus `bus` (at most 16 bytes, else `None`),
    /// in NO_BUS mode; send [`GREETING`] first.
    pub fn new(bus: &str) -> Option<Self> {
        let b = bus.as_bytes();
        if b.is_empty() || b.len() > MAX_BUS_NAME {
            return None;
        }
        let mut name = [0u8; MAX_BUS_NAME];
        name[..b.len()].copy_from_slice(b);
        Some(Self {
            bus: name,
            bus_len: b.len(),
            mode: Mode::NoBus,
            buf: [0; MAX_COMMAND],
            len: 0,
            in_command: false,
            overflow: false,
        })
    }

    /// The current mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// True once the client switched to raw mode: bus frames go to it.
    pub fn forwards_frames(&self) -> bool {
        self.mode == Mode::Raw
    }

    /// Feeds one received byte; returns what a command completed by it
    /// asks for.
    pub fn push(&mut self, byte: u8) -> Option<Event> {
        if !self.in_command {
            if byte == b'<' {
                self.in_command = true;
                self.len = 0;
                self.overflow = false;
            }
            return None;
        }
        match byte {
            b'<' => {
                // A new command starts inside an unfinished one.
                self.len = 0;
                self.overflow = false;
                Some(Event::Reply(Reply::Error(ErrorKind::Syntax)))
            }
            b'>' => {
                self.in_command = false;
                if self.overflow {
                    return Some(Event::Reply(Reply::Error(ErrorKind::TooLong)));
                }
                Some(match self.execute() {
                    Ok(e) => e,
                    Err(k) => Event::Reply(Reply::Error(k)),
                })
            }
            _ => {
                if self.len < MAX_COMMAND {
                    self.buf[self.len] = byte;
                    self.len += 1;
                } else {
                    self.overflow = true;
                }
                None
            }
        }
    }

    /// Feeds a chunk, calling `on_event` for each completed command.
    pub fn feed(&mut self, chunk: &[u8], mut on_event: impl FnMut(Event)) {
        for &b in chunk {
            if let Some(e) = self.push(b) {
                on_event(e);
            }
        }
    }

    fn execute(&mut self) -> Result<Event, ErrorKind> {
        let mut tokens: [&[u8]; 12] = [&[]; 12];
        let mut n = 0;
        for t in self.buf[..self.len]
            .split(|b| b.is_ascii_whitespace())
            .filter(|t| !t.is_empty())
        {
            if n == tokens.len() {
                return Err(ErrorKind::Syntax);
            }
            tokens[n] = t;
            n += 1;
        }
        let tokens = &tokens[..n];
        let Some((&cmd, args)) = tokens.split_first() else {
            return Err(ErrorKind::UnknownCommand);
        };
        let ok = Ok(Event::Reply(Reply::Ok));
        match (cmd, self.mode) {
            (b"open", Mode::NoBus) => match args {
                [name] if *name == &self.bus[..self.bus_len] => {
                    self.mode = Mode::Bcm;
                    ok
                }
                [_] => Err(ErrorKind::CouldNotOpenBus),
                _ => Err(ErrorKind::Syntax),
            },
            (b"rawmode", Mode::Bcm | Mode::Raw) if args.is_empty() => {
                self.mode = Mode::Raw;
                ok
            }
            (b"bcmmode", Mode::Bcm | Mode::Raw) if args.is_empty() => {
                self.mode = Mode::Bcm;
                ok
            }
            (b"echo", Mode::Bcm | Mode::Raw) if args.is_empty() => Ok(Event::Reply(Reply::Echo)),
            (b"send", Mode::Bcm | Mode::Raw) => parse_send(args).map(Event::Send),
            _ => Err(ErrorKind::UnknownCommand),
        }
    }
}

fn hex(t: &[u8], max_digits: usize) -> Option<u32> {
    if t.is_empty() || t.len() > max_digits {
        return None;
    }
    t.iter().try_fold(0u32, |acc, &c| {
        let d = (c as char).to_digit(16)?;
        Some(acc << 4 | d)
    })
}

fn parse_send(args: &[&[u8]]) -> Result<CanFrame, ErrorKind> {
    let [id, len, data @ ..] = args else {
        return Err(ErrorKind::Syntax);
    };
    if id.len() == 8 && hex(id, 8).is_some() {
        return Err(ErrorKind::ExtendedId);
    }
    let id = hex(id, 3).ok_or(ErrorKind::Syntax)?;
    let len = hex(len, 2).ok_or(ErrorKind::Syntax)? as usize;
    if len > 8 || data.len() != len || id > 0x7FF {
        return Err(ErrorKind::Syntax);
    }
    let mut bytes = [0u8; 8];
    for (b, t) in bytes.iter_mut().zip(data) {
        *b = hex(t, 2).ok_or(ErrorKind::Syntax)? as u8;
    }
    CanFrame::new(id as u16, &bytes[..len]).ok_or(ErrorKind::Syntax)
}

/// Longest `< frame ... >` line.
pub const MAX_LINE: usize = 64;

/// A formatted line, ready to send.
#[derive(Clone, Copy, Debug)]
pub struct Line {
    buf: [u8; MAX_LINE],
    len: usize,
}

impl Line {
    fn new() -> Self {
        Self {
            buf: [0; MAX_LINE],
            len: 0,
        }
    }

    fn put(&mut self, b: &[u8]) {
        let n = b.len().min(MAX_LINE - self.len);
        self.buf[self.len..self.len + n].copy_from_slice(&b[..n]);
        self.len += n;
    }

    fn put_dec(&mut self, mut v: u64, min_digits: usize) {
        let mut d = [0u8; 20];
        let mut i = d.len();
        while v > 0 || d.len() - i < min_digits.max(1) {
            i -= 1;
            d[i] = b'0' + (v % 10) as u8;
            v /= 10;
        }
        self.put(&d[i..]);
    }

    /// The bytes.
    pub fn as_bytes(&self) -> &[u8] {
        &self.buf[..self.len]
    }
}

const HEX: &[u8; 16] = b"0123456789ABCDEF";

/// `< frame ID SECS.USECS DATA >` for a frame received at `time_us`
/// microseconds (from any epoch; socketcand uses the kernel's receive
/// time).
pub fn format_frame(frame: &CanFrame, time_us: u64) -> Line {
    let mut l = Line::new();
    l.put(b"< frame ");
    let id = frame.id();
    l.put(&[
        HEX[(id >> 8) as usize & 0xF],
        HEX[(id >> 4) as usize & 0xF],
        HEX[id as usize & 0xF],
        b' ',
    ]);
    l.put_dec(time_us / 1_000_000, 1);
    l.put(b".");
    l.put_dec(time_us % 1_000_000, 6);
    l.put(b" ");
    for &b in frame.data() {
        l.put(&[HEX[(b >> 4) as usize], HEX[(b & 0xF) as usize]]);
    }
    l.put(b" >");
    l
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    fn events(s: &mut Server, input: &[u8]) -> Vec<Event> {
        let mut v = Vec::new();
        s.feed(input, |e| v.push(e));
        v
    }

    fn raw_server() -> Server {
        let mut s = Server::new("can0").unwrap();
        events(&mut s, b"< open can0 >< rawmode >");
        assert_eq!(s.mode(), Mode::Raw);
        s
    }

    fn frame(id: u16, d: &[u8]) -> Event {
        Event::Send(CanFrame::new(id, d).unwrap())
    }

    #[test]
    fn python_can_handshake() {
        // python-can sends exactly these, each as its own write, no newline.
        let mut s = Server::new("can0").unwrap();
        assert_eq!(GREETING, "< hi >");
        assert!(!s.forwards_frames());
        assert_eq!(events(&mut s, b"< open can0 >"), [Event::Reply(Reply::Ok)]);
        assert_eq!(Reply::Ok.text(), "< ok >");
        assert!(!s.forwards_frames());
        assert_eq!(events(&mut s, b"< rawmode >"), [Event::Reply(Reply::Ok)]);
        assert!(s.forwards_frames());
    }

    #[test]
    fn send_forms_python_can_and_socketcand_write() {
        let mut s = raw_server();
        // socketcand's documentation example.
        assert_eq!(
            events(&mut s, b"< send 123 8 11 22 33 44 55 66 77 88 >"),
            [frame(
                0x123,
                &[0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88]
            )]
        );
        // python-can: "{:03X}" id, "{:X}" length, "{:x}" bytes.
        assert_eq!(
            events(&mut s, b"< send 601 8 40 0 10 0 0 0 0 0 >"),
            [frame(0x601, &[0x40, 0x00, 0x10, 0, 0, 0, 0, 0])]
        );
        assert_eq!(
            events(&mut s, b"< send 7E5 2 a Ff >"),
            [frame(0x7E5, &[0x0A, 0xFF])]
        );
        // Empty data: two spaces before '>'.
        assert_eq!(events(&mut s, b"< send 000 0  >"), [frame(0x000, &[])]);
        // socketcand's own example without leading zeros.
        assert_eq!(events(&mut s, b"< send 1 1 1 >"), [frame(0x001, &[1])]);
        // Sending is allowed in BCM mode as well.
        let mut b = Server::new("can0").unwrap();
        events(&mut b, b"< open can0 >");
        assert_eq!(events(&mut b, b"< send 080 0  >"), [frame(0x080, &[])]);
    }

    #[test]
    fn split_chunks_give_the_same_events() {
        let input: &[u8] =
            b"junk< open can0 >\n< rawmode >< send 123 2 ab cd >  < echo >< send 7FF 0  >";
        let expect = [
            Event::Reply(Reply::Ok),
            Event::Reply(Reply::Ok),
            frame(0x123, &[0xAB, 0xCD]),
            Event::Reply(Reply::Echo),
            frame(0x7FF, &[]),
        ];
        for cut1 in 0..input.len() {
            for cut2 in cut1..input.len() {
                let mut s = Server::new("can0").unwrap();
                let mut v = events(&mut s, &input[..cut1]);
                v.extend(events(&mut s, &input[cut1..cut2]));
                v.extend(events(&mut s, &input[cut2..]));
                assert_eq!(v, expect, "cuts {cut1} {cut2}");
            }
        }
        let mut s = Server::new("can0").unwrap();
        let mut v = Vec::new();
        for &b in input {
            v.extend(s.push(b));
        }
        assert_eq!(v, expect);
    }

    #[test]
    fn malformed_commands_are_errors_and_change_nothing() {
        use ErrorKind::*;
        let err = |k| [Event::Reply(Reply::Error(k))];
        let mut s = Server::new("can0").unwrap();
        // Before open: only open is known.
        assert_eq!(events(&mut s, b"< rawmode >"), err(UnknownCommand));
        assert_eq!(events(&mut s, b"< send 123 0  >"), err(UnknownCommand));
        assert_eq!(events(&mut s, b"< open vcan9 >"), err(CouldNotOpenBus));
        assert_eq!(events(&mut s, b"< open >"), err(Syntax));
        assert_eq!(events(&mut s, b"<>"), err(UnknownCommand));
        assert_eq!(s.mode(), Mode::NoBus);
        let mut s = raw_server();
        let bad: &[(&[u8], ErrorKind)] = &[
            (b"< foo >", UnknownCommand),
            (b"< open can0 >", UnknownCommand),
            (b"< rawmode extra >", UnknownCommand),
            (b"< send 800 0  >", Syntax),
            (b"< send 1234 0  >", Syntax),
            (b"< send 12345678 0  >", ExtendedId),
            (b"< send 123 9 1 2 3 4 5 6 7 8 9 >", Syntax),
            (b"< send 123 2 11 >", Syntax),
            (b"< send 123 1 11 22 >", Syntax),
            (b"< send 123 1 GG >", Syntax),
            (b"< send 123 1 123 >", Syntax),
            (b"< send 12G 0  >", Syntax),
            (b"< send 123 >", Syntax),
            (b"< send 123 -1 >", Syntax),
            (b"< send 123 1 \xFF >", Syntax),
            (b"< send 1 1 1 1 1 1 1 1 1 1 1 1 >", Syntax),
        ];
        for (input, kind) in bad {
            assert_eq!(
                events(&mut s, input),
                err(*kind),
                "{:?}",
                std::str::from_utf8(input)
            );
            assert_eq!(s.mode(), Mode::Raw);
        }
        // A '<' inside a command: error, the new command is parsed.
        assert_eq!(
            events(&mut s, b"< send 12< echo >"),
            [
                Event::Reply(Reply::Error(Syntax)),
                Event::Reply(Reply::Echo)
            ]
        );
        // Too long: one error at its '>', nothing else, then back to normal.
        let mut long = Vec::from(&b"< send "[..]);
        long.extend(core::iter::repeat_n(b'1', 500));
        long.extend(b" >< echo >");
        assert_eq!(
            events(&mut s, &long),
            [
                Event::Reply(Reply::Error(TooLong)),
                Event::Reply(Reply::Echo)
            ]
        );
        // Garbage outside commands is ignored; '>' alone too.
        assert_eq!(events(&mut s, b"hello > \x00\xFF"), []);
        assert_eq!(
            Reply::Error(UnknownCommand).text(),
            "< error unknown command >"
        );
        assert!(Server::new("").is_none());
        assert!(Server::new("a_very_long_bus_name").is_none());
    }

    #[test]
    fn frame_lines() {
        // socketcand's documentation example: 0x123, 11 22 33 44 at
        // 23.424242, written as its code writes it (no spaces in the data).
        let f = CanFrame::new(0x123, &[0x11, 0x22, 0x33, 0x44]).unwrap();
        assert_eq!(
            format_frame(&f, 23_424_242).as_bytes(),
            b"< frame 123 23.424242 11223344 >"
        );
        let f = CanFrame::new(0x00A, &[]).unwrap();
        assert_eq!(format_frame(&f, 1).as_bytes(), b"< frame 00A 0.000001  >");
        let f = CanFrame::new(0x7FF, &[0xAB; 8]).unwrap();
        assert_eq!(
            format_frame(&f, 1_700_000_000_000_001).as_bytes(),
            b"< frame 7FF 1700000000.000001 ABABABABABABABAB >"
        );
        let f = CanFrame::new(0x5A1, &[0x0F, 0xF0]).unwrap();
        assert_eq!(
            format_frame(&f, 0).as_bytes(),
            b"< frame 5A1 0.000000 0FF0 >"
        );
        // The longest line fits: u64::MAX microseconds, 8 bytes.
        let l = format_frame(&CanFrame::new(0x7FF, &[0; 8]).unwrap(), u64::MAX);
        assert_eq!(
            l.as_bytes(),
            b"< frame 7FF 18446744073709.551615 0000000000000000 >"
        );
    }

    #[test]
    fn random_bytes_never_panic() {
        // 64-bit LCG (Knuth's constants) over an alphabet close to the
        // protocol's, so that many commands get parsed.
        let alphabet = b"<> <> sendopenrawmodecho can0 0123456789abcdefABCDEFxyz\n\xff";
        let mut x: u64 = 7;
        let mut s = raw_server();
        let mut count = 0usize;
        for _ in 0..200_000 {
            x = x
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let b = alphabet[(x >> 33) as usize % alphabet.len()];
            if s.push(b).is_some() {
                count += 1;
            }
        }
        assert!(count > 1000);
    }
}
