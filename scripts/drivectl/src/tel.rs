//! Telemetry on the host: a stream's bookkeeping (sequence
//! gaps are lost frames, drive time unwrapped) and the recording behind
//! `drivectl tel`.
use crate::link::{Final, Reply, Session};
use anyhow::{bail, Context as _, Result};
use drive::telemetry::{Sample, CHANNELS};
use std::io::Write;
use std::time::{Duration, Instant};

/// One running stream as the host sees it.
#[derive(Clone, Debug)]
pub struct Stream {
    /// Stream number the firmware gave.
    pub number: u8,
    /// Channel names in frame order.
    pub channels: Vec<String>,
    /// Samples per second of drive time.
    pub rate_hz: u32,
    /// Frames of this stream received.
    pub received: u64,
    /// Frames missing from the sequence (dropped in the firmware or lost
    /// on the link).
    pub lost: u64,
    next_seq: Option<u16>,
    last_raw_us: u32,
    time_us: u64,
}

/// The unit of a channel, `?` for an unknown name.
pub fn unit(name: &str) -> &'static str {
    CHANNELS
        .iter()
        .find(|c| c.name == name)
        .map_or("?", |c| c.unit)
}

/// Sends `line` and fails on `ERR` with the firmware's words.
pub fn ok(s: &mut Session, line: &str, timeout: Duration) -> Result<Reply> {
    let r = s.command(line, timeout)?;
    match &r.fin {
        Final::Ok => Ok(r),
        Final::Err { code, message } => bail!("`{line}`: ERR {code} {message}"),
    }
}

impl Stream {
    /// `tel start <rate_hz> <channels>` on the drive.
    pub fn start(
        s: &mut Session,
        rate_hz: u32,
        channels: &[String],
        timeout: Duration,
    ) -> Result<Self> {
        let r = ok(
            s,
            &format!("tel start {rate_hz} {}", channels.join(",")),
            timeout,
        )?;
        Self::start_from_reply(&r, rate_hz, channels)
    }

    /// The stream that a `tel start` reply `r` announced.
    pub fn start_from_reply(r: &Reply, rate_hz: u32, channels: &[String]) -> Result<Self> {
        let number = r
            .lines
            .iter()
            .find_map(|l| l.strip_prefix("stream: "))
            .and_then(|v| v.parse::<u8>().ok())
            .context("`tel start` reply without `stream: <n>`")?;
        Ok(Self {
            number,
            channels: channels.to_vec(),
            rate_hz,
            received: 0,
            lost: 0,
            next_seq: None,
            last_raw_us: 0,
            time_us: 0,
        })
    }

    /// Takes a frame of this stream: its drive time (s, unwrapped) and its
    /// values; `None` for another stream's frame or a wrong channel count.
    pub fn accept<'a>(&mut self, f: &'a Sample) -> Option<(f64, &'a [f32])> {
        if f.stream != self.number || usize::from(f.n) != self.channels.len() {
            return None;
        }
        match self.next_seq {
            None => self.time_us = u64::from(f.time_us),
            Some(want) => {
                self.lost += u64::from(f.seq.wrapping_sub(want));
                self.time_us += u64::from(f.time_us.wrapping_sub(self.last_raw_us));
            }
        }
        self.last_raw_us = f.time_us;
        self.next_seq = Some(f.seq.wrapping_add(1));
        self.received += 1;
        Some((self.time_us as f64 * 1e-6, &f.values[..usize::from(f.n)]))
    }
}

/// One recorded sample.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Drive time, s.
    pub time_s: f64,
    /// Values in channel order.
    pub values: Vec<f32>,
}

/// What `record` returns.
#[derive(Clone, Debug)]
pub struct Recording {
    /// Channel names.
    pub channels: Vec<String>,
    /// Samples per second of drive time.
    pub rate_hz: u32,
    /// The samples, drive time from the first.
    pub rows: Vec<Row>,
    /// Frames missing from the sequence within the recording.
    pub lost: u64,
    /// Frames that failed their checks during the recording.
    pub bad: u64,
    /// `status` replies received whole during the recording.
    pub status_replies: u32,
    /// Wall time of the recording.
    pub wall: Duration,
    /// Bytes per second of drive time the stream needs (`tel start`).
    pub bytes_per_s: u32,
}

/// Options of [`record`].
#[derive(Clone, Copy, Debug)]
pub struct RecordOptions {
    /// Send `status` this often during the recording and check that every
    /// reply is whole (the same lines as before the stream).
    pub status_every: Option<Duration>,
    /// Longest wait for a frame or a reply.
    pub timeout: Duration,
}

/// The keys (`name:` before the value) of a reply's lines.
fn keys(r: &Reply) -> Vec<String> {
    r.lines
        .iter()
        .map(|l| l.split(':').next().unwrap_or("").to_string())
        .collect()
}

