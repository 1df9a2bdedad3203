//! Live telemetry: the channel table, the decimating sampler with its
//! queue, and the frame format on the console UART (both ends: the firmware
//! encodes, `drivectl` decodes with the same code).
//!
//! Sampling: the control interrupt hands every control period's values to
//! [`Telemetry::on_step`]; a sample is the value of the one control period
//! at or after each sample instant `k / rate` of drive time (decimation by
//! picking, no averaging), so a 1 kHz stream in FOC (15.985 kHz) takes
//! every 16th period, in MPDTC (63.94 kHz) every 64th, with the drive time
//! of the picked period in the frame.
//!
//! Frame on the wire (docs/telemetry.md): `0x00`, COBS(payload), `0x00`.
//! The console's text never holds a zero byte, so a receiver tells frames
//! from text by the zeros alone; the firmware writes a frame in one piece
//! from the main loop, never inside a reply. Payload, little endian:
//!
//! | bytes | field |
//! |---|---|
//! | 1 | kind, [`KIND_SAMPLE`] |
//! | 1 | stream number (one per `tel start`) |
//! | 2 | sequence number in the stream, from 0, wraps at 65536 |
//! | 4 | drive time of the sample, us (wraps after 71.6 min) |
//! | 4 n | the `n` channels as `f32`, in the order of `tel start` |
//! | 2 | CRC-16/CCITT-FALSE of everything before |

use heapless::{Deque, Vec};

/// Channels per stream at most.
pub const MAX_CHANNELS: usize = 8;
/// The lowest sample rate, Hz of drive time; the highest is what the
/// console carries for the stream's channels ([`max_rate_hz`]).
pub const RATE_MIN_HZ: u32 = 1;
/// Kind byte of a sample frame.
pub const KIND_SAMPLE: u8 = 0x01;
/// Payload bytes before the channel values.
pub const HEADER_BYTES: usize = 8;
/// Baud rate of the console UART (UART1) on a board, 8N1.
pub const CONSOLE_BAUD: u32 = 921_600;
/// Bit times per byte on the console UART: 8N1 is a start bit, 8 data
/// bits and a stop bit.
pub const BITS_PER_BYTE: u32 = 10;
/// Bytes per second the console UART carries at [`CONSOLE_BAUD`].
pub const CONSOLE_BYTES_PER_S: u32 = CONSOLE_BAUD / BITS_PER_BYTE;
/// Share of the console's bytes a stream may take, percent; the rest is
/// the console's replies.
pub const BUDGET_PERCENT: u32 = 80;
/// Bytes per second a stream may take.
pub const BUDGET_BYTES_PER_S: u32 = CONSOLE_BYTES_PER_S * BUDGET_PERCENT / 100;

/// The highest sample rate, Hz of drive time, of a stream of `channels`
/// channels: the whole frames per second that fit [`BUDGET_BYTES_PER_S`].
/// The one place the limit is computed: `tel start` refuses above it,
/// `tel list` and `help tel` print it. 0 for a channel count outside
/// `1..=MAX_CHANNELS`.
pub const fn max_rate_hz(channels: usize) -> u32 {
    if channels == 0 || channels > MAX_CHANNELS {
        return 0;
    }
    BUDGET_BYTES_PER_S / frame_bytes(channels) as u32
}

/// Writes `max rate: 1 channel <r> Hz, 2 channels <r> Hz, ...` with the
/// link it follows from (no line end).
pub fn write_max_rates<W: core::fmt::Write>(out: &mut W) -> core::fmt::Result {
    out.write_str("max rate: ")?;
    for n in 1..=MAX_CHANNELS {
        let sep = if n == 1 { "" } else { ", " };
        let s = if n == 1 { "" } else { "s" };
        write!(out, "{sep}{n} channel{s} {} Hz", max_rate_hz(n))?;
    }
    write!(
        out,
        " of drive time ({BUDGET_PERCENT} % of the console's {CONSOLE_BYTES_PER_S} B/s at \
         {CONSOLE_BAUD} baud 8N1, {BITS_PER_BYTE} bits per byte)"
    )
}

/// What a channel samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChannelSpec {
    /// Name in `tel start` and `tel list`.
    pub name: &'static str,
    /// Unit (`1` for a ratio, `bits` for a bit set).
    pub unit: &'static str,
    /// What it is.
    pub what: &'static str,
}

