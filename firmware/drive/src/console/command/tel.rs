//! `tel`: the live telemetry stream (`crate::telemetry`): grammar and
//! replies. The samples themselves go out as binary frames between the
//! console's replies (docs/telemetry.md).
use super::super::{write_err, ErrorCode};
use super::{Outcome, ParseError, Spec};
#[cfg(doc)]
use crate::telemetry::max_rate_hz;
use crate::telemetry::{Counters, StreamSpec, TelStatus, CHANNELS, CONSOLE_BAUD};
use core::fmt::{self, Write};

/// The stream's owner: the firmware's sampler and its queue.
pub trait TelOps {
    /// Starts a stream (a running one ends); returns its number.
    fn start(&mut self, spec: StreamSpec) -> u8;
    /// Stops sampling; returns the stream's counters.
    fn stop(&mut self) -> Counters;
    /// The stream's state.
    fn status(&mut self) -> TelStatus;
}

/// The `tel` command.
pub const TEL: Spec = Spec {
    name: "tel",
    args: "list|start <rate_hz> <channels>|stop|status",
    help: "live telemetry: `list` the channels with units and the max rates, `start` a \
           stream of up to 8 comma-separated <channels> at <rate_hz> of drive time (from 1 \
           up to the max rate the console carries for that many channels, one control \
           period's value per sample) as binary frames between the replies, `stop`, \
           `status` (samples taken, sent, dropped)",
};

/// The line `tel list` and `help tel` end with: the max rate per channel
/// count, from the console's baud rate ([`max_rate_hz`]).
pub fn write_max_rates<W: Write>(out: &mut W) -> fmt::Result {
    crate::telemetry::write_max_rates(out)?;
    out.write_str("\r\n")
}

/// A parsed `tel` line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TelCmd {
    /// `tel list`.
    List,
    /// `tel start <rate_hz> <ch>[,<ch>...]`.
    Start(StreamSpec),
    /// `tel stop`.
    Stop,
    /// `tel status`.
    Status,
}

/// Parses the words after `tel`.
pub fn parse<'a>(args: &[&'a str]) -> Result<TelCmd, ParseError<'a>> {
    match args {
        ["list"] => Ok(TelCmd::List),
        ["stop"] => Ok(TelCmd::Stop),
        ["status"] => Ok(TelCmd::Status),
        ["start", rate, names] => StreamSpec::parse(rate, names)
            .map(TelCmd::Start)
            .map_err(ParseError::Tel),
        _ => Err(ParseError::BadArgs(
            "tel",
            "expected `tel list`, `tel start <rate_hz> <channels>`, `tel stop` or `tel status`",
        )),
    }
}

fn write_channels<W: Write>(out: &mut W, spec: &StreamSpec) -> fmt::Result {
    out.write_str("channels: ")?;
    for (k, &c) in spec.channels().iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        write!(out, "{sep}{}", CHANNELS[usize::from(c)].name)?;
    }
    out.write_str("\r\n")
}

fn write_spec<W: Write>(out: &mut W, spec: &StreamSpec) -> fmt::Result {
    write!(out, "rate: {} Hz of drive time\r\n", spec.rate_hz)?;
    write_channels(out, spec)?;
    write!(
        out,
        "bytes: {} B/s ({} baud console carries {} B/s)\r\n",
        spec.bytes_per_s(),
        CONSOLE_BAUD,
        CONSOLE_BAUD / 10
    )
}

fn write_counters<W: Write>(out: &mut W, c: &Counters) -> fmt::Result {
    write!(
        out,
        "samples: {} taken, {} sent, {} dropped\r\n",
        c.taken, c.sent, c.dropped
    )
}

