//! Whose telemetry frames are they: the running drive's one stream among
//! its clients (see [`crate::server`]).
//!
//! The firmware runs one stream; each `tel start` replaces it. Clients that
//! started a stream form a stack: the last one's stream runs, the ones
//! below are suspended. When the running one ends (its `tel stop`, its
//! client gone, or another client's `tel stop`), the one below is resumed:
//! the server sends its `tel start` line again, and its frames keep the
//! stream number and the sequence its client knows. The samples it missed
//! while suspended count as a gap in the sequence (lost frames, by the
//! drive time that passed), as a dropped frame would.
use drive::telemetry::Sample;

/// A telemetry line a client sent.
#[derive(Clone, Debug, PartialEq)]
pub enum TelLine {
    /// `tel start <rate_hz> <channels>`, the line as typed.
    Start { rate_hz: u32, line: String },
    /// `tel stop`.
    Stop,
}

impl TelLine {
    /// The telemetry line in `line`, if it is one that starts or stops the
    /// stream.
    pub fn parse(line: &str) -> Option<TelLine> {
        let mut w = line.split_whitespace();
        if w.next() != Some("tel") {
            return None;
        }
        match w.next() {
            Some("start") => Some(TelLine::Start {
                rate_hz: w.next()?.parse().ok()?,
                line: line.trim().to_string(),
            }),
            Some("stop") => Some(TelLine::Stop),
            _ => None,
        }
    }
}

/// One client's stream, as that client knows it.
#[derive(Clone, Debug)]
struct Want {
    client: u64,
    line: String,
    rate_hz: u32,
    /// The stream number in the client's `tel start` reply.
    client_no: u8,
    /// The firmware's number of the stream now carrying it.
    fw_no: u8,
    /// Added to the firmware's sequence numbers (wrapping).
    seq_offset: u16,
    /// The last frame sent to the client: its sequence and drive time.
    last: Option<(u16, u32)>,
    /// Set on a resume: the offset is fixed by the first frame after it.
    resumed: bool,
}

/// What the server does next for the telemetry.
#[derive(Clone, Debug, Default)]
pub struct Router {
    wants: Vec<Want>,
    /// The stream the firmware runs, if any.
    fw: Option<u8>,
    /// The client whose stream the server's own `tel start` resumes.
    resuming: Option<u64>,
    /// Frames of a stream number not yet known (its reply still coming).
    held: Vec<Sample>,
}

/// Frames held at most while a stream's number is unknown.
const HELD_MAX: usize = 256;

/// The stream number in a `tel start` reply.
fn stream_number(reply: &str) -> Option<u8> {
    reply
        .lines()
        .find_map(|l| l.trim().strip_prefix("stream: "))
        .and_then(|v| v.trim().parse().ok())
}

impl Router {
    /// The reply to `line` (sent by `client`; `server` is the server's own
    /// client id) has ended; `ok`: it ended with `OK`. Returns a line the
    /// server should send next (a resume), if any.
    pub fn reply(
        &mut self,
        client: u64,
        server: u64,
        line: &TelLine,
        reply: &str,
        ok: bool,
    ) -> Option<String> {
        match line {
            TelLine::Start { rate_hz, line } => {
                if client == server {
                    let who = self.resuming.take()?;
                    let at = self.wants.iter().position(|w| w.client == who)?;
                    match (ok, stream_number(reply)) {
                        (true, Some(n)) => {
                            let mut w = self.wants.remove(at);
                            w.fw_no = n;
                            w.resumed = true;
                            self.wants.push(w);
                            self.fw = Some(n);
                        }
                        // It cannot be resumed: it is gone for good.
                        _ => {
                            self.wants.remove(at);
                        }
                    }
                } else if let (true, Some(n)) = (ok, stream_number(reply)) {
                    self.wants.retain(|w| w.client != client);
                    self.wants.push(Want {
                        client,
                        line: line.clone(),
                        rate_hz: *rate_hz,
                        client_no: n,
                        fw_no: n,
                        seq_offset: 0,
                        last: None,
                        resumed: false,
                    });
                    self.fw = Some(n);
                    // A resume in flight lost the race: this one runs.
                    self.resuming = None;
                }
            }
            TelLine::Stop => {
                if ok {
                    self.fw = None;
                    if client != server {
                        self.wants.retain(|w| w.client != client);
                    }
                }
            }
        }
        self.resume()
    }