/// Every channel, in the order of [`Point::values`]. The indices are part
/// of nothing on the wire (a stream's frame carries its own order).
pub const CHANNELS: &[ChannelSpec] = &[
    ChannelSpec {
        name: "i_d",
        unit: "A",
        what: "d-axis current: ADC averages, Park transform with the encoder angle",
    },
    ChannelSpec {
        name: "i_q",
        unit: "A",
        what: "q-axis current, as i_d",
    },
    ChannelSpec {
        name: "torque",
        unit: "Nm",
        what: "torque from the measured currents, 1.5 p psi i_q",
    },
    ChannelSpec {
        name: "torque_ref",
        unit: "Nm",
        what: "torque reference the controller used in the period",
    },
    ChannelSpec {
        name: "position",
        unit: "rev",
        what: "multi-turn rotor position since boot or `pos zero`, as `status` position",
    },
    ChannelSpec {
        name: "velocity",
        unit: "rev/s",
        what: "rotor mechanical velocity, as `status` velocity",
    },
    ChannelSpec {
        name: "speed",
        unit: "rad/s",
        what: "electrical angular speed (pole pairs x mechanical) from the encoder's speed \
               window, as `status` speed",
    },
    ChannelSpec {
        name: "duty_a",
        unit: "1",
        what: "leg a: FOC commanded duty, MPDTC upper gate of the applied decision (0 or 1); \
               0 with the gates off",
    },
    ChannelSpec {
        name: "duty_b",
        unit: "1",
        what: "leg b, as duty_a",
    },
    ChannelSpec {
        name: "duty_c",
        unit: "1",
        what: "leg c, as duty_a",
    },
    ChannelSpec {
        name: "switching",
        unit: "bits",
        what: "MPDTC switching state of the applied decision (bit 2 leg a .. bit 0 leg c); \
               0 in FOC",
    },
    ChannelSpec {
        name: "faults",
        unit: "bits",
        what: "latched faults, bit n is fault code n + 1 (`fault`)",
    },
    ChannelSpec {
        name: "step_time",
        unit: "us",
        what: "duration of the control step (global timer at the board's clock)",
    },
];

/// Number of channels.
pub const CHANNEL_COUNT: usize = 13;
const _: () = assert!(CHANNELS.len() == CHANNEL_COUNT);

/// The index of channel `name`.
pub fn channel(name: &str) -> Option<usize> {
    CHANNELS.iter().position(|c| c.name == name)
}

/// One control period's values, indexed like [`CHANNELS`].
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Point {
    /// Drive time at the end of the period, s.
    pub time_s: f64,
    /// Channel values in their units.
    pub values: [f32; CHANNEL_COUNT],
}

/// What `tel start` asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StreamSpec {
    /// Samples per second of drive time.
    pub rate_hz: u32,
    /// Channel indices into [`CHANNELS`], in frame order (the first `n`).
    index: [u8; MAX_CHANNELS],
    /// Number of channels.
    n: u8,
}

/// Why a `tel start` is refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpecError<'a> {
    /// Rate below [`RATE_MIN_HZ`] or not a whole number.
    Rate,
    /// A name not in [`CHANNELS`].
    Unknown(&'a str),
    /// A channel named twice.
    Twice(&'a str),
    /// No channel, or more than [`MAX_CHANNELS`].
    Count,
    /// A rate above [`max_rate_hz`] of the channel count: more bytes per
    /// second than the console's share.
    Budget {
        /// Channels named.
        channels: usize,
        /// Rate asked for, Hz.
        rate_hz: u32,
    },
}

impl core::fmt::Display for SpecError<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            SpecError::Rate => write!(
                f,
                "rate must be a whole number of Hz, at least {RATE_MIN_HZ} (at most the \
                 max rate of `tel list`)"
            ),
            SpecError::Unknown(n) => {
                let n = n.get(..24).unwrap_or(n);
                write!(f, "no channel `{n}` (`tel list`)")
            }
            SpecError::Twice(n) => write!(f, "channel `{n}` named twice"),
            SpecError::Count => write!(f, "name 1 to {MAX_CHANNELS} channels, comma separated"),
            SpecError::Budget { channels, rate_hz } => {
                let s = if *channels == 1 { "" } else { "s" };
                write!(
                    f,
                    "{rate_hz} Hz is above the max rate of {channels} channel{s}, {} Hz: \
                     {}-byte frames at {rate_hz} Hz need {} B/s, the console UART \
                     ({CONSOLE_BAUD} baud 8N1) allows {BUDGET_BYTES_PER_S} B/s for telemetry",
                    max_rate_hz(*channels),
                    frame_bytes(*channels),
                    u64::from(*rate_hz) * frame_bytes(*channels) as u64,
                )
            }
        }
    }
}