/// Writes the reply of a `tel` command (an `ERR` line ends it when the build
/// has no stream).
pub fn execute<W: Write>(
    cmd: TelCmd,
    ops: Option<&mut dyn TelOps>,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if cmd == TelCmd::List {
        for c in CHANNELS {
            write!(out, "{} [{}] {}\r\n", c.name, c.unit, c.what)?;
        }
        write_max_rates(out)?;
        return Ok(Outcome::Ok);
    }
    let Some(ops) = ops else {
        write_err(
            out,
            ErrorCode::Unsupported,
            format_args!("tel: no telemetry stream in this build"),
        )?;
        return Ok(Outcome::Final);
    };
    match cmd {
        TelCmd::List => {}
        TelCmd::Start(spec) => {
            let n = ops.start(spec);
            write!(out, "stream: {n}\r\n")?;
            write_spec(out, &spec)?;
        }
        TelCmd::Stop => {
            let st = ops.status();
            let c = ops.stop();
            write!(out, "stream: {} stopped\r\n", st.stream)?;
            write_counters(out, &c)?;
        }
        TelCmd::Status => {
            let st = ops.status();
            match &st.spec {
                Some(spec) => {
                    write!(out, "stream: {} running\r\n", st.stream)?;
                    write_spec(out, spec)?;
                }
                None => write!(out, "stream: {} stopped\r\n", st.stream)?,
            }
            write_counters(out, &st.counters)?;
            write!(out, "queued: {} samples\r\n", st.queued)?;
        }
    }
    Ok(Outcome::Ok)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::console::{parse as parse_line, write_parse_error, Command};
    use crate::telemetry::{Point, Telemetry, CHANNEL_COUNT};
    use std::string::String;

    struct Fake(Telemetry<8>);

    impl TelOps for Fake {
        fn start(&mut self, spec: StreamSpec) -> u8 {
            self.0.start(spec)
        }
        fn stop(&mut self) -> Counters {
            self.0.stop()
        }
        fn status(&mut self) -> TelStatus {
            self.0.status()
        }
    }

    fn run(f: &mut Fake, line: &str) -> String {
        let mut out = String::new();
        match parse_line(line) {
            Ok(Command::Tel(c)) => {
                // The dispatcher ends a reply that the family left open.
                if execute(c, Some(f), &mut out).unwrap() == Outcome::Ok {
                    out.push_str("OK\r\n");
                }
            }
            Ok(other) => panic!("{other:?}"),
            Err(e) => write_parse_error(&mut out, e).unwrap(),
        }
        out
    }

    #[test]
    fn list_names_every_channel_with_its_unit() {
        let mut f = Fake(Telemetry::new());
        let r = run(&mut f, "tel list");
        // The channels, the max rates, OK.
        assert_eq!(r.lines().count(), CHANNEL_COUNT + 2);
        // By hand: 73,728 B/s for telemetry (80 % of 921600 baud at 10
        // bits per byte) over 17-byte frames (one channel), 45-byte (eight).
        assert!(
            r.contains("\r\nmax rate: 1 channel 4336 Hz, 2 channels 3510 Hz, "),
            "{r}"
        );
        assert!(r.contains(", 8 channels 1638 Hz of drive time"), "{r}");
        for n in [
            "i_d [A]",
            "torque [Nm]",
            "position [rev]",
            "velocity [rev/s]",
            "speed [rad/s]",
            "step_time [us]",
        ] {
            assert!(r.contains(n), "{n} in {r}");
        }
        assert!(r.ends_with("OK\r\n"));
    }

    #[test]
    fn start_status_stop() {
        let mut f = Fake(Telemetry::new());
        let r = run(&mut f, "tel start 1000 torque,i_q,torque_ref");
        assert!(r.starts_with("stream: 1\r\nrate: 1000 Hz"), "{r}");
        assert!(r.contains("channels: torque,i_q,torque_ref\r\n"), "{r}");
        // 25-byte frames (2 + 1 + 8 + 12 + 2) at 1 kHz.
        assert!(r.contains("bytes: 25000 B/s"), "{r}");
        for k in 0..3 {
            f.0.on_step(&Point {
                time_s: f64::from(k) * 1e-3,
                values: [0.0; CHANNEL_COUNT],
            });
        }
        let r = run(&mut f, "tel status");
        assert!(r.contains("stream: 1 running"), "{r}");
        assert!(r.contains("samples: 3 taken, 0 sent, 0 dropped"), "{r}");
        assert!(r.contains("queued: 3 samples"), "{r}");
        let r = run(&mut f, "tel stop");
        assert!(
            r.starts_with("stream: 1 stopped\r\nsamples: 3 taken"),
            "{r}"
        );
        assert!(run(&mut f, "tel status").contains("stream: 1 stopped"));
    }

    #[test]
    fn bad_starts_are_refused_and_change_nothing() {
        let mut f = Fake(Telemetry::new());
        run(&mut f, "tel start 100 i_d");
        for (line, why) in [
            ("tel start 0 i_d", "rate must be"),
            ("tel start 100 i_d,bogus", "no channel `bogus`"),
            ("tel start 100 i_d,i_d", "named twice"),
            (
                "tel start 10000 i_d,i_q,torque",
                "max rate of 3 channels, 2949 Hz",
            ),
            ("tel start 4337 i_d", "max rate of 1 channel, 4336 Hz"),
            ("tel start 100", "expected `tel list`"),
            ("tel bogus", "expected `tel list`"),
        ] {
            let r = run(&mut f, line);
            assert!(r.starts_with("ERR bad-args tel: "), "{line}: {r}");
            assert!(r.contains(why), "{line}: {r}");
            assert_eq!(r.lines().count(), 1, "{r}");
        }
        let st = f.0.status();
        assert_eq!((st.stream, st.spec.unwrap().rate_hz), (1, 100));
        // The advertised max rate starts.
        assert!(run(&mut f, "tel start 4336 i_d").ends_with("OK\r\n"));
    }

    #[test]
    fn without_a_stream_owner_start_is_unsupported() {
        let mut out = String::new();
        let Ok(Command::Tel(c)) = parse_line("tel status") else {
            panic!()
        };
        execute(c, None, &mut out).unwrap();
        assert!(out.starts_with("ERR unsupported tel:"), "{out}");
    }
}