    /// `client` is gone: returns `tel stop` if its stream was running.
    pub fn gone(&mut self, client: u64) -> Option<String> {
        let running = self.running() == Some(client);
        self.wants.retain(|w| w.client != client);
        if self.resuming == Some(client) {
            // Its resume is already queued; the stop after it ends it.
            return Some("tel stop".into());
        }
        running.then(|| "tel stop".into())
    }

    /// The client whose stream the firmware runs.
    pub fn running(&self) -> Option<u64> {
        let w = self.wants.last()?;
        (self.fw == Some(w.fw_no)).then_some(w.client)
    }

    fn resume(&mut self) -> Option<String> {
        if self.fw.is_some() || self.resuming.is_some() {
            return None;
        }
        let w = self.wants.last()?;
        self.resuming = Some(w.client);
        Some(w.line.clone())
    }

    /// Routes a frame: `(client, frame as the client knows it)`, or none
    /// (held while `waiting`, a `tel start` whose reply is still coming;
    /// else dropped: a stream nobody wants any more).
    pub fn frame(&mut self, f: Sample, waiting: bool) -> Option<(u64, Sample)> {
        let Some(w) = self.wants.last_mut() else {
            return self.hold(f, waiting);
        };
        if self.fw != Some(f.stream) || w.fw_no != f.stream {
            return self.hold(f, waiting);
        }
        if w.resumed {
            w.resumed = false;
            // Continue the client's sequence across the samples it missed,
            // counted from the drive time that passed.
            let missed = w.last.map_or(0, |(_, t)| {
                let dt_s = f64::from(f.time_us.wrapping_sub(t)) * 1e-6;
                (dt_s * f64::from(w.rate_hz)).round().max(1.0) as u16 - 1
            });
            let next = w.last.map_or(0, |(s, _)| s.wrapping_add(1));
            w.seq_offset = next.wrapping_add(missed).wrapping_sub(f.seq);
        }
        let mut g = f;
        g.stream = w.client_no;
        g.seq = f.seq.wrapping_add(w.seq_offset);
        w.last = Some((g.seq, g.time_us));
        Some((w.client, g))
    }

    fn hold(&mut self, f: Sample, waiting: bool) -> Option<(u64, Sample)> {
        if waiting && self.held.len() < HELD_MAX {
            self.held.push(f);
        }
        None
    }