impl StreamSpec {
    /// Parses `<rate_hz>` and `<ch>[,<ch>...]` and checks the byte budget.
    pub fn parse<'a>(rate: &str, names: &'a str) -> Result<Self, SpecError<'a>> {
        let rate_hz = rate
            .parse::<u32>()
            .ok()
            .filter(|r| *r >= RATE_MIN_HZ)
            .ok_or(SpecError::Rate)?;
        let mut channels: Vec<u8, MAX_CHANNELS> = Vec::new();
        for n in names.split(',') {
            let i = channel(n).ok_or(SpecError::Unknown(n))? as u8;
            if channels.contains(&i) {
                return Err(SpecError::Twice(n));
            }
            channels.push(i).map_err(|_| SpecError::Count)?;
        }
        let mut index = [0; MAX_CHANNELS];
        index[..channels.len()].copy_from_slice(&channels);
        if rate_hz > max_rate_hz(channels.len()) {
            return Err(SpecError::Budget {
                channels: channels.len(),
                rate_hz,
            });
        }
        Ok(Self {
            rate_hz,
            index,
            n: channels.len() as u8,
        })
    }

    /// Channel indices into [`CHANNELS`], in frame order.
    pub fn channels(&self) -> &[u8] {
        &self.index[..usize::from(self.n)]
    }

    /// Bytes per second of drive time on the wire.
    pub fn bytes_per_s(&self) -> u32 {
        self.rate_hz * frame_bytes(self.channels().len()) as u32
    }
}

/// Bytes of one frame on the wire with `n` channels: two delimiters, one
/// COBS code byte (a payload under 254 bytes needs exactly one), the
/// header, the values and the CRC.
pub const fn frame_bytes(n: usize) -> usize {
    2 + 1 + HEADER_BYTES + 4 * n + 2
}

/// The largest frame on the wire.
pub const FRAME_MAX: usize = frame_bytes(MAX_CHANNELS);

/// One queued sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Stream number.
    pub stream: u8,
    /// Sequence number.
    pub seq: u16,
    /// Drive time, us (wrapping).
    pub time_us: u32,
    /// Channel count.
    pub n: u8,
    /// Values in stream order.
    pub values: [f32; MAX_CHANNELS],
}