/// Streams `channels` at `rate_hz` for `seconds` of drive time, then
/// stops the stream. `progress` gets the share of drive time done (0..=1).
pub fn record(
    s: &mut Session,
    rate_hz: u32,
    channels: &[String],
    seconds: f64,
    opts: RecordOptions,
    progress: &mut dyn FnMut(f64),
) -> Result<Recording> {
    if !(seconds > 0.0 && seconds.is_finite()) {
        bail!("--seconds must be a positive number of seconds of drive time");
    }
    let reference = match opts.status_every {
        Some(_) => Some(keys(&ok(s, "status", opts.timeout)?)),
        None => None,
    };
    let bad0 = s.frames.bad();
    let mut st = Stream::start(s, rate_hz, channels, opts.timeout)?;
    let started = Instant::now();
    let mut rows: Vec<Row> = Vec::new();
    let mut t0 = None;
    let mut lost_at_end = 0;
    let mut status_replies = 0;
    let mut next_status = opts.status_every.map(|d| Instant::now() + d);
    let mut last_frame = Instant::now();
    'rec: loop {
        if let (Some(at), Some(every), Some(keys0)) = (next_status, opts.status_every, &reference) {
            if Instant::now() >= at {
                let r = ok(s, "status", opts.timeout).context("`status` while streaming")?;
                if keys(&r) != *keys0 {
                    bail!("`status` reply while streaming is not whole: {:?}", r.lines);
                }
                status_replies += 1;
                next_status = Some(Instant::now() + every);
            }
        }
        let Some(f) = s.frames.next(Duration::from_millis(50)) else {
            if last_frame.elapsed() > opts.timeout {
                bail!(
                    "no telemetry frame for {:?} ({} received)",
                    opts.timeout,
                    rows.len()
                );
            }
            continue;
        };
        for f in std::iter::once(f).chain(s.frames.drain()) {
            let Some((t, v)) = st.accept(&f) else {
                continue;
            };
            last_frame = Instant::now();
            let t0 = *t0.get_or_insert(t);
            if t - t0 >= seconds - 1e-9 {
                break 'rec;
            }
            lost_at_end = st.lost;
            rows.push(Row {
                time_s: t - t0,
                values: v.to_vec(),
            });
            progress(((t - t0) / seconds).min(1.0));
        }
    }
    let wall = started.elapsed();
    let _ = ok(s, "tel stop", opts.timeout)?;
    progress(1.0);
    let bytes_per_s = rate_hz * drive::telemetry::frame_bytes(channels.len()) as u32;
    Ok(Recording {
        channels: channels.to_vec(),
        rate_hz,
        rows,
        lost: lost_at_end,
        bad: s.frames.bad() - bad0,
        status_replies,
        wall,
        bytes_per_s,
    })
}

/// Writes the recording as CSV: `time_s` and one column per channel,
/// named `<channel>_<unit>`.
pub fn write_csv(rec: &Recording, out: &mut dyn Write) -> Result<()> {
    write!(out, "time_s")?;
    for c in &rec.channels {
        write!(out, ",{c}_{}", unit(c).replace('/', "_per_"))?;
    }
    writeln!(out)?;
    for r in &rec.rows {
        write!(out, "{:.6}", r.time_s)?;
        for v in &r.values {
            write!(out, ",{v}")?;
        }
        writeln!(out)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use drive::telemetry::MAX_CHANNELS;

    fn frame(stream: u8, seq: u16, time_us: u32) -> Sample {
        Sample {
            stream,
            seq,
            time_us,
            n: 2,
            values: [1.0; MAX_CHANNELS],
        }
    }

    fn stream() -> Stream {
        Stream {
            number: 4,
            channels: vec!["torque".into(), "i_q".into()],
            rate_hz: 1000,
            received: 0,
            lost: 0,
            next_seq: None,
            last_raw_us: 0,
            time_us: 0,
        }
    }

    #[test]
    fn gaps_in_the_sequence_are_lost_frames_across_the_wrap() {
        let mut st = stream();
        for seq in [65533u16, 65534, 1, 2, 5] {
            st.accept(&frame(4, seq, 0)).unwrap();
        }
        // 65535, 0, 3 and 4 are missing.
        assert_eq!((st.received, st.lost), (5, 4));
        assert!(st.accept(&frame(3, 6, 0)).is_none(), "another stream");
    }

    #[test]
    fn drive_time_unwraps_past_u32_microseconds() {
        let mut st = stream();
        let (t, _) = st.accept(&frame(4, 0, u32::MAX - 499)).unwrap();
        let (t2, _) = st.accept(&frame(4, 1, 500)).unwrap();
        assert!((t2 - t - 1e-3).abs() < 1e-9, "{t} {t2}");
    }

    #[test]
    fn csv_has_units_in_the_header() {
        let rec = Recording {
            channels: vec!["torque".into(), "velocity".into()],
            rate_hz: 1000,
            rows: vec![Row {
                time_s: 0.001,
                values: vec![0.25, -3.0],
            }],
            lost: 0,
            bad: 0,
            status_replies: 0,
            wall: Duration::ZERO,
            bytes_per_s: 0,
        };
        let mut out = Vec::new();
        write_csv(&rec, &mut out).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "time_s,torque_Nm,velocity_rev_per_s\n0.001000,0.25,-3\n"
        );
    }
}