    /// The held frames, to route again once a reply has been read.
    pub fn take_held(&mut self) -> Vec<Sample> {
        std::mem::take(&mut self.held)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SERVER: u64 = 0;

    fn frame(stream: u8, seq: u16, time_us: u32) -> Sample {
        Sample {
            stream,
            seq,
            time_us,
            n: 1,
            values: [0.0; drive::telemetry::MAX_CHANNELS],
        }
    }

    fn start(rate: u32, ch: &str) -> TelLine {
        TelLine::parse(&format!("tel start {rate} {ch}")).unwrap()
    }

    fn reply(n: u8) -> String {
        format!("tel start\r\nstream: {n}\r\nrate: x\r\n")
    }

    #[test]
    fn lines_are_recognised() {
        assert_eq!(
            TelLine::parse(" tel start 1000 torque,i_q "),
            Some(TelLine::Start {
                rate_hz: 1000,
                line: "tel start 1000 torque,i_q".into()
            })
        );
        assert_eq!(TelLine::parse("tel stop"), Some(TelLine::Stop));
        assert_eq!(TelLine::parse("tel status"), None);
        assert_eq!(TelLine::parse("tel start x torque"), None);
        assert_eq!(TelLine::parse("status"), None);
    }

    /// The page streams (client 1); a terminal's `drivectl tel` (client 2)
    /// takes the stream over and stops it: the page's stream is resumed,
    /// its frames under its own number, its sequence continued with the
    /// samples it missed as a gap.
    #[test]
    fn a_stream_taken_over_is_resumed_after_under_its_own_number() {
        let mut r = Router::default();
        let page = start(1000, "torque");
        assert_eq!(r.reply(1, SERVER, &page, &reply(1), true), None);
        assert_eq!(
            r.frame(frame(1, 0, 10_000), false),
            Some((1, frame(1, 0, 10_000)))
        );
        assert_eq!(
            r.frame(frame(1, 1, 11_000), false),
            Some((1, frame(1, 1, 11_000)))
        );
        // The terminal's stream: its frames go to it alone.
        let tel = start(500, "i_q");
        assert_eq!(r.reply(2, SERVER, &tel, &reply(2), true), None);
        assert_eq!(r.frame(frame(1, 2, 12_000), false), None, "the old stream");
        assert_eq!(
            r.frame(frame(2, 0, 20_000), false),
            Some((2, frame(2, 0, 20_000)))
        );
        assert_eq!(r.running(), Some(2));
        // Its stop resumes the page's.
        let resume = r.reply(2, SERVER, &TelLine::Stop, "OK", true);
        assert_eq!(resume.as_deref(), Some("tel start 1000 torque"));
        assert_eq!(r.reply(SERVER, SERVER, &page, &reply(3), true), None);
        assert_eq!(r.running(), Some(1));
        // 30 ms of drive time after its last sample at 1 kHz: 29 missed.
        let (c, f) = r.frame(frame(3, 0, 41_000), false).unwrap();
        assert_eq!((c, f.stream, f.seq, f.time_us), (1, 1, 31, 41_000));
        let (_, f) = r.frame(frame(3, 1, 42_000), false).unwrap();
        assert_eq!((f.stream, f.seq), (1, 32));
    }

    #[test]
    fn the_running_streams_client_gone_stops_it_and_resumes_the_one_below() {
        let mut r = Router::default();
        r.reply(1, SERVER, &start(100, "torque"), &reply(1), true);
        r.reply(2, SERVER, &start(100, "i_q"), &reply(2), true);
        // A suspended client gone: nothing to send.
        assert_eq!(r.gone(1), None);
        assert_eq!(r.running(), Some(2));
        r.reply(3, SERVER, &start(100, "i_d"), &reply(3), true);
        // The running one gone: stopped, then the one below resumed.
        assert_eq!(r.gone(3).as_deref(), Some("tel stop"));
        let resume = r.reply(SERVER, SERVER, &TelLine::Stop, "OK", true);
        assert_eq!(resume.as_deref(), Some("tel start 100 i_q"));
        r.reply(SERVER, SERVER, &start(100, "i_q"), &reply(4), true);
        assert_eq!(r.running(), Some(2));
        assert_eq!(r.frame(frame(4, 0, 0), false).map(|x| x.0), Some(2));
        // The last one stops: nothing left to resume.
        assert_eq!(r.reply(2, SERVER, &TelLine::Stop, "OK", true), None);
        assert_eq!(r.running(), None);
        assert_eq!(r.frame(frame(4, 1, 0), false), None);
    }

    #[test]
    fn a_refused_start_changes_nothing_and_early_frames_are_held() {
        let mut r = Router::default();
        r.reply(1, SERVER, &start(100, "torque"), &reply(1), true);
        // Refused (rate too high): the firmware still runs stream 1.
        assert_eq!(
            r.reply(2, SERVER, &start(9000, "torque"), "ERR bad-args x", false),
            None
        );
        assert_eq!(r.running(), Some(1));
        // Frames of stream 2 before its reply is read: held, then routed.
        assert_eq!(r.frame(frame(2, 0, 5), true), None);
        r.reply(2, SERVER, &start(100, "i_q"), &reply(2), true);
        let held = r.take_held();
        assert_eq!(held.len(), 1);
        assert_eq!(r.frame(held[0], false).map(|x| x.0), Some(2));
    }
}