impl Sample {
    /// Writes the frame (delimiters included) into `out`; returns its length.
    pub fn encode(&self, out: &mut [u8; FRAME_MAX]) -> usize {
        let n = usize::from(self.n);
        let mut p = [0u8; HEADER_BYTES + 4 * MAX_CHANNELS + 2];
        p[0] = KIND_SAMPLE;
        p[1] = self.stream;
        p[2..4].copy_from_slice(&self.seq.to_le_bytes());
        p[4..8].copy_from_slice(&self.time_us.to_le_bytes());
        for (k, v) in self.values[..n].iter().enumerate() {
            p[HEADER_BYTES + 4 * k..HEADER_BYTES + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
        }
        let len = HEADER_BYTES + 4 * n;
        let crc = crc16(&p[..len]);
        p[len..len + 2].copy_from_slice(&crc.to_le_bytes());
        out[0] = 0;
        let m = cobs_encode(&p[..len + 2], &mut out[1..]);
        out[1 + m] = 0;
        m + 2
    }
}

/// CRC-16/CCITT-FALSE: polynomial 0x1021, initial 0xFFFF, no reflection,
/// no final XOR.
pub fn crc16(data: &[u8]) -> u16 {
    let mut crc = 0xFFFFu16;
    for &b in data {
        crc ^= u16::from(b) << 8;
        for _ in 0..8 {
            crc = if crc & 0x8000 != 0 {
                (crc << 1) ^ 0x1021
            } else {
                crc << 1
            };
        }
    }
    crc
}

/// COBS encoding of `src` (shorter than 254 bytes) into `dst`; returns the
/// length (`src.len() + 1`). The result holds no zero byte.
fn cobs_encode(src: &[u8], dst: &mut [u8]) -> usize {
    let mut code_at = 0;
    let mut code = 1u8;
    let mut o = 1;
    for &b in src {
        if b == 0 {
            dst[code_at] = code;
            code_at = o;
            code = 1;
        } else {
            dst[o] = b;
            code += 1;
        }
        o += 1;
    }
    dst[code_at] = code;
    o
}

/// COBS decoding of one frame's bytes (no delimiters) into `dst`; `None`
/// if malformed or too long.
fn cobs_decode(src: &[u8], dst: &mut [u8]) -> Option<usize> {
    let (mut i, mut o) = (0, 0);
    while i < src.len() {
        let code = usize::from(src[i]);
        if code == 0 || i + code > src.len() {
            return None;
        }
        for &b in &src[i + 1..i + code] {
            *dst.get_mut(o)? = b;
            o += 1;
        }
        i += code;
        if code < 0xFF && i < src.len() {
            *dst.get_mut(o)? = 0;
            o += 1;
        }
    }
    Some(o)
}

/// Decodes a sample frame's bytes between the delimiters.
pub fn decode(frame: &[u8]) -> Option<Sample> {
    let mut p = [0u8; FRAME_MAX];
    let len = cobs_decode(frame, &mut p)?;
    if len < HEADER_BYTES + 2 || (len - HEADER_BYTES - 2) % 4 != 0 || p[0] != KIND_SAMPLE {
        return None;
    }
    let body = len - 2;
    if crc16(&p[..body]) != u16::from_le_bytes([p[body], p[body + 1]]) {
        return None;
    }
    let n = (body - HEADER_BYTES) / 4;
    if n > MAX_CHANNELS {
        return None;
    }
    let mut values = [0f32; MAX_CHANNELS];
    for (k, v) in values[..n].iter_mut().enumerate() {
        let at = HEADER_BYTES + 4 * k;
        *v = f32::from_le_bytes([p[at], p[at + 1], p[at + 2], p[at + 3]]);
    }
    Some(Sample {
        stream: p[1],
        seq: u16::from_le_bytes([p[2], p[3]]),
        time_us: u32::from_le_bytes([p[4], p[5], p[6], p[7]]),
        n: n as u8,
        values,
    })
}

/// What a received byte turned out to be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Demuxed {
    /// A byte of the console's text.
    Text(u8),
    /// Part of a frame; nothing complete yet.
    Nothing,
    /// A complete, valid frame.
    Frame(Sample),
    /// A frame that failed its checks (length, COBS or CRC).
    Bad,
}

/// Splits the console byte stream into text and frames (host side).
///
/// Outside a frame, a zero opens one; inside, a zero closes it. A frame
/// that fails its checks is dropped. If its length is a frame's length, a
/// byte was corrupted and the receiver is in step; otherwise a delimiter
/// was lost (text or another frame ran into it), and its closing zero is
/// taken as the opening of the next frame: the receiver is back in step at
/// the next good frame.
#[derive(Clone, Debug, Default)]
pub struct Demux {
    in_frame: bool,
    buf: Vec<u8, FRAME_MAX>,
    overlong: bool,
}

impl Demux {
    /// Outside a frame.
    pub const fn new() -> Self {
        Self {
            in_frame: false,
            buf: Vec::new(),
            overlong: false,
        }
    }

    /// One received byte.
    pub fn feed(&mut self, b: u8) -> Demuxed {
        if !self.in_frame {
            if b == 0 {
                self.in_frame = true;
                self.buf.clear();
                self.overlong = false;
                return Demuxed::Nothing;
            }
            return Demuxed::Text(b);
        }
        if b != 0 {
            if self.buf.push(b).is_err() {
                self.overlong = true;
            }
            return Demuxed::Nothing;
        }
        if self.buf.is_empty() {
            // Two zeros in a row: the second opens the frame.
            return Demuxed::Nothing;
        }
        let r = if self.overlong {
            None
        } else {
            decode(&self.buf)
        };
        let len = if self.overlong {
            usize::MAX / 2
        } else {
            self.buf.len()
        };
        self.buf.clear();
        self.overlong = false;
        match r {
            Some(s) => {
                self.in_frame = false;
                Demuxed::Frame(s)
            }
            None => {
                // COBS adds one byte to the payload of 8 + 4 n + 2 bytes.
                let n4 = (len as isize) - 11;
                self.in_frame = !(0..=4 * MAX_CHANNELS as isize).contains(&n4) || n4 % 4 != 0;
                Demuxed::Bad
            }
        }
    }
}

/// Counters of a stream.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// Samples taken (sequence numbers handed out).
    pub taken: u32,
    /// Samples dropped because the queue was full.
    pub dropped: u32,
    /// Frames sent.
    pub sent: u32,
}

/// `tel status`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TelStatus {
    /// The running stream, if any.
    pub spec: Option<StreamSpec>,
    /// Number of the current (or last) stream.
    pub stream: u8,
    /// Its counters.
    pub counters: Counters,
    /// Samples waiting to be sent.
    pub queued: usize,
}

/// The sampler and its queue of `Q` samples, between the control
/// interrupt (producer) and the console's main loop (consumer).
pub struct Telemetry<const Q: usize> {
    spec: Option<StreamSpec>,
    stream: u8,
    /// Drive time of the next sample instant, s; `None` until the first
    /// period after `start`.
    next_s: Option<f64>,
    counters: Counters,
    queue: Deque<Sample, Q>,
}

impl<const Q: usize> Default for Telemetry<Q> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const Q: usize> Telemetry<Q> {
    /// Stopped, empty.
    pub const fn new() -> Self {
        Self {
            spec: None,
            stream: 0,
            next_s: None,
            counters: Counters {
                taken: 0,
                dropped: 0,
                sent: 0,
            },
            queue: Deque::new(),
        }
    }

    /// Starts a new stream (the queue of the previous one is dropped);
    /// returns its number.
    pub fn start(&mut self, spec: StreamSpec) -> u8 {
        self.stream = self.stream.wrapping_add(1);
        self.spec = Some(spec);
        self.next_s = None;
        self.counters = Counters::default();
        self.queue.clear();
        self.stream
    }

    /// Stops sampling; queued samples are still sent.
    pub fn stop(&mut self) -> Counters {
        self.spec = None;
        self.counters
    }

    /// Status for `tel status`.
    pub fn status(&self) -> TelStatus {
        TelStatus {
            spec: self.spec,
            stream: self.stream,
            counters: self.counters,
            queued: self.queue.len(),
        }
    }

    /// One control period: queues a sample when a sample instant has come.
    pub fn on_step(&mut self, p: &Point) {
        let Some(spec) = self.spec else { return };
        let dt = 1.0 / f64::from(spec.rate_hz);
        let next = *self.next_s.get_or_insert(p.time_s);
        if p.time_s < next {
            return;
        }
        // The instant after this one; after a stall (no periods) the
        // instants missed are skipped, not sampled in a burst.
        let mut n = next + dt;
        if n <= p.time_s {
            n = p.time_s + dt;
        }
        self.next_s = Some(n);
        let mut values = [0f32; MAX_CHANNELS];
        for (v, &c) in values.iter_mut().zip(spec.channels()) {
            *v = p.values[usize::from(c)];
        }
        let s = Sample {
            stream: self.stream,
            seq: self.counters.taken as u16,
            time_us: (p.time_s * 1e6) as u64 as u32,
            n: spec.n,
            values,
        };
        self.counters.taken = self.counters.taken.wrapping_add(1);
        if self.queue.push_back(s).is_err() {
            self.counters.dropped = self.counters.dropped.wrapping_add(1);
        }
    }

    /// The next sample to send.
    pub fn pop(&mut self) -> Option<Sample> {
        let s = self.queue.pop_front()?;
        self.counters.sent = self.counters.sent.wrapping_add(1);
        Some(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc16_check_value() {
        // The catalogue's check value of CRC-16/CCITT-FALSE.
        assert_eq!(crc16(b"123456789"), 0x29B1);
    }

    #[test]
    fn cobs_known_cases() {
        // Examples of the COBS paper (Cheshire and Baker, 1999) as listed
        // in its common descriptions.
        let cases: &[(&[u8], &[u8])] = &[
            (&[0x00], &[0x01, 0x01]),
            (&[0x00, 0x00], &[0x01, 0x01, 0x01]),
            (&[0x11, 0x22, 0x00, 0x33], &[0x03, 0x11, 0x22, 0x02, 0x33]),
            (&[0x11, 0x22, 0x33, 0x44], &[0x05, 0x11, 0x22, 0x33, 0x44]),
            (&[0x11, 0x00, 0x00, 0x00], &[0x02, 0x11, 0x01, 0x01, 0x01]),
        ];
        for (raw, enc) in cases {
            let mut out = [0u8; 16];
            let n = cobs_encode(raw, &mut out);
            assert_eq!(&out[..n], *enc);
            let mut back = [0u8; 16];
            let m = cobs_decode(enc, &mut back).unwrap();
            assert_eq!(&back[..m], *raw);
        }
    }

    fn sample(n: u8, seq: u16) -> Sample {
        let mut values = [0f32; MAX_CHANNELS];
        for (k, v) in values[..usize::from(n)].iter_mut().enumerate() {
            // Values whose bytes hold zeros (0.0, 2.0 = 0x40000000).
            *v = [0.0, 2.0, -1.5e-3, 1e6, f32::MIN_POSITIVE, 7.25, -0.0, 3.0][k];
        }
        Sample {
            stream: 3,
            seq,
            time_us: 0x0100_0000 + u32::from(seq),
            n,
            values,
        }
    }

    #[test]
    fn frames_round_trip_with_their_length() {
        for n in 0..=MAX_CHANNELS as u8 {
            let s = sample(n, 256);
            let mut out = [0u8; FRAME_MAX];
            let len = s.encode(&mut out);
            assert_eq!(len, frame_bytes(usize::from(n)));
            assert_eq!(out[0], 0);
            assert_eq!(out[len - 1], 0);
            assert!(out[1..len - 1].iter().all(|&b| b != 0));
            assert_eq!(decode(&out[1..len - 1]), Some(s));
        }
    }

    #[test]
    fn a_flipped_bit_is_caught() {
        let mut out = [0u8; FRAME_MAX];
        let len = sample(3, 9).encode(&mut out);
        for i in 1..len - 1 {
            for bit in 0..8 {
                let mut f = out;
                f[i] ^= 1 << bit;
                if f[i] == 0 {
                    continue;
                }
                assert_eq!(decode(&f[1..len - 1]), None, "byte {i} bit {bit}");
            }
        }
    }

    #[test]
    fn demux_gives_text_whole_and_frames_between() {
        let mut wire = std::vec::Vec::new();
        wire.extend_from_slice(b"sta");
        let mut out = [0u8; FRAME_MAX];
        let len = sample(2, 1).encode(&mut out);
        wire.extend_from_slice(&out[..len]);
        wire.extend_from_slice(b"tus\r\nOK\r\n");
        let len2 = sample(2, 2).encode(&mut out);
        wire.extend_from_slice(&out[..len2]);
        let mut d = Demux::new();
        let (mut text, mut frames) = (std::vec::Vec::new(), std::vec::Vec::new());
        for &b in &wire {
            match d.feed(b) {
                Demuxed::Text(t) => text.push(t),
                Demuxed::Frame(s) => frames.push(s.seq),
                Demuxed::Nothing => {}
                Demuxed::Bad => panic!("bad frame"),
            }
        }
        assert_eq!(text, b"status\r\nOK\r\n");
        assert_eq!(frames, [1, 2]);
    }

    #[test]
    fn demux_recovers_after_a_lost_closing_zero() {
        let mut out = [0u8; FRAME_MAX];
        let mut wire = std::vec::Vec::new();
        let len = sample(1, 1).encode(&mut out);
        wire.extend_from_slice(&out[..len - 1]); // closing zero lost
        wire.extend_from_slice(b"OK\r\ndrive> ");
        for seq in 2..=3 {
            let len = sample(1, seq).encode(&mut out);
            wire.extend_from_slice(&out[..len]);
        }
        wire.extend_from_slice(b"x");
        let mut d = Demux::new();
        let mut got = std::vec::Vec::new();
        let mut bad = 0;
        let mut text = std::vec::Vec::new();
        for &b in &wire {
            match d.feed(b) {
                Demuxed::Frame(s) => got.push(s.seq),
                Demuxed::Bad => bad += 1,
                Demuxed::Text(t) => text.push(t),
                Demuxed::Nothing => {}
            }
        }
        // Frame 1 and the text inside it are lost; 2 and 3 come through.
        assert_eq!(bad, 1);
        assert_eq!(got, [2, 3]);
        assert_eq!(text, b"x");
    }

    fn point(t: f64) -> Point {
        let mut values = [0f32; CHANNEL_COUNT];
        for (k, v) in values.iter_mut().enumerate() {
            *v = k as f32;
        }
        Point { time_s: t, values }
    }

    #[test]
    fn one_khz_picks_one_period_per_ms_of_drive_time() {
        // MPDTC period 1564 PL cycles = 15.64 us; 0.5 s of drive time.
        let ts = 15.64e-6;
        let mut t = Telemetry::<1024>::new();
        let spec = StreamSpec::parse("1000", "torque,i_q,torque_ref").unwrap();
        assert_eq!(t.start(spec), 1);
        let periods = (0.5 / ts) as u64;
        let mut times = std::vec::Vec::new();
        for k in 1..=periods {
            t.on_step(&point(k as f64 * ts));
            while let Some(s) = t.pop() {
                assert_eq!(usize::from(s.n), 3);
                assert_eq!(&s.values[..3], &[2.0, 1.0, 3.0]);
                assert_eq!(usize::from(s.seq), times.len());
                times.push(f64::from(s.time_us) * 1e-6);
            }
        }
        // 0.5 s at 1 kHz: 500 instants, the first at the first period.
        assert_eq!(times.len(), 500);
        for w in times.windows(2) {
            let d = w[1] - w[0];
            assert!((d - 1e-3).abs() <= ts + 1e-6, "{d}");
        }
        let c = t.stop();
        assert_eq!((c.taken, c.dropped, c.sent), (500, 0, 500));
    }

    #[test]
    fn a_full_queue_counts_drops_and_the_sequence_shows_them() {
        let mut t = Telemetry::<4>::new();
        t.start(StreamSpec::parse("4000", "i_d").unwrap());
        for k in 0..10 {
            t.on_step(&point(f64::from(k) * 2.5e-4));
        }
        let st = t.status();
        assert_eq!(
            (st.counters.taken, st.counters.dropped, st.queued),
            (10, 6, 4)
        );
        let seqs: std::vec::Vec<u16> = core::iter::from_fn(|| t.pop()).map(|s| s.seq).collect();
        assert_eq!(seqs, [0, 1, 2, 3]);
    }

    #[test]
    fn start_is_checked_and_a_refusal_changes_nothing() {
        assert_eq!(StreamSpec::parse("0", "i_d"), Err(SpecError::Rate));
        assert_eq!(StreamSpec::parse("-5", "i_d"), Err(SpecError::Rate));
        assert_eq!(
            StreamSpec::parse("99999999999", "i_d"),
            Err(SpecError::Rate)
        );
        assert_eq!(StreamSpec::parse("1e3", "i_d"), Err(SpecError::Rate));
        assert_eq!(
            StreamSpec::parse("100", "i_d,nope"),
            Err(SpecError::Unknown("nope"))
        );
        assert_eq!(
            StreamSpec::parse("100", "i_d,i_d"),
            Err(SpecError::Twice("i_d"))
        );
        assert_eq!(
            StreamSpec::parse("100", "i_d,"),
            Err(SpecError::Unknown(""))
        );
        let nine = "i_d,i_q,torque,torque_ref,position,velocity,speed,duty_a,duty_b";
        assert_eq!(StreamSpec::parse("100", nine), Err(SpecError::Count));
        // 8 channels at 10 kHz: 450 kB/s, far beyond 921600 baud.
        let eight = "i_d,i_q,torque,torque_ref,position,velocity,speed,duty_a";
        let e = StreamSpec::parse("10000", eight).unwrap_err();
        assert_eq!(
            e,
            SpecError::Budget {
                channels: 8,
                rate_hz: 10_000
            }
        );
        assert_eq!(
            std::format!("{e}"),
            "10000 Hz is above the max rate of 8 channels, 1638 Hz: 45-byte frames at \
             10000 Hz need 450000 B/s, the console UART (921600 baud 8N1) allows 73728 B/s \
             for telemetry"
        );
        // The largest u32 rate: no overflow on the way to the refusal.
        let e = StreamSpec::parse("4294967295", "i_d").unwrap_err();
        assert!(std::format!("{e}").contains("need 73014444015 B/s"), "{e}");
        assert!(Telemetry::<4>::new().status().spec.is_none());
    }

    /// The rate limit against the link, by hand: 921600 baud at 10 bits
    /// per byte is 92,160 B/s, 80 % of it 73,728 B/s; a frame is
    /// 2 delimiters + 1 COBS byte + 8 header + 4 per channel + 2 CRC bytes.
    #[test]
    fn max_rate_is_the_frames_per_second_the_console_carries() {
        // n: frame bytes, floor(73728 / frame) Hz.
        let by_hand = [
            (1, 17, 4336),
            (2, 21, 3510),
            (3, 25, 2949),
            (4, 29, 2542),
            (5, 33, 2234),
            (6, 37, 1992),
            (7, 41, 1798),
            (8, 45, 1638),
        ];
        for (n, frame, max) in by_hand {
            assert_eq!(frame_bytes(n), frame, "{n}");
            assert_eq!(max_rate_hz(n), max, "{n}");
        }
        assert_eq!(max_rate_hz(0), 0);
        assert_eq!(max_rate_hz(9), 0);
        // The limit is exact: the max rate starts, one more Hz is refused.
        let names = [
            "i_d",
            "i_d,i_q",
            "i_d,i_q,torque,torque_ref,position,velocity,speed,duty_a",
        ];
        for (names, n, max) in [
            (names[0], 1, 4336),
            (names[1], 2, 3510),
            (names[2], 8, 1638),
        ] {
            let s = StreamSpec::parse(&std::format!("{max}"), names).unwrap();
            assert!(s.bytes_per_s() <= 73_728, "{names}");
            assert_eq!(
                StreamSpec::parse(&std::format!("{}", max + 1), names),
                Err(SpecError::Budget {
                    channels: n,
                    rate_hz: max + 1
                })
            );
        }
        let mut line = std::string::String::new();
        write_max_rates(&mut line).unwrap();
        assert!(
            line.starts_with(
                "max rate: 1 channel 4336 Hz, 2 channels 3510 Hz, 3 channels 2949 Hz, \
                 4 channels 2542 Hz, 5 channels 2234 Hz, 6 channels 1992 Hz, 7 channels \
                 1798 Hz, 8 channels 1638 Hz of drive time (80 % of the console's 92160 B/s \
                 at 921600 baud 8N1"
            ),
            "{line}"
        );
    }

    #[test]
    fn the_docs_list_every_channel_with_its_unit() {
        let doc = include_str!("../../../docs/telemetry.md");
        for c in CHANNELS {
            let row = doc
                .lines()
                .find(|l| l.starts_with('|') && l.contains(&std::format!("`{}`", c.name)))
                .unwrap_or_else(|| panic!("docs/telemetry.md: no row for {}", c.name));
            assert!(row.contains(&std::format!("| {} |", c.unit)), "{row}");
        }
    }

    #[test]
    fn eight_channels_at_one_khz_fit_the_console_uart() {
        // 45-byte frames at 1 kHz: 45,000 B/s of the 92,160 B/s that
        // 921600 baud 8N1 carries; 115200 baud (11,520 B/s) would not do.
        let eight = "i_d,i_q,torque,torque_ref,position,velocity,speed,step_time";
        let s = StreamSpec::parse("1000", eight).unwrap();
        assert_eq!(frame_bytes(8), 45);
        assert_eq!(s.bytes_per_s(), 45_000);
        assert!(f64::from(s.bytes_per_s()) < 0.5 * f64::from(CONSOLE_BYTES_PER_S));
        assert!(s.bytes_per_s() > 115_200 / 10);
        // The board's UART reference clock reaches the baud rate within 1 %.
        let d = crate::zynq::uart_divisors(50_000_000, CONSOLE_BAUD).unwrap();
        let err = f64::from(d.baud(50_000_000)) / f64::from(CONSOLE_BAUD) - 1.0;
        assert!(err.abs() < 0.01, "{err}");
    }
}
